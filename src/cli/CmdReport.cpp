// SPDX-License-Identifier: BSD-3-Clause
/* mhplan report DB -o DIR: runs analysis/report.py with an interpreter that has matplotlib and numpy. */
#include "src/cli/Commands.h"
#include "src/cli/Help.h"

#include "src/base/World.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace mhplan::cli
{
    namespace
    {
        volatile sig_atomic_t gChild = 0;
        volatile sig_atomic_t gSignal = 0;

        /** SIGTERM, SIGINT, SIGHUP while report.py runs: passed on to it (it then ends, and so does this
            process, with the signal's exit code). */
        void forwardSignal(int sig)
        {
            gSignal = sig;
            if (gChild > 0)
                ::kill(static_cast<pid_t>(gChild), sig);
        }

        /** The report script: $MHPLAN_ANALYSIS/report.py, the installed share/mhplan/analysis, or the source
            tree's analysis/. */
        std::string reportScript()
        {
            if (const char *env = std::getenv("MHPLAN_ANALYSIS"))
                return (fs::path(env) / "report.py").string();
            std::error_code ec;
            const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
            if (!ec)
            {
                const fs::path installed =
                    exe.parent_path().parent_path() / MHPLAN_INSTALLED_ANALYSIS_DIR / "report.py";
                if (fs::exists(installed))
                    return installed.string();
            }
            return (fs::path(MHPLAN_ANALYSIS_DIR) / "report.py").string();
        }

        /** Debian's interpreter carries python3-matplotlib and python3-numpy; a python3 earlier on PATH
            may not. $MHPLAN_PYTHON overrides. */
        std::string pythonInterpreter()
        {
            if (const char *env = std::getenv("MHPLAN_PYTHON"))
                return env;
            return "/usr/bin/python3";
        }
    } // namespace

    const CommandDoc &reportDoc()
    {
        static const CommandDoc doc{
            "report DATABASE [-o DIR] [--worlds DIR]",
            "write an HTML report (figures and tables) from a benchmark database into DIR/index.html",
            "Runs analysis/report.py with /usr/bin/python3 (numpy, matplotlib). The report asks this program "
            "for the worlds it draws (mhplan worlds FILE --json; MHPLAN_BIN is set for it).",
            {{"DATABASE", "an SQLite database written by mhplan bench (or ompl_benchmark_statistics)"}},
            {{"-o, --output", "DIR", "output directory (default: report)"},
             {"--worlds", "DIR", "directory that relative world_file paths in the database are relative to"}},
            {"report results/seeds.db -o report_seeds"},
            "0 written, 1 bad input (not a database, output not writable), 2 internal error"};
        return doc;
    }

    int cmdReport(const Argv &argv)
    {
        const std::string script = reportScript();
        if (!fs::exists(script))
            throw InputError("mhplan report: cannot find the analysis script " + script +
                             " (set MHPLAN_ANALYSIS to the directory holding report.py)");
        const std::string python = pythonInterpreter();
        if (access(python.c_str(), X_OK) != 0)
            throw InputError("mhplan report: no Python interpreter at " + python +
                             " (install python3-matplotlib and python3-numpy, or set MHPLAN_PYTHON)");
        std::vector<std::string> args{python, script};
        args.insert(args.end(), argv.begin(), argv.end());
        std::vector<char *> cargs;
        for (auto &a : args)
            cargs.push_back(a.data());
        cargs.push_back(nullptr);
        std::cout.flush();
        struct sigaction sa
        {
        }, old[3];
        sa.sa_handler = forwardSignal;
        sigemptyset(&sa.sa_mask);
        const int signals[3] = {SIGTERM, SIGINT, SIGHUP};
        for (int i = 0; i < 3; ++i)
            sigaction(signals[i], &sa, &old[i]);
        const pid_t pid = fork();
        if (pid < 0)
            throw InputError("mhplan report: cannot start " + python);
        if (pid == 0)
        {
            for (int i = 0; i < 3; ++i)
                sigaction(signals[i], &old[i], nullptr);
            // report.py asks this very program for the worlds it draws (mhplan worlds FILE --json).
            std::error_code ec;
            const fs::path self = fs::read_symlink("/proc/self/exe", ec);
            if (!ec)
                setenv("MHPLAN_BIN", self.c_str(), 1);
            execv(python.c_str(), cargs.data());
            _exit(127);
        }
        gChild = pid;
        if (gSignal != 0) // arrived between fork() and here
            ::kill(pid, gSignal);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        {
        }
        gChild = 0;
        for (int i = 0; i < 3; ++i)
            sigaction(signals[i], &old[i], nullptr);
        if (gSignal != 0)
            return 128 + gSignal;
        if (WIFSIGNALED(status))
            return 128 + WTERMSIG(status);
        return WIFEXITED(status) ? WEXITSTATUS(status) : 2;
    }
} // namespace mhplan::cli
