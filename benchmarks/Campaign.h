/* mhplan: benchmark campaigns. A campaign file (YAML, see benchmarks/README.md) names worlds and queries,
   planners with parameter overrides, limits, run count, seed and where the logs and the database go. Each
   (world, query) pair is one OMPL benchmark experiment. */
#ifndef MHPLAN_BENCH_CAMPAIGN_H
#define MHPLAN_BENCH_CAMPAIGN_H

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mhplan::bench
{
    /** \brief One planner configuration of a campaign. The same registry planner may appear several times
        under distinct display names. */
    struct PlannerSpec
    {
        /** \brief Name in the logs and the database (OMPL prefixes it with "geometric_"). */
        std::string displayName;
        /** \brief Registry name (see 'mhplan planners'). */
        std::string planner;
        /** \brief Parameter overrides, validated by the registry. */
        std::map<std::string, std::string> params;
        /** \brief Progress properties to sample, by name without the type ("best cost"); empty: all the
            planner declares. OMPL 1.5.2's BIT* crashes now and then when some of its progress properties are
            read while it plans. */
        std::vector<std::string> progress;
    };

    /** \brief A world of a campaign and the queries to run on it. */
    struct WorldSpec
    {
        /** \brief As written in the campaign: a path (relative to the campaign file or the working
            directory) or a shipped world's name. */
        std::string world;
        /** \brief Query names; empty means every query of the world. */
        std::vector<std::string> queries;
    };

    /** \brief A parsed campaign file. */
    struct Campaign
    {
        std::string name;
        /** \brief The file it was read from. */
        std::string file;
        std::vector<WorldSpec> worlds;
        std::vector<PlannerSpec> planners;
        /** \brief Seconds per run. */
        double timeLimit{1.0};
        /** \brief MB per run (OMPL's termination condition checks the process's memory). */
        double memoryLimit{4096.0};
        /** \brief Runs per planner and experiment. */
        unsigned int runs{10};
        /** \brief Campaign seed; per-experiment and per-process seeds derive from it (see deriveSeed). */
        std::uint32_t seed{1};
        /** \brief Seconds between two samples of the planners' progress properties. */
        double progressInterval{0.05};
        /** \brief Export each run's planner data ("graph states", "graph motions") as OMPL's benchmark does;
            off saves the time (a PRM* roadmap takes about as long to export as to build). */
        bool plannerData{true};
        /** \brief Collision back end: auto, analytic, fcl or grid. */
        std::string collision{"auto"};
        /** \brief The SQLite database (relative paths are relative to the working directory). */
        std::string database;
        /** \brief Directory of the per-experiment .log files (default: the database path + ".logs"). */
        std::string logDir;
    };

    /** \brief Read a campaign file; throws InputError naming the file, line and field on any problem. */
    Campaign loadCampaign(const std::string &path);

    /** \brief Parse campaign YAML; \e fileName is used in messages and to resolve relative world paths. */
    Campaign parseCampaign(const std::string &text, const std::string &fileName);

    /** \brief One (world, query) experiment of a campaign. */
    struct Experiment
    {
        /** \brief Position in the campaign's enumeration (worlds in order, then their queries). */
        std::size_t index{0};
        /** \brief "WORLD-QUERY" (also the log file's stem). */
        std::string name;
        std::string worldFile;
        std::string worldName;
        std::string query;
        /** \brief deriveSeed(campaign seed, name, 0). */
        std::uint32_t seed{1};
        /** \brief Fingerprint of everything that determines the experiment's results (world file contents,
            query, planners, limits, runs, seeds); a log with another fingerprint is re-run. */
        std::string configHash;
    };

    /** \brief Resolve a world argument to a file path (a shipped world's name or a path). */
    using WorldResolver = std::function<std::string(const std::string &)>;

    /** \brief Load every world of the campaign, check its queries and list the experiments in campaign
        order. Relative world paths are tried relative to the campaign file first, then given to
        \e resolve. Throws InputError for a missing world or query or a duplicate experiment. */
    std::vector<Experiment> enumerateExperiments(const Campaign &campaign, const WorldResolver &resolve);

    /** \brief The seed of a sub-task: a 64-bit mix (splitmix64 over FNV-1a) of \e base, \e label and
        \e index, mapped to [1, 2^32 - 1] (OMPL refuses 0). */
    std::uint32_t deriveSeed(std::uint32_t base, const std::string &label, std::uint64_t index);

    /** \brief 64-bit FNV-1a hash of a string, as 16 hex digits. */
    std::string fingerprint(const std::string &text);

    /** \brief The experiments of shard \e part (1-based) of \e parts: those with index % parts == part - 1.
     */
    std::vector<Experiment> shardExperiments(const std::vector<Experiment> &all, unsigned int part,
                                             unsigned int parts);

    /** \brief A file-system-safe version of an experiment name. */
    std::string safeFileStem(const std::string &name);
} // namespace mhplan::bench

#endif
