// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: benchmark campaigns. A campaign file (YAML, see benchmarks/README.md) names worlds and queries,
   planners with parameter overrides, limits, run count, seed and where the logs and the database go. Each
   (world, query) pair is one OMPL benchmark experiment. */
#ifndef MHPLAN_BENCH_CAMPAIGN_H
#define MHPLAN_BENCH_CAMPAIGN_H

#include "src/base/PlannerRegistry.h"
#include "src/registry/Registry.h"
#include "src/base/World.h"
#include "benchmarks/GeneratedWorlds.h"
#include "src/collision/Problem.h"

#include <algorithm>
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
        /** \brief Runs per experiment of this planner; 0: the campaign's \c runs (see runsOf()). */
        unsigned int runs{0};
        /** \brief Line of its entry in the campaign file. */
        int line{0};
        /** \brief The state spaces the planner declares (cap:: flags of its registry entry). */
        unsigned capabilities{0};
        /** \brief For each world space flag the planner does not declare: why, in one sentence naming a
            planner that runs there (PlannerRegistry::whyNotApplicable). */
        std::map<unsigned, std::string> refusals{};
    };

    /** \brief A world of a campaign and the queries to run on it. */
    struct WorldSpec
    {
        /** \brief As written in the campaign: a path (relative to the campaign file or the working
            directory) or a shipped world's name. */
        std::string world;
        /** \brief Query names; empty means every query of the world. */
        std::vector<std::string> queries;
        /** \brief A world generated at campaign time (GeneratedWorlds.h; then \c world is empty). */
        GeneratedWorldSpec generated;
        /** \brief A MovingAI benchmark set {map: FILE.map, scen: FILE.map.scen, ...} (then \c world is the
            map and \c scen the scenario; each selected .scen problem is one experiment). */
        std::string scen;
        /** \brief Which .scen problems (ScenIO.h: buckets, every k-th, the first K per bucket). */
        std::vector<int> scenBuckets;
        unsigned int scenEvery{1};
        unsigned int scenPerBucket{0};
        /** \brief Line of the entry in the campaign file (1-based; 0 when built in code), for messages. */
        int line{0};
        /** \brief The entry's set-ups (key setup; docs/setups.md): every query runs once per set-up; empty:
            the campaign's. */
        std::vector<ValiditySetup> setups;
        /** \brief An OMPL.app problem file {cfg: FILE} (docs/omplapp.md), as written (relative to the
           campaign file); then \c world is empty and the entry is one experiment on the problem's meshes. */
        std::string cfg;
    };

    /** \brief One controller configuration of a simulation experiment (Controllers.h). */
    struct ControllerSpec
    {
        /** \brief Name in the logs and the database after "sim:" (default: the controller's name). */
        std::string displayName;
        /** \brief Controller name as makeController accepts it ("dapf", "aapf", "plan:ThetaStar", ...). */
        std::string controller;
        /** \brief Parameter overrides (Controller::setParameter), checked before anything runs. */
        std::map<std::string, std::string> params;
        /** \brief Line of the entry in the campaign file (1-based; 0 when built in code), for messages. */
        int line{0};
    };

    /** \brief A simulation experiment of a campaign: one scenario (ScenarioIO.h), its controllers, runs. */
    struct SimulationSpec
    {
        /** \brief As written: a scenario file path (relative to the campaign file first) or a shipped name.
         */
        std::string scenario;
        std::vector<ControllerSpec> controllers;
        /** \brief Runs per controller; 0: the campaign's \c runs. */
        unsigned int runs{0};
        /** \brief Base seed of this experiment; 0: the campaign's \c seed. */
        std::uint32_t seed{0};
        /** \brief Each run k starts every robot at a point drawn uniformly from the disc of this radius (m)
            about its scenario start (redrawn while invalid); the same draw for every controller at run k. */
        double startJitter{0.0};
        /** \brief Each run k turns every robot's initial heading by a uniform angle in [-h, h] (rad). */
        double headingJitter{0.0};
        /** \brief A run that gives no result within this many wall-clock seconds is killed (Crash). */
        double wallLimit{600.0};
        /** \brief Line of the entry in the campaign file (1-based; 0 when built in code), for messages. */
        int line{0};
    };

    /** \brief With time_limit_kind: cpu, a run still ends after this many times its CPU limit (+ 10 s) of
        wall-clock time. */
    constexpr double kCpuLimitWallFactor = 10.0;

    /** \brief A parsed campaign file. */
    struct Campaign
    {
        std::string name;
        /** \brief The file it was read from. */
        std::string file;
        std::vector<WorldSpec> worlds;
        std::vector<PlannerSpec> planners;
        /** \brief Simulation experiments (may be the only experiments: then worlds and planners may be
            absent). */
        std::vector<SimulationSpec> simulations;
        /** \brief Seconds per run. */
        double timeLimit{1.0};
        /** \brief What \c timeLimit bounds: false: wall-clock seconds (OMPL's maxTime); true
            (time_limit_kind: cpu): CPU seconds of the run's process, so that time-bounded planners get the
            same budget however loaded the machine is (the wall clock then only stops a run after
            kCpuLimitWallFactor x timeLimit + 10 s). */
        bool cpuTimeLimit{false};
        /** \brief Wall-clock seconds a planning run may go without a result before it is killed and recorded
            as Crash (campaign key wall_limit; counted from the run's start and from each of its messages:
            its setup, then its solve() and metrics); 0: the default, 2 x runWallBound + 20 s. Simulation
            runs have their own, SimulationSpec::wallLimit. */
        double wallLimit{0.0};
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
        /** \brief Collision back end: auto, analytic, fcl, grid or hash. */
        std::string collision{"auto"};
        /** \brief The SQLite database (relative paths are relative to the working directory). */
        std::string database;
        /** \brief The database of the simulation experiments; empty: see simulationDatabaseFile(). Planner
            Arena lists every column of the experiments table as a problem parameter, so planning and
            simulation experiments in one database would show each other's columns as "all (aggregate)". */
        std::string simulationDatabase;
        /** \brief Directory of the per-experiment .log files (default: the database path + ".logs"). */
        std::string logDir;
        /** \brief Key skip_inapplicable: a planner that cannot run on a world's state space (its declared
            capabilities) is skipped there (Experiment::skipped) instead of refusing the campaign. */
        bool skipInapplicable{false};
        /** \brief Key setup (docs/setups.md): the set-ups of every world entry without its own; default the
            exact set-up alone. */
        std::vector<ValiditySetup> setups{ValiditySetup{}};
    };

    /** \brief What a set-up adds to an experiment's name: "" (exact), "-app" (app at the default
        resolution), "-appR" (app at resolution R). */
    std::string setupSuffix(const ValiditySetup &setup);

    /** \brief Read a campaign file; throws InputError naming the file, line and field on any problem.
        Controller names "plan:<PLANNER>" are checked against \e registry. */
    Campaign loadCampaign(const std::string &path, const PlannerRegistry &registry = builtinPlanners());

    /** \brief Parse campaign YAML; \e fileName is used in messages and to resolve relative world paths. */
    Campaign parseCampaign(const std::string &text, const std::string &fileName,
                           const PlannerRegistry &registry = builtinPlanners());

    /** \brief Runs of planner \e p in every planning experiment of \e c (its own \c runs, else the
        campaign's). */
    inline unsigned int runsOf(const Campaign &c, const PlannerSpec &p)
    {
        return p.runs > 0 ? p.runs : c.runs;
    }

    /** \brief Where the simulation experiments of \e campaign go: its \c simulationDatabase when given; else,
        when the campaign has planning experiments too, \c database with "-sim" before its extension
        (results/seeds.db -> results/seeds-sim.db); else \c database itself. */
    std::string simulationDatabaseFile(const Campaign &campaign);

    /** \brief One (world, query) planning experiment or one scenario's simulation experiment. */
    struct Experiment
    {
        /** \brief Marks a planning experiment in \c simulation. */
        static constexpr std::size_t kNoSimulation = static_cast<std::size_t>(-1);
        /** \brief Position in the campaign's enumeration (worlds in order, then their queries). */
        std::size_t index{0};
        /** \brief "WORLD-QUERY" (also the log file's stem). */
        std::string name;
        std::string worldFile;
        std::string worldName;
        std::string query;
        /** \brief For a MovingAI experiment: the .scen file, its line, bucket and optimum (cells), mhplan's
            octile optimum of the problem (cells), and the start and goal (world coordinates); else line 0. */
        std::string scenFile;
        int scenLine{0};
        int scenBucket{0};
        double scenOptimum{0.0};
        double octileOptimum{0.0};
        double startX{0.0}, startY{0.0}, goalX{0.0}, goalY{0.0};
        /** \brief The validity set-up the runs use (docs/setups.md); part of the name (setupSuffix) and of
            the fingerprint (app only: exact experiments keep their fingerprints). */
        ValiditySetup setup;
        /** \brief For a simulation experiment: its index in Campaign::simulations (else kNoSimulation). */
        std::size_t simulation{kNoSimulation};
        /** \brief For a simulation experiment: the scenario file and the scenario's name. */
        std::string scenarioFile;
        std::string scenarioName;
        /** \brief An OMPL.app problem ({cfg: FILE}): \c worldFile is the .cfg file, \c worldName its
           problem's name; its meshes are part of configHash and inputHash. */
        bool cfg{false};
        /** \brief Runs per planner or controller. */
        unsigned int runs{0};
        /** \brief deriveSeed(campaign seed, name, 0) (simulations: their own seed when given). */
        std::uint32_t seed{1};
        /** \brief Fingerprint of everything that determines the experiment's results (world file contents,
            query, planners, limits, runs, seeds); a log with another fingerprint is re-run. */
        std::string configHash;
        /** \brief fingerprint() of the world (planning) or scenario (simulation) file's bytes as they were
            when the campaign was enumerated: the experiment process checks the bytes it loads against it,
            and the merge checks the file again (a file edited while the campaign runs is never mixed in). */
        std::string inputHash;
        /** \brief Indices in Campaign::planners of the planners not run here: they cannot run on the world's
            state space (skip_inapplicable). */
        std::vector<std::size_t> skipped;
        bool skips(std::size_t planner) const
        {
            return std::find(skipped.begin(), skipped.end(), planner) != skipped.end();
        }
    };

    /** \brief The fingerprint of experiment \e e's input files as they are now (Experiment::inputHash):
        the world or scenario file's bytes; for an OMPL.app problem the .cfg file's and both meshes'. A file
        that cannot be read gives "(unreadable)". */
    std::string inputFingerprint(const Experiment &e);

    /** \brief The query of planning experiment \e e on its \e world: a MovingAI problem's start and goal,
       else the world's query of that name. */
    Query experimentQuery(const World &world, const Experiment &e);

    /** \brief Resolve a world argument to a file path (a shipped world's name or a path). */
    using WorldResolver = std::function<std::string(const std::string &)>;

    /** \brief Load every world of the campaign, check its queries and list the experiments in campaign
        order: the planning experiments (worlds in order, then their queries), then one experiment per
        simulation entry ("SCENARIO-sim"). Relative world and scenario paths are tried relative to the
        campaign file first, then given to \e resolve. Throws InputError for a missing world, query or
        scenario, a bad scenario file, a duplicate experiment, or a planner that cannot run on a world's state
        space (naming the planner's line; with skip_inapplicable: Experiment::skipped instead). */
    std::vector<Experiment> enumerateExperiments(const Campaign &campaign, const WorldResolver &resolve);

    /** \brief The seed of run \e run of controller \e displayName in a simulation experiment (also the
        seed of that run's process and of its Simulation). */
    std::uint32_t simulationRunSeed(const Experiment &experiment, const std::string &displayName,
                                    std::size_t run);
    /** \brief The seed of the start perturbation of run \e run of a simulation experiment (shared by all
        its controllers, so that their runs are paired). */
    std::uint32_t simulationStartSeed(const Experiment &experiment, std::size_t run);

    /** \brief The seed of a sub-task: a 64-bit mix (splitmix64 over FNV-1a) of \e base, \e label and
        \e index, mapped to [1, 2^32 - 1] (OMPL refuses 0). */
    std::uint32_t deriveSeed(std::uint32_t base, const std::string &label, std::uint64_t index);

    /** \brief 64-bit FNV-1a hash of a string, as 16 hex digits. */
    std::string fingerprint(const std::string &text);

    /** \brief The FNV-1a hash of fingerprint() fed piece by piece: a copy continues from where it was, so a
        long common prefix (a world file) is hashed once for all the texts that start with it. */
    class Fingerprint
    {
      public:
        void add(const std::string &text);
        /** \brief 16 hex digits, as fingerprint(all the text added). */
        std::string hex() const;

      private:
        std::uint64_t h_{1469598103934665603ULL};
    };

    /** \brief The experiments of shard \e part (1-based) of \e parts: those with index % parts == part - 1.
     */
    std::vector<Experiment> shardExperiments(const std::vector<Experiment> &all, unsigned int part,
                                             unsigned int parts);

    /** \brief The name under which \e file (a log, a side file, a generated world, a script) is written
        before it is renamed to its own name: "FILE.mhplan-tmp.HOST.PID" (the host as safeFileStem makes it).
        The name says whose it is: a campaign removes only its own experiments' temporary files of dead
        processes on this host, never another host's, never a file it did not make. */
    std::string temporaryFile(const std::string &file);
    /** \brief The part of temporaryFile(file) before the process id. */
    std::string temporaryFilePrefix(const std::string &file);

    /** \brief A file-system-safe version of an experiment name. */
    std::string safeFileStem(const std::string &name);
} // namespace mhplan::bench

#endif
