// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench --slurm: a campaign as a Slurm job array. mhplan writes two batch scripts and leaves the
   scheduling to Slurm: an array job whose task i runs "mhplan bench CAMPAIGN --shard i/N" into the shared
   log directory, and a merge job that depends on the whole array (afterok) and builds the database with
   --merge-only. Resubmitting submits only the shards that still have missing experiments (every task also
   skips the experiments whose logs are complete). See benchmarks/README.md, "Slurm". */
#ifndef MHPLAN_BENCH_SLURM_H
#define MHPLAN_BENCH_SLURM_H

#include "benchmarks/Campaign.h"

#include <string>
#include <vector>

namespace mhplan::bench
{
    /** \brief How the campaign is laid out on the cluster. */
    struct SlurmOptions
    {
        /** \brief Array tasks, each one shard i/N of the campaign (1..10000). */
        unsigned int shards{1};
        /** \brief sbatch --partition (empty: the cluster's default). */
        std::string partition;
        /** \brief sbatch --time of each task, in Slurm's format (empty: estimated from the campaign). */
        std::string timeLimit;
        /** \brief sbatch --mem of each task in MB (0: the cluster's default). */
        unsigned long memoryMB{0};
        /** \brief sbatch --cpus-per-task; each task runs with --jobs equal to it. */
        unsigned int cpus{1};
        /** \brief The mhplan executable the tasks run (absolute). */
        std::string executable;
        /** \brief The campaign file (absolute). */
        std::string campaignFile;
        /** \brief The directory the tasks start in (relative paths of the campaign resolve from it). */
        std::string workDir;
        /** \brief Options passed on to every task and the merge (--database, --logs, --runs, ...). */
        std::vector<std::string> passThrough;
    };

    /** \brief The two batch scripts of a campaign. */
    struct SlurmScripts
    {
        std::string directory; ///< LOGS/slurm: the scripts, the tasks' output, the submitted job ids
        std::string arrayScript;
        std::string mergeScript;
        /** \brief The --array list of the shards with missing experiments ("1-4", "2,4"; empty: none). */
        std::string missingShards;
        /** \brief The --time written into the array script. */
        std::string taskTime;
    };

    /** \brief Check \e options (shards, cpus, memory, time format); throws InputError naming the option. */
    void checkSlurmOptions(const SlurmOptions &options);

    /** \brief Slurm's time format for \e seconds ("D-HH:MM:SS"), rounded up to whole minutes. */
    std::string slurmTime(double seconds);

    /** \brief A generous estimate of one task's wall time: its shard's runs x (time limit + 1 s) / cpus,
        doubled, plus 10 minutes (iteration-bounded planners may take longer; pass --time then). */
    double estimateTaskSeconds(const Campaign &campaign, const std::vector<Experiment> &all,
                               const SlurmOptions &options);

    /** \brief The array list "1-3,5" of the sorted 1-based indices \e shards. */
    std::string arrayList(const std::vector<unsigned int> &shards);

    /** \brief Write LOGS/slurm/array.sbatch and merge.sbatch for \e campaign (its logDir and database
        already overridden as the command line asks) and work out which shards have missing experiments. */
    SlurmScripts writeSlurmScripts(const Campaign &campaign, const std::vector<Experiment> &all,
                                   const SlurmOptions &options);

    /** \brief The job ids of one submission. */
    struct SlurmSubmission
    {
        std::string arrayJob; ///< empty when no shard had missing experiments
        std::string mergeJob;
    };

    /** \brief Submit the array job (only the missing shards) and the merge job (afterok on the array,
        cancelled by Slurm if a task fails) with \e sbatch; records the ids in LOGS/slurm/submitted.
        Throws std::runtime_error with sbatch's message when a submission fails. */
    SlurmSubmission submitSlurmJobs(const SlurmScripts &scripts, const std::string &sbatch = "sbatch");
} // namespace mhplan::bench

#endif
