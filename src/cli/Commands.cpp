// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/cli/Commands.h"

#include "mhplan/cli/Args.h"
#include "mhplan/collision/Collision.h"
#include "mhplan/io/Generators.h"
#include "mhplan/io/GridIO.h"
#include "mhplan/optimum/Optimum.h"
#include "mhplan/collision/Problem.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/sim/Controllers.h"
#include "mhplan/draw/Svg.h"
#include "mhplan/collision/Validity.h"
#include "mhplan/io/WorldIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace fs = std::filesystem;

namespace mhplan::cli
{
    std::string environmentsDir()
    {
        if (const char *env = std::getenv("MHPLAN_ENVIRONMENTS"))
            return env;
        // An installed program uses its share/mhplan/environments; a build tree the source tree's worlds.
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec)
        {
            const fs::path installed = exe.parent_path().parent_path() / MHPLAN_INSTALLED_ENVIRONMENTS_DIR;
            if (fs::is_directory(installed))
                return installed.string();
        }
        return MHPLAN_ENVIRONMENTS_DIR;
    }

    std::string resolveWorldPath(const std::string &arg)
    {
        if (fs::exists(arg))
            return arg;
        for (const char *ext : {".yaml", ".yml", ".map", ".pgm"})
        {
            const fs::path p = fs::path(environmentsDir()) / (arg + ext);
            if (fs::exists(p))
                return p.string();
        }
        throw InputError("world '" + arg + "': no such file, and no shipped world of that name in " +
                         environmentsDir() + " (see 'mhplan worlds')");
    }

    std::vector<std::string> shippedWorldFiles()
    {
        std::vector<std::string> out;
        if (!fs::is_directory(environmentsDir()))
            return out;
        for (const auto &e : fs::directory_iterator(environmentsDir()))
        {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
                out.push_back(e.path().string());
        }
        std::sort(out.begin(), out.end());
        return out;
    }

    World loadWorldArg(const Args &args)
    {
        if (args.positional().size() != 1)
            throw InputError("mhplan " + args.command() +
                             ": expected exactly one WORLD argument (a file or a shipped "
                             "world name; see 'mhplan worlds')");
        return loadWorld(resolveWorldPath(args.positional()[0]));
    }

    Query queryFromArgs(const World &world, const Args &args)
    {
        if (args.has("start") || args.has("goal"))
        {
            if (!(args.has("start") && args.has("goal")))
                throw InputError("mhplan " + args.command() + ": give both --start X,Y and --goal X,Y");
            if (args.has("query"))
                throw InputError("mhplan " + args.command() + ": give either --query or --start/--goal");
            return {"command-line", args.point("start"), args.point("goal")};
        }
        return world.queryOrDefault(args.get("query"));
    }

    std::uint_fast32_t seedFromArgs(const Args &args)
    {
        const long long seed = args.integer("seed", 0);
        if (args.has("seed") && (seed <= 0 || seed > 0xFFFFFFFFLL))
            throw InputError("mhplan " + args.command() + ": --seed must be in [1, 4294967295] (got " +
                             args.get("seed") + ")");
        // Without --seed, OMPL's own first seed (from the clock; on 64-bit Linux wider than 32 bits) is
        // folded into [1, 2^32 - 1] and set, so that the printed seed, given as --seed, reproduces the run.
        const std::uint_fast32_t used =
            args.has("seed") ? static_cast<std::uint_fast32_t>(seed)
                             : static_cast<std::uint_fast32_t>(ompl::RNG::getSeed() % 0xFFFFFFFFULL + 1);
        ompl::RNG::setSeed(used);
        return used;
    }

    OptimumOrReason optimumOrReason(const World &world, const Query &query)
    {
        OptimumOrReason out;
        try
        {
            out.result = computeOptimum(world, query);
            if (!out.result.found)
                out.reason = "start and goal are not connected";
        }
        catch (const InputError &e)
        {
            out.reason = e.what();
        }
        return out;
    }

    int cmdPlan(const Argv &argv)
    {
        const Args args(
            "plan", argv,
            {{"query", "start", "goal", "planner", "time", "seed", "backend", "svg"}, {"set"}, {}});
        // The seed must be fixed before any OMPL random number generator exists.
        const std::uint_fast32_t seed = seedFromArgs(args);
        const World world = loadWorldArg(args);
        const Query query = queryFromArgs(world, args);
        const std::string plannerName = args.get("planner", "RRTstar");
        const double timeLimit = args.number("time", 1.0);
        if (!(timeLimit > 0.0))
            throw InputError("mhplan plan: --time must be > 0 seconds (got " + args.get("time") + ")");
        std::map<std::string, std::string> params;
        for (const auto &kv : args.all("set"))
            parseKeyValue(kv, params);

        const CollisionModelPtr model =
            makeCollisionModel(world, parseCollisionBackend(args.get("backend", "auto")));
        og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model);
        ob::PlannerPtr planner =
            PlannerRegistry::builtin().create(plannerName, ss->getSpaceInformation(), params);
        ss->setPlanner(planner);
        ss->setup();

        std::cout << "world:     " << world.name << " (" << world.type() << ", " << world.obstacleCount()
                  << " obstacles, robot radius " << world.robotRadius << ")\n";
        std::cout << "query:     " << query.name << " (" << query.start.x << ", " << query.start.y << ") -> ("
                  << query.goal.x << ", " << query.goal.y << ")\n";
        std::cout << "planner:   " << plannerName << "\n";
        std::cout << "seed:      " << seed << "\n";
        std::cout << "collision: " << model->name() << "\n";

        const ompl::time::point t0 = ompl::time::now();
        const ob::PlannerStatus status = ss->solve(timeLimit);
        const double solveTime = ompl::time::seconds(ompl::time::now() - t0);
        std::cout << "status:    " << status.asString() << "\n";
        std::cout << std::setprecision(6) << "time:      " << solveTime << " s\n";
        if (!ss->haveSolutionPath())
        {
            std::cout << "no path\n";
            return 3;
        }
        const og::PathGeometric &path = ss->getSolutionPath();
        const std::vector<Vec2> pts = pathPoints(path);
        bool collisionFree = true;
        for (std::size_t i = 1; i < pts.size(); ++i)
            collisionFree = collisionFree && model->segmentValid(pts[i - 1], pts[i]);
        const double length = polylineLength(pts);
        std::cout << std::setprecision(9) << "length:    " << length << "\n";
        const OptimumOrReason optimum = optimumOrReason(world, query);
        const bool exactPath = status == ob::PlannerStatus::EXACT_SOLUTION && ss->haveExactSolutionPath();
        if (optimum.result.found)
        {
            std::cout << "optimum:   " << optimum.result.length << " (" << optimum.result.method << ")\n";
            // A gap means something only for a path that reaches the goal and is collision-free.
            if (exactPath && collisionFree)
                std::cout << std::setprecision(4)
                          << "gap:       " << 100.0 * optimalityGap(length, optimum.result) << " %\n"
                          << std::setprecision(9);
            else
                std::cout << "gap:       - ("
                          << (exactPath ? "the path is not collision-free" : "no exact path") << ")\n";
        }
        else
            std::cout << "optimum:   not available (" << optimum.reason << ")\n";
        std::cout << "valid:     " << (collisionFree ? "yes" : "NO") << " (exact segment check)\n";
        std::cout << "path:      " << pts.size() << " states\n";
        for (const auto &p : pts)
            std::cout << "  " << p.x << " " << p.y << "\n";
        if (args.has("svg"))
        {
            writeTextFile(
                args.get("svg"),
                worldSvg(world, &query, {{pts, plannerName + " (" + status.asString() + ")", "#d62728"}}));
            std::cout << "svg:       " << args.get("svg") << "\n";
        }
        return status == ob::PlannerStatus::EXACT_SOLUTION && collisionFree ? 0 : 3;
    }

    int cmdGenerate(const Argv &argv)
    {
        const Args args("generate", argv,
                        {{"seed", "count", "min-size", "max-size", "bounds", "radius", "width", "height",
                          "cell-size", "density", "name", "output"},
                         {},
                         {}});
        if (args.positional().size() != 1)
            throw InputError("mhplan generate: expected one kind: circles, rectangles, maze or grid");
        const std::string kind = args.positional()[0];
        GeneratorOptions o;
        const long long seed = args.integer("seed", 1);
        if (seed < 0)
            throw InputError("mhplan generate: --seed must be >= 0");
        o.seed = static_cast<std::uint64_t>(seed);
        const long long count = args.integer("count", static_cast<long long>(o.count));
        if (count < 0 || count > 10000000)
            throw InputError("mhplan generate: --count must be in [0, 10000000] (got " + args.get("count") +
                             ")");
        o.count = static_cast<std::size_t>(count);
        o.minSize = args.number("min-size", o.minSize);
        o.maxSize = args.number("max-size", o.maxSize);
        o.robotRadius = args.number("radius", o.robotRadius);
        o.width = static_cast<int>(args.integer("width", o.width));
        o.height = static_cast<int>(args.integer("height", o.height));
        o.cellSize = args.number("cell-size", o.cellSize);
        o.density = args.number("density", o.density);
        if (args.has("bounds"))
        {
            const std::vector<double> b = parseNumberList("--bounds", args.get("bounds"));
            if (b.size() != 4)
                throw InputError("mhplan generate: --bounds expects xmin,xmax,ymin,ymax");
            o.bounds = {b[0], b[1], b[2], b[3]};
        }
        World world;
        if (kind == "circles")
            world = generateCircles(o);
        else if (kind == "rectangles")
            world = generateRectangles(o);
        else if (kind == "maze")
            world = generateMaze(o);
        else if (kind == "grid")
            world = generateGrid(o);
        else
            throw InputError("mhplan generate: unknown kind '" + kind +
                             "'; accepted: circles, rectangles, maze, grid");
        if (args.has("name"))
            world.name = args.get("name");
        const std::string out = args.get("output");
        const bool asMap = out.size() > 4 && out.substr(out.size() - 4) == ".map";
        if (asMap && !world.isGrid())
            throw InputError("mhplan generate: a .map output needs a grid world (maze or grid)");
        const std::string text = asMap ? movingAIMapText(*world.grid) : worldToYaml(world);
        if (out.empty())
            std::cout << text;
        else
        {
            writeTextFile(out, text);
            std::cerr << "wrote " << out << "\n";
        }
        return 0;
    }

    int cmdWorlds(const Argv &argv)
    {
        const Args args("worlds", argv, {{}, {}, {}});
        std::vector<std::string> files = args.positional();
        if (files.empty())
            files = shippedWorldFiles();
        else
            for (auto &f : files)
                f = resolveWorldPath(f);
        std::cout << std::left << std::setw(22) << "name" << std::setw(9) << "type" << std::setw(11)
                  << "obstacles" << std::setw(8) << "radius" << std::setw(16) << "bounds"
                  << "queries / source\n";
        for (const auto &f : files)
        {
            const World w = loadWorld(f);
            std::ostringstream bounds;
            bounds << w.bounds.width() << " x " << w.bounds.height();
            std::string queries;
            for (const auto &q : w.queries)
                queries += (queries.empty() ? "" : ",") + q.name;
            std::cout << std::left << std::setw(22) << w.name << std::setw(9) << w.type() << std::setw(11)
                      << w.obstacleCount() << std::setw(8) << w.robotRadius << std::setw(16) << bounds.str()
                      << (queries.empty() ? "-" : queries) << " / " << (w.source.empty() ? f : w.source)
                      << "\n";
        }
        return 0;
    }

    int cmdPlanners(const Argv &argv)
    {
        const Args args("planners", argv, {{}, {}, {}});
        const PlannerRegistry &reg = PlannerRegistry::builtin();
        std::vector<std::string> names = args.positional();
        if (names.empty())
            names = reg.names();
        // A throw-away 2D problem to instantiate each planner and read its declared parameters.
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        for (const auto &name : names)
        {
            const PlannerEntry &e = reg.get(name);
            const ob::PlannerPtr p = e.allocate(si);
            std::cout << name << " [" << e.origin << "] " << e.description << "\n";
            std::map<std::string, std::string> values;
            p->params().getParams(values);
            for (const auto &kv : values)
                std::cout << "    " << std::left << std::setw(28) << kv.first << " default " << std::setw(12)
                          << kv.second << " range " << p->params()[kv.first].getRangeSuggestion() << "\n";
        }
        return 0;
    }

    int cmdControllers(const Argv &argv)
    {
        const Args args("controllers", argv, {{}, {}, {}});
        for (const auto &name : args.positional())
            controllerParameters(name); // refuses an unknown name before anything is printed
        printControllers(std::cout, args.positional());
        return 0;
    }
} // namespace mhplan::cli

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
            const PlannerRegistry &reg = PlannerRegistry::builtin();
            for (const auto &name : reg.names())
                if (reg.get(name).origin == "mhplan")
                    out.push_back(name);
            return out;
        }
    } // namespace

    int cmdCompare(const Argv &argv)
    {
        const Args args("compare", argv, {{"planners", "time", "runs", "seed"}, {}, {}});
        const std::uint_fast32_t seed = seedFromArgs(args);
        const double timeLimit = args.number("time", 1.0);
        if (!(timeLimit > 0.0))
            throw InputError("mhplan compare: --time must be > 0 seconds");
        const long long runs = args.integer("runs", 1);
        if (runs < 1 || runs > 1000)
            throw InputError("mhplan compare: --runs must be in [1, 1000] (got " + args.get("runs") + ")");
        std::vector<std::string> planners =
            args.has("planners") ? splitList(args.get("planners")) : defaultComparePlanners();
        if (planners.empty())
            throw InputError("mhplan compare: --planners names no planner (got '" + args.get("planners") +
                             "'); give a comma-separated list, e.g. RRTstar,SMA");
        for (const auto &p : planners)
            PlannerRegistry::builtin().get(p); // refuse unknown names before any work
        std::vector<std::string> files;
        for (const auto &w : args.positional())
            files.push_back(resolveWorldPath(w));
        if (files.empty())
            files = shippedWorldFiles();

        std::cout << "seed " << seed << ", time limit " << timeLimit << " s, " << runs
                  << " run(s) per pair\n\n";
        std::cout << std::left << std::setw(18) << "world" << std::setw(17) << "planner" << std::right
                  << std::setw(7) << "exact" << std::setw(12) << "best len" << std::setw(12) << "median len"
                  << std::setw(12) << "optimum" << std::setw(12) << "median gap" << std::setw(11)
                  << "time [s]"
                  << "\n";
        for (const auto &file : files)
        {
            const World world = loadWorld(file);
            const Query &query = world.queryOrDefault("");
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
                std::vector<double> lengths;
                double totalTime = 0.0;
                int exact = 0;
                for (long long r = 0; r < runs; ++r)
                {
                    og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model);
                    ss->setPlanner(PlannerRegistry::builtin().create(name, ss->getSpaceInformation()));
                    const ompl::time::point t0 = ompl::time::now();
                    const ob::PlannerStatus status = ss->solve(timeLimit);
                    totalTime += ompl::time::seconds(ompl::time::now() - t0);
                    if (status != ob::PlannerStatus::EXACT_SOLUTION || !ss->haveExactSolutionPath())
                        continue;
                    const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
                    bool ok = true;
                    for (std::size_t i = 1; i < pts.size() && ok; ++i)
                        ok = model->segmentValid(pts[i - 1], pts[i]);
                    if (!ok)
                        continue;
                    ++exact;
                    lengths.push_back(polylineLength(pts));
                }
                std::sort(lengths.begin(), lengths.end());
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
                    const std::size_t n = lengths.size();
                    const double med = n % 2 ? lengths[n / 2] : 0.5 * (lengths[n / 2 - 1] + lengths[n / 2]);
                    median << med;
                    if (optimum.result.found)
                        gap << 100.0 * optimalityGap(med, optimum.result) << "%";
                    else
                        gap << "-";
                }
                std::cout << std::left << std::setw(18) << world.name << std::setw(17) << name << std::right
                          << std::setw(4) << exact << "/" << std::left << std::setw(2) << runs << std::right
                          << std::setw(12) << best.str() << std::setw(12) << median.str() << std::setw(12)
                          << optText.str() << std::setw(12) << gap.str() << std::setw(11) << std::fixed
                          << std::setprecision(3) << totalTime / static_cast<double>(runs) << "\n"
                          << std::defaultfloat;
            }
        }
        return 0;
    }
} // namespace mhplan::cli
