// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the scheduler of a campaign. It checks the campaign, skips the experiments whose logs
   are complete (resume), runs the others in up to `jobs` experiment processes at a time, follows their
   run reports for the progress bar and the summary, and merges the logs into the database. */
#include "benchmarks/CampaignRunner.h"

#include "benchmarks/Database.h"
#include "benchmarks/ExperimentRuns.h"
#include "benchmarks/Improvements.h"
#include "benchmarks/Progress.h"
#include "src/io/InputFile.h"
#include "src/io/WorldIO.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace mhplan::bench
{
    using namespace detail;

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
        /** Refuse a directory where no file can be created (checked before any run starts); \e subject
            names what goes there ("the logs to 'DIR'", "the database 'FILE'"). */
        void checkWritableDirectory(const fs::path &dir, const std::string &subject)
        {
            const auto refuse = [&](const std::string &why) {
                throw InputError("cannot write " + subject + " (directory '" + dir.string() + "': " + why +
                                 ")");
            };
            std::error_code ec;
            fs::create_directories(dir, ec);
            if (ec)
                refuse(ec.message());
            const fs::path probe = dir / (".mhplan-write-test." + std::to_string(::getpid()));
            std::ofstream out(probe, std::ios::binary | std::ios::trunc);
            out << "mhplan\n";
            out.close();
            const int err = errno;
            fs::remove(probe, ec);
            if (!out)
                refuse(std::strerror(err ? err : EIO));
        }

        /** Remove the temporary files (temporaryFile(): "<file>.mhplan-tmp.<host>.<PID>") of \e experiments'
            logs and side files that processes of this host which no longer exist left in the log directory
            when they were killed while writing. Nothing else is touched: not another experiment's, not
            another host's (its process ids mean nothing here), not a file mhplan did not name. */
        void removeStaleTemporaryFiles(const Campaign &campaign, const std::vector<const Experiment *> &mine)
        {
            std::set<std::string> prefixes;
            for (const Experiment *e : mine)
                for (const std::string &file :
                     {logFile(campaign, *e), pathsFile(campaign, *e), improvementsFile(campaign, *e)})
                    prefixes.insert(fs::path(temporaryFilePrefix(file)).filename().string());
            std::error_code ec;
            for (fs::directory_iterator it(campaign.logDir, ec), end; !ec && it != end; it.increment(ec))
            {
                const std::string name = it->path().filename().string();
                const std::size_t dot = name.rfind('.');
                if (dot == std::string::npos || dot + 1 == name.size() ||
                    name.find_first_not_of("0123456789", dot + 1) != std::string::npos ||
                    prefixes.count(name.substr(0, dot + 1)) == 0)
                    continue;
                const long pid = std::atol(name.c_str() + dot + 1);
                if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
                    fs::remove(it->path(), ec);
            }
        }
        /** The lock of a campaign's log directory held while a bench runs (flock; released when the process
            ends, however it ends). A whole campaign (--shard 1/1) locks it exclusively, a shard shares it and
            locks its own shard exclusively: two benches on one campaign never run the same experiment twice
            at once; the second waits, saying so, and then finds the first one's logs complete. (flock does
            not reach across the nodes of a cluster: there the shards of one array job are disjoint.) */
        class CampaignLock
        {
          public:
            CampaignLock(const Campaign &c, unsigned int shard, unsigned int shards, std::ostream *msg)
            {
                std::error_code ec;
                fs::create_directories(c.logDir, ec);
                const std::string whole = (fs::path(c.logDir) / ".mhplan-bench.lock").string();
                const std::string part =
                    (fs::path(c.logDir) / (".mhplan-bench-shard-" + std::to_string(shard) + "-of-" +
                                           std::to_string(shards) + ".lock"))
                        .string();
                fds_[0] = take(whole, shards == 1 ? LOCK_EX : LOCK_SH, msg);
                if (shards > 1)
                    fds_[1] = take(part, LOCK_EX, msg);
                // Who holds it, for the message of the next one.
                const int own = fds_[shards > 1 ? 1 : 0];
                if (own >= 0 && ::ftruncate(own, 0) == 0)
                {
                    const std::string who = currentHostName() + " " + std::to_string(::getpid()) + "\n";
                    if (::pwrite(own, who.data(), who.size(), 0) < 0)
                    {
                    }
                }
            }
            ~CampaignLock()
            {
                for (int fd : fds_)
                    if (fd >= 0)
                        ::close(fd);
            }
            CampaignLock(const CampaignLock &) = delete;
            CampaignLock &operator=(const CampaignLock &) = delete;

          private:
            static int take(const std::string &file, int mode, std::ostream *msg)
            {
                const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
                if (fd < 0)
                    return -1; // an unwritable log directory is refused later, with its reason
                if (::flock(fd, mode | LOCK_NB) == 0)
                    return fd;
                std::string holder;
                {
                    std::ifstream in(file);
                    std::string host;
                    long pid = 0;
                    if (in >> host >> pid)
                        holder = " (process " + std::to_string(pid) + " on " + host + ")";
                }
                if (msg)
                    *msg << "mhplan bench: another mhplan bench" << holder
                         << " is running this campaign (lock " << file << "); waiting for it to finish"
                         << std::endl;
                while (::flock(fd, mode) != 0 && errno == EINTR)
                {
                }
                if (msg)
                    *msg << "mhplan bench: the other mhplan bench has finished; going on" << std::endl;
                return fd;
            }

            int fds_[2]{-1, -1};
        };
    } // namespace

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
        const PlannerRegistry &registry = options.registry ? *options.registry : builtinPlanners();
        std::ostream *msg = options.messages;

        const std::vector<Experiment> all = enumerateExperiments(campaign, options.resolveWorld);
        const std::vector<Experiment> mine = shardExperiments(all, options.shardIndex, options.shardCount);
        if (all.empty())
            throw InputError(campaign.file + ": the campaign has no experiments (no worlds, no simulations)");
        for (const auto &p : campaign.planners)
            registry.get(p.planner); // unknown names fail here with the list of registered planners
        if (!campaign.planners.empty() && campaign.wallLimit > 0.0 &&
            campaign.wallLimit <= campaign.timeLimit)
        {
            // The file's values are checked when it is read; this catches a time limit given later (--time).
            std::ostringstream why;
            why << campaign.file << ": wall_limit (" << campaign.wallLimit
                << " s) must exceed the time limit (" << campaign.timeLimit
                << " s): every planning run would be killed";
            throw InputError(why.str());
        }
        // The planners' parameters on the first world's problem (an OMPL.app problem's planners were
        // checked on its space's flag when the campaign was read; their parameters on R^2).
        const auto firstWorld = std::find_if(all.begin(), all.end(),
                                             [](const Experiment &e)
                                             { return e.simulation == Experiment::kNoSimulation && !e.cfg; });
        if (!campaign.planners.empty() && firstWorld != all.end())
        {
            const World world = loadWorld(firstWorld->worldFile);
            validatePlanners(campaign, registry, world, experimentQuery(world, *firstWorld));
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
            if (e.simulation != Experiment::kNoSimulation)
                return campaign.simulations[e.simulation].controllers.size() * e.runs;
            std::size_t planningRuns = 0; // every planner's own count, but the skipped ones
            for (std::size_t p = 0; p < campaign.planners.size(); ++p)
                planningRuns += e.skips(p) ? 0 : mhplan::bench::runsOf(campaign, campaign.planners[p]);
            return planningRuns;
        };

        // Before deciding what to run: a bench running this campaign now is waited for.
        std::unique_ptr<CampaignLock> lock;
        if (options.run)
            lock = std::make_unique<CampaignLock>(campaign, options.shardIndex, options.shardCount, msg);

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
        // skip_inapplicable: what is not run, said once per planner.
        std::map<std::size_t, std::vector<std::string>> notRun;
        for (const auto &e : mine)
            for (const std::size_t p : e.skipped)
                notRun[p].push_back(e.name);
        if (msg)
            for (const auto &kv : notRun)
            {
                *msg << "mhplan bench: not run (cannot run on the world's state space, skip_inapplicable): "
                     << campaign.planners[kv.first].displayName << " on";
                for (const std::string &name : kv.second)
                    *msg << " " << name;
                *msg << "\n";
            }

        // Where the campaign writes, checked before any run starts.
        if (options.run && !todo.empty())
            checkWritableDirectory(campaign.logDir, "the logs to '" + campaign.logDir + "'");
        if (options.merge)
        {
            for (const std::string &file : {campaign.database, simulationDatabaseFile(campaign)})
            {
                const fs::path db = fs::absolute(file);
                checkWritableDirectory(db.parent_path(), "the database '" + file + "'");
                if (fs::is_directory(db))
                    throw InputError("the database '" + file + "' is a directory");
                checkDatabaseFile(file);
            }
        }

        if (options.run && !todo.empty())
            checkOversubscription(static_cast<unsigned int>(std::min<std::size_t>(options.jobs, todo.size())),
                                  availableCores(), options.oversubscribe, msg);

        if (options.run && !todo.empty())
        {
            machineCpuInfo(); // once for every experiment and run process (MachineInfo.cpp)
            removeStaleTemporaryFiles(campaign, todo);
            const std::string host = currentHostName();
            std::vector<std::size_t> slotRuns(slots, 0);
            for (const Experiment *e : todo)
            {
                if (e->simulation == Experiment::kNoSimulation)
                    for (std::size_t p = 0; p < campaign.planners.size(); ++p)
                        slotRuns[p] += e->skips(p) ? 0 : e->runs;
                else
                    for (std::size_t ci = 0; ci < campaign.simulations[e->simulation].controllers.size();
                         ++ci)
                        slotRuns[slotBase[e->simulation] + ci] += e->runs;
            }
            ProgressBar bar(options.progressBar && ::isatty(2), todo.size(), slotRuns, campaign.timeLimit);
            struct Active
            {
                const Experiment *experiment;
                std::unique_ptr<ChildProcess> process;
                bool ended{false};
                double workerSeconds{0.0};
                double solveSeconds{0.0};
                double cpuSeconds{0.0};
                std::size_t runsSeen{0};
            };
            std::map<pid_t, Active> active;
            std::size_t nextTodo = 0, expDone = 0, runsDone = 0;
            ::signal(SIGPIPE, SIG_IGN);
            std::string parsedFile; // the world file parsed last, its world and fingerprint
            std::unique_ptr<const World> parsedWorld;
            std::string parsedHash;
            while (nextTodo < todo.size() || !active.empty())
            {
                while (nextTodo < todo.size() && active.size() < options.jobs)
                {
                    const Experiment *e = todo[nextTodo++];
                    if (e->simulation == Experiment::kNoSimulation && !e->cfg && e->worldFile != parsedFile)
                    {
                        // Parsed once here for the experiments of this world (they come in world order);
                        // a file that does not load is left to the experiment process, which says why.
                        parsedFile = e->worldFile;
                        parsedWorld.reset();
                        try
                        {
                            std::string bytes;
                            World w = loadWorld(parsedFile, &bytes);
                            parsedHash = fingerprint(bytes);
                            parsedWorld = std::make_unique<const World>(std::move(w));
                        }
                        catch (const std::exception &)
                        {
                        }
                    }
                    std::vector<int> others;
                    for (const auto &kv : active)
                        others.push_back(kv.second.process->fd());
                    auto process = std::make_unique<ChildProcess>(
                        [&](int fd)
                        {
                            int code = 0;
                            try
                            {
                                const Clock::time_point w0 = Clock::now();
                                SolveTimes solve;
                                if (e->simulation == Experiment::kNoSimulation)
                                {
                                    ExperimentSetup xs;
                                    xs.campaign = &campaign;
                                    xs.experiment = e;
                                    xs.registry = &registry;
                                    xs.parsed = parsedWorld.get();
                                    xs.parsedHash = parsedHash;
                                    prepareExperiment(xs);
                                    code = runPlanningExperiment(xs, fd, solve);
                                }
                                else
                                {
                                    SimulationSetup xs;
                                    xs.campaign = &campaign;
                                    xs.experiment = e;
                                    xs.spec = &campaign.simulations[e->simulation];
                                    xs.registry = &registry;
                                    const std::string bytes =
                                        readInputFile(e->scenarioFile, kMaxYamlBytes, "scenario file");
                                    checkInputUnchanged(*e, bytes, e->scenarioFile);
                                    xs.scenario = parseScenarioYaml(bytes, e->scenarioFile);
                                    xs.slotBase = slotBase[e->simulation];
                                    code = runSimulationExperiment(xs, fd, solve);
                                }
                                std::ostringstream done;
                                done.precision(17);
                                done << secondsSince(w0) << " " << solve.wall << " " << solve.cpu;
                                sendMessage(fd, 'e', e->index, done.str());
                            }
                            catch (const std::exception &ex)
                            {
                                std::cerr << "mhplan bench: experiment " << e->name
                                          << " failed: " << ex.what() << "\n";
                                code = 4;
                            }
                            ::close(fd);
                            std::cout.flush();
                            std::cerr.flush();
                            ::_exit(code);
                        },
                        others);
                    const pid_t pid = process->pid();
                    // For --status: which process runs the experiment (left behind if it is killed).
                    std::ofstream(runningMarker(campaign, *e), std::ios::trunc) << host << " " << pid << "\n";
                    active[pid] = Active{e, std::move(process), false, 0.0, 0.0, 0.0, 0};
                }
                std::vector<pollfd> pfds;
                std::vector<pid_t> pids;
                for (const auto &kv : active)
                {
                    if (kv.second.ended)
                        continue;
                    pfds.push_back({kv.second.process->fd(), POLLIN, 0});
                    pids.push_back(kv.first);
                }
                if (!pfds.empty())
                    ::poll(pfds.data(), pfds.size(), 200);
                for (std::size_t i = 0; i < pfds.size(); ++i)
                {
                    if (!(pfds[i].revents & (POLLIN | POLLHUP | POLLERR)))
                        continue;
                    Active &a = active[pids[i]];
                    a.ended = !a.process->read(
                        [&](const Message &m)
                        {
                            std::istringstream in(m.payload);
                            if (m.type == 'r')
                            {
                                int crashed = 0;
                                std::size_t slot = 0;
                                double seconds = 0.0;
                                in >> crashed >> slot >> seconds;
                                bar.recordRun(slot, seconds);
                                ++runsDone;
                                ++a.runsSeen;
                                ++summary.runs;
                                summary.crashes += crashed ? 1 : 0;
                            }
                            else if (m.type == 'e')
                                in >> a.workerSeconds >> a.solveSeconds >> a.cpuSeconds;
                        });
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
                    const Active &a = it->second;
                    const int status = a.process->wait();
                    ++expDone;
                    // Runs a failed process never reported still count as done for the bar.
                    const std::size_t expected = runsOf(*a.experiment);
                    runsDone += expected > a.runsSeen ? expected - a.runsSeen : 0;
                    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                                    logIsComplete(logFile(campaign, *a.experiment), a.experiment->configHash);
                    std::error_code ec;
                    fs::remove(runningMarker(campaign, *a.experiment), ec);
                    if (ok)
                    {
                        ++summary.completed;
                        summary.workerSeconds += a.workerSeconds;
                        summary.solveSeconds += a.solveSeconds;
                        summary.cpuSeconds += a.cpuSeconds;
                        fs::remove(failedMarker(campaign, *a.experiment), ec);
                    }
                    else
                    {
                        ++summary.failed;
                        const std::string why = WIFSIGNALED(status)
                                                    ? "signal " + std::to_string(WTERMSIG(status))
                                                    : "exit code " + std::to_string(WEXITSTATUS(status));
                        summary.errors.push_back("experiment " + a.experiment->name + " failed (" + why +
                                                 "); re-run the campaign to retry it");
                        std::ofstream(failedMarker(campaign, *a.experiment), std::ios::trunc)
                            << why << " on " << host << "\n";
                    }
                    if (msg && !(options.progressBar && ::isatty(2)))
                        *msg << "[" << expDone << "/" << todo.size() << "] " << a.experiment->name
                             << (ok ? " done" : " FAILED") << " (" << std::fixed << std::setprecision(1)
                             << a.workerSeconds << " s)\n"
                             << std::defaultfloat;
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
            std::vector<std::string> problems;
            summary.mergedLogs = mergeDatabase(campaign, all, options.statisticsTool, problems);
            summary.mergeSeconds = secondsSince(m0);
            summary.rejected = problems.size();
            summary.errors.insert(summary.errors.end(), problems.begin(), problems.end());
            // The database is the whole campaign's: say which experiments it lacks (a shard not run, a
            // failed experiment, a log set aside), so that a partial database is never taken for all.
            std::vector<std::string> missing;
            for (const auto &e : all)
                if (!logIsComplete(logFile(campaign, e), e.configHash))
                    missing.push_back(e.name);
            summary.missing = missing.size();
            if (!missing.empty())
            {
                std::string names;
                for (std::size_t i = 0; i < missing.size() && i < 20; ++i)
                    names += (i ? ", " : "") + missing[i];
                if (missing.size() > 20)
                    names +=
                        ", ... (" + std::to_string(missing.size() - 20) + " more; mhplan bench --status)";
                summary.errors.push_back(
                    std::to_string(missing.size()) + " of " + std::to_string(all.size()) +
                    " experiments have no complete log and are not in the database: " + names +
                    " (run the campaign, or its missing shards, again)");
            }
        }
        summary.wallSeconds = secondsSince(t0);
        return summary;
    }
} // namespace mhplan::bench
