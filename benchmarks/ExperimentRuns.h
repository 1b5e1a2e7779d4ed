// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: one experiment process. It runs every planner (or every controller of a simulation) of
   the campaign on its experiment, the runs in sequence in a child process that is replaced when it dies or
   hangs (ChildProcess.h; a crash costs only the run in flight), reports every run to
   the campaign process and writes the experiment's log (OMPL's format and writer) and its sidecars. */
#ifndef MHPLAN_BENCH_EXPERIMENT_RUNS_H
#define MHPLAN_BENCH_EXPERIMENT_RUNS_H

#include "benchmarks/Campaign.h"
#include "benchmarks/ChildProcess.h"
#include "benchmarks/OmplAdapters.h"
#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/io/CfgIO.h"
#include "src/sim/Simulation.h"

#include <ompl/geometric/SimpleSetup.h>

#include <limits>
#include <optional>
#include <ostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    class PlannerRegistry;
}

namespace mhplan::bench::detail
{
    /** Numbers as OMPL writes them (full precision; "nan"/"inf" become NULL in the database). */
    std::string num(double v);

    /** Summed over an experiment's runs: OMPL's "time" (wall-clock seconds of solve) and "cpu time". */
    struct SolveTimes
    {
        double wall{0.0};
        double cpu{0.0};
    };

    /** Wall-clock bound of a run of \e c: its time limit, or with CPU-time limits the safety bound
        kCpuLimitWallFactor x limit + 10 s. */
    double runWallBound(const Campaign &c);

    /** Seconds a planning run of \e c may stay silent before it is killed (Crash): the campaign's
        wall_limit, by default 2 x runWallBound(c) + 20 s. */
    double planningWatchdog(const Campaign &c);

    /** Everything a planning experiment's processes share (built before the children are forked; nothing
        here owns a random number generator). */
    struct ExperimentSetup
    {
        const Campaign *campaign{nullptr};
        const Experiment *experiment{nullptr};
        const PlannerRegistry *registry{nullptr};
        /** The world as the campaign's process parsed it, and the fingerprint of the bytes parsed (or null):
            the experiment process reads the file's bytes and takes this world when they are the same,
            instead of parsing them again (a world of 10^5 queries, 0.7 s per experiment). */
        const World *parsed{nullptr};
        std::string parsedHash;
        World world;
        Query query;
        /** An OMPL.app problem's experiment ({cfg: FILE}, Experiment::cfg): its meshes and set-up
            (CfgWorlds.cpp); then \c world and \c query are unused. */
        std::shared_ptr<const LoadedCfgProblem> mesh;
        CollisionModelPtr model;
        double optimum{std::numeric_limits<double>::quiet_NaN()};
        double optimumSeconds{0.0};
        double metricStep{1e-3};
    };

    /** Throw (the experiment fails, no log is written) when the \e bytes an experiment process loaded from
        \e file are not those the campaign fingerprinted when it started (Experiment::inputHash): runs on an
        edited world or scenario would otherwise carry the fingerprint of the original. */
    void checkInputUnchanged(const Experiment &e, const std::string &bytes, const std::string &file);

    /** The CPU description of the logs (`lscpu`'s output, run once per process tree without a shell;
        MachineInfo.cpp also answers OMPL's ompl::machine::getCPUInfo() with it). Call it before forking so
        that the children inherit it. */
    const std::string &machineCpuInfo();

    /** Build the shared problem of an experiment (no random number generator is created here). */
    void prepareExperiment(ExperimentSetup &xs);
    /** The SimpleSetup of the experiment's problem (its world and query, or its OMPL.app problem's
        meshes), the object made by \e make when given. */
    ompl::geometric::SimpleSetupPtr experimentSimpleSetup(const ExperimentSetup &xs,
                                                          const SimpleSetupFactory &make = nullptr);
    /** prepareExperiment of an OMPL.app problem (CfgWorlds.cpp): its inputs checked against the campaign's
        fingerprint, its meshes loaded. */
    void prepareCfgExperiment(ExperimentSetup &xs);
    /** The run properties of \e path on an OMPL.app problem: its length, the independent dense check
        against the meshes (collision free, poses); returns the path for the paths sidecar: "x y yaw;..."
        (SE(2)) or "x y z qw qx qy qz;..." (SE(3)). */
    std::string cfgRunProperties(const ExperimentSetup &xs, const ompl::base::SpaceInformation &si,
                                 const ompl::geometric::PathGeometric &path,
                                 ompl::tools::Benchmark::RunProperties &run);
    /** The experiment properties of an OMPL.app problem (world, space, meshes, query points). */
    void cfgExperimentParameters(const ExperimentSetup &xs, std::map<std::string, std::string> &parameters);

    /** The SimpleSetup of a benchmark run (benchmarks/README.md, "Overhead"). OMPL's Benchmark prints its
        setup before every run (SimpleSetup::print), and SpaceInformation::printProperties in it measures the
        space: sanity checks, 1000 validity checks, 1000 motions and 3000 samples timed, about 1 ms per run,
        for a text that a run process throws away (the log's setup text is printed once by the experiment
        process). With printSeeds(n) set, print() leaves that measuring out and instead makes \e n of OMPL's
        random number generators and drops them: the measuring's only effect on what follows is the
        generators its samplers make, each taking the next seed of OMPL's seed sequence, so every later
        generator (the planner's samplers, the path simplifier's) gets the same seed, and the run the same
        random numbers, as under OMPL's own print. Without it, print() is OMPL's. */
    class RunSetup : public ompl::geometric::SimpleSetup
    {
      public:
        explicit RunSetup(const ompl::base::StateSpacePtr &space) : ompl::geometric::SimpleSetup(space) {}

        void print(std::ostream &out) const override;

        /** \brief Leave the space's measuring out of print() (see above), taking \e seeds seeds instead. */
        void printSeeds(std::size_t seeds) { printSeeds_ = seeds; }

        /** \brief The seeds to take: how many more seeds OMPL's print() takes on this setup than the print()
            without measuring (measured here, by the seeds of the generators made after either; the caller
            seeds its runs afterwards). std::nullopt when that cannot be told: OMPL's print() then stays. */
        std::optional<std::size_t> measurePrintSeeds();

      private:
        std::optional<std::size_t> printSeeds_;
    };

    /** Experiment process of a planning experiment: every planner of the campaign, every run in its own
        child process; then the log and the sidecars. Reports each run to \e progressFd; returns the exit
        code of the process. */
    int runPlanningExperiment(ExperimentSetup &xs, int progressFd, SolveTimes &times);

    /** Everything the run processes of a simulation experiment share. */
    struct SimulationSetup
    {
        const Campaign *campaign{nullptr};
        const Experiment *experiment{nullptr};
        const SimulationSpec *spec{nullptr};
        /** \brief The planners of "plan:<PLANNER>" controllers: the campaign's registry. */
        const PlannerRegistry *registry{nullptr};
        Scenario scenario;
        /** Progress slot of the first controller (see ProgressBar). */
        std::size_t slotBase{0};
    };

    /** Experiment process of a simulation experiment: every controller, every run, each in its own
        process; then the log (OMPL's format and writer) and an empty path sidecar. */
    int runSimulationExperiment(SimulationSetup &xs, int progressFd, SolveTimes &times);

    /** The data of one planner (or controller) across all its runs, gathered from several processes. */
    struct PlannerRecord
    {
        std::map<std::string, std::string> common;
        std::string properties;
        std::vector<std::string> progressNames;
        std::vector<ompl::tools::Benchmark::RunProperties> runs;
        std::vector<ompl::tools::Benchmark::RunProgressData> progress;
        std::vector<std::string> paths;
        std::vector<std::string> improvements;
        std::vector<bool> have;
    };

    /** Tell the campaign process that a run ended: message 'r' EXPERIMENT "CRASHED SLOT SECONDS". */
    void reportRun(int progressFd, std::size_t experiment, bool crashed, std::size_t slot, double seconds);

    /** Say on stderr why a run process crashed. */
    void reportCrash(const std::string &experiment, const std::string &what, std::size_t run,
                     const ChildOutcome &outcome, double watchdog);

    /** The record of a run whose process ended without sending one: status Crash, the time it ran. */
    ompl::tools::Benchmark::RunProperties crashRun(double elapsed, std::size_t runIndex, std::uint32_t seed);

    /** Write an experiment's path sidecar (and its improvements sidecar when given) and then its log with
        OMPL's writer and the real version line. Every file is written under a temporary name and renamed
        when complete, the log last: a log on disk means a finished experiment. The log records the side
        files' fingerprints (experiment property kSidecarsProperty), so that the merge takes a log and its
        side files together or not at all. */
    void writeExperimentFiles(const Campaign &c, const Experiment &e, AssembledBenchmark &bench,
                              const std::string &paths, const std::string &improvements = "");

    /** The experiment property of the side files' fingerprints: "PATHS/IMPROVEMENTS", fingerprint() of
        each file's bytes (an absent improvements file counts as empty). */
    constexpr const char *kSidecarsProperty = "sidecars";

    /** Check every planner and parameter in a throw-away process (so that the campaign process never
        allocates a random number generator before the run processes set their seeds). */
    void validatePlanners(const Campaign &c, const PlannerRegistry &registry, const World &world,
                          const Query &query);

    /** Check every controller and parameter of the simulations in a throw-away process (controllers may
        own planners and random number generators). Messages name the campaign file and line. */
    void validateControllers(const Campaign &c, const PlannerRegistry &registry);
} // namespace mhplan::bench::detail

#endif
