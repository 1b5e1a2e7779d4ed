// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: planning experiments. Every run of every planner is one child process that runs the
   planner once through ompl::tools::Benchmark and sends its record; the experiment process assembles the
   runs into OMPL's experiment record and writes the log. */
#include "benchmarks/ExperimentRuns.h"

#include "benchmarks/CampaignRunner.h"

#include "src/base/Version.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidValidity.h"
#include "src/io/InputFile.h"
#include "src/io/WorldIO.h"
#include "src/metrics/MetricList.h"
#include "src/optimum/Optimum.h"
#include "src/registry/Registry.h"

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <iostream>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace ot = ompl::tools;
namespace fs = std::filesystem;

namespace mhplan::bench::detail
{
    namespace
    {
        std::string encodePath(const std::vector<Vec2> &pts)
        {
            std::string out;
            for (const Vec2 &p : pts)
                out += num(p.x) + " " + num(p.y) + ";";
            return out;
        }

        /** "x y yaw;x y yaw;...": the poses of a path of an SE(2)-based world (the report draws the robot's
            footprint along it). */
        std::string encodePoses(const std::vector<Pose2> &poses)
        {
            std::string out;
            for (const Pose2 &p : poses)
                out += num(p.x) + " " + num(p.y) + " " + num(p.yaw) + ";";
            return out;
        }

        /** Every registered metric (MetricList.h) as a run property. */
        void storeMetrics(const MetricPath &path, ot::Benchmark::RunProperties &run)
        {
            for (const auto &[property, value] : evaluatePathMetrics(path))
            {
                if (!value)
                    continue;
                const std::string type = property.substr(property.rfind(' ') + 1);
                if (type == "BOOLEAN")
                    run[property] = *value != 0.0 ? "1" : "0";
                else if (type == "INTEGER")
                    run[property] = std::to_string(static_cast<long long>(*value));
                else
                    run[property] = num(*value);
            }
        }

        /** The experiment properties of a world's experiment (world, robot, query). */
        void worldExperimentParameters(const ExperimentSetup &xs,
                                       std::map<std::string, std::string> &parameters)
        {
            parameters["world TEXT"] = xs.world.name;
            parameters["world_file TEXT"] =
                fs::absolute(xs.experiment->worldFile).lexically_normal().string();
            parameters["world_type TEXT"] = xs.world.type();
            parameters["obstacle_count INTEGER"] = std::to_string(xs.world.obstacleCount());
            if (xs.world.isGrid())
                parameters["grid_cells INTEGER"] =
                    std::to_string(static_cast<long long>(xs.world.grid->width()) * xs.world.grid->height());
            parameters["robot_radius REAL"] = num(xs.world.robotRadius);
            if (xs.world.isRigid())
            {
                // Only SE(2)-based experiments carry these (r2 experiments keep their columns).
                parameters["space TEXT"] = toString(xs.world.space);
                if (xs.world.turningRadius > 0.0)
                    parameters["turning_radius REAL"] = num(xs.world.turningRadius);
                parameters["robot_reach REAL"] = num(xs.world.robotReach());
            }
            parameters["query TEXT"] = xs.query.name;
            std::ostringstream q;
            if (xs.world.isRigid())
                q << "(" << xs.query.start.x << "," << xs.query.start.y << "," << xs.query.startYaw << ")->("
                  << xs.query.goal.x << "," << xs.query.goal.y << "," << xs.query.goalYaw << ")";
            else
                q << "(" << xs.query.start.x << "," << xs.query.start.y << ")->(" << xs.query.goal.x << ","
                  << xs.query.goal.y << ")";
            parameters["query_points TEXT"] = q.str();
        }

        struct WorkerInfo
        {
            std::string host;
            std::string cpuInfo;
        };

        /** One run of an experiment's sequence: planner \e planner, its run \e runIndex, its seed. */
        struct RunSlot
        {
            std::size_t planner;
            std::size_t runIndex;
            std::uint32_t seed;
        };

        /** How many seeds of OMPL's seed sequence \e f takes: the seed of the generator made after it, found
            among those made after the same starting seed. std::nullopt beyond \e most. */
        std::optional<std::size_t> seedsTaken(const std::function<void()> &f, std::size_t most)
        {
            constexpr std::uint32_t kStart = 20240611;
            seedRunProcess(kStart);
            f();
            const auto after = ompl::RNG().getLocalSeed();
            seedRunProcess(kStart);
            for (std::size_t n = 0; n <= most; ++n)
                if (ompl::RNG().getLocalSeed() == after)
                    return n;
            return std::nullopt;
        }

        /** The seeds RunSetup::print takes instead of OMPL's measuring on this experiment's setup, measured
            once per run process (before its first run sets its seed). */
        std::optional<std::size_t> runPrintSeeds(const ExperimentSetup &xs)
        {
            static const std::optional<std::size_t> seeds = [&]
            {
                const og::SimpleSetupPtr ss = experimentSimpleSetup(
                    xs, [](const ob::StateSpacePtr &space) { return std::make_shared<RunSetup>(space); });
                ss->getSpaceInformation()->setup();
                return static_cast<RunSetup &>(*ss).measurePrintSeeds();
            }();
            return seeds;
        }

        /** In the run process: run \e spec once (run \e runIndex) through ompl::tools::Benchmark and send
            the run's properties, path and progress to \e fd, every message with the run's position \e slot
            in the experiment's sequence, the last one 'E'. Everything the run makes (the SimpleSetup, the
            planner, the benchmark) is made after the run's seed is set and destroyed when it ends. */
        void runPlannerOnce(ExperimentSetup &xs, const PlannerSpec &spec, std::size_t runIndex,
                            std::uint32_t seed, std::size_t slot, int fd)
        {
            ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
            const std::optional<std::size_t> printSeeds = runPrintSeeds(xs);
            // The seed before any random number generator of the run exists (ChildProcess.h).
            seedRunProcess(seed);
            const Campaign &c = *xs.campaign;
            // The problem is built here, after the seed: OMPL's SimpleSetup owns a random number
            // generator (its path simplifier's).
            const og::SimpleSetupPtr ss = experimentSimpleSetup(
                xs, [](const ob::StateSpacePtr &space) { return std::make_shared<RunSetup>(space); });
            if (printSeeds)
                static_cast<RunSetup &>(*ss).printSeeds(*printSeeds);
            const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
            ob::PlannerPtr inner = xs.registry->create(spec.planner, si, spec.params);
            inner->setName(spec.displayName);
            auto planner = std::make_shared<PlannerDataSwitch>(inner, c.plannerData, spec.progress);
            // CPU time of every run; with time_limit_kind: cpu also its limit.
            planner->setCpuClock(processCpuSeconds, c.cpuTimeLimit ? c.timeLimit : 0.0);
            ss->setPlanner(planner);
            ImprovementRecorder improvements;
            planner->setRecorder(&improvements);

            ot::Benchmark benchmark(*ss, xs.experiment->name);
            benchmark.addPlanner(planner);
            CerrCapture capture;
            // OMPL's collector samples the progress properties from the start of solve() at a fixed
            // interval but not at its end: the post-run event adds that last sample.
            std::map<std::string, std::string> finalSample;
            // State and motion checks of the run (docs/setups.md, "Checks counted"): the checker and the
            // validator count their calls; the run's are those between the pre- and the post-run event.
            CheckCounts checksBefore;
            benchmark.setPreRunEvent(
                [&](const ob::PlannerPtr &p)
                {
                    checksBefore = checkCounts(*si);
                    const auto &data = benchmark.getRecordedExperimentData();
                    std::map<std::string, std::string> common;
                    p->params().getParams(common);
                    p->getSpaceInformation()->params().getParams(common);
                    std::ostringstream props;
                    p->printProperties(props);
                    std::string names = "time REAL";
                    for (const auto &kv : p->getPlannerProgressProperties())
                        names += std::string(1, kGroupSep) + kv.first;
                    const auto &fns = inner->getPlannerProgressProperties();
                    const auto best = fns.find("best cost REAL");
                    improvements.attach(p->getProblemDefinition(), best == fns.end() ? nullptr : best->second,
                                        kImprovementPollInterval);
                    sendMessage(fd, 'C', slot, encodeMap(common));
                    sendMessage(fd, 'S', slot,
                                encodeMap({{"host", data.host},
                                           {"cpu", data.cpuInfo},
                                           {"properties", props.str()},
                                           {"progress", names}}));
                });
            benchmark.setPostRunEvent(
                [&](const ob::PlannerPtr &p, ot::Benchmark::RunProperties &run)
                {
                    const std::string crash = std::to_string(static_cast<int>(ob::PlannerStatus::CRASH));
                    // OMPL's benchmark catches a std::runtime_error thrown by solve() and only
                    // reports it on std::cerr: that is a crash too.
                    if (capture.take().find("error executing planner") != std::string::npos)
                    {
                        run["status ENUM"] = crash;
                        run["solved BOOLEAN"] = "0";
                    }
                    if (!c.plannerData)
                    {
                        run.erase("graph states INTEGER");
                        run.erase("graph motions INTEGER");
                    }
                    const CheckCounts checks = checkCounts(*si) - checksBefore;
                    if (checks.haveState)
                        run["state checks INTEGER"] = std::to_string(checks.state);
                    run["motion checks INTEGER"] = std::to_string(checks.motion);
                    run["run index INTEGER"] = std::to_string(runIndex);
                    run["run seed INTEGER"] = std::to_string(seed);
                    run["cpu time REAL"] = num(planner->cpuSeconds());
                    run["exact optimum length REAL"] = num(xs.optimum);
                    if (!p->getPlannerProgressProperties().empty())
                    {
                        finalSample["time REAL"] = run["time REAL"];
                        for (const auto &kv : p->getPlannerProgressProperties())
                            finalSample[kv.first] = kv.second();
                    }
                    for (const char *name : {"iterations INTEGER", "fitness evaluations INTEGER"})
                    {
                        const auto &fns = p->getPlannerProgressProperties();
                        const auto it = fns.find(name);
                        if (it != fns.end() && run.count(name) == 0)
                            run[name] = it->second();
                    }
                    std::string path;
                    const ob::ProblemDefinitionPtr &pdef = p->getProblemDefinition();
                    if (pdef->hasSolution() && run["status ENUM"] != crash)
                    {
                        const auto *geo = pdef->getSolutionPath()->as<og::PathGeometric>();
                        const bool exact = pdef->hasExactSolution();
                        if (xs.mesh)
                        {
                            path = cfgRunProperties(xs, *si, *geo, run);
                            if (exact)
                                run["optimality gap REAL"] = num(std::nan(""));
                        }
                        else if (xs.world.isRigid())
                        {
                            std::vector<Pose2> poses;
                            storeMetrics(rigidRunMetricPath(xs.world, *si, *geo, xs.metricStep, exact,
                                                            xs.optimum, poses),
                                         run);
                            path = encodePoses(poses);
                        }
                        else
                        {
                            const std::vector<Vec2> pts = pathPoints(*geo);
                            storeMetrics(
                                planarMetricPath(xs.world, pts, *xs.model, xs.metricStep, exact, xs.optimum),
                                run);
                            path = encodePath(pts);
                        }
                    }
                    const std::vector<Improvement> better =
                        run["status ENUM"] == crash ? std::vector<Improvement>{} : improvements.finish(*pdef);
                    run["improvements INTEGER"] = std::to_string(better.size());
                    std::map<std::string, std::string> payload = run;
                    payload["\x01path"] = path;
                    payload["\x01improvements"] = encodeImprovements(better);
                    sendMessage(fd, 'R', slot, encodeMap(payload));
                });
            const ot::Benchmark::Request req(runWallBound(c), c.memoryLimit, 1, c.progressInterval, false,
                                             false, false);
            benchmark.benchmark(req);
            const auto &pd = benchmark.getRecordedExperimentData().planners;
            if (!pd.empty() && !pd[0].runsProgressData.empty())
            {
                std::string payload;
                double lastTime = -1.0;
                for (const auto &sample : pd[0].runsProgressData.back())
                {
                    payload += encodeMap(sample) + kGroupSep;
                    const auto t = sample.find("time REAL");
                    if (t != sample.end())
                        lastTime = std::max(lastTime, std::atof(t->second.c_str()));
                }
                const auto t = finalSample.find("time REAL");
                if (t != finalSample.end() && std::atof(t->second.c_str()) > lastTime)
                    payload += encodeMap(finalSample) + kGroupSep;
                sendMessage(fd, 'G', slot, payload);
            }
            sendMessage(fd, 'E', slot, "");
        }

        /** The run process of an experiment (docs: benchmarks/README.md, "How runs are executed"): runs
            \e order[from], order[from + 1], ... one after the other, each from its own seed, and ends when
           all are done. A run that crashes or hangs ends the process; the experiment process records that run
            as Crash and starts a new run process for the runs after it. Never returns. */
        [[noreturn]] void runServerChild(ExperimentSetup &xs, const std::vector<RunSlot> &order,
                                         std::size_t from, int fd)
        {
            finishRunChild(fd,
                           [&]()
                           {
                               for (std::size_t i = from; i < order.size(); ++i)
                                   runPlannerOnce(xs, xs.campaign->planners[order[i].planner],
                                                  order[i].runIndex, order[i].seed, i, fd);
                           });
        }
    } // namespace

    void RunSetup::print(std::ostream &out) const
    {
        if (!printSeeds_)
        {
            og::SimpleSetup::print(out);
            return;
        }
        // OMPL's print (SimpleSetup::print) without SpaceInformation::printProperties' measuring, whose
        // generators are made and dropped.
        for (std::size_t i = 0; i < *printSeeds_; ++i)
            ompl::RNG();
        si_->printSettings(out);
        if (planner_)
        {
            planner_->printProperties(out);
            planner_->printSettings(out);
        }
        pdef_->print(out);
    }

    std::optional<std::size_t> RunSetup::measurePrintSeeds()
    {
        std::ostringstream sink;
        const std::optional<std::size_t> saved = printSeeds_;
        printSeeds_.reset();
        const std::optional<std::size_t> omplPrint = seedsTaken([&] { print(sink); }, 1000);
        printSeeds_ = 0;
        const std::optional<std::size_t> without = seedsTaken([&] { print(sink); }, 1000);
        printSeeds_ = saved;
        if (!omplPrint || !without || *without > *omplPrint)
            return std::nullopt;
        return *omplPrint - *without;
    }

    double runWallBound(const Campaign &c)
    {
        return c.cpuTimeLimit ? kCpuLimitWallFactor * c.timeLimit + 10.0 : c.timeLimit;
    }

    double planningWatchdog(const Campaign &c)
    {
        return c.wallLimit > 0.0 ? c.wallLimit : 2.0 * runWallBound(c) + 20.0;
    }

    og::SimpleSetupPtr experimentSimpleSetup(const ExperimentSetup &xs, const SimpleSetupFactory &make)
    {
        if (xs.mesh)
            return makeMeshSetup(xs.mesh->spec, make);
        return make ? makeSimpleSetup(xs.world, xs.query, xs.model, make, xs.experiment->setup)
                    : makeSimpleSetup(xs.world, xs.query, xs.model, xs.experiment->setup);
    }

    /** Build the shared problem of an experiment (no random number generator is created here). */
    void prepareExperiment(ExperimentSetup &xs)
    {
        const Campaign &c = *xs.campaign;
        const Experiment &e = *xs.experiment;
        machineCpuInfo(); // once here, inherited by every run process
        if (e.cfg)
        {
            prepareCfgExperiment(xs); // no exact optimum on meshes: the report measures to the best found
            return;
        }
        std::string bytes;
        bool reused = false;
        if (xs.parsed)
        {
            try
            {
                bytes = readInputFile(e.worldFile, kMaxGridFileBytes, "world file");
                reused = fingerprint(bytes) == xs.parsedHash;
            }
            catch (const InputError &)
            {
            }
        }
        if (reused)
            xs.world = *xs.parsed; // the same bytes, parsed by the campaign's process
        else
            xs.world = loadWorld(e.worldFile, &bytes);
        checkInputUnchanged(e, bytes, e.worldFile);
        xs.query = experimentQuery(xs.world, e); // a MovingAI problem: from its .scen line
        xs.model = makeCollisionModel(xs.world, parseCollisionBackend(c.collision));
        xs.metricStep = defaultMetricStep(xs.world);
        const Clock::time_point t0 = Clock::now();
        if (xs.world.isRigid())
        {
            // No exact optimum in SE(2)-based spaces: the optimum columns stay empty (NULL) and the report
            // measures gaps to the best cost any planner found (docs/spaces.md).
            xs.optimumSeconds = 0.0;
            return;
        }
        try
        {
            const OptimumResult opt = computeOptimum(xs.world, xs.query);
            if (opt.found)
                xs.optimum = opt.length;
        }
        catch (const InputError &ex)
        {
            // E.g. grid worlds with a robot radius: no exact optimum, no gap; the runs still count.
            std::cerr << "mhplan bench: " << e.name << ": no exact optimum (" << ex.what() << ")\n";
        }
        xs.optimumSeconds = secondsSince(t0);
    }

    int runPlanningExperiment(ExperimentSetup &xs, int progressFd, SolveTimes &times)
    {
        const Campaign &c = *xs.campaign;
        const Experiment &e = *xs.experiment;
        const Clock::time_point t0 = Clock::now();
        const ompl::time::point start = ompl::time::now();
        WorkerInfo info;
        std::vector<PlannerRecord> records(c.planners.size());
        times = SolveTimes{};
        const int crashCode = static_cast<int>(ob::PlannerStatus::CRASH);
        const double watchdog = planningWatchdog(c);

        std::vector<RunSlot> order; // every planner's runs, in campaign order
        for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
        {
            if (e.skips(pi))
                continue; // cannot run on this world's space (skip_inapplicable): not run, not recorded
            const PlannerSpec &spec = c.planners[pi];
            PlannerRecord &rec = records[pi];
            const unsigned int runs = runsOf(c, spec);
            rec.runs.resize(runs);
            rec.progress.resize(runs);
            rec.paths.resize(runs);
            rec.improvements.resize(runs);
            rec.have.assign(runs, false);
            for (std::size_t k = 0; k < runs; ++k)
                order.push_back({pi, k, deriveSeed(e.seed, spec.displayName, k)});
        }
        // One run process runs the runs in sequence; when it dies or hangs, the run in flight is a Crash and
        // a new run process goes on with the next run.
        std::size_t next = 0;
        while (next < order.size())
        {
            std::size_t current = next; // the run in flight
            double currentStart = 0.0;  // when it started, in seconds since the fork
            const ChildOutcome outcome = runChildProcess(
                watchdog, [&](int fd) { runServerChild(xs, order, next, fd); },
                [&](const Message &m, double sinceFork)
                {
                    if (m.index >= order.size())
                        return;
                    const RunSlot &slot = order[m.index];
                    PlannerRecord &rec = records[slot.planner];
                    if (m.type == 'C')
                        rec.common = decodeMap(m.payload);
                    else if (m.type == 'S')
                    {
                        const auto s = decodeMap(m.payload);
                        info.host = s.at("host");
                        info.cpuInfo = s.at("cpu");
                        rec.properties = s.at("properties");
                        rec.progressNames = splitOn(s.at("progress"), kGroupSep);
                        std::sort(rec.progressNames.begin(), rec.progressNames.end());
                        if (rec.progressNames.size() == 1) // only "time": no progress properties
                            rec.progressNames.clear();
                    }
                    else if (m.type == 'R')
                    {
                        auto props = decodeMap(m.payload);
                        rec.paths[slot.runIndex] = props["\x01path"];
                        props.erase("\x01path");
                        rec.improvements[slot.runIndex] = props["\x01improvements"];
                        props.erase("\x01improvements");
                        rec.runs[slot.runIndex] = props;
                        rec.have[slot.runIndex] = true;
                        const auto t = props.find("time REAL");
                        if (t != props.end())
                            times.wall += std::atof(t->second.c_str());
                        const auto cpu = props.find("cpu time REAL");
                        if (cpu != props.end())
                            times.cpu += std::atof(cpu->second.c_str());
                        reportRun(progressFd, e.index, props["status ENUM"] == std::to_string(crashCode),
                                  slot.planner, sinceFork - currentStart);
                    }
                    else if (m.type == 'G')
                    {
                        ot::Benchmark::RunProgressData data;
                        for (const auto &sample : splitOn(m.payload, kGroupSep))
                            data.push_back(decodeMap(sample));
                        rec.progress[slot.runIndex] = data;
                    }
                    else if (m.type == 'E')
                    {
                        current = m.index + 1;
                        currentStart = sinceFork;
                    }
                },
                {progressFd});
            if (current >= order.size())
                break;
            // The run in flight ended its process without its record: a Crash.
            const RunSlot &slot = order[current];
            PlannerRecord &rec = records[slot.planner];
            if (!rec.have[slot.runIndex])
            {
                ot::Benchmark::RunProperties crash = crashRun(outcome.elapsed, slot.runIndex, slot.seed);
                crash["exact optimum length REAL"] = num(xs.optimum);
                rec.runs[slot.runIndex] = crash;
                rec.have[slot.runIndex] = true;
                times.wall += outcome.elapsed;
                reportRun(progressFd, e.index, true, slot.planner, outcome.runSeconds - currentStart);
                reportCrash(e.name, "planner " + c.planners[slot.planner].displayName, slot.runIndex, outcome,
                            watchdog);
            }
            next = current + 1;
        }

        // Assemble the experiment with OMPL's own record and writer.
        const og::SimpleSetupPtr ss = experimentSimpleSetup(xs);
        AssembledBenchmark bench(*ss, e.name);
        auto &x = bench.experiment();
        x.name = e.name;
        x.maxTime = c.timeLimit;
        x.maxMem = c.memoryLimit;
        x.runCount = c.runs; // OMPL's per-experiment count; a planner's own count is its run list's length
        for (const auto &p : c.planners)
            x.runCount = std::max<unsigned int>(x.runCount, runsOf(c, p));
        x.startTime = start;
        x.seed = e.seed;
        x.host = info.host;
        x.cpuInfo = info.cpuInfo;
        std::ostringstream setupInfo;
        ss->print(setupInfo);
        setupInfo << "\nProperties of benchmarked planners:\n";
        for (const auto &r : records)
            setupInfo << r.properties;
        x.setupInfo = setupInfo.str();
        x.parameters["campaign TEXT"] = c.name;
        x.parameters["kind TEXT"] = "planning";
        if (xs.mesh)
            cfgExperimentParameters(xs, x.parameters);
        else
            worldExperimentParameters(xs, x.parameters);
        // Experiment properties go to the database verbatim (no NaN to NULL conversion): leave an unknown
        // optimum out.
        if (std::isfinite(xs.optimum))
        {
            x.parameters["exact_optimum REAL"] = num(xs.optimum);
            x.parameters["optimum_seconds REAL"] = num(xs.optimumSeconds);
        }
        if (e.scenLine > 0)
        {
            // Both optima in cells: the .scen file's and mhplan's octile one (checked to agree at
            // enumeration); exact_optimum (metres) is the any-angle optimum every planner's gap is measured
            // against.
            x.parameters["scen_file TEXT"] = fs::absolute(e.scenFile).lexically_normal().string();
            x.parameters["scen_line INTEGER"] = std::to_string(e.scenLine);
            x.parameters["scen_bucket INTEGER"] = std::to_string(e.scenBucket);
            x.parameters["scen_optimum REAL"] = num(e.scenOptimum);
            x.parameters["octile_optimum REAL"] = num(e.octileOptimum);
            x.parameters["octile_optimum_m REAL"] = num(e.octileOptimum * xs.world.grid->cellSize());
        }
        x.parameters["collision_backend TEXT"] =
            xs.mesh ? "fcl-mesh" : (xs.world.isRigid() ? "fcl-rigid" : xs.model->name());
        // Which validity set-up the runs used (docs/setups.md); the app set-up's resolution.
        x.parameters["validity_setup TEXT"] = e.setup.name();
        if (e.setup.app())
            x.parameters["validity_resolution REAL"] = num(e.setup.resolution);
        // The machine's load while the experiment ran (benchmarks/README.md, "Parallel runs"): the share of a
        // core its planners had (CPU seconds over wall seconds of solve(), over all runs), the system's
        // 1-minute load average at its end and the cores this process may use. The report states them.
        if (times.wall > 0.0)
            x.parameters["cpu_share REAL"] = num(times.cpu / times.wall);
        const double load = loadAverage();
        if (load >= 0.0)
            x.parameters["load_average REAL"] = num(load);
        x.parameters["cores_available INTEGER"] = std::to_string(availableCores());
        x.parameters["config_hash TEXT"] = e.configHash;
        x.parameters["mhplan_version TEXT"] = version();
        for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
        {
            if (e.skips(pi))
                continue;
            ot::Benchmark::PlannerExperiment pe;
            pe.name = "geometric_" + c.planners[pi].displayName;
            pe.common = records[pi].common;
            pe.runs = records[pi].runs;
            if (!records[pi].progressNames.empty())
            {
                pe.progressPropertyNames = records[pi].progressNames;
                pe.runsProgressData = records[pi].progress;
            }
            x.planners.push_back(std::move(pe));
        }
        x.totalDuration = secondsSince(t0);

        std::ostringstream paths;
        paths
            << "# mhplan solution paths: planner <TAB> run index <TAB> x y;x y;... (SE(2)-based worlds: x y "
               "yaw;...)\n";
        for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
            for (std::size_t k = 0; k < records[pi].paths.size(); ++k)
                if (!records[pi].paths[k].empty())
                    paths << "geometric_" << c.planners[pi].displayName << "\t" << k << "\t"
                          << records[pi].paths[k] << "\n";
        std::vector<std::string> plannerNames;
        std::vector<std::vector<std::string>> improvements;
        for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
        {
            if (e.skips(pi))
                continue;
            plannerNames.push_back("geometric_" + c.planners[pi].displayName);
            improvements.push_back(records[pi].improvements);
        }
        writeExperimentFiles(c, e, bench, paths.str(), improvementsFileText(plannerNames, improvements));
        return 0;
    }
} // namespace mhplan::bench::detail
