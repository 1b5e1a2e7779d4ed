// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: running a benchmark campaign. Every (world, query) experiment is one ompl::tools::Benchmark
   experiment, every simulation entry one experiment whose "planners" are its controllers; runs execute in
   child processes so that a planner that throws, aborts, crashes or hangs
   is recorded with status Crash while the campaign goes on. Logs are OMPL benchmark logs (one per
   experiment, with a real version line), merged into one SQLite database by ompl_benchmark_statistics. */
#ifndef MHPLAN_BENCH_CAMPAIGN_RUNNER_H
#define MHPLAN_BENCH_CAMPAIGN_RUNNER_H

#include "benchmarks/Campaign.h"
#include "src/sim/Simulation.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace mhplan
{
    class PlannerRegistry;
}

namespace mhplan::bench
{
    /** \brief How to run a campaign. */
    struct RunOptions
    {
        /** \brief Experiments run at the same time, each in its own process (1..256). */
        unsigned int jobs{1};
        /** \brief Run only part \e shardIndex (1-based) of \e shardCount disjoint parts. */
        unsigned int shardIndex{1};
        unsigned int shardCount{1};
        /** \brief Run the experiments whose logs are missing or stale. */
        bool run{true};
        /** \brief Append the finished logs to the campaign's database afterwards. */
        bool merge{true};
        /** \brief Run more experiments at once than there are cores available (availableCores()); without
            it runCampaign refuses, because time-limited planners would silently get a fraction of a core. */
        bool oversubscribe{false};
        /** \brief Draw a progress bar on stderr (only when stderr is a terminal). */
        bool progressBar{true};
        /** \brief Where progress lines and the summary go when there is no bar (may be null). */
        std::ostream *messages{nullptr};
        /** \brief The converter from logs to the database. */
        std::string statisticsTool{"/usr/bin/ompl_benchmark_statistics"};
        /** \brief Planners to draw from, for the campaign's planners and its "plan:<PLANNER>" controllers
            (default: builtinPlanners()). */
        const PlannerRegistry *registry{nullptr};
        /** \brief How world names are resolved (required). */
        WorldResolver resolveWorld;
    };

    /** \brief What a campaign did and how long it took. */
    struct CampaignSummary
    {
        std::size_t experiments{0}; ///< experiments in this shard
        std::size_t skipped{0};     ///< already complete (resume)
        std::size_t completed{0};   ///< run now, log written
        std::size_t failed{0};      ///< worker process failed (no log)
        std::size_t runs{0};        ///< planner runs executed now
        std::size_t crashes{0};     ///< of which recorded as Crash
        std::size_t mergedLogs{0};  ///< logs appended to the database now
        std::size_t missing{0};     ///< merging: experiments of the campaign without a complete log
        std::size_t rejected{0};    ///< merging: logs not taken (side files or input files changed)
        double wallSeconds{0.0};    ///< whole call
        double workerSeconds{0.0};  ///< sum over experiments of their processes' wall time
        double solveSeconds{0.0};   ///< sum of the planners' solve times (OMPL's "time" of each run)
        double cpuSeconds{0.0};     ///< sum of the runs' CPU times (column cpu_time)
        double mergeSeconds{0.0};   ///< building the database
        std::vector<std::string> errors;
        /** \brief (worker + merge - solve) / (worker + merge): time outside solve calls. */
        double overheadFraction() const;
    };

    /** \brief The cores this process may use: its CPU affinity mask (which honours taskset, cgroup cpusets
        and Slurm's task binding), and inside a Slurm job no more than the CPUs allocated to it
        (SLURM_CPUS_PER_TASK, else SLURM_JOB_CPUS_PER_NODE). At least 1. */
    unsigned int availableCores();

    /** \brief The system's 1-minute load average (getloadavg: runnable and running tasks, over all cores);
        -1 when the system does not tell. */
    double loadAverage();

    /** \brief Refuse (InputError naming --jobs and --oversubscribe) or, when \e allow, warn on \e warn
        (may be null) when \e concurrent experiment processes exceed \e cores. */
    void checkOversubscription(unsigned int concurrent, unsigned int cores, bool allow, std::ostream *warn);

    /** \brief Where an experiment stands (mhplan bench --status). */
    enum class ExperimentState
    {
        Complete, ///< its log is complete with the current fingerprint
        Missing,  ///< never run, or its log is stale (another fingerprint) or unfinished
        Running,  ///< an experiment process on this host is running it, or one on another host started it
        Failed    ///< its process failed, or was killed (the marker of a dead process is left)
    };

    /** \brief The state of \e experiment and why (e.g. "exit code 4 on node3", "started on node2 by
        process 123"). */
    ExperimentState experimentState(const Campaign &campaign, const Experiment &experiment, std::string &why);

    /** \brief "complete", "missing", "running", "failed". */
    const char *stateName(ExperimentState state);

    /** \brief The markers the scheduler keeps next to an experiment's log: LOG.running (host and process
        of the experiment in flight) and LOG.failed (why its last attempt failed). */
    std::string runningMarker(const Campaign &campaign, const Experiment &experiment);
    std::string failedMarker(const Campaign &campaign, const Experiment &experiment);
    /** \brief This machine's host name (as the markers record it). */
    std::string currentHostName();

    /** \brief Run (the shard of) a campaign and merge its logs. Throws InputError for a bad campaign
        (unknown planner or parameter, missing world) before any work starts. */
    CampaignSummary runCampaign(const Campaign &campaign, const RunOptions &options);

    /** \brief Perturb the robots' starts of \e scenario for one run of a simulation experiment: every robot's
        start moves to a point drawn uniformly from the disc of radius \e startJitter about it, redrawn (up to
        1000 times, else kept) until the robot is inside the bounds, off the static obstacles, off the moving
        obstacles at its join time and off every other robot's start; its heading turns by a uniform angle in
        [-headingJitter, headingJitter]. Portable (splitmix64), deterministic in \e seed; nothing changes when
        both radii are 0. */
    void applyStartJitter(Scenario &scenario, double startJitter, double headingJitter, std::uint32_t seed);

    /** \brief The log file of an experiment. */
    std::string logFile(const Campaign &campaign, const Experiment &experiment);
    /** \brief The solution-path sidecar of an experiment's log (tab-separated: planner, run, points). */
    std::string pathsFile(const Campaign &campaign, const Experiment &experiment);

    /** \brief True when \e log exists, is complete and was made with configuration \e configHash. */
    bool logIsComplete(const std::string &log, const std::string &configHash);

    /** \brief Append the complete logs of \e experiments that the database does not hold yet (or holds
        from another configuration, which is replaced) with ompl_benchmark_statistics, then add their
        solution paths to the table solution_paths(runid, idx, x, y). Planning experiments go to the
        campaign's database, simulation experiments to simulationDatabaseFile(campaign) (the same file for a
        campaign of simulations only). A log is identified by its experiment and content fingerprint (not
        its path), taken only with the side files it was written with and only while its world or scenario
        file is unchanged; \e problems receives why a log was not taken. Returns the number of logs
        merged. */
    std::size_t mergeDatabase(const Campaign &campaign, const std::vector<Experiment> &experiments,
                              const std::string &statisticsTool, std::vector<std::string> &problems);
} // namespace mhplan::bench

#endif
