// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: simulation experiments. Every run of every controller is one child process that runs the
   simulation once and sends its record; the experiment process writes the log in OMPL's format. Also the
   start perturbation of the runs. */
#include "benchmarks/CampaignRunner.h"
#include "benchmarks/ExperimentRuns.h"

#include "src/base/Version.h"
#include "src/sim/Controllers.h"
#include "src/sim/ScenarioIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/MachineSpecs.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace ot = ompl::tools;
namespace fs = std::filesystem;

namespace mhplan::bench
{
    namespace detail
    {
        namespace
        {
            /** A run or log property name from a free-form label: lower case letters, digits and single
             * blanks.
             */
            std::string propertyWords(const std::string &label)
            {
                std::string out;
                bool blank = false;
                for (char ch : label)
                {
                    const auto u = static_cast<unsigned char>(ch);
                    if (std::isalnum(u))
                    {
                        if (blank && !out.empty())
                            out += ' ';
                        blank = false;
                        out += static_cast<char>(std::tolower(u));
                    }
                    else
                        blank = true;
                }
                return out.empty() ? "unnamed" : out;
            }

            /** One line of text (log values must not span lines). */
            std::string oneLine(std::string s)
            {
                for (char &ch : s)
                    if (ch == '\n' || ch == '\r')
                        ch = ' ';
                return s;
            }

            /** The run properties of a simulation run (column names: the words joined by '_'). */
            ot::Benchmark::RunProperties simulationProperties(const SimulationResult &r, double wallSeconds)
            {
                ot::Benchmark::RunProperties run;
                const std::size_t robots = r.robots.size();
                int status = static_cast<int>(ob::PlannerStatus::TIMEOUT);
                if (r.allDone)
                    status = static_cast<int>(ob::PlannerStatus::EXACT_SOLUTION);
                else if (r.done > 0)
                    status = static_cast<int>(ob::PlannerStatus::APPROXIMATE_SOLUTION);
                double traversal = 0.0, length = 0.0;
                for (const auto &rr : r.robots)
                {
                    traversal += rr.traversalTime;
                    length += rr.pathLength;
                }
                run["time REAL"] = num(wallSeconds);
                run["status ENUM"] = std::to_string(status);
                run["solved BOOLEAN"] = r.allDone ? "1" : "0";
                run["makespan REAL"] = num(r.makespan);
                run["flowtime REAL"] = num(r.flowtime);
                run["mean traversal time REAL"] = num(robots ? traversal / static_cast<double>(robots)
                                                             : std::numeric_limits<double>::quiet_NaN());
                run["collisions INTEGER"] = std::to_string(r.collisions());
                run["static collisions INTEGER"] = std::to_string(r.staticCollisions);
                run["moving collisions INTEGER"] = std::to_string(r.movingCollisions);
                run["robot collisions INTEGER"] = std::to_string(r.robotCollisions);
                run["robots done INTEGER"] = std::to_string(r.done);
                run["robots stuck INTEGER"] = std::to_string(r.stuck);
                run["robots unfinished INTEGER"] = std::to_string(r.unfinished);
                run["min robot distance REAL"] = num(r.minRobotDistance);
                run["min obstacle clearance REAL"] = num(r.minObstacleClearance);
                run["total path length REAL"] = num(length);
                run["steps INTEGER"] = std::to_string(r.steps);
                run["simulated time REAL"] = num(r.simulatedTime);
                run["robot steps INTEGER"] = std::to_string(r.robotSteps);
                run["robot steps per second REAL"] =
                    num(wallSeconds > 0.0 ? static_cast<double>(r.robotSteps) / wallSeconds
                                          : std::numeric_limits<double>::quiet_NaN());
                for (const auto &kv : r.counters)
                    run["controller " + propertyWords(kv.first) + " REAL"] = num(kv.second);
                return run;
            }

            /** One run of a simulation experiment's sequence. */
            struct SimulationSlot
            {
                std::size_t controller;
                std::size_t runIndex;
                std::uint32_t seed;
                std::uint32_t startSeed;
            };

            /** In the run process: controller \e spec on the scenario (starts perturbed by \e startSeed),
                seeded with \e seed, properties sent to \e fd with the run's position \e slot, the last
                message 'E'. */
            void runSimulationOnce(const SimulationSetup &xs, const ControllerSpec &spec,
                                   std::size_t runIndex, std::uint32_t seed, std::uint32_t startSeed,
                                   std::size_t slot, int fd)
            {
                ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
                // As for planners: the seed before any random number generator exists in this
                // process (plan-then-follow controllers run OMPL planners).
                seedRunProcess(seed);
                Scenario scenario = xs.scenario;
                applyStartJitter(scenario, xs.spec->startJitter, xs.spec->headingJitter, startSeed);
                const ControllerPtr controller = makeController(spec.controller, *xs.registry);
                for (const auto &kv : spec.params)
                    controller->setParameter(kv.first, kv.second);
                std::map<std::string, std::string> common;
                for (const auto &kv : controller->parameters())
                    common[oneLine(kv.first)] = oneLine(kv.second);
                common["controller"] = spec.controller;
                sendMessage(fd, 'C', slot, encodeMap(common));
                Simulation sim(std::move(scenario), controller, seed);
                const Clock::time_point t0 = Clock::now();
                const double cpu0 = processCpuSeconds();
                const SimulationResult result = sim.run();
                const double cpu = processCpuSeconds() - cpu0;
                const double wall = result.wallTime > 0.0 ? result.wallTime : secondsSince(t0);
                ot::Benchmark::RunProperties run = simulationProperties(result, wall);
                run["run index INTEGER"] = std::to_string(runIndex);
                run["run seed INTEGER"] = std::to_string(seed);
                run["start seed INTEGER"] = std::to_string(startSeed);
                run["cpu time REAL"] = num(cpu);
                sendMessage(fd, 'R', slot, encodeMap(run));
                sendMessage(fd, 'E', slot, "");
            }

            /** The run process of a simulation experiment: runs \e order[from], ... in sequence (as the
                planning experiments' run processes do, PlanningRun.cpp). Never returns. */
            [[noreturn]] void runSimulationServer(const SimulationSetup &xs,
                                                  const std::vector<SimulationSlot> &order, std::size_t from,
                                                  int fd)
            {
                finishRunChild(fd,
                               [&]()
                               {
                                   for (std::size_t i = from; i < order.size(); ++i)
                                       runSimulationOnce(xs, xs.spec->controllers[order[i].controller],
                                                         order[i].runIndex, order[i].seed, order[i].startSeed,
                                                         i, fd);
                               });
            }
        } // namespace

        int runSimulationExperiment(SimulationSetup &xs, int progressFd, SolveTimes &times)
        {
            const Campaign &c = *xs.campaign;
            const Experiment &e = *xs.experiment;
            const SimulationSpec &spec = *xs.spec;
            const Clock::time_point t0 = Clock::now();
            const ompl::time::point start = ompl::time::now();
            const double watchdog = spec.wallLimit;
            times = SolveTimes{};
            std::vector<PlannerRecord> records(spec.controllers.size());
            std::vector<SimulationSlot> order;
            for (std::size_t ci = 0; ci < spec.controllers.size(); ++ci)
            {
                const ControllerSpec &ctl = spec.controllers[ci];
                records[ci].runs.resize(e.runs);
                records[ci].have.assign(e.runs, false);
                for (std::size_t k = 0; k < e.runs; ++k)
                    order.push_back(
                        {ci, k, simulationRunSeed(e, ctl.displayName, k), simulationStartSeed(e, k)});
            }
            // One run process for the runs in sequence, replaced when it dies or hangs (the run in flight is
            // a Crash).
            std::size_t next = 0;
            while (next < order.size())
            {
                std::size_t current = next;
                double currentStart = 0.0;
                const ChildOutcome outcome = runChildProcess(
                    watchdog, [&](int fd) { runSimulationServer(xs, order, next, fd); },
                    [&](const Message &m, double sinceFork)
                    {
                        if (m.index >= order.size())
                            return;
                        const SimulationSlot &slot = order[m.index];
                        PlannerRecord &rec = records[slot.controller];
                        if (m.type == 'C')
                            rec.common = decodeMap(m.payload);
                        else if (m.type == 'R')
                        {
                            auto props = decodeMap(m.payload);
                            rec.runs[slot.runIndex] = props;
                            rec.have[slot.runIndex] = true;
                            times.wall += std::atof(props["time REAL"].c_str());
                            times.cpu += std::atof(props["cpu time REAL"].c_str());
                            reportRun(progressFd, e.index, false, xs.slotBase + slot.controller,
                                      sinceFork - currentStart);
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
                const SimulationSlot &slot = order[current];
                PlannerRecord &rec = records[slot.controller];
                if (!rec.have[slot.runIndex])
                {
                    ot::Benchmark::RunProperties crash = crashRun(outcome.elapsed, slot.runIndex, slot.seed);
                    crash["start seed INTEGER"] = std::to_string(slot.startSeed);
                    rec.runs[slot.runIndex] = crash;
                    rec.have[slot.runIndex] = true;
                    times.wall += outcome.elapsed;
                    reportRun(progressFd, e.index, true, xs.slotBase + slot.controller,
                              outcome.runSeconds - currentStart);
                    reportCrash(e.name, "controller " + spec.controllers[slot.controller].displayName,
                                slot.runIndex, outcome, watchdog);
                }
                next = current + 1;
            }

            // OMPL's benchmark record needs a SimpleSetup: the plane of the scenario's bounds.
            const Box &b = xs.scenario.world.bounds;
            auto space = std::make_shared<ob::RealVectorStateSpace>(2);
            ob::RealVectorBounds bounds(2);
            bounds.setLow(0, b.xmin);
            bounds.setHigh(0, b.xmax);
            bounds.setLow(1, b.ymin);
            bounds.setHigh(1, b.ymax);
            space->setBounds(bounds);
            og::SimpleSetup ss(space);
            AssembledBenchmark bench(ss, e.name);
            auto &x = bench.experiment();
            x.name = e.name;
            x.maxTime = xs.scenario.settings.timeLimit; // simulated seconds
            x.maxMem = c.memoryLimit;
            x.runCount = e.runs;
            x.startTime = start;
            x.seed = e.seed;
            x.host = ompl::machine::getHostname();
            x.cpuInfo = ompl::machine::getCPUInfo();
            std::ostringstream setup;
            setup << "mhplan simulation experiment: scenario " << xs.scenario.name << " (" << e.scenarioFile
                  << ")\n";
            if (!xs.scenario.description.empty())
                setup << "description: " << oneLine(xs.scenario.description) << "\n";
            if (!xs.scenario.source.empty())
                setup << "source: " << oneLine(xs.scenario.source) << "\n";
            if (!xs.scenario.assumptions.empty())
                setup << "assumptions: " << oneLine(xs.scenario.assumptions) << "\n";
            setup << "robots: " << xs.scenario.robots.size()
                  << ", moving obstacles: " << xs.scenario.movingObstacles.size()
                  << ", static obstacles: " << xs.scenario.world.obstacleCount() << "\ndt "
                  << xs.scenario.settings.dt << " s, time limit " << xs.scenario.settings.timeLimit
                  << " s (simulated), stuck timeout " << xs.scenario.settings.stuckTimeout << " s\n"
                  << "start jitter " << spec.startJitter << " m, heading jitter " << spec.headingJitter
                  << " rad\n";
            for (std::size_t ci = 0; ci < spec.controllers.size(); ++ci)
            {
                setup << "controller sim:" << spec.controllers[ci].displayName << " ("
                      << spec.controllers[ci].controller << ")";
                for (const auto &kv : records[ci].common)
                    if (kv.first != "controller")
                        setup << " " << kv.first << "=" << kv.second;
                setup << "\n";
            }
            x.setupInfo = setup.str();
            x.parameters["campaign TEXT"] = c.name;
            x.parameters["kind TEXT"] = "simulation";
            x.parameters["scenario TEXT"] = oneLine(xs.scenario.name);
            x.parameters["scenario_file TEXT"] = fs::absolute(e.scenarioFile).lexically_normal().string();
            x.parameters["obstacle_count INTEGER"] = std::to_string(xs.scenario.world.obstacleCount());
            x.parameters["robot_count INTEGER"] = std::to_string(xs.scenario.robots.size());
            x.parameters["moving_obstacle_count INTEGER"] =
                std::to_string(xs.scenario.movingObstacles.size());
            x.parameters["start_jitter REAL"] = num(spec.startJitter);
            x.parameters["heading_jitter REAL"] = num(spec.headingJitter);
            x.parameters["sim_dt REAL"] = num(xs.scenario.settings.dt);
            x.parameters["sim_time_limit REAL"] = num(xs.scenario.settings.timeLimit);
            for (const auto &kv : xs.scenario.reference)
            {
                // Experiment properties go to the database verbatim: only finite numbers.
                std::string key = propertyWords(kv.first);
                std::replace(key.begin(), key.end(), ' ', '_');
                if (std::isfinite(kv.second))
                    x.parameters["reference_" + key + " REAL"] = num(kv.second);
            }
            x.parameters["config_hash TEXT"] = e.configHash;
            x.parameters["mhplan_version TEXT"] = version();
            for (std::size_t ci = 0; ci < spec.controllers.size(); ++ci)
            {
                ot::Benchmark::PlannerExperiment pe;
                pe.name = "sim:" + spec.controllers[ci].displayName;
                pe.common = records[ci].common;
                pe.runs = records[ci].runs;
                x.planners.push_back(std::move(pe));
            }
            x.totalDuration = secondsSince(t0);
            writeExperimentFiles(c, e, bench,
                                 "# mhplan solution paths: planner <TAB> run index <TAB> x y;x y;...\n"
                                 "# (simulation experiment: no paths)\n");
            return 0;
        }
    } // namespace detail

    void applyStartJitter(Scenario &scenario, double startJitter, double headingJitter, std::uint32_t seed)
    {
        if (!(startJitter > 0.0) && !(headingJitter > 0.0))
            return;
        std::uint64_t state = seed;
        const auto uniform = [&state]
        {
            std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
            z ^= z >> 31;
            return static_cast<double>(z >> 11) * 0x1.0p-53; // [0, 1)
        };
        World pointWorld = scenario.world;
        pointWorld.robotRadius = 0.0;
        pointWorld.queries.clear();
        const CollisionModelPtr model = makeCollisionModel(pointWorld);
        const Box &b = scenario.world.bounds;
        constexpr double kTwoPi = 6.283185307179586;
        auto &robots = scenario.robots;
        for (std::size_t i = 0; i < robots.size(); ++i)
        {
            RobotSpec &r = robots[i];
            if (startJitter > 0.0)
            {
                const auto valid = [&](const Vec2 &p)
                {
                    if (!(p.x >= b.xmin + r.radius && p.x <= b.xmax - r.radius && p.y >= b.ymin + r.radius &&
                          p.y <= b.ymax - r.radius))
                        return false;
                    if (model->clearance(p) < r.radius)
                        return false;
                    for (std::size_t j = 0; j < robots.size(); ++j)
                        if (j != i && distance(p, robots[j].start) < r.radius + robots[j].radius)
                            return false;
                    for (const auto &o : scenario.movingObstacles)
                        if (distance(p, o.motion.positionAt(r.joinTime)) < r.radius + o.radius)
                            return false;
                    return true;
                };
                for (int attempt = 0; attempt < 1000; ++attempt)
                {
                    const double rho = startJitter * std::sqrt(uniform());
                    const double phi = kTwoPi * uniform();
                    const Vec2 p(r.start.x + rho * std::cos(phi), r.start.y + rho * std::sin(phi));
                    if (valid(p))
                    {
                        r.start = p;
                        break;
                    }
                }
            }
            if (headingJitter > 0.0)
                r.heading += (2.0 * uniform() - 1.0) * headingJitter;
        }
    }
} // namespace mhplan::bench
