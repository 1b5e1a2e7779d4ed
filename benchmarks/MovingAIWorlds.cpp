// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/MovingAIWorlds.h"

#include "src/base/World.h"
#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/io/ScenIO.h"
#include "src/io/WorldIO.h"
#include "src/optimum/Optimum.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>

namespace mhplan::bench::detail
{
    void readMovingAIWorld(const YamlReader &r, const YAML::Node &entry, const std::string &field,
                           WorldSpec &w)
    {
        r.allowKeys(entry, field, {"map", "scen", "problems_per_bucket", "buckets", "every"});
        w.line = entry.Mark().line + 1;
        w.world = r.nonEmptyText(entry["map"], field + ".map");
        w.scen = r.nonEmptyText(r.require(entry, "scen", field + ".scen"), field + ".scen");
        if (entry["problems_per_bucket"].IsDefined())
            w.scenPerBucket = static_cast<unsigned int>(
                r.integer(entry["problems_per_bucket"], field + ".problems_per_bucket", 1, 1000000));
        if (entry["every"].IsDefined())
            w.scenEvery = static_cast<unsigned int>(r.integer(entry["every"], field + ".every", 1, 1000000));
        const YAML::Node b = entry["buckets"];
        if (b.IsDefined())
        {
            if (!b.IsSequence() || b.size() == 0)
                r.fail(b, field + ".buckets", "expected a non-empty list of bucket numbers");
            for (std::size_t k = 0; k < b.size(); ++k)
                w.scenBuckets.push_back(static_cast<int>(
                    r.integer(b[k], field + ".buckets[" + std::to_string(k) + "]", 0, 2147483647LL)));
        }
    }

    void appendMovingAIExperiments(const Campaign &campaign, const WorldSpec &spec, std::size_t index,
                                   const std::function<std::string(const std::string &)> &locate,
                                   const std::string &common, std::set<std::string> &names,
                                   std::vector<Experiment> &out)
    {
        const std::string where =
            campaign.file + ":" + std::to_string(spec.line) + ": worlds[" + std::to_string(index) + "]: ";
        std::string mapFile, scenFile;
        World world;
        std::string mapText; // the bytes parsed: hashed once for all the selected problems
        std::vector<ScenProblem> problems;
        try
        {
            mapFile = locate(spec.world);
            scenFile = locate(spec.scen);
            world = loadWorld(mapFile, &mapText);
            if (!world.isGrid())
                throw InputError(mapFile + ": not a grid map (expected a MovingAI .map)");
            problems = loadMovingAIScen(scenFile, *world.grid);
        }
        catch (const InputError &e)
        {
            throw InputError(where + e.what());
        }
        ScenSelection selection;
        selection.buckets = spec.scenBuckets;
        selection.every = spec.scenEvery;
        selection.perBucket = spec.scenPerBucket;
        const std::vector<ScenProblem> selected = selectScenProblems(problems, selection);
        if (selected.empty())
            throw InputError(where + "no problem of " + scenFile + " is selected (buckets, every, " +
                             "problems_per_bucket)");
        const OccupancyGrid &grid = *world.grid;
        const CollisionModelPtr model = makeCollisionModel(world, parseCollisionBackend(campaign.collision));
        Fingerprint prefix;
        prefix.add(common);
        prefix.add("map ");
        prefix.add(mapText);
        const std::string inputHash = fingerprint(mapText);
        for (const ScenProblem &p : selected)
        {
            Query q;
            q.name = "b" + std::to_string(p.bucket) + "-l" + std::to_string(p.line);
            q.start = grid.cellCenter(p.sx, grid.rowToIy(p.sy));
            q.goal = grid.cellCenter(p.gx, grid.rowToIy(p.gy));
            const std::string at = scenFile + ":" + std::to_string(p.line) + ": ";
            try
            {
                validateQuery(world, q, *model);
            }
            catch (const InputError &e)
            {
                throw InputError(where + at + e.what());
            }
            const OptimumResult octile = computeGridOctileOptimum(world, q);
            if (!octile.found)
                throw InputError(where + at + "the .scen optimum is " + std::to_string(p.optimal) +
                                 " but mhplan finds no 8-connected path from start to goal");
            if (!scenOptimumMatches(p.optimal, octile.lengthCells))
            {
                std::ostringstream msg;
                msg.precision(10);
                msg << where << at << "field 'optimal-length': the .scen optimum " << p.optimal
                    << " differs from mhplan's octile optimum " << octile.lengthCells
                    << " (cells; accepted: within max(1e-4, 1e-5 x optimum))";
                throw InputError(msg.str());
            }
            Experiment e;
            e.index = out.size();
            e.name = world.name + "-" + q.name;
            e.worldFile = mapFile;
            e.worldName = world.name;
            e.query = q.name;
            e.scenFile = scenFile;
            e.scenLine = p.line;
            e.scenBucket = p.bucket;
            e.scenOptimum = p.optimal;
            e.octileOptimum = octile.lengthCells;
            e.startX = q.start.x;
            e.startY = q.start.y;
            e.goalX = q.goal.x;
            e.goalY = q.goal.y;
            e.runs = campaign.runs;
            if (!names.insert(e.name).second)
                throw InputError(where + "experiment '" + e.name +
                                 "' appears twice (the same map and .scen problem listed twice)");
            e.seed = deriveSeed(campaign.seed, e.name, 0);
            std::ostringstream tail;
            tail.precision(17);
            tail << "\nscen " << q.name << " " << q.start.x << " " << q.start.y << " " << q.goal.x << " "
                 << q.goal.y << " " << p.optimal << "\n";
            Fingerprint all = prefix;
            all.add(tail.str());
            e.configHash = all.hex();
            e.inputHash = inputHash;
            out.push_back(std::move(e));
        }
    }
} // namespace mhplan::bench::detail
