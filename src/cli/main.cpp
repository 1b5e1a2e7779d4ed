// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the command-line program. One table of subcommands; each lives in its own function. */
#include "mhplan/cli/Commands.h"
#include "mhplan/base/Version.h"
#include "mhplan/base/World.h"

#include <ompl/util/Console.h>

#include <cstring>
#include <exception>
#include <functional>
#include <iostream>
#include <map>

namespace
{
    struct Command
    {
        std::function<int(const mhplan::cli::Argv &)> run;
        const char *usage;
    };

    const std::map<std::string, Command> &commands()
    {
        using namespace mhplan::cli;
        static const std::map<std::string, Command> table = {
            {"plan",
             {cmdPlan,
              "plan WORLD [--query NAME | --start X,Y --goal X,Y] [--planner NAME] [--time S] [--seed N]\n"
              "        [--set key=value]... [--backend auto|analytic|fcl|grid|hash] [--svg FILE]"}},
            {"generate",
             {cmdGenerate,
              "generate circles|rectangles|maze|grid [--seed N] [--count N] [--min-size M] [--max-size M]\n"
              "        [--bounds xmin,xmax,ymin,ymax] [--radius R] [--width W] [--height H]\n"
              "        [--cell-size S] [--density D] [--name NAME] [--output FILE.yaml|FILE.map]"}},
            {"worlds",
             {cmdWorlds, "worlds [WORLD...]   (shipped worlds, or describe and validate the given files)"}},
            {"compare",
             {cmdCompare,
              "compare [WORLD...] [--planners A,B,...] [--time S] [--runs N] [--seed N]\n"
              "        (plan every shipped world, or the given ones, with each planner; print a table)"}},
            {"optimum",
             {cmdOptimum,
              "optimum WORLD [--query NAME | --start X,Y --goal X,Y] [--octile] [--svg FILE]\n"
              "        (the exact shortest path: tangent graph, any-angle or 8-connected on grids)"}},
            {"report",
             {cmdReport,
              "report DATABASE [-o DIR]   (HTML report: figures and tables from a benchmark database)"}},
            {"bench",
             {cmdBench,
              "bench CAMPAIGN [--jobs N] [--shard i/N] [--merge-only] [--no-merge] [--list]\n"
              "        [--database FILE] [--logs DIR] [--runs N] [--time S] [--seed N] [--no-progress]"}},
            {"scen",
             {cmdScen,
              "scen MAP.map SCEN.scen [--planner AStar] [--time S] [--verbose]\n"
              "        (run every problem of a MovingAI scenario file; compare lengths with its optima)"}},
            {"sim",
             {cmdSim,
              "sim SCENARIO --controller NAME [--seed N] [--set key=value]... [--time-limit S]\n"
              "        [--svg FILE] [--no-replay] [--gif FILE] [--gif-width PX] [--fps F] [--max-frames N]\n"
              "        [--csv FILE]   (run a moving-world scenario, e.g. mapf_15robots; exit 0: all robots\n"
              "        done, 3: some stuck or unfinished, 1: bad input)"}},
            {"arena",
             {cmdArena, "arena DB [--port N] [--host H] [--no-install]   (serve OMPL's Planner Arena on a\n"
                        "        benchmark database; prints the URL; Ctrl-C stops it)"}},
            {"planners",
             {cmdPlanners, "planners [NAME...] (registered planners, their parameters, defaults, ranges)"}},
            {"controllers",
             {cmdControllers,
              "controllers [NAME...] (moving-world controllers for sim, their parameters, defaults, "
              "ranges)"}},
        };
        return table;
    }

    void usage(std::ostream &out)
    {
        out << "mhplan " << mhplan::version() << " (OMPL " << mhplan::omplVersion()
            << "): metaheuristic path planners in OMPL\n\nusage:\n";
        for (const auto &kv : commands())
            out << "  mhplan " << kv.second.usage << "\n";
        out << "  mhplan version\n";
    }
} // namespace

int main(int argc, char **argv)
{
    if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "help") == 0)
    {
        usage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 1 : 0;
    }
    const std::string name = argv[1];
    if (name == "version" || name == "--version")
    {
        std::cout << "mhplan " << mhplan::version() << " (OMPL " << mhplan::omplVersion() << ")\n";
        return 0;
    }
    const auto it = commands().find(name);
    if (it == commands().end())
    {
        std::cerr << "mhplan: unknown command '" << name << "'\n";
        usage(std::cerr);
        return 1;
    }
    // OMPL's informational chatter goes to stderr-level only when asked.
    ompl::msg::setLogLevel(std::getenv("MHPLAN_VERBOSE") ? ompl::msg::LOG_DEBUG : ompl::msg::LOG_WARN);
    try
    {
        return it->second.run(mhplan::cli::Argv(argv + 2, argv + argc));
    }
    catch (const mhplan::InputError &e)
    {
        // Messages from the option parser already start with "mhplan NAME: ": print that prefix once.
        std::string what = e.what();
        const std::string prefix = "mhplan " + name + ": ";
        for (const std::string &p : {prefix, name + ": "})
            if (what.compare(0, p.size(), p) == 0)
                what = what.substr(p.size());
        std::cerr << prefix << "error: " << what << "\n";
        return 1;
    }
    catch (const std::exception &e)
    {
        std::cerr << "mhplan " << name << ": internal error: " << e.what() << "\n";
        return 2;
    }
}
