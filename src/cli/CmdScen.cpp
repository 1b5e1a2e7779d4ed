// SPDX-License-Identifier: BSD-3-Clause
/* mhplan scen: run every problem of a MovingAI scenario file and compare the lengths with the file's optima.
 */
#include "mhplan/cli/Commands.h"

#include "mhplan/cli/Args.h"
#include "mhplan/collision/Collision.h"
#include "mhplan/collision/Problem.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/io/WorldIO.h"

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
    namespace
    {
        /** \brief One line of a MovingAI .scen file (coordinates: x = column, y = row from the top). */
        struct ScenProblem
        {
            int line{0};
            int bucket{0};
            int sx{0}, sy{0}, gx{0}, gy{0};
            double optimal{0.0};
        };

        bool parseInt(const std::string &s, int &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            const long v = std::strtol(s.c_str(), &end, 10);
            if (errno != 0 || end != s.c_str() + s.size() || v < -2147483647L || v > 2147483647L)
                return false;
            out = static_cast<int>(v);
            return true;
        }

        bool parseReal(const std::string &s, double &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            out = std::strtod(s.c_str(), &end);
            return errno == 0 && end == s.c_str() + s.size() && std::isfinite(out);
        }

        /** \brief Parse a scenario file for \e grid; throws InputError naming the file and line. */
        std::vector<ScenProblem> parseScen(const std::string &path, const OccupancyGrid &grid)
        {
            std::ifstream in(path);
            if (!in)
                throw InputError(path + ": cannot open the scenario file");
            std::vector<ScenProblem> out;
            std::string text;
            int lineNo = 0;
            bool haveVersion = false;
            while (std::getline(in, text))
            {
                ++lineNo;
                if (!text.empty() && text.back() == '\r')
                    text.pop_back();
                std::istringstream fields(text);
                std::vector<std::string> f;
                for (std::string w; fields >> w;)
                    f.push_back(w);
                if (f.empty())
                    continue;
                const std::string where = path + ":" + std::to_string(lineNo) + ": ";
                if (!haveVersion)
                {
                    double version = 0.0;
                    if (f.size() != 2 || f[0] != "version" || !parseReal(f[1], version))
                        throw InputError(where + "expected the header 'version 1', got '" + text + "'");
                    if (version < 1.0 || version >= 2.0)
                        throw InputError(where + "unsupported scenario version '" + f[1] +
                                         "' (supported: version 1)");
                    haveVersion = true;
                    continue;
                }
                if (f.size() != 9)
                    throw InputError(where +
                                     "expected 9 fields (bucket map width height start-x start-y goal-x " +
                                     "goal-y optimal-length), got " + std::to_string(f.size()));
                ScenProblem p;
                p.line = lineNo;
                int width = 0, height = 0;
                const char *names[] = {"bucket", "width", "height", "start-x", "start-y", "goal-x", "goal-y"};
                int *targets[] = {&p.bucket, &width, &height, &p.sx, &p.sy, &p.gx, &p.gy};
                const std::size_t columns[] = {0, 2, 3, 4, 5, 6, 7};
                for (std::size_t k = 0; k < 7; ++k)
                    if (!parseInt(f[columns[k]], *targets[k]))
                        throw InputError(where + "field '" + names[k] + "': expected an integer, got '" +
                                         f[columns[k]] + "'");
                if (!parseReal(f[8], p.optimal) || p.optimal < 0.0)
                    throw InputError(where + "field 'optimal-length': expected a number >= 0, got '" + f[8] +
                                     "'");
                if (width != grid.width() || height != grid.height())
                    throw InputError(where + "map size " + std::to_string(width) + " x " +
                                     std::to_string(height) + " does not match the map (" +
                                     std::to_string(grid.width()) + " x " + std::to_string(grid.height()) +
                                     ")");
                const auto cellOk = [&](int x, int y, const char *what)
                {
                    if (x < 0 || y < 0 || x >= width || y >= height)
                        throw InputError(where + what + " (" + std::to_string(x) + ", " + std::to_string(y) +
                                         ") is outside the map");
                    if (grid.blocked(x, grid.rowToIy(y)))
                        throw InputError(where + what + " (" + std::to_string(x) + ", " + std::to_string(y) +
                                         ") is a blocked cell");
                };
                cellOk(p.sx, p.sy, "start");
                cellOk(p.gx, p.gy, "goal");
                out.push_back(p);
            }
            if (!haveVersion)
                throw InputError(path + ": empty scenario file (expected the header 'version 1')");
            if (out.empty())
                throw InputError(path + ": the scenario has no problems");
            return out;
        }
    } // namespace

    int cmdScen(const Argv &argv)
    {
        const Args args("scen", argv, {{"planner", "time"}, {}, {"verbose"}});
        if (args.positional().size() != 2)
            throw InputError("mhplan scen: expected two arguments, MAP.map SCEN.scen");
        const std::string mapPath = args.positional()[0];
        const std::string scenPath = args.positional()[1];
        const std::string plannerName = args.get("planner", "AStar");
        PlannerRegistry::builtin().get(plannerName); // refuse an unknown name before any work
        const double timeLimit = args.number("time", 0.0);
        if (args.has("time") && !(timeLimit > 0.0))
            throw InputError("mhplan scen: --time must be > 0 seconds (got " + args.get("time") + ")");
        const bool verbose = args.has("verbose");

        const World world = loadWorld(mapPath);
        if (!world.isGrid())
            throw InputError(mapPath + ": not a grid map (expected a MovingAI .map)");
        const OccupancyGrid &grid = *world.grid;
        const std::vector<ScenProblem> problems = parseScen(scenPath, grid);
        const CollisionModelPtr model = makeCollisionModel(world, CollisionBackend::Grid);

        std::cout << "map:       " << mapPath << " (" << grid.width() << " x " << grid.height() << ", "
                  << grid.blockedCount() << " blocked)\n";
        std::cout << "scenario:  " << scenPath << " (" << problems.size() << " problems)\n";
        std::cout << "planner:   " << plannerName << "\n";

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
        ob::PlannerPtr planner = PlannerRegistry::builtin().create(plannerName, ss->getSpaceInformation());
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
            const bool match = exact && std::fabs(length - p.optimal) <= std::max(1e-4, 1e-5 * p.optimal);
            matched += match ? 1 : 0;
            if (verbose || !match)
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
