// SPDX-License-Identifier: BSD-3-Clause
/* mhplan compare: every planner on every world's first query (or --query); a table (or JSON) of success,
   lengths, the optimum, the gap and time; "n/a" where a planner's declared capabilities exclude the world's
   space (PlannerRegistry::whyNotApplicable). */
#include "src/metrics/MetricList.h"
#include "src/collision/RigidValidity.h"
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "src/optimum/Optimum.h"
#include "src/registry/Registry.h"

#include <ompl/util/Time.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan::cli
{
    namespace
    {
        std::vector<std::string> splitList(const std::string &text)
        {
            std::vector<std::string> out;
            std::stringstream ss(text);
            std::string item;
            while (std::getline(ss, item, ','))
                if (!item.empty())
                    out.push_back(item);
            return out;
        }

        /** The default comparison set: OMPL's optimizing baselines plus every mhplan planner registered. */
        std::vector<std::string> defaultComparePlanners()
        {
            std::vector<std::string> out = {"RRTstar", "InformedRRTstar", "PRMstar", "BITstar"};
            const PlannerRegistry &reg = builtinPlanners();
            for (const auto &name : reg.names())
                if (reg.get(name).origin == "mhplan")
                    out.push_back(name);
            return out;
        }
    } // namespace

    const CommandDoc &compareDoc()
    {
        static const CommandDoc doc{
            "compare [WORLD...] [options]",
            "plan the first query (or --query) of every shipped world (or of the given ones) with each "
            "planner; print a table of success, lengths, optimum, gap and time",
            "A run counts as exact when the planner reports an exact solution whose path passes the exact "
            "segment check. Lengths and the gap are over exact runs; the gap is that of the median length. "
            "A planner that cannot run on a world's state space (it declares other spaces, see `mhplan "
            "planners`) is not run there: its row says n/a, and the reasons follow the table.",
            {{"WORLD", "world files or names of shipped worlds (default: every shipped world)"}},
            {{"--planners", "A,B,...",
              "comma-separated planners (default: RRTstar, InformedRRTstar, PRMstar, BITstar and every "
              "mhplan planner)"},
             {"--query", "NAME", "the named query of each world (default: each world's first query)"},
             {"--time", "S", "time limit per run in seconds, 0.001..1000000 (default 1)"},
             {"--runs", "N", "runs per world and planner, 1..1000 (default 1)"},
             options::seed(),
             options::setup(),
             options::resolution(),
             options::json("one result per world and planner")},
            {"compare bfo_case1 lrsma_scenario1 --planners RRTstar,SMA,LRSMA --runs 5 --time 0.5 --seed 3",
             "compare --planners BITstar,GA --json"}};
        return doc;
    }

    int cmdCompare(const Argv &argv)
    {
        const Args args("compare", argv,
                        {{"planners", "time", "runs", "seed", "query", "setup", "resolution"}, {}, {"json"}});
        const ValiditySetup setup = setupFromArgs(args);
        const std::uint_fast32_t seed = seedFromArgs(args);
        const double timeLimit = args.timeLimit(1.0);
        const long long runs = args.integer("runs", 1);
        if (runs < 1 || runs > 1000)
            throw InputError("mhplan compare: --runs must be in [1, 1000] (got " + args.get("runs") + ")");
        std::vector<std::string> planners =
            args.has("planners") ? splitList(args.get("planners")) : defaultComparePlanners();
        if (planners.empty())
            throw InputError("mhplan compare: --planners names no planner (got '" + args.get("planners") +
                             "'); give a comma-separated list, e.g. RRTstar,SMA");
        for (const auto &p : planners)
            builtinPlanners().get(p); // refuse unknown names before any work
        std::vector<std::string> files;
        for (const auto &w : args.positional())
            files.push_back(resolveWorldPath(w));
        if (files.empty())
            files = shippedWorldFiles();

        const bool json = args.has("json");
        JsonWriter out(std::cout);
        if (json)
        {
            out.beginObject()
                .field("command", "compare")
                .field("seed", static_cast<unsigned long long>(seed))
                .field("time_limit", timeLimit)
                .field("runs", runs)
                .field("setup", setup.name());
            out.key("resolution");
            setup.app() ? out.value(setup.resolution) : out.null();
            out.key("results").beginArray();
        }
        else
            std::cout << "seed " << seed << ", time limit " << timeLimit << " s, " << runs
                      << " run(s) per pair, set-up " << setup.describe() << "\n\n";
        // Column widths that fit every name (a name never runs into the next column).
        int worldWidth = 17, plannerWidth = 16;
        for (const auto &f : files)
            worldWidth =
                std::max(worldWidth, static_cast<int>(std::filesystem::path(f).stem().string().size()));
        for (const auto &p : planners)
            plannerWidth = std::max(plannerWidth, static_cast<int>(p.size()));
        const auto names = [&](const std::string &world, const std::string &planner)
        {
            std::cout << std::left << std::setw(worldWidth) << world << ' ' << std::setw(plannerWidth)
                      << planner << ' ' << std::right;
        };
        if (!json)
        {
            names("world", "planner");
            std::cout << std::setw(7) << "exact" << std::setw(12) << "best len" << std::setw(12)
                      << "median len" << std::setw(12) << "optimum" << std::setw(12) << "median gap"
                      << std::setw(11) << "time [s]"
                      << "\n";
        }
        std::vector<std::string> reasons; // why the n/a rows are n/a, once per planner
        for (const auto &file : files)
        {
            const World world = loadWorld(file);
            const Query &query = world.queryOrDefault(args.get("query"));
            const CollisionModelPtr model = makeCollisionModel(world);
            const OptimumOrReason optimum = optimumOrReason(world, query);
            std::ostringstream optText;
            optText << std::fixed << std::setprecision(4);
            if (optimum.result.found)
                optText << optimum.result.length;
            else
                optText << "-";
            for (const auto &name : planners)
            {
                const std::string why = builtinPlanners().whyNotApplicable(
                    name, spaceFlag(world.space),
                    "the " + spaceName(spaceFlag(world.space)) + " world '" + world.name + "'");
                if (!why.empty())
                {
                    if (json)
                    {
                        out.beginObject().field("world", world.name).field("file", file);
                        out.key("query");
                        writeQuery(out, query);
                        out.field("planner", name)
                            .field("applicable", false)
                            .field("reason", why)
                            .endObject();
                        continue;
                    }
                    const std::string note =
                        name + " plans on " + spaceList(builtinPlanners().get(name).capabilities) + " only";
                    if (std::find(reasons.begin(), reasons.end(), note) == reasons.end())
                        reasons.push_back(note);
                    names(world.name, name);
                    std::cout << std::setw(7) << "n/a" << std::setw(12) << "-" << std::setw(12) << "-"
                              << std::setw(12) << optText.str() << std::setw(12) << "-" << std::setw(11)
                              << "-"
                              << "\n";
                    continue;
                }
                std::vector<double> lengths;
                // Every registered metric (src/metrics/MetricList.h) of the exact runs, as a campaign
                // prepares the path; the lengths are the list's "path length".
                std::map<std::string, std::vector<double>> values;
                const auto keep = [&](const MetricPath &path)
                {
                    for (const auto &[property, value] : evaluatePathMetrics(path))
                    {
                        std::vector<double> &v = values[property];
                        if (value && !std::isnan(*value))
                            v.push_back(*value);
                        if (property == "path length REAL")
                            lengths.push_back(*value);
                    }
                };
                const double noOptimum =
                    optimum.result.found ? optimum.result.length : std::numeric_limits<double>::quiet_NaN();
                double totalTime = 0.0;
                int exact = 0;
                for (long long r = 0; r < runs; ++r)
                {
                    og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model, setup);
                    ss->setPlanner(builtinPlanners().create(name, ss->getSpaceInformation()));
                    const ompl::time::point t0 = ompl::time::now();
                    const ob::PlannerStatus status = ss->solve(timeLimit);
                    totalTime += ompl::time::seconds(ompl::time::now() - t0);
                    if (status != ob::PlannerStatus::EXACT_SOLUTION || !ss->haveExactSolutionPath())
                        continue;
                    if (world.isRigid())
                    {
                        // The robot checked independently along the space's interpolation; its metric.
                        std::vector<Pose2> poses;
                        const MetricPath path = rigidRunMetricPath(
                            world, *ss->getSpaceInformation(), ss->getSolutionPath(),
                            defaultMetricStep(world), true, std::numeric_limits<double>::quiet_NaN(), poses);
                        if (!path.collisionFree)
                            continue;
                        ++exact;
                        keep(path);
                        continue;
                    }
                    const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
                    bool ok = true;
                    for (std::size_t i = 1; i < pts.size() && ok; ++i)
                        ok = model->segmentValid(pts[i - 1], pts[i]);
                    if (!ok)
                        continue;
                    ++exact;
                    keep(planarMetricPath(world, pts, *model, defaultMetricStep(world), true, noOptimum));
                }
                const auto medianOf = [](std::vector<double> &v)
                {
                    std::sort(v.begin(), v.end());
                    const std::size_t n = v.size();
                    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
                };
                const std::size_t n = lengths.size();
                const double med = medianOf(lengths);
                if (json)
                {
                    out.beginObject().field("world", world.name).field("file", file);
                    out.key("query");
                    writeQuery(out, query);
                    out.field("planner", name)
                        .field("applicable", true)
                        .field("runs", runs)
                        .field("exact", exact);
                    out.key("optimum");
                    optimum.result.found ? out.value(optimum.result.length) : out.null();
                    out.key("best_length");
                    n ? out.value(lengths.front()) : out.null();
                    out.key("median_length");
                    n ? out.value(med) : out.null();
                    out.key("median_gap_percent");
                    n &&optimum.result.found ? out.value(100.0 * optimalityGap(med, optimum.result))
                                             : out.null();
                    out.field("mean_time", totalTime / static_cast<double>(runs));
                    out.key("median_metrics").beginObject();
                    for (const PathMetric &m : pathMetrics())
                    {
                        std::vector<double> &v = values[m.property];
                        out.key(metricColumn(m.property));
                        v.empty() ? out.null() : out.value(medianOf(v));
                    }
                    out.endObject().endObject();
                    continue;
                }
                std::ostringstream best, median, gap;
                best << std::fixed << std::setprecision(4);
                median << std::fixed << std::setprecision(4);
                gap << std::fixed << std::setprecision(2);
                if (lengths.empty())
                {
                    best << "-";
                    median << "-";
                    gap << "-";
                }
                else
                {
                    best << lengths.front();
                    median << med;
                    if (optimum.result.found)
                        gap << 100.0 * optimalityGap(med, optimum.result) << "%";
                    else
                        gap << "-";
                }
                names(world.name, name);
                std::cout << std::setw(4) << exact << "/" << std::left << std::setw(2) << runs << std::right
                          << std::setw(12) << best.str() << std::setw(12) << median.str() << std::setw(12)
                          << optText.str() << std::setw(12) << gap.str() << std::setw(11) << std::fixed
                          << std::setprecision(3) << totalTime / static_cast<double>(runs) << "\n"
                          << std::defaultfloat;
            }
        }
        if (json)
            out.endArray().endObject().finish();
        else if (!reasons.empty())
        {
            std::cout
                << "\nn/a: not run, the planner cannot run on the world's state space (`mhplan planners` "
                   "lists each planner's spaces):\n";
            for (const std::string &why : reasons)
                std::cout << "  " << why << "\n";
        }
        return 0;
    }
} // namespace mhplan::cli
