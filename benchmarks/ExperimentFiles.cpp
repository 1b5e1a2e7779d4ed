// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: what the planning and the simulation experiment processes share: run reports, crash
   records and the experiment's files. */
#include "benchmarks/ExperimentRuns.h"

#include "benchmarks/CampaignRunner.h"

#include "src/base/Version.h"

#include <ompl/base/PlannerStatus.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace mhplan::bench::detail
{
    /** Numbers as OMPL writes them (full precision; "nan"/"inf" become NULL in the database). */
    std::string num(double v)
    {
        if (std::isnan(v))
            return "nan";
        if (std::isinf(v))
            return v > 0 ? "inf" : "-inf";
        char buf[40];
        std::snprintf(buf, sizeof(buf), "%.17g", v);
        return buf;
    }

    void checkInputUnchanged(const Experiment &e, const std::string &bytes, const std::string &file)
    {
        if (!e.inputHash.empty() && fingerprint(bytes) != e.inputHash)
            throw std::runtime_error(
                "'" + file + "' changed after the campaign started (fingerprint " + fingerprint(bytes) +
                ", expected " + e.inputHash +
                "); not run, so that no log mixes two versions of it: re-run the campaign");
    }

    void reportRun(int progressFd, std::size_t experiment, bool crashed, std::size_t slot, double seconds)
    {
        std::ostringstream msg;
        msg.precision(17);
        msg << (crashed ? 1 : 0) << " " << slot << " " << seconds;
        sendMessage(progressFd, 'r', experiment, msg.str());
    }

    void reportCrash(const std::string &experiment, const std::string &what, std::size_t run,
                     const ChildOutcome &outcome, double watchdog)
    {
        std::ostringstream why;
        if (outcome.killed)
            why << "killed after " << watchdog << " s without progress";
        else if (WIFSIGNALED(outcome.status))
            why << "signal " << WTERMSIG(outcome.status) << " (" << strsignal(WTERMSIG(outcome.status))
                << ")";
        else
            why << "exit code " << WEXITSTATUS(outcome.status) << (outcome.error.empty() ? "" : ": ")
                << outcome.error;
        // One write: experiment processes running at the same time share stderr, and a line written in
        // pieces could be cut by another's.
        std::ostringstream line;
        line << (::isatty(2) ? "\n" : "") << "mhplan bench: " << experiment << ": " << what << " run " << run
             << " crashed (" << why.str() << "); recorded as Crash\n";
        const std::string text = line.str();
        std::cerr.flush();
        writeAll(2, text);
    }

    ompl::tools::Benchmark::RunProperties crashRun(double elapsed, std::size_t runIndex, std::uint32_t seed)
    {
        ompl::tools::Benchmark::RunProperties crash;
        crash["time REAL"] = num(elapsed);
        crash["status ENUM"] = std::to_string(static_cast<int>(ompl::base::PlannerStatus::CRASH));
        crash["solved BOOLEAN"] = "0";
        crash["run index INTEGER"] = std::to_string(runIndex);
        crash["run seed INTEGER"] = std::to_string(seed);
        return crash;
    }

    void writeExperimentFiles(const Campaign &c, const Experiment &e, AssembledBenchmark &bench,
                              const std::string &paths, const std::string &improvements)
    {
        bench.experiment().parameters[std::string(kSidecarsProperty) + " TEXT"] =
            fingerprint(paths) + "/" + fingerprint(improvements);
        std::ostringstream log;
        bench.saveResultsToStream(log);
        std::string text = log.str();
        // Debian's OMPL 1.5.2 writes an empty version ("OMPL version "); Planner Arena needs the real
        // one.
        const std::string versionLine = "OMPL version " + omplVersion();
        if (text.rfind("OMPL version", 0) == 0)
            text.replace(0, text.find('\n'), versionLine);
        else
            text = versionLine + "\n" + text;
        fs::create_directories(c.logDir);
        const auto atomicWrite = [](const std::string &file, const std::string &content)
        {
            const std::string tmp = temporaryFile(file);
            {
                std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
                out << content;
                out.close();
                if (!out)
                {
                    const int err = errno;
                    std::error_code ec;
                    fs::remove(tmp, ec);
                    throw std::runtime_error("cannot write '" + tmp + "': " + std::strerror(err ? err : EIO));
                }
            }
            // Complete under its temporary name; the rename makes it visible at once.
            fs::rename(tmp, file);
        };
        atomicWrite(pathsFile(c, e), paths);
        if (!improvements.empty())
            atomicWrite(improvementsFile(c, e), improvements);
        atomicWrite(logFile(c, e), text);
    }
} // namespace mhplan::bench::detail
