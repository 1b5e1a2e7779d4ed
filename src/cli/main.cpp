// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the command-line program. One table of subcommands; each lives in its own function. */
#include "src/cli/Commands.h"
#include "src/cli/Help.h"
#include "src/base/Version.h"
#include "src/base/World.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>

namespace
{
    struct Command
    {
        std::function<int(const mhplan::cli::Argv &)> run;
        const mhplan::cli::CommandDoc &(*doc)();
    };

    /** Every subcommand: its function and its help table (Help.h). A new subcommand is one entry here. */
    const std::map<std::string, Command> &commands()
    {
        using namespace mhplan::cli;
        static const std::map<std::string, Command> table = {
            {"plan", {cmdPlan, planDoc}},
            {"generate", {cmdGenerate, generateDoc}},
            {"worlds", {cmdWorlds, worldsDoc}},
            {"compare", {cmdCompare, compareDoc}},
            {"optimum", {cmdOptimum, optimumDoc}},
            {"report", {cmdReport, reportDoc}},
            {"bench", {cmdBench, benchDoc}},
            {"scen", {cmdScen, scenDoc}},
            {"sim", {cmdSim, simDoc}},
            {"arena", {cmdArena, arenaDoc}},
            {"planners", {cmdPlanners, plannersDoc}},
            {"controllers", {cmdControllers, controllersDoc}},
            {"scenarios", {cmdScenarios, scenariosDoc}},
        };
        return table;
    }

    void usage(std::ostream &out)
    {
        out << "mhplan " << mhplan::version() << " (OMPL " << mhplan::omplVersion()
            << "): metaheuristic path planners in OMPL\n\nusage: mhplan SUBCOMMAND [ARGS] [OPTIONS]\n\n"
            << "subcommands:\n";
        for (const auto &kv : commands())
            out << "  " << std::left << std::setw(13) << kv.first << kv.second.doc().summary << "\n";
        out << "  " << std::left << std::setw(13) << "version"
            << "print mhplan's and OMPL's versions\n"
            << "\n'mhplan SUBCOMMAND --help' (or 'mhplan help SUBCOMMAND') shows a subcommand's arguments, "
               "every "
               "option and examples.\n\nenvironment variables:\n";
        for (const auto &kv : mhplan::cli::environmentVariables())
            out << "  " << std::left << std::setw(21) << kv.first << kv.second << "\n";
    }

    /** OMPL's messages as the program prints them: warnings and errors on stderr, information on stdout,
        without OMPL's source file and line. An error is held back until the next message or the end of the
        run: a planner that refuses the problem logs its reason and throws it, and main() prints it once. */
    class CliOutputHandler : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel level, const char *, int) override
        {
            flush();
            switch (level)
            {
            case ompl::msg::LOG_ERROR:
                pending_ = text;
                return;
            case ompl::msg::LOG_WARN:
                std::cerr << "Warning: " << text << std::endl;
                return;
            case ompl::msg::LOG_INFO:
                std::cout << "Info:    " << text << std::endl;
                return;
            default:
                std::cout << "Debug:   " << text << std::endl;
                return;
            }
        }
        /** Print the held error, if any. */
        void flush()
        {
            if (!pending_.empty())
                std::cerr << "Error:   " << pending_ << std::endl;
            pending_.clear();
        }
        /** Forget the held error when it is \e text (main() prints it itself). */
        void drop(const std::string &text)
        {
            if (pending_ == text)
                pending_.clear();
        }

      private:
        std::string pending_;
    };

    /** `--help` or `-h` anywhere after the subcommand asks for its help (before any other check). */
    bool asksForHelp(int argc, char **argv)
    {
        for (int i = 2; i < argc; ++i)
            if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
                return true;
        return false;
    }
} // namespace

int main(int argc, char **argv)
{
    if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ||
        (std::strcmp(argv[1], "help") == 0 && argc == 2))
    {
        usage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 1 : 0;
    }
    const bool helpCommand = std::strcmp(argv[1], "help") == 0;
    const std::string name = helpCommand ? argv[2] : argv[1];
    if ((name == "version" || name == "--version") && (helpCommand || asksForHelp(argc, argv)))
    {
        std::cout << "usage: mhplan version\n\nprint mhplan's and OMPL's versions\n";
        return 0;
    }
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
    if (helpCommand || asksForHelp(argc, argv))
    {
        mhplan::cli::printCommandHelp(std::cout, it->second.doc());
        return 0;
    }
    // OMPL's informational chatter goes to stderr-level only when asked.
    ompl::msg::setLogLevel(std::getenv("MHPLAN_VERBOSE") ? ompl::msg::LOG_DEBUG : ompl::msg::LOG_WARN);
    static CliOutputHandler handler; // outlives every thread that may log
    ompl::msg::useOutputHandler(&handler);
    // Print a held error before leaving, whatever the way out.
    struct FlushAtExit
    {
        ~FlushAtExit() { handler.flush(); }
    } flushAtExit;
    try
    {
        const int rc = it->second.run(mhplan::cli::Argv(argv + 2, argv + argc));
        // Output that could not be written (a full disk, /dev/full, a closed pipe) is an error, not rc 0.
        std::cout.flush();
        errno = 0;
        const bool written = std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout);
        if (!written)
        {
            std::cerr << "mhplan " << name << ": error: cannot write the output to standard output"
                      << (errno ? std::string(" (") + std::strerror(errno) + ")" : std::string()) << "\n";
            return rc != 0 ? rc : 1;
        }
        return rc;
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
    catch (const ompl::Exception &e)
    {
        // A planner refusing the problem at setup() (docs/conventions.md): the message names the planner
        // and what it needs; printed once (OMPL's log of it is dropped). A problem the user can change, not
        // a defect.
        handler.drop(e.what());
        std::cerr << "mhplan " << name << ": error: " << e.what() << "\n";
        return 1;
    }
    catch (const std::exception &e)
    {
        std::cerr << "mhplan " << name << ": internal error: " << e.what() << "\n";
        return 2;
    }
}
