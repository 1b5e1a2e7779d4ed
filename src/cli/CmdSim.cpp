// SPDX-License-Identifier: BSD-3-Clause
/* mhplan sim SCENARIO: run a moving-world scenario with a controller, print per-robot and run metrics, and
   draw the run (SVG with a replay, animated GIF) or write its trajectories (CSV). */
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/sim/Controllers.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"
#include "src/draw/SimRender.h"
#include "src/sim/Simulation.h"
#include "src/sim/SimulationReport.h"
#include "src/draw/Svg.h"

#include <ompl/util/Time.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace mhplan::cli
{
    namespace
    {
        int positiveInt(const Args &args, const std::string &name, long long fallback, long long lo,
                        long long hi)
        {
            const long long v = args.integer(name, fallback);
            if (v < lo || v > hi)
                throw InputError("mhplan sim: --" + name + " must be in [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "] (got " + args.get(name) + ")");
            return static_cast<int>(v);
        }
    } // namespace

    const CommandDoc &simDoc()
    {
        static const CommandDoc doc{
            "sim SCENARIO --controller NAME [options]",
            "run a moving-world scenario with a controller; print per-robot and run metrics; draw the run",
            "Scenarios: 'mhplan scenarios'; controllers and their parameters: 'mhplan controllers'.",
            {{"SCENARIO", "a scenario file or the name of a shipped scenario (e.g. mapf_15robots)"}},
            {{"--controller", "NAME",
              "dapf, aapf, bfo, atbfo or plan:<PLANNER> (required; see 'mhplan controllers')"},
             options::seed(),
             {"--set", "KEY=VALUE",
              "set a controller parameter (repeatable); plan:<PLANNER> takes planner.<name>=value for the "
              "planner's parameters"},
             {"--time-limit", "S", "simulated seconds before the run stops (default: the scenario's)"},
             options::svg("the run (static picture with an animated replay unless --no-replay)"),
             {"--no-replay", "", "the SVG without the animated replay"},
             {"--gif", "FILE", "write an animated GIF of the run (the directory must be writable)"},
             {"--gif-width", "PX", "GIF width in pixels, 16..4096 (default 480)"},
             {"--fps", "F", "frames per second of the replay and the GIF, (0, 100] (default 10)"},
             {"--max-frames", "N",
              "at most this many frames in the replay and the GIF, 2..100000 (default 300)"},
             {"--csv", "FILE", "write every robot's trajectory as CSV"}},
            {"sim mapf_2robots --controller aapf --seed 2 --svg run.svg",
             "sim mapf_15robots --controller plan:ThetaStar --set plan_time=0.2 --gif run.gif",
             "sim bfo_case3_lines --controller plan:SMA --set planner.population_size=40 --csv traj.csv"},
            "0 every robot done, 1 bad input, 2 internal error, 3 some robot stuck or unfinished"};
        return doc;
    }

    int cmdSim(const Argv &argv)
    {
        const Args args(
            "sim", argv,
            {{"controller", "seed", "svg", "gif", "csv", "time-limit", "gif-width", "fps", "max-frames"},
             {"set"},
             {"no-replay"}});
        for (const char *output : {"svg", "gif", "csv"})
            checkOutputFile(args, output);
        if (args.positional().size() != 1)
            throw InputError(
                "mhplan sim: expected exactly one SCENARIO (a scenario file or the name of a shipped "
                "scenario, e.g. mapf_2robots)");
        if (!args.has("controller"))
        {
            std::string names;
            for (const auto &n : controllerNames())
                names += (names.empty() ? "" : ", ") + n;
            throw InputError("mhplan sim: --controller NAME is required; controllers: " + names);
        }
        // The seed must be fixed before any OMPL random number generator exists (plan:<planner> controllers).
        const std::uint_fast32_t seed = seedFromArgs(args);
        Scenario scenario = loadScenario(resolveScenarioPath(args.positional()[0]));
        if (args.has("time-limit"))
        {
            const double limit = args.number("time-limit", 0.0);
            if (!(limit > 0.0) || std::isinf(limit))
                throw InputError("mhplan sim: --time-limit must be > 0 seconds (got " +
                                 args.get("time-limit") + ")");
            if (limit / scenario.settings.dt > 1e7)
                throw InputError("mhplan sim: --time-limit " + args.get("time-limit") + " at dt " +
                                 std::to_string(scenario.settings.dt) +
                                 " s would take more than 10^7 steps (the limit of a scenario)");
            scenario.settings.timeLimit = limit;
        }
        GifOptions gif;
        gif.width = positiveInt(args, "gif-width", gif.width, 16, 4096);
        gif.maxFrames = positiveInt(args, "max-frames", gif.maxFrames, 2, 100000);
        gif.fps = args.number("fps", gif.fps);
        if (!(gif.fps > 0.0) || gif.fps > 100.0)
            throw InputError("mhplan sim: --fps must be in (0, 100] (got " + args.get("fps") + ")");

        const ControllerPtr controller = makeController(args.get("controller"));
        std::map<std::string, std::string> params;
        for (const auto &kv : args.all("set"))
            parseKeyValue(kv, params);
        for (const auto &kv : params)
            controller->setParameter(kv.first, kv.second);

        std::cout << "scenario:   " << scenario.name << " (" << scenario.file << ")\n";
        std::cout << "world:      " << scenario.world.type() << ", " << scenario.world.obstacleCount()
                  << " static obstacles, " << scenario.movingObstacles.size() << " moving obstacles, "
                  << scenario.robots.size() << " robots\n";
        std::cout << "controller: " << controller->name();
        const auto shown = controller->parameters();
        if (!shown.empty())
        {
            std::cout << " (";
            bool first = true;
            for (const auto &kv : shown)
            {
                std::cout << (first ? "" : ", ") << kv.first << "=" << kv.second;
                first = false;
            }
            std::cout << ")";
        }
        std::cout << "\nseed:       " << seed << "\n";

        Simulation sim(scenario, controller, static_cast<std::uint32_t>(seed));
        const SimulationResult r = sim.run();

        printSimulationReport(std::cout, r); // its last line: the controller's counters

        if (args.has("csv"))
        {
            writeTextFile(args.get("csv"), trajectoryCsv(r));
            std::cout << "csv:        " << args.get("csv") << "\n";
        }
        if (args.has("svg"))
        {
            writeTextFile(args.get("svg"),
                          simulationSvg(scenario, r, !args.has("no-replay"), gif.maxFrames, gif.fps));
            std::cout << "svg:        " << args.get("svg") << "\n";
        }
        if (args.has("gif"))
        {
            const ompl::time::point t0 = ompl::time::now();
            writeSimulationGif(scenario, r, args.get("gif"), gif);
            std::cout << "gif:        " << args.get("gif") << " (" << fs::file_size(args.get("gif"))
                      << " bytes, " << std::setprecision(3) << ompl::time::seconds(ompl::time::now() - t0)
                      << " s)\n";
        }
        return r.allDone ? 0 : 3;
    }
} // namespace mhplan::cli
