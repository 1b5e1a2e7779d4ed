// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/bench/CampaignRunner.h"

#include "mhplan/collision/Collision.h"
#include "mhplan/sim/Controllers.h"
#include "mhplan/collision/Metrics.h"
#include "mhplan/collision/Problem.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/sim/ScenarioIO.h"
#include "mhplan/sim/Simulation.h"
#include "mhplan/base/Version.h"
#include "mhplan/base/World.h"
#include "mhplan/io/WorldIO.h"
#include "mhplan/bench/Improvements.h"

#include "mhplan/optimum/Optimum.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/MachineSpecs.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <sqlite3.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace ot = ompl::tools;
namespace fs = std::filesystem;

namespace mhplan::bench
{
    double CampaignSummary::overheadFraction() const
    {
        const double total = workerSeconds + mergeSeconds;
        return total > 0.0 ? std::max(0.0, total - solveSeconds) / total : 0.0;
    }

    std::string logFile(const Campaign &campaign, const Experiment &experiment)
    {
        return (fs::path(campaign.logDir) / (safeFileStem(experiment.name) + ".log")).string();
    }

    std::string pathsFile(const Campaign &campaign, const Experiment &experiment)
    {
        return (fs::path(campaign.logDir) / (safeFileStem(experiment.name) + ".paths")).string();
    }

    namespace
    {
        using Clock = std::chrono::steady_clock;

        double secondsSince(Clock::time_point t0)
        {
            return std::chrono::duration<double>(Clock::now() - t0).count();
        }

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

        // --- a tiny message protocol over pipes: "<type> <index> <bytes>\n<payload>" ----------------------

        constexpr char kFieldSep = '\x1f';
        constexpr char kRecordSep = '\x1e';
        constexpr char kGroupSep = '\x1d';

        std::string encodeMap(const std::map<std::string, std::string> &m)
        {
            std::string out;
            for (const auto &kv : m)
                out += kv.first + kFieldSep + kv.second + kRecordSep;
            return out;
        }

        std::map<std::string, std::string> decodeMap(const std::string &s)
        {
            std::map<std::string, std::string> m;
            std::size_t pos = 0;
            while (pos < s.size())
            {
                const std::size_t end = s.find(kRecordSep, pos);
                const std::string rec =
                    s.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
                const std::size_t f = rec.find(kFieldSep);
                if (f != std::string::npos)
                    m[rec.substr(0, f)] = rec.substr(f + 1);
                if (end == std::string::npos)
                    break;
                pos = end + 1;
            }
            return m;
        }

        std::vector<std::string> splitOn(const std::string &s, char sep)
        {
            std::vector<std::string> out;
            std::size_t pos = 0;
            while (pos <= s.size())
            {
                const std::size_t end = s.find(sep, pos);
                if (end == std::string::npos)
                {
                    if (pos < s.size())
                        out.push_back(s.substr(pos));
                    break;
                }
                out.push_back(s.substr(pos, end - pos));
                pos = end + 1;
            }
            return out;
        }

        /** A forked process with a pipe from child to parent: in the child (pid 0) \c fd is the write end,
            in the parent the read end; the other end is closed on each side. Output is flushed first so
            that buffered text is not written twice. */
        struct Forked
        {
            pid_t pid;
            int fd;
        };

        Forked forkWithPipe()
        {
            int fds[2];
            if (::pipe(fds) != 0)
                throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
            std::cout.flush();
            std::cerr.flush();
            const pid_t pid = ::fork();
            if (pid < 0)
                throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
            ::close(pid == 0 ? fds[0] : fds[1]);
            return {pid, pid == 0 ? fds[1] : fds[0]};
        }

        void writeAll(int fd, const std::string &data)
        {
            std::size_t done = 0;
            while (done < data.size())
            {
                const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
                if (n < 0 && errno == EINTR)
                    continue;
                if (n <= 0)
                    return; // the reader is gone; nothing sensible left to do
                done += static_cast<std::size_t>(n);
            }
        }

        void sendMessage(int fd, char type, std::size_t index, const std::string &payload)
        {
            std::ostringstream head;
            head << type << ' ' << index << ' ' << payload.size() << '\n';
            writeAll(fd, head.str() + payload);
        }

        struct Message
        {
            char type{0};
            std::size_t index{0};
            std::string payload;
        };

        /** Incremental parser of the message stream. */
        class MessageReader
        {
          public:
            void feed(const char *data, std::size_t n) { buffer_.append(data, n); }
            bool next(Message &m)
            {
                const std::size_t nl = buffer_.find('\n');
                if (nl == std::string::npos)
                    return false;
                std::istringstream head(buffer_.substr(0, nl));
                std::size_t bytes = 0;
                head >> m.type >> m.index >> bytes;
                if (buffer_.size() < nl + 1 + bytes)
                    return false;
                m.payload = buffer_.substr(nl + 1, bytes);
                buffer_.erase(0, nl + 1 + bytes);
                return true;
            }

          private:
            std::string buffer_;
        };

        std::string encodePath(const std::vector<Vec2> &pts)
        {
            std::string out;
            for (const Vec2 &p : pts)
                out += num(p.x) + " " + num(p.y) + ";";
            return out;
        }

        /** Gives access to the experiment record so that runs gathered from several processes can be
            written with OMPL's own log writer. */
        class AssembledBenchmark : public ot::Benchmark
        {
          public:
            using ot::Benchmark::Benchmark;
            CompleteExperiment &experiment() { return exp_; }
        };

        /** Everything an experiment's processes share (built before the children are forked; nothing here
            owns a random number generator). */
        struct ExperimentSetup
        {
            const Campaign *campaign{nullptr};
            const Experiment *experiment{nullptr};
            const PlannerRegistry *registry{nullptr};
            World world;
            Query query;
            CollisionModelPtr model;
            double optimum{std::numeric_limits<double>::quiet_NaN()};
            double optimumSeconds{0.0};
            double metricStep{1e-3};
        };

        /** Captures what OMPL's benchmark writes to std::cerr when a planner throws. */
        class CerrCapture
        {
          public:
            CerrCapture() : old_(std::cerr.rdbuf(buffer_.rdbuf())) {}
            ~CerrCapture() { std::cerr.rdbuf(old_); }
            std::string take()
            {
                std::string s = buffer_.str();
                buffer_.str("");
                return s;
            }

          private:
            std::ostringstream buffer_;
            std::streambuf *old_;
        };

        /** Runs another planner unchanged (same name, parameters, specs) but hands OMPL's benchmark its
           planner data only when asked (exporting the roadmap of a PRM* run costs about as much time as the
           run itself) and only the progress properties the campaign selects. */
        class PlannerDataSwitch : public ob::Planner
        {
          public:
            PlannerDataSwitch(ob::PlannerPtr inner, bool plannerData,
                              const std::vector<std::string> &progress)
                : ob::Planner(inner->getSpaceInformation(), inner->getName()), inner_(std::move(inner)),
                  plannerData_(plannerData)
            {
                specs_ = inner_->getSpecs();
                params_ = inner_->params();
                for (const auto &kv : inner_->getPlannerProgressProperties())
                {
                    // "best cost REAL" is selected by "best cost".
                    const std::string name = kv.first.substr(0, kv.first.find_last_of(' '));
                    if (progress.empty() ||
                        std::find(progress.begin(), progress.end(), name) != progress.end())
                        addPlannerProgressProperty(kv.first, kv.second);
                }
            }
            void setProblemDefinition(const ob::ProblemDefinitionPtr &pdef) override
            {
                ob::Planner::setProblemDefinition(pdef);
                inner_->setProblemDefinition(pdef);
            }
            ob::PlannerStatus solve(const ob::PlannerTerminationCondition &ptc) override
            {
                if (recorder_)
                    recorder_->begin();
                const ob::PlannerStatus status = inner_->solve(ptc);
                if (recorder_)
                    recorder_->end();
                return status;
            }
            /** Times solve() for \e recorder (Improvements.h). */
            void setRecorder(ImprovementRecorder *recorder) { recorder_ = recorder; }
            void clear() override
            {
                ob::Planner::clear();
                inner_->clear();
            }
            void setup() override
            {
                ob::Planner::setup();
                inner_->setup();
            }
            void checkValidity() override { inner_->checkValidity(); }
            void printProperties(std::ostream &out) const override { inner_->printProperties(out); }
            void printSettings(std::ostream &out) const override { inner_->printSettings(out); }
            void getPlannerData(ob::PlannerData &data) const override
            {
                if (plannerData_)
                    inner_->getPlannerData(data);
            }

          private:
            ob::PlannerPtr inner_;
            bool plannerData_;
            ImprovementRecorder *recorder_{nullptr};
        };

        /** The end of a run process: run \e body; an exception is reported on \e fd as an 'X' message
            (exit code 3), then the process exits without running destructors. */
        [[noreturn]] void finishRunChild(int fd, const std::function<void()> &body)
        {
            int code = 0;
            try
            {
                body();
            }
            catch (const std::exception &e)
            {
                sendMessage(fd, 'X', 0, e.what());
                code = 3;
            }
            catch (...)
            {
                sendMessage(fd, 'X', 0, "unknown exception");
                code = 3;
            }
            ::close(fd);
            ::_exit(code);
        }

        /** Child process: run \e spec once (run \e runIndex) through ompl::tools::Benchmark and send the
           run's properties, path and progress to \e fd. One process per run: the seed applies to exactly this
           run, OMPL's memory figure is this run's, a crash takes nothing else with it, and no planner is ever
            cleared or destroyed (the process just ends). Never returns. */
        [[noreturn]] void runPlannerChild(ExperimentSetup &xs, const PlannerSpec &spec, std::size_t runIndex,
                                          std::uint32_t seed, int fd)
        {
            finishRunChild(
                fd,
                [&]()
                {
                    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
                    // The seed must be set before any random number generator exists in this process; the
                    // campaign process and the experiment process never allocate one.
                    ompl::RNG::setSeed(seed);
                    const Campaign &c = *xs.campaign;
                    // The problem is built here, after the seed: OMPL's SimpleSetup owns a random number
                    // generator (its path simplifier's).
                    const og::SimpleSetupPtr ss = makeSimpleSetup(xs.world, xs.query, xs.model);
                    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
                    ob::PlannerPtr inner = xs.registry->create(spec.planner, si, spec.params);
                    inner->setName(spec.displayName);
                    auto planner = std::make_shared<PlannerDataSwitch>(inner, c.plannerData, spec.progress);
                    ss->setPlanner(planner);
                    ImprovementRecorder improvements;
                    planner->setRecorder(&improvements);

                    ot::Benchmark benchmark(*ss, xs.experiment->name);
                    benchmark.addPlanner(planner);
                    CerrCapture capture;
                    // OMPL's collector samples the progress properties from the start of solve() at a fixed
                    // interval but not at its end: the post-run event adds that last sample.
                    std::map<std::string, std::string> finalSample;
                    benchmark.setPreRunEvent(
                        [&](const ob::PlannerPtr &p)
                        {
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
                            improvements.attach(p->getProblemDefinition(),
                                                best == fns.end() ? nullptr : best->second,
                                                kImprovementPollInterval);
                            sendMessage(fd, 'C', 0, encodeMap(common));
                            sendMessage(fd, 'S', 0,
                                        encodeMap({{"host", data.host},
                                                   {"cpu", data.cpuInfo},
                                                   {"properties", props.str()},
                                                   {"progress", names}}));
                        });
                    benchmark.setPostRunEvent(
                        [&](const ob::PlannerPtr &p, ot::Benchmark::RunProperties &run)
                        {
                            const std::string crash =
                                std::to_string(static_cast<int>(ob::PlannerStatus::CRASH));
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
                            run["run index INTEGER"] = std::to_string(runIndex);
                            run["run seed INTEGER"] = std::to_string(seed);
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
                                const std::vector<Vec2> pts = pathPoints(*geo);
                                const PathMetrics m = computePathMetrics(pts, *xs.model, xs.metricStep);
                                run["path length REAL"] = num(m.length);
                                run["collision free BOOLEAN"] = m.collisionFree ? "1" : "0";
                                run["min clearance REAL"] = num(m.minClearance);
                                run["mean clearance REAL"] = num(m.meanClearance);
                                run["smoothness REAL"] = num(m.smoothness);
                                run["max curvature REAL"] = num(m.maxCurvature);
                                run["angle over length REAL"] = num(m.angleOverLength);
                                run["cusps INTEGER"] = std::to_string(m.cusps);
                                if (pdef->hasExactSolution())
                                    run["optimality gap REAL"] =
                                        num(optimalityGapPercent(m.length, xs.optimum));
                                path = encodePath(pts);
                            }
                            const std::vector<Improvement> better = run["status ENUM"] == crash
                                                                        ? std::vector<Improvement>{}
                                                                        : improvements.finish(*pdef);
                            run["improvements INTEGER"] = std::to_string(better.size());
                            std::map<std::string, std::string> payload = run;
                            payload["\x01path"] = path;
                            payload["\x01improvements"] = encodeImprovements(better);
                            sendMessage(fd, 'R', runIndex, encodeMap(payload));
                        });
                    const ot::Benchmark::Request req(c.timeLimit, c.memoryLimit, 1, c.progressInterval, false,
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
                        sendMessage(fd, 'G', runIndex, payload);
                    }
                    sendMessage(fd, 'E', runIndex, "");
                });
        }

        /** The data of one planner across all its runs (possibly gathered from several processes). */
        struct PlannerRecord
        {
            std::map<std::string, std::string> common;
            std::string properties;
            std::vector<std::string> progressNames;
            std::vector<ot::Benchmark::RunProperties> runs;
            std::vector<ot::Benchmark::RunProgressData> progress;
            std::vector<std::string> paths;
            std::vector<std::string> improvements;
            std::vector<bool> have;
        };

        struct WorkerInfo
        {
            std::string host;
            std::string cpuInfo;
        };

        /** How a run process ended. */
        struct ChildOutcome
        {
            /** Killed by the watchdog (no message for \c watchdog seconds). */
            bool killed{false};
            /** waitpid status. */
            int status{0};
            /** Text of an 'X' message (an exception in the run process). */
            std::string error;
            /** Seconds from the last message (or the start) to the end, capped at the watchdog when killed:
                the time recorded for a crashed run. */
            double elapsed{0.0};
            /** Seconds from the fork to the end. */
            double runSeconds{0.0};
        };

        /** Fork a run process that executes \e body(fd) (which must end the process with _exit), hand each
            message it sends to \e onMessage (with the seconds since the fork), and kill it when it sends
            nothing for \e watchdog seconds. */
        ChildOutcome runChildProcess(int progressFd, double watchdog, const std::function<void(int)> &body,
                                     const std::function<void(const Message &, double)> &onMessage)
        {
            const auto [pid, fd] = forkWithPipe();
            if (pid == 0)
            {
                ::prctl(PR_SET_PDEATHSIG, SIGKILL);
                const rlimit noCore{0, 0}; // a crashing run leaves no core file behind
                ::setrlimit(RLIMIT_CORE, &noCore);
                ::close(progressFd);
                body(fd);
                ::_exit(5); // body must not return
            }
            ChildOutcome out;
            MessageReader reader;
            const Clock::time_point runStart = Clock::now();
            Clock::time_point last = runStart;
            char buf[65536];
            while (true)
            {
                pollfd pfd{fd, POLLIN, 0};
                const int r = ::poll(&pfd, 1, 200);
                if (r < 0 && errno == EINTR)
                    continue;
                if (r == 0)
                {
                    if (secondsSince(last) > watchdog)
                    {
                        ::kill(pid, SIGKILL);
                        out.killed = true;
                        break;
                    }
                    continue;
                }
                const ssize_t n = ::read(fd, buf, sizeof(buf));
                if (n < 0 && errno == EINTR)
                    continue;
                if (n <= 0)
                    break;
                reader.feed(buf, static_cast<std::size_t>(n));
                Message m;
                while (reader.next(m))
                {
                    last = Clock::now();
                    if (m.type == 'X')
                        out.error = m.payload;
                    else
                        onMessage(m, secondsSince(runStart));
                }
            }
            ::close(fd);
            while (::waitpid(pid, &out.status, 0) < 0 && errno == EINTR)
            {
            }
            out.elapsed = std::min(secondsSince(last), out.killed ? watchdog : 1e9);
            out.runSeconds = secondsSince(runStart);
            return out;
        }

        /** Tell the campaign process that a run ended: "r EXPERIMENT CRASHED SLOT SECONDS". */
        void reportRun(int progressFd, std::size_t experiment, bool crashed, std::size_t slot, double seconds)
        {
            std::ostringstream msg;
            msg << "r " << experiment << " " << (crashed ? 1 : 0) << " " << slot << " " << seconds << "\n";
            writeAll(progressFd, msg.str());
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
            std::cerr << (::isatty(2) ? "\n" : "") << "mhplan bench: " << experiment << ": " << what
                      << " run " << run << " crashed (" << why.str() << "); recorded as Crash\n";
        }

        /** Write an experiment's path sidecar and then (atomically, last: a log on disk means a finished
            experiment) its log with OMPL's writer and the real version line. */
        void writeExperimentFiles(const Campaign &c, const Experiment &e, const AssembledBenchmark &bench,
                                  const std::string &paths, const std::string &improvements = "")
        {
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
                const std::string tmp = file + ".tmp" + std::to_string(::getpid());
                {
                    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
                    out << content;
                    if (!out)
                        throw std::runtime_error("cannot write '" + tmp + "'");
                }
                fs::rename(tmp, file);
            };
            atomicWrite(pathsFile(c, e), paths);
            if (!improvements.empty())
                atomicWrite(improvementsFile(c, e), improvements);
            atomicWrite(logFile(c, e), text);
        }

        /** Experiment process: run every planner of the campaign on this experiment in child processes,
            then write the log and the path sidecar. Reports each run to \e progressFd. */
        int runExperimentProcess(ExperimentSetup &xs, int progressFd, double &solveSeconds)
        {
            const Campaign &c = *xs.campaign;
            const Experiment &e = *xs.experiment;
            const Clock::time_point t0 = Clock::now();
            const ompl::time::point start = ompl::time::now();
            WorkerInfo info;
            std::vector<PlannerRecord> records(c.planners.size());
            solveSeconds = 0.0;
            const int crashCode = static_cast<int>(ob::PlannerStatus::CRASH);
            const double watchdog = 2.0 * c.timeLimit + 20.0;

            for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
            {
                const PlannerSpec &spec = c.planners[pi];
                PlannerRecord &rec = records[pi];
                rec.runs.resize(c.runs);
                rec.progress.resize(c.runs);
                rec.paths.resize(c.runs);
                rec.improvements.resize(c.runs);
                rec.have.assign(c.runs, false);
                for (std::size_t next = 0; next < c.runs; ++next)
                {
                    const std::uint32_t seed = deriveSeed(e.seed, spec.displayName, next);
                    const ChildOutcome outcome = runChildProcess(
                        progressFd, watchdog, [&](int fd) { runPlannerChild(xs, spec, next, seed, fd); },
                        [&](const Message &m, double runSeconds)
                        {
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
                            else if (m.type == 'R' && m.index < c.runs)
                            {
                                auto props = decodeMap(m.payload);
                                rec.paths[m.index] = props["\x01path"];
                                props.erase("\x01path");
                                rec.improvements[m.index] = props["\x01improvements"];
                                props.erase("\x01improvements");
                                rec.runs[m.index] = props;
                                rec.have[m.index] = true;
                                const auto t = props.find("time REAL");
                                if (t != props.end())
                                    solveSeconds += std::atof(t->second.c_str());
                                reportRun(progressFd, e.index,
                                          props["status ENUM"] == std::to_string(crashCode), pi, runSeconds);
                            }
                            else if (m.type == 'G' && m.index < c.runs)
                            {
                                ot::Benchmark::RunProgressData data;
                                for (const auto &sample : splitOn(m.payload, kGroupSep))
                                    data.push_back(decodeMap(sample));
                                rec.progress[m.index] = data;
                            }
                        });
                    const std::size_t k = next;
                    if (rec.have[k])
                        continue;
                    ot::Benchmark::RunProperties crash;
                    crash["time REAL"] = num(outcome.elapsed);
                    crash["status ENUM"] = std::to_string(crashCode);
                    crash["solved BOOLEAN"] = "0";
                    crash["run index INTEGER"] = std::to_string(k);
                    crash["run seed INTEGER"] = std::to_string(seed);
                    crash["exact optimum length REAL"] = num(xs.optimum);
                    rec.runs[k] = crash;
                    rec.have[k] = true;
                    solveSeconds += outcome.elapsed;
                    reportRun(progressFd, e.index, true, pi, outcome.runSeconds);
                    reportCrash(e.name, "planner " + spec.displayName, k, outcome, watchdog);
                }
            }

            // Assemble the experiment with OMPL's own record and writer.
            const og::SimpleSetupPtr ss = makeSimpleSetup(xs.world, xs.query, xs.model);
            AssembledBenchmark bench(*ss, e.name);
            auto &x = bench.experiment();
            x.name = e.name;
            x.maxTime = c.timeLimit;
            x.maxMem = c.memoryLimit;
            x.runCount = c.runs;
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
            x.parameters["world TEXT"] = xs.world.name;
            x.parameters["world_file TEXT"] = fs::absolute(e.worldFile).lexically_normal().string();
            x.parameters["world_type TEXT"] = xs.world.type();
            x.parameters["obstacle_count INTEGER"] = std::to_string(xs.world.obstacleCount());
            if (xs.world.isGrid())
                x.parameters["grid_cells INTEGER"] =
                    std::to_string(static_cast<long long>(xs.world.grid->width()) * xs.world.grid->height());
            x.parameters["robot_radius REAL"] = num(xs.world.robotRadius);
            x.parameters["query TEXT"] = xs.query.name;
            std::ostringstream q;
            q << "(" << xs.query.start.x << "," << xs.query.start.y << ")->(" << xs.query.goal.x << ","
              << xs.query.goal.y << ")";
            x.parameters["query_points TEXT"] = q.str();
            // Experiment properties go to the database verbatim (no NaN to NULL conversion): leave an unknown
            // optimum out.
            if (std::isfinite(xs.optimum))
            {
                x.parameters["exact_optimum REAL"] = num(xs.optimum);
                x.parameters["optimum_seconds REAL"] = num(xs.optimumSeconds);
            }
            x.parameters["collision_backend TEXT"] = xs.model->name();
            x.parameters["config_hash TEXT"] = e.configHash;
            x.parameters["mhplan_version TEXT"] = version();
            for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
            {
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
            paths << "# mhplan solution paths: planner <TAB> run index <TAB> x y;x y;...\n";
            for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
                for (std::size_t k = 0; k < c.runs; ++k)
                    if (!records[pi].paths[k].empty())
                        paths << "geometric_" << c.planners[pi].displayName << "\t" << k << "\t"
                              << records[pi].paths[k] << "\n";
            std::vector<std::string> plannerNames;
            std::vector<std::vector<std::string>> improvements;
            for (std::size_t pi = 0; pi < c.planners.size(); ++pi)
            {
                plannerNames.push_back("geometric_" + c.planners[pi].displayName);
                improvements.push_back(records[pi].improvements);
            }
            writeExperimentFiles(c, e, bench, paths.str(), improvementsFileText(plannerNames, improvements));
            return 0;
        }

        // --- simulation experiments -----------------------------------------------------------------------

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

        /** A run or log property name from a free-form label: lower case letters, digits and single blanks.
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

        /** Run process of a simulation: controller \e spec on the scenario (starts perturbed by
            \e startSeed), seeded with \e seed, properties sent to \e fd. Never returns. */
        [[noreturn]] void runSimulationChild(const SimulationSetup &xs, const ControllerSpec &spec,
                                             std::size_t runIndex, std::uint32_t seed,
                                             std::uint32_t startSeed, int fd)
        {
            finishRunChild(fd,
                           [&]()
                           {
                               ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
                               // As for planners: the seed before any random number generator exists in this
                               // process (plan-then-follow controllers run OMPL planners).
                               ompl::RNG::setSeed(seed);
                               Scenario scenario = xs.scenario;
                               applyStartJitter(scenario, xs.spec->startJitter, xs.spec->headingJitter,
                                                startSeed);
                               const ControllerPtr controller = makeController(spec.controller, *xs.registry);
                               for (const auto &kv : spec.params)
                                   controller->setParameter(kv.first, kv.second);
                               std::map<std::string, std::string> common;
                               for (const auto &kv : controller->parameters())
                                   common[oneLine(kv.first)] = oneLine(kv.second);
                               common["controller"] = spec.controller;
                               sendMessage(fd, 'C', 0, encodeMap(common));
                               Simulation sim(std::move(scenario), controller, seed);
                               const Clock::time_point t0 = Clock::now();
                               const SimulationResult result = sim.run();
                               const double wall = result.wallTime > 0.0 ? result.wallTime : secondsSince(t0);
                               ot::Benchmark::RunProperties run = simulationProperties(result, wall);
                               run["run index INTEGER"] = std::to_string(runIndex);
                               run["run seed INTEGER"] = std::to_string(seed);
                               run["start seed INTEGER"] = std::to_string(startSeed);
                               sendMessage(fd, 'R', runIndex, encodeMap(run));
                               sendMessage(fd, 'E', runIndex, "");
                           });
        }

        /** Experiment process of a simulation experiment: every controller, every run, each in its own
            process; then the log (OMPL's format and writer) and an empty path sidecar. */
        int runSimulationProcess(SimulationSetup &xs, int progressFd, double &solveSeconds)
        {
            const Campaign &c = *xs.campaign;
            const Experiment &e = *xs.experiment;
            const SimulationSpec &spec = *xs.spec;
            const Clock::time_point t0 = Clock::now();
            const ompl::time::point start = ompl::time::now();
            const int crashCode = static_cast<int>(ob::PlannerStatus::CRASH);
            const double watchdog = spec.wallLimit;
            solveSeconds = 0.0;
            std::vector<PlannerRecord> records(spec.controllers.size());
            for (std::size_t ci = 0; ci < spec.controllers.size(); ++ci)
            {
                const ControllerSpec &ctl = spec.controllers[ci];
                PlannerRecord &rec = records[ci];
                rec.runs.resize(e.runs);
                rec.have.assign(e.runs, false);
                for (std::size_t k = 0; k < e.runs; ++k)
                {
                    const std::uint32_t seed = simulationRunSeed(e, ctl.displayName, k);
                    const std::uint32_t startSeed = simulationStartSeed(e, k);
                    const ChildOutcome outcome = runChildProcess(
                        progressFd, watchdog,
                        [&](int fd) { runSimulationChild(xs, ctl, k, seed, startSeed, fd); },
                        [&](const Message &m, double runSeconds)
                        {
                            if (m.type == 'C')
                                rec.common = decodeMap(m.payload);
                            else if (m.type == 'R' && m.index < e.runs)
                            {
                                auto props = decodeMap(m.payload);
                                rec.runs[m.index] = props;
                                rec.have[m.index] = true;
                                solveSeconds += std::atof(props["time REAL"].c_str());
                                reportRun(progressFd, e.index, false, xs.slotBase + ci, runSeconds);
                            }
                        });
                    if (rec.have[k])
                        continue;
                    ot::Benchmark::RunProperties crash;
                    crash["time REAL"] = num(outcome.elapsed);
                    crash["status ENUM"] = std::to_string(crashCode);
                    crash["solved BOOLEAN"] = "0";
                    crash["run index INTEGER"] = std::to_string(k);
                    crash["run seed INTEGER"] = std::to_string(seed);
                    crash["start seed INTEGER"] = std::to_string(startSeed);
                    rec.runs[k] = crash;
                    rec.have[k] = true;
                    solveSeconds += outcome.elapsed;
                    reportRun(progressFd, e.index, true, xs.slotBase + ci, outcome.runSeconds);
                    reportCrash(e.name, "controller " + ctl.displayName, k, outcome, watchdog);
                }
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

        /** Build the shared problem of an experiment (no random number generator is created here). */
        void prepareExperiment(ExperimentSetup &xs)
        {
            const Campaign &c = *xs.campaign;
            const Experiment &e = *xs.experiment;
            xs.world = loadWorld(e.worldFile);
            xs.query = xs.world.query(e.query);
            xs.model = makeCollisionModel(xs.world, parseCollisionBackend(c.collision));
            xs.metricStep = defaultMetricStep(xs.world);
            const Clock::time_point t0 = Clock::now();
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

        /** Run \e check in a throw-away child process; the message it returns (empty = fine) is thrown here
            as InputError. A crash of the child is a runtime_error naming \e what. */
        void checkInChildProcess(const std::function<std::string()> &check, const std::string &what)
        {
            const auto [pid, fd] = forkWithPipe();
            if (pid == 0)
            {
                std::string error;
                try
                {
                    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
                    error = check();
                }
                catch (const std::exception &ex)
                {
                    error = ex.what();
                }
                writeAll(fd, error);
                ::close(fd);
                ::_exit(0);
            }
            std::string error;
            char buf[4096];
            ssize_t n;
            while ((n = ::read(fd, buf, sizeof(buf))) > 0 || (n < 0 && errno == EINTR))
                if (n > 0)
                    error.append(buf, static_cast<std::size_t>(n));
            ::close(fd);
            int status = 0;
            ::waitpid(pid, &status, 0);
            if (!error.empty())
                throw InputError(error);
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
                throw std::runtime_error("checking the campaign's " + what + " crashed the checking process");
        }

        /** Check every planner and parameter in a throw-away process (so that this process never
            allocates a random number generator before the run processes set their seeds). */
        void validatePlanners(const Campaign &c, const PlannerRegistry &registry, const World &world,
                              const Query &query)
        {
            checkInChildProcess(
                [&]() -> std::string
                {
                    const CollisionModelPtr model =
                        makeCollisionModel(world, parseCollisionBackend(c.collision));
                    const og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model);
                    for (std::size_t i = 0; i < c.planners.size(); ++i)
                    {
                        try
                        {
                            registry.create(c.planners[i].planner, ss->getSpaceInformation(),
                                            c.planners[i].params);
                        }
                        catch (const std::exception &ex)
                        {
                            return c.file + ": planners[" + std::to_string(i) + "] (" +
                                   c.planners[i].displayName + "): " + ex.what();
                        }
                    }
                    return {};
                },
                "planners");
        }

        /** Check every controller and parameter of the simulations in a throw-away process (controllers may
            own planners and random number generators). Messages name the campaign file and line. */
        void validateControllers(const Campaign &c, const PlannerRegistry &registry)
        {
            checkInChildProcess(
                [&]() -> std::string
                {
                    for (std::size_t si = 0; si < c.simulations.size(); ++si)
                        for (std::size_t ci = 0; ci < c.simulations[si].controllers.size(); ++ci)
                        {
                            const ControllerSpec &spec = c.simulations[si].controllers[ci];
                            try
                            {
                                const ControllerPtr controller = makeController(spec.controller, registry);
                                for (const auto &kv : spec.params)
                                    controller->setParameter(kv.first, kv.second);
                            }
                            catch (const std::exception &ex)
                            {
                                return c.file + ":" + std::to_string(spec.line) + ": simulations[" +
                                       std::to_string(si) + "].controllers[" + std::to_string(ci) + "] (" +
                                       spec.displayName + "): " + ex.what();
                            }
                        }
                    return {};
                },
                "controllers");
        }

        std::string formatDuration(double s)
        {
            if (!std::isfinite(s) || s < 0)
                return "--";
            const long total = std::lround(s);
            std::ostringstream out;
            if (total >= 3600)
                out << total / 3600 << "h" << std::setw(2) << std::setfill('0') << (total / 60) % 60 << "m";
            else if (total >= 60)
                out << total / 60 << "m" << std::setw(2) << std::setfill('0') << total % 60 << "s";
            else
                out << total << "s";
            return out.str();
        }

        /** Terminal progress: experiments and runs done, crashes, elapsed time and ETA. The ETA weighs the
            runs still to do by each planner's mean run time so far (the time limit for planners not seen yet)
            and scales by the ratio of elapsed time to the run time done (parallelism and overhead). */
        class ProgressBar
        {
          public:
            /** \e slotRuns: runs to do per slot (a planner, or a controller of a simulation); \e guess: the
                seconds assumed per run of a slot not seen yet. */
            ProgressBar(bool enabled, std::size_t experiments, std::vector<std::size_t> slotRuns,
                        double guess)
                : enabled_(enabled), experiments_(experiments), start_(Clock::now()), guess_(guess),
                  total_(std::move(slotRuns)), sum_(total_.size(), 0.0), count_(total_.size(), 0)
            {
                for (std::size_t n : total_)
                    runs_ += n;
            }
            void recordRun(std::size_t slot, double seconds)
            {
                if (slot < sum_.size())
                {
                    sum_[slot] += seconds;
                    ++count_[slot];
                }
            }
            /** Seconds still needed, or a negative number when unknown. */
            double eta() const
            {
                double done = 0.0, todo = 0.0;
                for (std::size_t p = 0; p < sum_.size(); ++p)
                {
                    done += sum_[p];
                    const double mean = count_[p] ? sum_[p] / static_cast<double>(count_[p]) : guess_;
                    todo += mean * static_cast<double>(total_[p] > count_[p] ? total_[p] - count_[p] : 0);
                }
                if (!(done > 0.0))
                    return -1.0;
                return todo * secondsSince(start_) / done;
            }
            void update(std::size_t expDone, std::size_t runsDone, std::size_t crashes, bool force = false)
            {
                if (!enabled_)
                    return;
                if (!force && secondsSince(lastDraw_) < 0.2)
                    return;
                lastDraw_ = Clock::now();
                const double elapsed = secondsSince(start_);
                const double frac = runs_ ? static_cast<double>(runsDone) / static_cast<double>(runs_) : 1.0;
                const double remaining = eta();
                const int width = 28;
                const int filled = static_cast<int>(frac * width);
                std::ostringstream line;
                line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
                     << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << std::setw(3)
                     << static_cast<int>(100.0 * frac) << "% experiments " << expDone << "/" << experiments_
                     << " runs " << runsDone << "/" << runs_;
                if (crashes > 0)
                    line << " crashes " << crashes;
                line << " elapsed " << formatDuration(elapsed) << " ETA " << formatDuration(remaining)
                     << "   ";
                std::cerr << line.str() << std::flush;
            }
            void finish()
            {
                if (enabled_)
                    std::cerr << "\n";
            }

          private:
            bool enabled_;
            std::size_t experiments_;
            std::size_t runs_{0};
            Clock::time_point start_;
            Clock::time_point lastDraw_{};
            double guess_;
            std::vector<std::size_t> total_;
            std::vector<double> sum_;
            std::vector<std::size_t> count_;
        };
    } // namespace

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

    bool logIsComplete(const std::string &log, const std::string &configHash)
    {
        std::ifstream in(log);
        if (!in)
            return false;
        std::string line;
        bool hashOk = false;
        std::size_t n = 0;
        while (std::getline(in, line) && n < 64 && !hashOk)
        {
            ++n;
            if (line.rfind("config_hash TEXT = ", 0) == 0)
                hashOk = line.substr(19) == configHash;
        }
        if (!hashOk)
            return false;
        // A finished log ends with the last planner's "." line.
        std::string last;
        while (std::getline(in, line))
            if (!line.empty())
                last = line;
        return last == ".";
    }

    CampaignSummary runCampaign(const Campaign &campaign, const RunOptions &options)
    {
        const Clock::time_point t0 = Clock::now();
        if (!options.resolveWorld)
            throw std::invalid_argument("runCampaign: options.resolveWorld must be set");
        if (options.jobs < 1 || options.jobs > 256)
            throw InputError("--jobs must be in [1, 256] (got " + std::to_string(options.jobs) + ")");
        const PlannerRegistry &registry = options.registry ? *options.registry : PlannerRegistry::builtin();
        std::ostream *msg = options.messages;

        const std::vector<Experiment> all = enumerateExperiments(campaign, options.resolveWorld);
        const std::vector<Experiment> mine = shardExperiments(all, options.shardIndex, options.shardCount);
        if (all.empty())
            throw InputError(campaign.file + ": the campaign has no experiments (no worlds, no simulations)");
        for (const auto &p : campaign.planners)
            registry.get(p.planner); // unknown names fail here with the list of registered planners
        if (!campaign.planners.empty() && all.front().simulation == Experiment::kNoSimulation)
        {
            const World world = loadWorld(all.front().worldFile);
            validatePlanners(campaign, registry, world, world.query(all.front().query));
        }
        if (!campaign.simulations.empty())
            validateControllers(campaign, registry);
        // Progress slots: the planners, then every controller of every simulation.
        std::vector<std::size_t> slotBase(campaign.simulations.size(), 0);
        std::size_t slots = campaign.planners.size();
        for (std::size_t si = 0; si < campaign.simulations.size(); ++si)
        {
            slotBase[si] = slots;
            slots += campaign.simulations[si].controllers.size();
        }
        const auto runsOf = [&](const Experiment &e)
        {
            return e.simulation == Experiment::kNoSimulation
                       ? campaign.planners.size() * e.runs
                       : campaign.simulations[e.simulation].controllers.size() * e.runs;
        };

        CampaignSummary summary;
        summary.experiments = mine.size();
        std::vector<const Experiment *> todo;
        for (const auto &e : mine)
        {
            if (logIsComplete(logFile(campaign, e), e.configHash))
                ++summary.skipped;
            else
                todo.push_back(&e);
        }
        if (msg && summary.skipped > 0)
            *msg << "mhplan bench: " << summary.skipped << " of " << mine.size()
                 << " experiments already complete (logs in " << campaign.logDir << "), skipping them\n";

        if (options.run && !todo.empty())
        {
            fs::create_directories(campaign.logDir);
            std::vector<std::size_t> slotRuns(slots, 0);
            for (const Experiment *e : todo)
            {
                if (e->simulation == Experiment::kNoSimulation)
                    for (std::size_t p = 0; p < campaign.planners.size(); ++p)
                        slotRuns[p] += e->runs;
                else
                    for (std::size_t ci = 0; ci < campaign.simulations[e->simulation].controllers.size();
                         ++ci)
                        slotRuns[slotBase[e->simulation] + ci] += e->runs;
            }
            ProgressBar bar(options.progressBar && ::isatty(2), todo.size(), slotRuns, campaign.timeLimit);
            struct Active
            {
                const Experiment *experiment;
                int fd;
                std::string buffer;
                bool ended{false};
                double workerSeconds{0.0};
                double solveSeconds{0.0};
                std::size_t runsSeen{0};
            };
            std::map<pid_t, Active> active;
            std::size_t nextTodo = 0, expDone = 0, runsDone = 0;
            ::signal(SIGPIPE, SIG_IGN);
            while (nextTodo < todo.size() || !active.empty())
            {
                while (nextTodo < todo.size() && active.size() < options.jobs)
                {
                    const Experiment *e = todo[nextTodo++];
                    const auto [pid, fd] = forkWithPipe();
                    if (pid == 0)
                    {
                        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
                        for (const auto &kv : active)
                            ::close(kv.second.fd);
                        int code = 0;
                        try
                        {
                            const Clock::time_point w0 = Clock::now();
                            double solve = 0.0;
                            if (e->simulation == Experiment::kNoSimulation)
                            {
                                ExperimentSetup xs;
                                xs.campaign = &campaign;
                                xs.experiment = e;
                                xs.registry = &registry;
                                prepareExperiment(xs);
                                code = runExperimentProcess(xs, fd, solve);
                            }
                            else
                            {
                                SimulationSetup xs;
                                xs.campaign = &campaign;
                                xs.experiment = e;
                                xs.spec = &campaign.simulations[e->simulation];
                                xs.registry = &registry;
                                xs.scenario = loadScenario(e->scenarioFile);
                                xs.slotBase = slotBase[e->simulation];
                                code = runSimulationProcess(xs, fd, solve);
                            }
                            std::ostringstream done;
                            done.precision(17);
                            done << "e " << e->index << " " << secondsSince(w0) << " " << solve << "\n";
                            writeAll(fd, done.str());
                        }
                        catch (const std::exception &ex)
                        {
                            std::cerr << "mhplan bench: experiment " << e->name << " failed: " << ex.what()
                                      << "\n";
                            code = 4;
                        }
                        ::close(fd);
                        std::cout.flush();
                        std::cerr.flush();
                        ::_exit(code);
                    }
                    active[pid] = Active{e, fd, "", false, 0.0, 0.0, 0};
                }
                std::vector<pollfd> pfds;
                std::vector<pid_t> pids;
                for (const auto &kv : active)
                {
                    if (kv.second.ended)
                        continue;
                    pfds.push_back({kv.second.fd, POLLIN, 0});
                    pids.push_back(kv.first);
                }
                if (!pfds.empty())
                    ::poll(pfds.data(), pfds.size(), 200);
                for (std::size_t i = 0; i < pfds.size(); ++i)
                {
                    if (!(pfds[i].revents & (POLLIN | POLLHUP | POLLERR)))
                        continue;
                    Active &a = active[pids[i]];
                    char buf[4096];
                    const ssize_t n = ::read(a.fd, buf, sizeof(buf));
                    if (n <= 0)
                    {
                        if (n < 0 && errno == EINTR)
                            continue;
                        a.ended = true;
                        continue;
                    }
                    a.buffer.append(buf, static_cast<std::size_t>(n));
                    std::size_t nl;
                    while ((nl = a.buffer.find('\n')) != std::string::npos)
                    {
                        std::istringstream line(a.buffer.substr(0, nl));
                        a.buffer.erase(0, nl + 1);
                        char type = 0;
                        std::size_t index = 0;
                        line >> type >> index;
                        if (type == 'r')
                        {
                            int crashed = 0;
                            std::size_t planner = 0;
                            double seconds = 0.0;
                            line >> crashed >> planner >> seconds;
                            bar.recordRun(planner, seconds);
                            ++runsDone;
                            ++a.runsSeen;
                            ++summary.runs;
                            summary.crashes += crashed ? 1 : 0;
                        }
                        else if (type == 'e')
                            line >> a.workerSeconds >> a.solveSeconds;
                    }
                }
                bar.update(expDone, runsDone, summary.crashes);
                // Reap finished experiment processes.
                for (auto it = active.begin(); it != active.end();)
                {
                    if (!it->second.ended)
                    {
                        ++it;
                        continue;
                    }
                    int status = 0;
                    if (::waitpid(it->first, &status, 0) < 0 && errno == EINTR)
                        continue;
                    const Active &a = it->second;
                    ++expDone;
                    // Runs a failed process never reported still count as done for the bar.
                    const std::size_t expected = runsOf(*a.experiment);
                    runsDone += expected > a.runsSeen ? expected - a.runsSeen : 0;
                    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                                    logIsComplete(logFile(campaign, *a.experiment), a.experiment->configHash);
                    if (ok)
                    {
                        ++summary.completed;
                        summary.workerSeconds += a.workerSeconds;
                        summary.solveSeconds += a.solveSeconds;
                    }
                    else
                    {
                        ++summary.failed;
                        summary.errors.push_back("experiment " + a.experiment->name + " failed (" +
                                                 (WIFSIGNALED(status)
                                                      ? "signal " + std::to_string(WTERMSIG(status))
                                                      : "exit code " + std::to_string(WEXITSTATUS(status))) +
                                                 "); re-run the campaign to retry it");
                    }
                    if (msg && !(options.progressBar && ::isatty(2)))
                        *msg << "[" << expDone << "/" << todo.size() << "] " << a.experiment->name
                             << (ok ? " done" : " FAILED") << " (" << std::fixed << std::setprecision(1)
                             << a.workerSeconds << " s)\n"
                             << std::defaultfloat;
                    ::close(a.fd);
                    it = active.erase(it);
                    bar.update(expDone, runsDone, summary.crashes, true);
                }
            }
            bar.finish();
        }

        if (options.merge)
        {
            const Clock::time_point m0 = Clock::now();
            // Merge every complete log of the whole campaign (all shards), so that one final step after
            // sharded runs builds the database.
            summary.mergedLogs = mergeDatabase(campaign, all, options.statisticsTool);
            summary.mergeSeconds = secondsSince(m0);
        }
        summary.wallSeconds = secondsSince(t0);
        return summary;
    }

    // --- the database
    // ---------------------------------------------------------------------------------------

    namespace
    {
        class Database
        {
          public:
            explicit Database(const std::string &file)
            {
                if (sqlite3_open(file.c_str(), &db_) != SQLITE_OK)
                {
                    const std::string err = db_ ? sqlite3_errmsg(db_) : "out of memory";
                    sqlite3_close(db_);
                    throw std::runtime_error("cannot open database '" + file + "': " + err);
                }
                sqlite3_busy_timeout(db_, 10000);
                exec("PRAGMA foreign_keys = ON");
            }
            ~Database() { sqlite3_close(db_); }
            sqlite3 *handle() { return db_; }
            Database(const Database &) = delete;
            Database &operator=(const Database &) = delete;

            void exec(const std::string &sql)
            {
                char *err = nullptr;
                if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK)
                {
                    const std::string e = err ? err : "?";
                    sqlite3_free(err);
                    throw std::runtime_error("database: " + e + " in: " + sql);
                }
            }

            bool hasTable(const std::string &name)
            {
                Statement st(*this, "SELECT count(*) FROM sqlite_master WHERE type='table' AND name=?");
                st.bind(1, name);
                return st.step() && st.integer(0) > 0;
            }

            class Statement
            {
              public:
                Statement(Database &db, const std::string &sql) : db_(db)
                {
                    if (sqlite3_prepare_v2(db.db_, sql.c_str(), -1, &st_, nullptr) != SQLITE_OK)
                        throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db.db_)) +
                                                 " in: " + sql);
                }
                ~Statement() { sqlite3_finalize(st_); }
                Statement(const Statement &) = delete;
                Statement &operator=(const Statement &) = delete;
                void bind(int i, const std::string &v)
                {
                    sqlite3_bind_text(st_, i, v.c_str(), -1, SQLITE_TRANSIENT);
                }
                void bind(int i, long long v) { sqlite3_bind_int64(st_, i, v); }
                void bind(int i, double v) { sqlite3_bind_double(st_, i, v); }
                bool step()
                {
                    const int rc = sqlite3_step(st_);
                    if (rc == SQLITE_ROW)
                        return true;
                    if (rc != SQLITE_DONE)
                        throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db_.db_)));
                    return false;
                }
                void reset()
                {
                    sqlite3_reset(st_);
                    sqlite3_clear_bindings(st_);
                }
                long long integer(int col) { return sqlite3_column_int64(st_, col); }
                std::string text(int col)
                {
                    const auto *t = sqlite3_column_text(st_, col);
                    return t ? reinterpret_cast<const char *>(t) : "";
                }

              private:
                Database &db_;
                sqlite3_stmt *st_{nullptr};
            };

          private:
            sqlite3 *db_{nullptr};
        };

        /** Run a program with arguments; its standard output goes to \e outputFile. Returns the exit code. */
        int runProgram(const std::vector<std::string> &argv, const std::string &outputFile)
        {
            std::cout.flush();
            std::cerr.flush();
            const pid_t pid = ::fork();
            if (pid < 0)
                throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
            if (pid == 0)
            {
                const int fd = ::open(outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
                if (fd >= 0)
                {
                    ::dup2(fd, 1);
                    ::dup2(fd, 2);
                    ::close(fd);
                }
                std::vector<char *> args;
                for (const auto &a : argv)
                    args.push_back(const_cast<char *>(a.c_str()));
                args.push_back(nullptr);
                ::execv(args[0], args.data());
                ::_exit(127);
            }
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
            {
            }
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        }

        std::string readAll(const std::string &file)
        {
            std::ifstream in(file);
            std::ostringstream ss;
            ss << in.rdbuf();
            return ss.str();
        }
    } // namespace

    std::size_t mergeDatabase(const Campaign &campaign, const std::vector<Experiment> &experiments,
                              const std::string &statisticsTool)
    {
        struct Pending
        {
            const Experiment *experiment;
            std::string log;
            std::string content;
        };
        std::vector<Pending> pending;
        long long maxBefore = 0;
        const fs::path dbPath(campaign.database);
        if (dbPath.has_parent_path())
            fs::create_directories(dbPath.parent_path());
        {
            Database db(campaign.database);
            db.exec("CREATE TABLE IF NOT EXISTS mhplan_logs (file TEXT PRIMARY KEY, experiment TEXT, "
                    "experimentid INTEGER, log_fingerprint TEXT, merged DATETIME)");
            std::map<std::string, std::pair<std::string, long long>> merged;
            {
                Database::Statement st(db, "SELECT file, log_fingerprint, experimentid FROM mhplan_logs");
                while (st.step())
                    merged[st.text(0)] = {st.text(1), st.integer(2)};
            }
            const bool haveExperiments = db.hasTable("experiments");
            for (const auto &e : experiments)
            {
                const std::string log = logFile(campaign, e);
                if (!logIsComplete(log, e.configHash))
                    continue;
                const std::string key = fs::absolute(log).lexically_normal().string();
                const std::string content = fingerprint(readAll(log));
                const auto it = merged.find(key);
                if (it != merged.end() && it->second.first == content)
                    continue;
                if (it != merged.end() && haveExperiments)
                {
                    // The experiment was re-run with another configuration: replace its old rows.
                    Database::Statement del(db, "DELETE FROM experiments WHERE id = ?");
                    del.bind(1, it->second.second);
                    del.step();
                    Database::Statement del2(db, "DELETE FROM mhplan_logs WHERE file = ?");
                    del2.bind(1, key);
                    del2.step();
                }
                pending.push_back({&e, log, content});
            }
            if (pending.empty())
                return 0;
            if (haveExperiments)
            {
                Database::Statement st(db, "SELECT coalesce(max(id), 0) FROM experiments");
                if (st.step())
                    maxBefore = st.integer(0);
            }
        }

        std::vector<std::string> argv{statisticsTool, "-a", "-d", campaign.database};
        for (const auto &p : pending)
            argv.push_back(p.log);
        const std::string output = campaign.database + ".merge-output.txt";
        const int rc = runProgram(argv, output);
        if (rc != 0)
            throw std::runtime_error(statisticsTool + " failed with exit code " + std::to_string(rc) + ":\n" +
                                     readAll(output));
        fs::remove(output);

        Database db(campaign.database);
        db.exec("BEGIN");
        db.exec("CREATE TABLE IF NOT EXISTS paths (runid INTEGER PRIMARY KEY, points TEXT, "
                "FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE)");
        std::vector<long long> ids;
        {
            Database::Statement st(db, "SELECT id FROM experiments WHERE id > ? ORDER BY id");
            st.bind(1, maxBefore);
            while (st.step())
                ids.push_back(st.integer(0));
        }
        if (ids.size() != pending.size())
            throw std::runtime_error("database '" + campaign.database + "': expected " +
                                     std::to_string(pending.size()) +
                                     " new experiments after the merge, found " + std::to_string(ids.size()) +
                                     " (was it written concurrently?)");
        Database::Statement record(db,
                                   "INSERT OR REPLACE INTO mhplan_logs VALUES (?, ?, ?, ?, datetime('now'))");
        Database::Statement findRun(
            db, "SELECT runs.id FROM runs JOIN plannerConfigs ON runs.plannerid = "
                "plannerConfigs.id WHERE runs.experimentid = ? AND plannerConfigs.name = ? "
                "AND runs.run_index = ?");
        Database::Statement insertPath(db, "INSERT OR REPLACE INTO paths VALUES (?, ?)");
        for (std::size_t i = 0; i < pending.size(); ++i)
        {
            const Experiment &e = *pending[i].experiment;
            record.bind(1, fs::absolute(pending[i].log).lexically_normal().string());
            record.bind(2, e.name);
            record.bind(3, ids[i]);
            record.bind(4, pending[i].content);
            record.step();
            record.reset();
            std::ifstream in(pathsFile(campaign, e));
            std::string line;
            while (std::getline(in, line))
            {
                if (line.empty() || line[0] == '#')
                    continue;
                const std::vector<std::string> cols = splitOn(line, '\t');
                if (cols.size() != 3)
                    continue;
                findRun.bind(1, ids[i]);
                findRun.bind(2, cols[0]);
                findRun.bind(3, std::atoll(cols[1].c_str()));
                const bool found = findRun.step();
                const long long runId = found ? findRun.integer(0) : -1;
                findRun.reset();
                if (!found)
                    continue;
                insertPath.bind(1, runId);
                insertPath.bind(2, cols[2]);
                insertPath.step();
                insertPath.reset();
            }
            insertImprovements(db.handle(), ids[i], improvementsFile(campaign, e));
        }
        db.exec("COMMIT");
        return pending.size();
    }
} // namespace mhplan::bench
