// SPDX-License-Identifier: BSD-3-Clause
/* Faults and shards of a campaign, through the mhplan program as a user runs it. A small iteration-bounded
   campaign (tests/data/bench_faults.yaml: five planning and two simulation experiments) is run once
   uninterrupted; then `mhplan bench` is killed with SIGKILL (its whole process group) at ten moments, and
   resumed each time: five drawn from a fixed seed while the experiments run, five while it merges (timed by
   the merge's work file, DATABASE.merging: one kill as the planning database's merge begins, one as the
   simulation database's begins, three at random moments after the first begins). After every kill both
   databases on disk are whole (every experiment once, recorded in mhplan_logs, with exactly its runs of the
   uninterrupted run); at the end they hold exactly the runs of the uninterrupted run: the same experiments
   once each, the same runs with the same seeds and costs. Shards:
   uneven sizes, k > 2, disjoint, covering every experiment, planning and simulation mixed; shards run at the
   same time into one log directory and merged at the end give the uninterrupted database again. */
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"

#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace mhplan;
using namespace mhplan::bench;
namespace fs = std::filesystem;

namespace
{
    const std::string kCampaign = std::string(MHPLAN_TEST_DATA_DIR) + "/bench_faults.yaml";

    fs::path freshDir(const std::string &tag)
    {
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_faults_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir);
        return dir;
    }

    /** Start `mhplan ARGS` in a process group of its own, its output to \e output. */
    pid_t spawnMhplan(const std::vector<std::string> &args, const std::string &output)
    {
        const pid_t pid = ::fork();
        if (pid == 0)
        {
            ::setpgid(0, 0);
            const int fd = ::open(output.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
            if (fd >= 0)
            {
                ::dup2(fd, 1);
                ::dup2(fd, 2);
                ::close(fd);
            }
            std::vector<char *> argv{const_cast<char *>(MHPLAN_BINARY)};
            for (const auto &a : args)
                argv.push_back(const_cast<char *>(a.c_str()));
            argv.push_back(nullptr);
            ::execv(argv[0], argv.data());
            ::_exit(127);
        }
        if (pid > 0)
            ::setpgid(pid, pid); // also here: the group exists before the parent may kill it
        return pid;
    }

    int exitCode(int status)
    {
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    int waitFor(pid_t pid)
    {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
        {
        }
        return exitCode(status);
    }

    std::string readFile(const std::string &file)
    {
        std::ifstream in(file);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }

    /** The experiment logs in \e dir (a log appears, under its name, only when complete). */
    std::size_t completeLogs(const std::string &dir)
    {
        std::error_code ec;
        std::size_t n = 0;
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
            n += it->path().extension() == ".log" ? 1 : 0;
        return n;
    }

    std::vector<std::string> benchArgs(const fs::path &dir, std::vector<std::string> more = {})
    {
        std::vector<std::string> args{"bench", kCampaign, "--no-progress", "--database",
                                      (dir / "f.db").string()};
        args.insert(args.end(), more.begin(), more.end());
        return args;
    }

    /** Rows of \e sql as text ("NULL" for NULL), from a read-only connection. */
    std::vector<std::vector<std::string>> query(const std::string &db, const std::string &sql)
    {
        std::vector<std::vector<std::string>> rows;
        sqlite3 *h = nullptr;
        if (sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
        {
            ADD_FAILURE() << "cannot open " << db;
            sqlite3_close(h);
            return rows;
        }
        char *err = nullptr;
        const auto collect = [](void *out, int n, char **values, char **) -> int
        {
            std::vector<std::string> row;
            for (int i = 0; i < n; ++i)
                row.emplace_back(values[i] ? values[i] : "NULL");
            static_cast<std::vector<std::vector<std::string>> *>(out)->push_back(row);
            return 0;
        };
        if (sqlite3_exec(h, sql.c_str(), collect, &rows, &err) != SQLITE_OK)
            ADD_FAILURE() << db << ": " << (err ? err : "?") << " in " << sql;
        sqlite3_free(err);
        sqlite3_close(h);
        return rows;
    }

    long long scalar(const std::string &db, const std::string &sql)
    {
        const auto rows = query(db, sql);
        return rows.empty() ? -1 : std::atoll(rows[0][0].c_str());
    }

    /** What a database holds, as compared here: the experiment names (with repeats), and per run
        (experiment, planner, run index) its seed, status and results (costs of planning runs, makespan and
        flowtime of simulation runs). Times are wall-clock and left out. */
    struct Contents
    {
        std::multiset<std::string> experiments;
        std::map<std::string, std::string> runs;
        long long runRows{0};
        long long logs{0};
        long long paths{0};
    };

    /** The campaign's simulation database beside \e db (Campaign.h: simulationDatabaseFile). */
    std::string simulationDb(const std::string &db)
    {
        const fs::path p(db);
        return (p.parent_path() / (p.stem().string() + "-sim" + p.extension().string())).string();
    }

    bool hasTable(const std::string &db, const std::string &table)
    {
        return scalar(db, "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = '" + table +
                              "'") == 1;
    }

    /** What one database file holds (\e planning: the planning database, else the simulation one); nothing
        when it does not exist. */
    void addContents(const std::string &file, bool planning, Contents &c)
    {
        if (!fs::exists(file))
            return;
        if (hasTable(file, "mhplan_logs"))
            c.logs += scalar(file, "SELECT count(*) FROM mhplan_logs");
        if (!hasTable(file, "experiments")) // a merge that had nothing to append
            return;
        for (const auto &r : query(file, "SELECT name FROM experiments"))
            c.experiments.insert(r[0]);
        const std::string results =
            planning ? "runs.best_cost, runs.path_length" : "runs.makespan, runs.flowtime";
        for (const auto &r : query(file, "SELECT experiments.name, plannerConfigs.name, runs.run_index, "
                                         "runs.run_seed, runs.status, " +
                                             results +
                                             " FROM runs "
                                             "JOIN experiments ON runs.experimentid = experiments.id "
                                             "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id"))
            c.runs[r[0] + "|" + r[1] + "|" + r[2]] = "seed " + r[3] + " status " + r[4] +
                                                     (planning ? " cost " : " makespan ") + r[5] +
                                                     (planning ? " length " : " flowtime ") + r[6];
        c.runRows += scalar(file, "SELECT count(*) FROM runs");
        c.paths += scalar(file, "SELECT count(*) FROM paths");
    }

    /** What the campaign's two databases hold together: planning runs in \e db, simulation runs in its
        simulation database. */
    Contents contents(const std::string &db)
    {
        Contents c;
        addContents(db, true, c);
        addContents(simulationDb(db), false, c);
        return c;
    }

    /** A database of the campaign, as a kill may leave it, is whole: every experiment in it once and
        recorded in mhplan_logs, each with exactly its runs of the uninterrupted run \e reference (none half
        appended, none missing, the same seeds and results). */
    void expectWhole(const std::string &file, bool planning, const Contents &reference)
    {
        Contents got;
        addContents(file, planning, got);
        const std::set<std::string> names(got.experiments.begin(), got.experiments.end());
        EXPECT_EQ(names.size(), got.experiments.size()) << file << ": an experiment appended twice";
        EXPECT_EQ(got.logs, static_cast<long long>(got.experiments.size())) << file;
        long long expected = 0;
        for (const auto &kv : reference.runs)
            expected += names.count(kv.first.substr(0, kv.first.find('|'))) ? 1 : 0;
        EXPECT_EQ(got.runRows, expected) << file;
        for (const auto &kv : got.runs)
        {
            const auto it = reference.runs.find(kv.first);
            if (it == reference.runs.end())
                ADD_FAILURE() << file << ": a run the uninterrupted run does not have: " << kv.first;
            else
                EXPECT_EQ(kv.second, it->second) << file << ": " << kv.first;
        }
    }

    /** The work file of a merge into \e db (DATABASE.merging, benchmarks/README.md "The database": a copy
        of DATABASE renamed over it once complete, removed when there was nothing to append), as it was when
        constructed: fresh() says whether a merge made or rewrote it since, and it still exists. A kill
        leaves the file behind; the next merge reuses it (same inode, truncated: a new modification time). */
    class MergeWorkFile
    {
      public:
        explicit MergeWorkFile(std::string db) : file_(std::move(db) + ".merging"), before_(stamp()) {}
        bool fresh() const
        {
            const Stamp now = stamp();
            return now.exists && !(now == before_);
        }

      private:
        struct Stamp
        {
            bool exists{false};
            ino_t inode{0};
            long long seconds{0}, nanoseconds{0};
            bool operator==(const Stamp &o) const
            {
                return exists == o.exists && inode == o.inode && seconds == o.seconds &&
                       nanoseconds == o.nanoseconds;
            }
        };
        Stamp stamp() const
        {
            struct stat st
            {
            };
            if (::stat(file_.c_str(), &st) != 0)
                return {};
            return {true, st.st_ino, static_cast<long long>(st.st_mtim.tv_sec),
                    static_cast<long long>(st.st_mtim.tv_nsec)};
        }
        std::string file_;
        Stamp before_;
    };

    void expectSameContents(const Contents &got, const Contents &want)
    {
        EXPECT_EQ(got.experiments, want.experiments);
        EXPECT_EQ(got.runRows, want.runRows);
        EXPECT_EQ(got.logs, want.logs);
        EXPECT_EQ(got.paths, want.paths);
        EXPECT_EQ(got.runs.size(), want.runs.size());
        for (const auto &kv : want.runs)
        {
            const auto it = got.runs.find(kv.first);
            if (it == got.runs.end())
                ADD_FAILURE() << "run missing: " << kv.first;
            else
                EXPECT_EQ(it->second, kv.second) << kv.first;
        }
    }

    class CampaignFaults : public ::testing::Test
    {
      protected:
        /** The uninterrupted run, once per test process, made by the first test's SetUp: googletest reports
            every test of a suite whose SetUpTestSuite fails as skipped (CTest then shows "Skipped"), a
            failure in SetUp fails its test. */
        static void runReference()
        {
            referenceTried_ = true;
            const fs::path dir = freshDir("reference");
            const std::string out = (dir / "out.txt").string();
            const auto t0 = std::chrono::steady_clock::now();
            const int rc = waitFor(spawnMhplan(benchArgs(dir, {"--jobs", "2"}), out));
            wallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            ASSERT_EQ(rc, 0) << readFile(out);
            // "wall time: W s (solve S s, experiment processes P s, database M s)"
            const std::string text = readFile(out);
            // Each run's seed takes effect without OMPL's complaint that generation had already started.
            EXPECT_EQ(text.find("Random number generation already started"), std::string::npos) << text;
            const std::size_t at = text.find(", database ");
            ASSERT_NE(at, std::string::npos) << text;
            mergeSeconds_ = std::atof(text.c_str() + at + 11);
            reference_ = new Contents(contents((dir / "f.db").string()));
        }
        static void TearDownTestSuite()
        {
            delete reference_;
            reference_ = nullptr;
            fs::remove_all(fs::temp_directory_path() / ("mhplan_test_faults_" + std::to_string(::getpid())));
        }
        void SetUp() override
        {
            if (!referenceTried_)
                runReference();
            ASSERT_NE(reference_, nullptr) << "the reference campaign failed (reported by the first test)";
            // The reference itself: 5 planning experiments x 2 planners x 2 runs, 2 + 1 simulation runs.
            ASSERT_EQ(reference_->experiments.size(), 7u);
            ASSERT_EQ(reference_->runRows, 5 * 2 * 2 + 2 + 1);
            ASSERT_EQ(reference_->logs, 7);
        }
        static Contents *reference_;
        static bool referenceTried_;
        /** The uninterrupted run's wall time and the part of it spent merging. */
        static double wallSeconds_, mergeSeconds_;
    };
    Contents *CampaignFaults::reference_ = nullptr;
    bool CampaignFaults::referenceTried_ = false;
    double CampaignFaults::wallSeconds_ = 0.0;
    double CampaignFaults::mergeSeconds_ = 0.0;
} // namespace

TEST_F(CampaignFaults, KilledAtRandomMomentsAndResumedHoldsExactlyTheUninterruptedRuns)
{
    const fs::path dir = freshDir("killed");
    const std::string db = (dir / "f.db").string(), sim = simulationDb(db), out = (dir / "out.txt").string();
    ompl::RNG rng(20261201);
    int killed = 0, killedMergingPlanning = 0, killedMergingSimulations = 0;
    for (int attempt = 0; attempt < 10; ++attempt)
    {
        // When to kill. Attempts 0-4: at a moment drawn after the start, while the experiments run (the
        // uninterrupted run spent wall - merge seconds on them, half of it per attempt), or as soon as a
        // merge begins, whichever comes first: no attempt before 5 completes the campaign. 5: as soon as the
        // planning database's merge begins; 6: as soon as the simulation database's begins (after the
        // planning one's completed); 7-9: at a moment drawn within the uninterrupted run's merge time after a
        // merge began, so that kills land inside ompl_benchmark_statistics and the recording after it.
        const MergeWorkFile planningMerge(db), simulationMerge(sim);
        const bool inMerge = attempt >= 5;
        const double delay =
            attempt < 5
                ? rng.uniformReal(0.0, std::min(0.5, 0.5 * std::max(0.1, wallSeconds_ - mergeSeconds_)))
            : attempt < 7 ? 0.0
                          : rng.uniformReal(0.0, 0.8 * mergeSeconds_);
        const auto mergeBegan = [&]()
        {
            if (attempt == 5)
                return planningMerge.fresh();
            if (attempt == 6)
                return simulationMerge.fresh();
            return planningMerge.fresh() || simulationMerge.fresh();
        };
        const pid_t pid = spawnMhplan(benchArgs(dir, {"--jobs", "2"}), out);
        ASSERT_GT(pid, 0);
        auto t0 = std::chrono::steady_clock::now();
        bool exited = false, clockRuns = !inMerge;
        int status = 0;
        while (!exited)
        {
            if (!inMerge && mergeBegan())
                break;
            if (!clockRuns && mergeBegan())
            {
                clockRuns = true;
                t0 = std::chrono::steady_clock::now();
            }
            if (clockRuns &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() >= delay)
                break;
            exited = ::waitpid(pid, &status, WNOHANG) == pid;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        if (!exited)
        {
            ::kill(-pid, SIGKILL);
            EXPECT_EQ(waitFor(pid), 128 + SIGKILL);
            ++killed;
            // The process group is dead: a work file this attempt made that is still there was a merge in
            // flight (a finished merge renames its work file, one with nothing to append removes it).
            killedMergingPlanning += planningMerge.fresh() ? 1 : 0;
            killedMergingSimulations += simulationMerge.fresh() ? 1 : 0;
        }
        else
            EXPECT_EQ(exitCode(status), 0) << readFile(out);
        // Whatever the moment, both databases on disk are whole.
        SCOPED_TRACE("after attempt " + std::to_string(attempt));
        expectWhole(db, true, *reference_);
        expectWhole(sim, false, *reference_);
    }
    std::cout << "killed " << killed
              << " of 10 attempts: " << killed - killedMergingPlanning - killedMergingSimulations
              << " while running experiments, " << killedMergingPlanning
              << " while merging the planning database, " << killedMergingSimulations
              << " while merging the simulation database\n";
    EXPECT_GE(killed, 7); // attempts 0-6 are killed before the campaign ends
    EXPECT_GE(killedMergingPlanning, 1);
    EXPECT_GE(killedMergingSimulations, 1);

    // Resumed to the end; a further resume finds nothing to do.
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(dir, {"--jobs", "2"}), out)), 0) << readFile(out);
    fs::remove(out);
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(dir), out)), 0) << readFile(out);
    EXPECT_NE(readFile(out).find("experiments: 7 (0 run now, 7 already complete, 0 failed)"),
              std::string::npos)
        << readFile(out);
    EXPECT_NE(readFile(out).find("(0 log(s) appended)"), std::string::npos) << readFile(out);
    EXPECT_FALSE(fs::exists(db + ".merging"));
    expectSameContents(contents(db), *reference_);
}

TEST_F(CampaignFaults, UnevenShardsAreDisjointCoverEverythingAndMergeToTheUninterruptedRun)
{
    const Campaign campaign = loadCampaign(kCampaign);
    const auto resolve = [](const std::string &name)
    { return fs::exists(name) ? name : std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml"; };
    const std::vector<Experiment> all = enumerateExperiments(campaign, resolve);
    ASSERT_EQ(all.size(), 7u);
    for (unsigned int k : {2u, 3u, 4u, 5u, 7u, 9u})
    {
        std::map<std::size_t, unsigned int> owner;
        std::size_t smallest = all.size(), largest = 0;
        for (unsigned int i = 1; i <= k; ++i)
        {
            const auto part = shardExperiments(all, i, k);
            smallest = std::min(smallest, part.size());
            largest = std::max(largest, part.size());
            for (const auto &e : part)
                EXPECT_TRUE(owner.emplace(e.index, i).second)
                    << e.name << " in shards " << owner[e.index] << " and " << i << " of " << k;
        }
        EXPECT_EQ(owner.size(), all.size()) << "shards of " << k << " miss experiments";
        EXPECT_LE(largest - smallest, 1u) << k << " shards";
    }
    // Three shards of seven: 3, 2 and 2 experiments, planning and simulation experiments mixed.
    std::set<int> kinds;
    for (unsigned int i = 1; i <= 3; ++i)
        for (const auto &e : shardExperiments(all, i, 3))
            kinds.insert((e.simulation == Experiment::kNoSimulation ? 0 : 10) + static_cast<int>(i));
    EXPECT_EQ(kinds.size(), 5u) << "expected shards with planning experiments and shards with simulations";

    // The three shards at the same time into one log directory (a shard writes logs, no database), then the
    // merge.
    const fs::path dir = freshDir("shards");
    const std::string db = (dir / "f.db").string();
    std::vector<pid_t> pids;
    for (unsigned int i = 1; i <= 3; ++i)
        pids.push_back(spawnMhplan(benchArgs(dir, {"--shard", std::to_string(i) + "/3"}),
                                   (dir / ("out" + std::to_string(i) + ".txt")).string()));
    for (unsigned int i = 1; i <= 3; ++i)
        EXPECT_EQ(waitFor(pids[i - 1]), 0) << readFile((dir / ("out" + std::to_string(i) + ".txt")).string());
    EXPECT_FALSE(fs::exists(db));
    EXPECT_EQ(completeLogs(db + ".logs"), 7u);
    const std::string out = (dir / "merge.txt").string();
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(dir, {"--merge-only"}), out)), 0) << readFile(out);
    EXPECT_NE(readFile(out).find("(7 log(s) appended)"), std::string::npos) << readFile(out);
    expectSameContents(contents(db), *reference_);
}

TEST(BenchCli, UnwritableLogOrDatabaseDirectoryIsRefusedBeforeAnyRun)
{
    const fs::path dir = freshDir("unwritable");
    for (const auto &[args, path] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--database", "/proc/x.db", "--logs", (dir / "logs").string()}, "/proc/x.db"},
             {{"--database", (dir / "ok.db").string(), "--logs", "/proc/logs"}, "/proc/logs"},
             {{"--database", "/proc/x.db", "--merge-only"}, "/proc/x.db"}})
    {
        std::vector<std::string> all{"bench", kCampaign, "--no-progress"};
        all.insert(all.end(), args.begin(), args.end());
        const std::string out = (dir / "out.txt").string();
        fs::remove(out);
        EXPECT_EQ(waitFor(spawnMhplan(all, out)), 1) << readFile(out);
        const std::string text = readFile(out);
        EXPECT_NE(text.find("'" + path + "'"), std::string::npos) << text;
        EXPECT_EQ(text.find("internal error"), std::string::npos) << text;
        EXPECT_EQ(text.find(" done ("), std::string::npos) << "a run started: " << text;
    }
    EXPECT_FALSE(fs::exists(dir / "logs" / "bfo_case1-default.log"));
    EXPECT_FALSE(fs::exists(dir / "ok.db"));
    fs::remove_all(dir.parent_path());
}

// Issue 19: a log directory that fills up (a 32 KiB tmpfs: room for a few of the seven experiments' files)
// fails the experiments that do not fit, each with its file and "No space left on device" (exit 3, as for
// any failed experiment; the database holds the complete ones), and leaves no temporary file behind. Once
// there is room again (the tmpfs remounted larger), the re-run campaign takes the logs it kept as done and
// runs the rest: its database is the uninterrupted run's, nothing appended twice. Needs root (mount);
// skipped with the reason otherwise.
TEST_F(CampaignFaults, FullLogDirectoryFailsClearlyAndResumesToTheUninterruptedRun)
{
    const fs::path dir = freshDir("full");
    const fs::path logs = dir / "logs";
    fs::create_directories(logs);
    if (::geteuid() != 0)
        GTEST_SKIP() << "needs root to mount a small tmpfs";
    if (::mount("tmpfs", logs.c_str(), "tmpfs", 0, "size=32k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs on " << logs << ": " << std::strerror(errno);
    struct Unmount
    {
        std::string path;
        ~Unmount() { ::umount(path.c_str()); }
    } unmount{logs.string()};
    const std::string out = (dir / "out.txt").string();
    const int rc = waitFor(spawnMhplan(benchArgs(dir, {"--jobs", "2", "--logs", logs.string()}), out));
    const std::string text = readFile(out);
    EXPECT_EQ(rc, 3) << text;
    EXPECT_NE(text.find("cannot write '" + logs.string() + "/"), std::string::npos) << text;
    EXPECT_NE(text.find("No space left on device"), std::string::npos) << text;
    EXPECT_NE(text.find("re-run the campaign to retry it"), std::string::npos) << text;
    EXPECT_EQ(text.find("internal error"), std::string::npos) << text;
    EXPECT_LT(completeLogs(logs.string()), 7u) << "the tmpfs held every log: the test tests nothing";
    for (const auto &entry : fs::directory_iterator(logs))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
            << "temporary file left behind: " << entry.path();

    ASSERT_EQ(::mount("tmpfs", logs.c_str(), "tmpfs", MS_REMOUNT, "size=4m"), 0) << std::strerror(errno);
    const int resumed = waitFor(spawnMhplan(benchArgs(dir, {"--jobs", "2", "--logs", logs.string()}), out));
    ASSERT_EQ(resumed, 0) << readFile(out);
    expectSameContents(contents((dir / "f.db").string()), *reference_);
}

// Issue 26: the same "exactly the uninterrupted run" check after what is not a kill: two benches on the
// campaign at once while one of its world files is edited and restored, the finished folder copied elsewhere
// and run again there, and a side file truncated before the merge.
TEST_F(CampaignFaults, ConcurrentBenchesEditedWorldsMovedFoldersAndTruncatedSideFilesGiveTheUninterruptedRun)
{
    const fs::path dir = freshDir("integrity");
    // The campaign's shipped worlds from a copy that the test may edit.
    const fs::path environments = dir / "environments";
    fs::copy(MHPLAN_ENVIRONMENTS_DIR, environments, fs::copy_options::recursive);
    const fs::path world = environments / "bfo_case1.yaml";
    const std::string original = readFile(world.string());
    ::setenv("MHPLAN_ENVIRONMENTS", environments.c_str(), 1);
    const std::string db = (dir / "f.db").string();
    const std::string out1 = (dir / "out1.txt").string(), out2 = (dir / "out2.txt").string();
    const pid_t first = spawnMhplan(benchArgs(dir), out1);
    const pid_t second = spawnMhplan(benchArgs(dir), out2);
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    std::string edited = original;
    edited.replace(edited.find("radius: 0.7"), 11, "radius: 0.9");
    std::ofstream(world, std::ios::trunc) << edited; // one circle grows while the campaign runs ...
    const int rc1 = waitFor(first), rc2 = waitFor(second);
    std::ofstream(world, std::ios::trunc) << original; // ... and is restored
    EXPECT_TRUE(rc1 == 0 || rc1 == 3) << readFile(out1);
    EXPECT_TRUE(rc2 == 0 || rc2 == 3) << readFile(out2);
    EXPECT_NE((readFile(out1) + readFile(out2)).find("waiting for it to finish"), std::string::npos)
        << readFile(out1) << readFile(out2);
    const std::string out3 = (dir / "out3.txt").string();
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(dir), out3)), 0) << readFile(out3);
    expectSameContents(contents(db), *reference_);

    // The finished folder elsewhere: nothing runs, nothing is merged twice.
    const fs::path moved = freshDir("integrity_moved");
    for (const char *name : {"f.db", "f-sim.db", "f.db.logs"})
        fs::copy(dir / name, moved / name, fs::copy_options::recursive);
    const std::string out4 = (moved / "out4.txt").string();
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(moved), out4)), 0) << readFile(out4);
    EXPECT_NE(readFile(out4).find("experiments: 7 (0 run now, 7 already complete"), std::string::npos)
        << readFile(out4);
    expectSameContents(contents((moved / "f.db").string()), *reference_);

    // A truncated side file: its log is refused, the experiment runs again.
    const fs::path logs = moved / "f.db.logs";
    fs::remove(moved / "f.db");
    fs::remove(moved / "f-sim.db");
    const fs::path paths = logs / "bfo_case2-default.paths";
    const std::string text = readFile(paths.string());
    ASSERT_GT(text.size(), 20u);
    std::ofstream(paths, std::ios::trunc) << text.substr(0, text.size() / 2);
    const std::string out5 = (moved / "out5.txt").string();
    EXPECT_EQ(waitFor(spawnMhplan(benchArgs(moved, {"--merge-only"}), out5)), 3) << readFile(out5);
    EXPECT_NE(readFile(out5).find("bfo_case2-default: its side files"), std::string::npos) << readFile(out5);
    const std::string out6 = (moved / "out6.txt").string();
    ASSERT_EQ(waitFor(spawnMhplan(benchArgs(moved), out6)), 0) << readFile(out6);
    ::unsetenv("MHPLAN_ENVIRONMENTS");
    expectSameContents(contents((moved / "f.db").string()), *reference_);
}
