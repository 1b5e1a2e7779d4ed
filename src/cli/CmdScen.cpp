// SPDX-License-Identifier: BSD-3-Clause
/* mhplan scen: run every problem of a MovingAI scenario file and compare the lengths with the file's optima.
 */
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/io/ScenIO.h"
#include "src/io/WorldIO.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan::cli
{
    const CommandDoc &scenDoc()
    {
        static const CommandDoc doc{
            "scen MAP.map SCEN.scen [options]",
            "run every problem of a MovingAI scenario file and compare the lengths with the file's optima",
            "Lengths are in cells (the .scen file's unit); a length matches when it is within max(1e-4, "
            "1e-5 x optimal) of the file's optimal length (8-connected octile lengths: AStar reproduces "
            "them).",
            {{"MAP.map", "the MovingAI map"}, {"SCEN.scen", "its scenario file (version 1)"}},
            {{"--planner", "NAME", "the planner (default AStar; one planner object for all problems)"},
             {"--time", "S",
              "time limit per problem in seconds, > 0 (default: none, until the planner stops)"},
             {"--verbose", "", "print every problem, not only the mismatches"},
             options::json("every problem's result and the totals")},
            {"scen arena.map arena.map.scen",
             "scen arena.map arena.map.scen --planner ThetaStar --time 1 --json"},
            "0 every length matches, 1 bad input, 2 internal error, 3 some length does not match"};
        return doc;
    }

    int cmdScen(const Argv &argv)
    {
        const Args args("scen", argv, {{"planner", "time"}, {}, {"verbose", "json"}});
        const bool json = args.has("json");
        if (args.positional().size() != 2)
            throw InputError("mhplan scen: expected two arguments, MAP.map SCEN.scen");
        const std::string mapPath = args.positional()[0];
        const std::string scenPath = args.positional()[1];
        const std::string plannerName = args.get("planner", "AStar");
        builtinPlanners().get(plannerName); // refuse an unknown name before any work
        const double timeLimit = args.has("time") ? args.timeLimit(0.0) : 0.0;
        const bool verbose = args.has("verbose");

        const World world = loadWorld(mapPath);
        if (!world.isGrid())
            throw InputError(mapPath + ": not a grid map (expected a MovingAI .map)");
        const OccupancyGrid &grid = *world.grid;
        const std::vector<ScenProblem> problems = loadMovingAIScen(scenPath, grid);
        const CollisionModelPtr model = makeCollisionModel(world, CollisionBackend::Grid);

        JsonWriter out(std::cout);
        if (json)
            out.beginObject()
                .field("command", "scen")
                .field("map", mapPath)
                .field("scenario", scenPath)
                .field("planner", plannerName)
                .field("problems", problems.size())
                .key("results")
                .beginArray();
        else
            std::cout << "map:       " << mapPath << " (" << grid.width() << " x " << grid.height() << ", "
                      << grid.blockedCount() << " blocked)\n";
        if (!json)
            std::cout << "scenario:  " << scenPath << " (" << problems.size() << " problems)\n"
                      << "planner:   " << plannerName << "\n";

        // One setup and one planner for all problems: only start and goal change.
        const auto query = [&](const ScenProblem &p)
        {
            Query q;
            q.name = "line " + std::to_string(p.line);
            q.start = grid.cellCenter(p.sx, grid.rowToIy(p.sy));
            q.goal = grid.cellCenter(p.gx, grid.rowToIy(p.gy));
            return q;
        };
        og::SimpleSetupPtr ss = makeSimpleSetup(world, query(problems.front()), model);
        ob::PlannerPtr planner = builtinPlanners().create(plannerName, ss->getSpaceInformation());
        ss->setPlanner(planner);
        ss->setup();
        const auto &props = planner->getPlannerProgressProperties();
        const auto iterations = props.find("iterations INTEGER");
        const double threshold = 1e-9 * std::hypot(world.bounds.width(), world.bounds.height());

        std::size_t matched = 0;
        unsigned long totalIterations = 0;
        double totalSeconds = 0.0;
        for (const ScenProblem &p : problems)
        {
            const Query q = query(p);
            validateQuery(world, q, *model);
            ss->clear();
            ob::ScopedState<> start(ss->getStateSpace()), goal(ss->getStateSpace());
            start[0] = q.start.x;
            start[1] = q.start.y;
            goal[0] = q.goal.x;
            goal[1] = q.goal.y;
            ss->setStartAndGoalStates(start, goal, threshold);
            const ompl::time::point t0 = ompl::time::now();
            const ob::PlannerStatus status =
                ss->solve(timeLimit > 0.0 ? ob::timedPlannerTerminationCondition(timeLimit)
                                          : ob::plannerNonTerminatingCondition());
            totalSeconds += ompl::time::seconds(ompl::time::now() - t0);
            if (iterations != props.end())
                totalIterations += std::stoul(iterations->second());
            const bool exact = status == ob::PlannerStatus::EXACT_SOLUTION && ss->haveExactSolutionPath();
            const double length = exact ? ss->getSolutionPath().length() / grid.cellSize() : 0.0;
            const bool match = exact && scenOptimumMatches(p.optimal, length);
            matched += match ? 1 : 0;
            if (json)
            {
                out.beginObject().field("line", p.line).field("bucket", p.bucket);
                out.key("start").beginArray().value(p.sx).value(p.sy).endArray();
                out.key("goal").beginArray().value(p.gx).value(p.gy).endArray();
                out.field("status", status.asString()).field("exact", exact);
                out.key("length");
                exact ? out.value(length) : out.null();
                out.field("optimal", p.optimal).field("match", match).endObject();
            }
            else if (verbose || !match)
            {
                std::cout << std::setprecision(10) << scenPath << ":" << p.line << ": bucket " << p.bucket
                          << ", (" << p.sx << ", " << p.sy << ") -> (" << p.gx << ", " << p.gy << "): ";
                if (exact)
                    std::cout << "length " << length;
                else
                    std::cout << "no exact path (" << status.asString() << ")";
                std::cout << ", optimal " << p.optimal << (match ? "" : "  MISMATCH") << "\n";
            }
        }
        if (json)
        {
            out.endArray().field("matched", matched).field("time", totalSeconds);
            out.key("iterations");
            iterations != props.end() ? out.value(totalIterations) : out.null();
            out.endObject().finish();
            return matched == problems.size() ? 0 : 3;
        }
        std::cout << std::setprecision(6) << "time:      " << totalSeconds << " s";
        if (iterations != props.end())
            std::cout << ", " << totalIterations << " iterations"
                      << (totalSeconds > 0.0 ? " (" +
                                                   std::to_string(static_cast<long long>(
                                                       std::llround(totalIterations / totalSeconds))) +
                                                   " per second)"
                                             : std::string());
        std::cout << "\n" << matched << " of " << problems.size() << " lengths match\n";
        return matched == problems.size() ? 0 : 3;
    }
} // namespace mhplan::cli
