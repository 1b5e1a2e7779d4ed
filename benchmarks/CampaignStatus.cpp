// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the cores a campaign may use (oversubscription) and where each experiment stands
   (--status): complete logs, markers of experiments in flight and of failed attempts. */
#include "benchmarks/CampaignRunner.h"

#include "src/base/World.h"

#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>

namespace mhplan::bench
{
    namespace
    {
        /** The leading positive integer of \e text ("2", "4(x3)", "2,1"), 0 when there is none. */
        unsigned int leadingCount(const char *text)
        {
            if (text == nullptr)
                return 0;
            char *end = nullptr;
            const long n = std::strtol(text, &end, 10);
            return end != text && n > 0 && n < 1000000 ? static_cast<unsigned int>(n) : 0;
        }

        std::string hostName()
        {
            char host[256] = {0};
            if (::gethostname(host, sizeof(host) - 1) != 0)
                return "unknown";
            return host;
        }
    } // namespace

    unsigned int availableCores()
    {
        unsigned int cores = 0;
        cpu_set_t set;
        CPU_ZERO(&set);
        if (::sched_getaffinity(0, sizeof(set), &set) == 0)
            cores = static_cast<unsigned int>(CPU_COUNT(&set));
        if (cores == 0)
        {
            const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
            cores = n > 0 ? static_cast<unsigned int>(n) : 1;
        }
        // Without task/affinity or task/cgroup a Slurm task sees the whole node: its allocation is in the
        // environment.
        if (std::getenv("SLURM_JOB_ID") != nullptr)
        {
            unsigned int slurm = leadingCount(std::getenv("SLURM_CPUS_PER_TASK"));
            if (slurm == 0)
                slurm = leadingCount(std::getenv("SLURM_JOB_CPUS_PER_NODE"));
            if (slurm > 0 && slurm < cores)
                cores = slurm;
        }
        return cores;
    }

    double loadAverage()
    {
        double load[1] = {-1.0};
        return ::getloadavg(load, 1) == 1 ? load[0] : -1.0;
    }

    void checkOversubscription(unsigned int concurrent, unsigned int cores, bool allow, std::ostream *warn)
    {
        if (concurrent <= cores)
            return;
        std::ostringstream what;
        what << concurrent << " experiments at once (--jobs) on " << cores
             << " core(s) available to this process (its CPU affinity; in a Slurm task the CPUs allocated to "
                "it): each run would get about "
             << (100 * cores / concurrent)
             << " % of a core, and time-limited planners would do that much less";
        if (!allow)
            throw InputError("mhplan bench: " + what.str() + ". Use --jobs " + std::to_string(cores) +
                             ", or --oversubscribe to run anyway (then consider time_limit_kind: cpu)");
        if (warn)
            *warn << "mhplan bench: warning: " << what.str() << " (--oversubscribe)\n";
    }

    std::string runningMarker(const Campaign &campaign, const Experiment &experiment)
    {
        return logFile(campaign, experiment) + ".running";
    }

    std::string failedMarker(const Campaign &campaign, const Experiment &experiment)
    {
        return logFile(campaign, experiment) + ".failed";
    }

    const char *stateName(ExperimentState state)
    {
        switch (state)
        {
        case ExperimentState::Complete:
            return "complete";
        case ExperimentState::Missing:
            return "missing";
        case ExperimentState::Running:
            return "running";
        case ExperimentState::Failed:
            return "failed";
        }
        return "?";
    }

    ExperimentState experimentState(const Campaign &campaign, const Experiment &experiment, std::string &why)
    {
        why.clear();
        if (logIsComplete(logFile(campaign, experiment), experiment.configHash))
            return ExperimentState::Complete;
        {
            // "HOST PID": the experiment process that runs it (Scheduler.cpp).
            std::ifstream in(runningMarker(campaign, experiment));
            std::string host;
            long pid = 0;
            if (in >> host >> pid)
            {
                if (host != hostName())
                {
                    why = "started on " + host + " by process " + std::to_string(pid);
                    return ExperimentState::Running;
                }
                if (pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM))
                {
                    why = "process " + std::to_string(pid);
                    return ExperimentState::Running;
                }
                why = "its process " + std::to_string(pid) + " on " + host + " ended without a log (killed)";
                return ExperimentState::Failed;
            }
        }
        std::ifstream failed(failedMarker(campaign, experiment));
        if (failed && std::getline(failed, why))
            return ExperimentState::Failed;
        std::ifstream log(logFile(campaign, experiment));
        if (log)
            why = "its log is stale or unfinished";
        return ExperimentState::Missing;
    }

    std::string currentHostName()
    {
        return hostName();
    }

    std::string temporaryFilePrefix(const std::string &file)
    {
        return file + ".mhplan-tmp." + safeFileStem(hostName()) + ".";
    }

    std::string temporaryFile(const std::string &file)
    {
        return temporaryFilePrefix(file) + std::to_string(::getpid());
    }
} // namespace mhplan::bench
