// SPDX-License-Identifier: BSD-3-Clause
/* mhplan planners / controllers / scenarios: what can be planned with, driven by and simulated, with every
   parameter's default, range and meaning. */
#include "src/cli/Commands.h"

#include "src/base/Parameters.h"
#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/registry/Registry.h"
#include "src/sim/Controllers.h"
#include "src/sim/ScenarioIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace ob = ompl::base;
namespace fs = std::filesystem;

namespace mhplan::cli
{
    namespace
    {
        const char *const kIterationsNote =
            "iterations versus max_iterations (population planners): 'iterations' is the papers' T, the "
            "length of the coefficient schedules (e.g. SMA's a = atanh(1 - t/T)); it does not stop a run. "
            "'max_iterations' bounds the iterations of one solve() call (0 = run until the time limit; the "
            "schedule then restarts after T iterations). Memetic, lattice and field planners have only "
            "max_iterations (generations, expansions or steps per solve() call).";

        struct ParameterRow
        {
            std::string name, value, range, description;
        };

        /** The declared parameters of planner \e entry, read from a throw-away 2D problem with OMPL's
            messages silenced (constructing some OMPL planners warns about the missing problem). */
        std::vector<ParameterRow> plannerParameters(const PlannerEntry &entry)
        {
            auto space = std::make_shared<ob::RealVectorStateSpace>(2);
            space->setBounds(0.0, 1.0);
            auto si = std::make_shared<ob::SpaceInformation>(space);
            ompl::msg::noOutputHandler();
            ob::PlannerPtr p;
            try
            {
                p = entry.allocate(si);
            }
            catch (...)
            {
                ompl::msg::restorePreviousOutputHandler();
                throw;
            }
            std::map<std::string, std::string> values;
            p->params().getParams(values);
            ompl::msg::restorePreviousOutputHandler();
            std::vector<ParameterRow> out;
            for (const auto &kv : values)
                out.push_back({kv.first, kv.second, p->params()[kv.first].getRangeSuggestion(),
                               parameterDescription(p->params()[kv.first])});
            return out;
        }
    } // namespace

    const CommandDoc &plannersDoc()
    {
        static const CommandDoc doc{
            "planners [NAME...] [--json]",
            "list the registered planners with their parameters, defaults, ranges and what each does",
            kIterationsNote,
            {{"NAME", "planners to list (default: all); an unknown name is refused"}},
            {options::json("the planners and their parameters")},
            {"planners", "planners SMA LRSMA", "planners --json"}};
        return doc;
    }

    int cmdPlanners(const Argv &argv)
    {
        const Args args("planners", argv, {{}, {}, {"json"}});
        const PlannerRegistry &reg = builtinPlanners();
        std::vector<std::string> names = args.positional();
        if (names.empty())
            names = reg.names();
        for (const auto &name : names)
            reg.get(name); // refuses an unknown name before anything is printed
        if (args.has("json"))
        {
            JsonWriter out(std::cout);
            out.beginObject().field("command", "planners").key("planners").beginArray();
            for (const auto &name : names)
            {
                const PlannerEntry &e = reg.get(name);
                out.beginObject()
                    .field("name", name)
                    .field("origin", e.origin)
                    .field("description", e.description)
                    .field("improved", e.has(cap::Improved))
                    .field("needs_clearance", e.has(cap::NeedsClearance))
                    .field("anytime", e.has(cap::Anytime))
                    .field("deterministic", e.has(cap::Deterministic));
                out.key("spaces").beginArray();
                for (unsigned flag = 1; flag <= cap::OtherSpace; flag <<= 1)
                    if (e.runsOn(flag))
                        out.value(spaceName(flag));
                out.endArray();
                out.key("parameters").beginArray();
                for (const ParameterRow &p : plannerParameters(e))
                    out.beginObject()
                        .field("name", p.name)
                        .field("default", p.value)
                        .field("range", p.range)
                        .field("description", p.description)
                        .endObject();
                out.endArray().endObject();
            }
            out.endArray().endObject().finish();
            return 0;
        }
        bool schedules = false; // a listed planner has both 'iterations' and 'max_iterations'
        for (const auto &name : names)
        {
            const PlannerEntry &e = reg.get(name);
            std::cout << name << " [" << e.origin << "] " << e.description << "\n";
            // What the planner declares (PlannerEntry::capabilities).
            std::cout << "    runs on: " << spaceList(e.capabilities & ~cap::OtherSpace)
                      << (e.runsOn(cap::OtherSpace) ? " (and tries other spaces)" : " only") << "; "
                      << (e.has(cap::Anytime) ? "anytime" : "stops at its first solution")
                      << (e.has(cap::Deterministic) ? ", deterministic" : "")
                      << (e.has(cap::NeedsClearance) ? ", needs a checker that computes clearance" : "")
                      << (e.has(cap::Improved)   ? ", improved variant"
                          : e.origin == "mhplan" ? ", faithful"
                                                 : "")
                      << "\n";
            const std::vector<ParameterRow> rows = plannerParameters(e);
            const auto hasRow = [&](const char *n) {
                return std::any_of(rows.begin(), rows.end(),
                                   [&](const ParameterRow &r) { return r.name == n; });
            };
            schedules = schedules || (hasRow("iterations") && hasRow("max_iterations"));
            for (const ParameterRow &p : rows)
            {
                std::cout << "    " << std::left << std::setw(28) << p.name << " default " << std::setw(12)
                          << p.value << " range ";
                if (p.description.empty())
                    std::cout << p.range;
                else
                    std::cout << std::setw(16) << p.range << " " << p.description;
                std::cout << "\n";
            }
        }
        if (schedules)
            std::cout << "\n" << kIterationsNote << "\n";
        return 0;
    }

    const CommandDoc &controllersDoc()
    {
        static const CommandDoc doc{
            "controllers [NAME...]",
            "list the moving-world controllers of 'mhplan sim' with their parameters, defaults, ranges and "
            "what each does",
            "plan:<PLANNER> plans with any planner of 'mhplan planners' and follows the path; set the "
            "planner's "
            "own parameters with --set planner.<name>=value (e.g. --set planner.population_size=40); "
            "'mhplan controllers plan:SMA' lists them.",
            {{"NAME", "controllers to list (default: all; plan:<PLANNER> for a plan-and-follow controller)"}},
            {},
            {"controllers", "controllers aapf plan:ThetaStar"}};
        return doc;
    }

    int cmdControllers(const Argv &argv)
    {
        const Args args("controllers", argv, {{}, {}, {}});
        for (const auto &name : args.positional())
            controllerParameters(name); // refuses an unknown name before anything is printed
        printControllers(std::cout, args.positional());
        return 0;
    }

    namespace
    {
        std::vector<std::string> shippedScenarioFiles()
        {
            std::vector<std::string> out;
            const fs::path dir = fs::path(environmentsDir()) / "scenarios";
            std::error_code ec;
            if (!fs::is_directory(dir, ec))
                return out;
            for (const auto &e : fs::directory_iterator(dir))
            {
                const std::string ext = e.path().extension().string();
                if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
                    out.push_back(e.path().string());
            }
            std::sort(out.begin(), out.end());
            return out;
        }
    } // namespace

    const CommandDoc &scenariosDoc()
    {
        static const CommandDoc doc{
            "scenarios [SCENARIO...]",
            "list the moving-world scenarios of 'mhplan sim' (shipped, or the given files) with their "
            "robots, "
            "obstacles and settings",
            "Settings: dt (time step, s), time_limit (the run ends then, s), stuck_timeout and "
            "stuck_distance "
            "(a robot whose distance to its goal has not dropped by stuck_distance m within stuck_timeout s "
            "is "
            "stuck), goal_tolerance (m); robots: radius (m), max speed (m/s), tasks (goals in order).",
            {{"SCENARIO", "scenario files or names of shipped scenarios (default: every shipped scenario)"}},
            {},
            {"scenarios", "scenarios mapf_15robots"}};
        return doc;
    }

    int cmdScenarios(const Argv &argv)
    {
        const Args args("scenarios", argv, {{}, {}, {}});
        std::vector<std::string> files;
        for (const auto &s : args.positional())
            files.push_back(resolveScenarioPath(s));
        if (files.empty())
            files = shippedScenarioFiles();
        std::vector<Scenario> scenarios;
        for (const auto &f : files)
            scenarios.push_back(loadScenario(f)); // refuses a bad file before anything is printed
        for (const Scenario &s : scenarios)
        {
            std::size_t tasks = 0;
            double maxSpeed = 0.0, radius = 0.0;
            for (const RobotSpec &r : s.robots)
            {
                tasks += r.tasks.size();
                maxSpeed = std::max(maxSpeed, r.maxSpeed);
                radius = std::max(radius, r.radius);
            }
            const SimulationSettings &st = s.settings;
            std::cout << s.name << " (" << s.file << ")\n";
            if (!s.description.empty())
                std::cout << "    " << s.description << "\n";
            std::cout << "    robots " << s.robots.size() << " (" << tasks << " tasks, radius up to "
                      << radius << " m, speed up to " << maxSpeed << " m/s), static obstacles "
                      << s.world.obstacleCount() << ", moving obstacles " << s.movingObstacles.size() << "\n"
                      << "    dt " << st.dt << " s, time_limit " << st.timeLimit << " s, stuck_timeout "
                      << st.stuckTimeout << " s, stuck_distance " << st.stuckDistance << " m, goal_tolerance "
                      << st.goalTolerance << " m\n";
            if (!s.reference.empty())
            {
                std::cout << "    paper:";
                for (const auto &kv : s.reference)
                    std::cout << " " << kv.first << "=" << kv.second;
                std::cout << "\n";
            }
        }
        return 0;
    }
} // namespace mhplan::cli
