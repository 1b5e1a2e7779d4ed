// SPDX-License-Identifier: BSD-3-Clause
/* mhplan plan WORLD: one planner on one query; the path, its length, the exact optimum and the gap. */
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/collision/Collision.h"
#include "src/metrics/MetricList.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidValidity.h"
#include "src/draw/Svg.h"
#include "src/io/WorldIO.h"
#include "src/optimum/Optimum.h"
#include "src/registry/Registry.h"

#include <ompl/util/Time.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan::cli
{
    namespace
    {
        std::vector<Vec2> placed(const World &world, const Pose2 &pose)
        {
            std::vector<Vec2> out;
            for (const Vec2 &v : world.robotPolygon)
                out.push_back(placePoint(pose, v));
            return out;
        }

        /** The polygon robot's outline at the query's start and goal and along the driven poses \e dense:
            a pose every \e spacing metres of travel, and wherever the heading turned by 30 degrees since the
            last one drawn (a rotation in place shows), at most about 80 (docs/cli.md, "plan"). */
        std::vector<SvgFootprint> pathFootprints(const World &world, const Query &query,
                                                 const std::vector<Pose2> &dense, const std::string &color)
        {
            std::vector<SvgFootprint> out;
            if (world.robotPolygon.empty())
                return out;
            double travel = 0.0;
            for (std::size_t i = 1; i < dense.size(); ++i)
                travel += std::hypot(dense[i].x - dense[i - 1].x, dense[i].y - dense[i - 1].y);
            const double spacing = std::max(1.5 * world.robotReach(), travel / 60.0);
            const double turn = M_PI / 6.0;
            const Pose2 *last = nullptr;
            double since = 0.0;
            for (std::size_t i = 0; i < dense.size(); ++i)
            {
                if (i > 0)
                    since += std::hypot(dense[i].x - dense[i - 1].x, dense[i].y - dense[i - 1].y);
                const bool turned =
                    last != nullptr && std::abs(std::remainder(dense[i].yaw - last->yaw, 2.0 * M_PI)) >= turn;
                if (last == nullptr || since >= spacing || turned || i + 1 == dense.size())
                {
                    out.push_back({placed(world, dense[i]), color, "pose " + std::to_string(out.size())});
                    last = &dense[i];
                    since = 0.0;
                }
            }
            out.push_back(
                {placed(world, {query.start.x, query.start.y, query.startYaw}), "#2ca02c", "start"});
            out.push_back({placed(world, {query.goal.x, query.goal.y, query.goalYaw}), "#1f77b4", "goal"});
            return out;
        }
    } // namespace

    const CommandDoc &planDoc()
    {
        static const CommandDoc doc{
            "plan WORLD [options]",
            "plan one query of a world with one planner; print the path, its length, the exact optimum and "
            "the gap",
            "The path is checked with the exact segment model; the gap is reported only for an exact, "
            "collision-free path of a world whose exact optimum is known. An OMPL.app problem file "
            "(PROBLEM.cfg, docs/omplapp.md) takes --planner (default: the file's first), --set, --time "
            "(default: the file's time_limit), --seed, --quiet, and also --validator certified|discrete and "
            "--path FILE (the path's states) and --svg FILE (the problem from above, the robot's footprint "
            "along "
            "the path); its path is checked densely against the meshes. A 3D YAML world (space r3 or se3, "
            "docs/worlds3d.md) takes the same options and --query NAME (default: its first query).",
            {{"WORLD", "a world file (.yaml, .map), the name of a shipped world (see 'mhplan worlds'), an "
                       "OMPL.app problem file (.cfg) or a 3D YAML world"}},
            {options::query(),
             options::start(),
             options::goal(),
             {"--planner", "NAME", "the planner (default RRTstar; see 'mhplan planners')"},
             {"--time", "S", "time limit of solve() in seconds, 0.001..1000000 (default 1)"},
             options::seed(),
             {"--set", "KEY=VALUE",
              "set a planner parameter (repeatable; names, defaults and ranges: 'mhplan planners NAME')"},
             {"--backend", "NAME",
              "collision model: auto (default: the exact model of the world's type), analytic, fcl, grid or "
              "hash"},
             options::setup(),
             options::resolution(),
             options::svg("the world, the query and the path; a polygon robot's footprint at the start, the "
                          "goal and along the path"),
             options::json("the run (world, query, planner parameters, status, length, optimum, gap, path)"),
             {"--quiet", "", "leave out the list of the path's states (text output)"}},
            {"plan bfo_case1 --planner SMA --time 2 --seed 7",
             "plan lrsma_scenario1 --planner LRSMA --set population_size=40 --set iterations=200 --svg p.svg",
             "plan gms_grid20 --planner ThetaStar --json --quiet",
             "plan environments/omplapp/bugtrap.cfg --planner kpiece --time 2",
             "plan environments/3d/narrow_passage.yaml --planner RRTstar --svg p.svg"},
            "0 exact collision-free path, 1 bad input, 2 internal error, 3 no exact or no collision-free "
            "path"};
        return doc;
    }

    int cmdPlan(const Argv &argv)
    {
        if (isCfgArgument(argv))
            return cmdPlanCfg(argv);
        const Args args(
            "plan", argv,
            {{"query", "start", "goal", "planner", "time", "seed", "backend", "svg", "setup", "resolution"},
             {"set"},
             {"json", "quiet"}});
        checkOutputFile(args, "svg");
        const ValiditySetup setup = setupFromArgs(args);
        // The seed must be fixed before any OMPL random number generator exists.
        const std::uint_fast32_t seed = seedFromArgs(args);
        const World world = loadWorldArg(args);
        const Query query = queryFromArgs(world, args);
        const std::string plannerName = args.get("planner", "RRTstar");
        const double timeLimit = args.timeLimit(1.0);
        std::map<std::string, std::string> params;
        for (const auto &kv : args.all("set"))
            parseKeyValue(kv, params);
        const bool json = args.has("json");

        // Known before anything runs: the planner's declared spaces (one message, naming one that runs).
        const std::string notApplicable = builtinPlanners().whyNotApplicable(
            plannerName, spaceFlag(world.space),
            "the " + spaceName(spaceFlag(world.space)) + " world '" + world.name + "'");
        if (!notApplicable.empty())
            throw InputError(notApplicable);
        const CollisionModelPtr model =
            makeCollisionModel(world, parseCollisionBackend(args.get("backend", "auto")));
        og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model, setup);
        ob::PlannerPtr planner = builtinPlanners().create(plannerName, ss->getSpaceInformation(), params);
        ss->setPlanner(planner);
        ss->setup();

        if (!json)
        {
            std::cout << "world:     " << world.name << " (" << world.type() << ", " << world.obstacleCount()
                      << " obstacles, ";
            if (world.robotPolygon.empty())
                std::cout << "robot radius " << world.robotRadius << ")\n";
            else
                std::cout << "robot polygon of " << world.robotPolygon.size() << " vertices, reach "
                          << world.robotReach() << ")\n";
            if (world.isRigid())
            {
                std::cout << "space:     " << toString(world.space);
                if (world.turningRadius > 0.0)
                    std::cout << " (turning radius " << world.turningRadius << ")";
                std::cout << "\n";
                std::cout << "query:     " << query.name << " (" << query.start.x << ", " << query.start.y
                          << ", yaw " << query.startYaw << ") -> (" << query.goal.x << ", " << query.goal.y
                          << ", yaw " << query.goalYaw << ")\n";
            }
            else
                std::cout << "query:     " << query.name << " (" << query.start.x << ", " << query.start.y
                          << ") -> (" << query.goal.x << ", " << query.goal.y << ")\n";
            std::cout << "planner:   " << plannerName << "\n";
            std::cout << "seed:      " << seed << "\n";
            std::cout << "collision: "
                      << (world.isRigid() ? "fcl rigid body, certified motions" : model->name()) << "\n";
            std::cout << "setup:     " << setup.describe() << "\n";
        }

        const ompl::time::point t0 = ompl::time::now();
        const CheckCounts checksBefore = checkCounts(*ss->getSpaceInformation());
        const ob::PlannerStatus status = ss->solve(timeLimit);
        const double solveTime = ompl::time::seconds(ompl::time::now() - t0);
        const CheckCounts checks = checkCounts(*ss->getSpaceInformation()) - checksBefore;
        const bool havePath = ss->haveSolutionPath();
        std::vector<Vec2> pts = havePath ? pathPoints(ss->getSolutionPath()) : std::vector<Vec2>{};
        bool collisionFree = havePath;
        const bool exactPath = status == ob::PlannerStatus::EXACT_SOLUTION && ss->haveExactSolutionPath();
        // Every registered metric (src/metrics/MetricList.h), the path prepared as a campaign prepares it;
        // the length and the cusps printed below are the list's.
        std::vector<std::pair<std::string, std::optional<double>>> metrics;
        const auto metric = [&metrics](const std::string &property)
        {
            for (const auto &[name, value] : metrics)
                if (name == property)
                    return value;
            return std::optional<double>();
        };
        const double noOptimum = std::numeric_limits<double>::quiet_NaN();
        double length = 0.0;
        RigidPathMetrics rigid;
        std::vector<Pose2> poses;
        if (world.isRigid() && havePath)
        {
            // Independent dense check along the space's interpolation; the cost in the space's metric.
            const og::PathGeometric &path = ss->getSolutionPath();
            std::vector<Pose2> stored;
            metrics = evaluatePathMetrics(rigidRunMetricPath(world, *ss->getSpaceInformation(), path,
                                                             defaultMetricStep(world), exactPath, noOptimum,
                                                             stored, &rigid));
            collisionFree = rigid.collisionFree;
            for (std::size_t i = 0; i < path.getStateCount(); ++i)
                poses.push_back(statePose(path.getState(i)));
            // Draw what the robot drives (a car's arcs), not the chords between waypoints.
            std::vector<Vec2> drawn;
            const std::size_t every = std::max<std::size_t>(1, rigid.poses.size() / 2000);
            for (std::size_t i = 0; i < rigid.poses.size(); i += every)
                drawn.emplace_back(rigid.poses[i].x, rigid.poses[i].y);
            drawn.emplace_back(rigid.poses.back().x, rigid.poses.back().y);
            pts = drawn;
        }
        else
            for (std::size_t i = 1; i < pts.size(); ++i)
                collisionFree = collisionFree && model->segmentValid(pts[i - 1], pts[i]);
        const OptimumOrReason optimum =
            havePath ? optimumOrReason(world, query) : OptimumOrReason{OptimumResult{}, "no path"};
        if (!world.isRigid() && havePath)
            metrics = evaluatePathMetrics(
                planarMetricPath(world, pts, *model, defaultMetricStep(world), exactPath,
                                 optimum.result.found ? optimum.result.length : noOptimum));
        length = metric("path length REAL").value_or(0.0);
        const auto cusps = static_cast<unsigned long long>(metric("cusps INTEGER").value_or(0.0));
        const bool withGap = optimum.result.found && exactPath && collisionFree;
        const int code = status == ob::PlannerStatus::EXACT_SOLUTION && collisionFree ? 0 : 3;
        if (args.has("svg") && havePath)
            writeTextFile(args.get("svg"),
                          worldSvg(world, &query,
                                   {{pts, plannerName + " (" + status.asString() + ")", "#d62728"}}, 0.0,
                                   pathFootprints(world, query, rigid.poses, "#d62728")));

        if (json)
        {
            JsonWriter out(std::cout);
            out.beginObject().field("command", "plan");
            out.key("world");
            writeWorldSummary(out, world);
            out.key("query");
            writeQuery(out, query, world.isRigid());
            out.field("space", toString(world.space));
            out.field("planner", plannerName);
            std::map<std::string, std::string> values;
            planner->params().getParams(values);
            out.key("parameters").beginObject();
            for (const auto &kv : values)
                out.field(kv.first, kv.second);
            out.endObject();
            out.field("seed", static_cast<unsigned long long>(seed))
                .field("collision", model->name())
                .field("setup", setup.name());
            out.key("resolution");
            setup.app() ? out.value(setup.resolution) : out.null();
            out.field("state_checks", static_cast<unsigned long long>(checks.state))
                .field("motion_checks", static_cast<unsigned long long>(checks.motion))
                .field("time_limit", timeLimit)
                .field("status", status.asString())
                .field("exact", exactPath)
                .field("solve_time", solveTime)
                .field("valid", collisionFree);
            out.key("length");
            havePath ? out.value(length) : out.null();
            out.key("optimum");
            if (optimum.result.found)
                out.beginObject()
                    .field("length", optimum.result.length)
                    .field("method", optimum.result.method)
                    .endObject();
            else
                out.null();
            out.field("optimum_reason", optimum.reason);
            out.key("gap_percent");
            withGap ? out.value(100.0 * optimalityGap(length, optimum.result)) : out.null();
            out.key("path").points(pts);
            out.key("poses").beginArray();
            for (const Pose2 &p : poses)
                out.beginArray().value(p.x).value(p.y).value(p.yaw).endArray();
            out.endArray();
            out.key("cusps");
            world.space == SpaceType::ReedsShepp &&havePath ? out.value(cusps) : out.null();
            out.key("metrics");
            if (havePath)
            {
                out.beginObject();
                for (const auto &[property, value] : metrics)
                {
                    out.key(metricColumn(property));
                    const std::string type = property.substr(property.rfind(' ') + 1);
                    if (!value)
                        out.null();
                    else if (type == "BOOLEAN")
                        out.value(*value != 0.0);
                    else if (type == "INTEGER")
                        out.value(static_cast<long long>(*value));
                    else
                        out.value(*value);
                }
                out.endObject();
            }
            else
                out.null();
            out.key("svg");
            args.has("svg") && havePath ? out.value(args.get("svg")) : out.null();
            out.field("exit_code", code).endObject().finish();
            return code;
        }

        std::cout << "status:    " << status.asString() << "\n";
        std::cout << std::setprecision(6) << "time:      " << solveTime << " s\n";
        if (!havePath)
        {
            std::cout << "no path\n";
            return 3;
        }
        if (world.isRigid())
        {
            std::cout << std::setprecision(9) << "cost:      " << length << " (path length in the "
                      << toString(world.space) << " metric"
                      << (world.space == SpaceType::SE2 ? ": |dxy| + 0.5 |dyaw|" : ": the car's path length")
                      << ")\n";
            if (world.space == SpaceType::ReedsShepp)
                std::cout << "cusps:     " << cusps << " (reversals of driving direction)\n";
        }
        else
            std::cout << std::setprecision(9) << "length:    " << length << "\n";
        if (optimum.result.found)
        {
            std::cout << "optimum:   " << optimum.result.length << " (" << optimum.result.method << ")\n";
            // A gap means something only for a path that reaches the goal and is collision-free.
            if (withGap)
                std::cout << std::setprecision(4)
                          << "gap:       " << 100.0 * optimalityGap(length, optimum.result) << " %\n"
                          << std::setprecision(9);
            else
                std::cout << "gap:       - ("
                          << (exactPath ? "the path is not collision-free" : "no exact path") << ")\n";
        }
        else
            std::cout << "optimum:   not available (" << optimum.reason << ")\n";
        std::cout << "checks:    " << checks.state << " state, " << checks.motion << " motion\n";
        std::cout << "valid:     " << (collisionFree ? "yes" : "NO")
                  << (world.isRigid()
                          ? " (independent dense check of the robot along the space's interpolation)"
                          : " (exact segment check)")
                  << "\n";
        std::ostringstream listed; // every registered metric, "-" where it has no value for this path
        for (const auto &[property, value] : metrics)
        {
            listed << (listed.tellp() > 0 ? ", " : "") << metricColumn(property) << " ";
            value ? listed << std::setprecision(6) << *value : listed << "-";
        }
        std::cout << "metrics:   " << listed.str() << "\n";
        if (world.isRigid())
        {
            std::cout << "path:      " << poses.size() << " states (x y yaw)\n";
            if (!args.has("quiet"))
                for (const auto &p : poses)
                    std::cout << "  " << p.x << " " << p.y << " " << p.yaw << "\n";
        }
        else
        {
            std::cout << "path:      " << pts.size() << " states\n";
            if (!args.has("quiet"))
                for (const auto &p : pts)
                    std::cout << "  " << p.x << " " << p.y << "\n";
        }
        if (args.has("svg"))
            std::cout << "svg:       " << args.get("svg") << "\n";
        return code;
    }
} // namespace mhplan::cli
