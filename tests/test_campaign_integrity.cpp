// SPDX-License-Identifier: BSD-3-Clause
/* Issue 26: campaign data you can trust. A small iteration-bounded campaign (one world of two queries, GA
   with three iterations, two runs) is run through the mhplan program as a user runs it, and then copied, run
   twice at once, sharded, edited and truncated: the database never holds an experiment twice, never mixes two
   versions of a world, never takes a log without the side files it was written with, says which experiments
   it lacks, keeps its link, mode and hard links, and no file that is not the campaign's own is deleted. */
#include "BenchSupport.h"

#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "benchmarks/ExperimentRuns.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace mhplan;
using namespace mhplan::bench;
namespace fs = std::filesystem;

namespace
{
    const char *kWorld =
        "name: w\nbounds: [0, 10, 0, 10]\nobstacles:\n  - circle: {center: [5, 5], radius: 1}\n"
        "queries:\n  - {name: a, start: [1, 1], goal: [9, 9]}\n"
        "  - {name: b, start: [1, 9], goal: [9, 1]}\n";
    const char *kCampaign =
        "campaign: integ\ntime_limit: 5\nruns: 2\nseed: 3\nprogress_interval: 0.01\n"
        "planner_data: false\nworlds: [w.yaml]\nplanners:\n"
        "  - planner: GA\n    params: {population_size: 8, iterations: 3, max_iterations: 3}\n";

    /** A fresh directory holding the campaign (c.yaml) and its world (w.yaml). */
    fs::path campaignDir(const std::string &tag)
    {
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_integrity_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir);
        std::ofstream(dir / "w.yaml") << kWorld;
        std::ofstream(dir / "c.yaml") << kCampaign;
        return dir;
    }

    struct Result
    {
        int code;
        std::string out;
    };

    pid_t spawn(const std::vector<std::string> &args, const std::string &output)
    {
        const pid_t pid = ::fork();
        if (pid == 0)
        {
            const int fd = ::open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
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
        return pid;
    }

    std::string readAll(const fs::path &file)
    {
        std::ifstream in(file);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }

    Result finish(pid_t pid, const std::string &output)
    {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
        {
        }
        return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), readAll(output)};
    }

    /** `mhplan bench DIR/c.yaml --no-progress --database DB ARGS...` */
    Result runBench(const fs::path &dir, const std::string &db, std::vector<std::string> more = {})
    {
        std::vector<std::string> args{"bench", (dir / "c.yaml").string(), "--no-progress", "--database", db};
        args.insert(args.end(), more.begin(), more.end());
        static int calls = 0;
        const std::string output = (dir / ("out" + std::to_string(++calls) + ".txt")).string();
        return finish(spawn(args, output), output);
    }

    bool has(const std::string &text, const std::string &part)
    {
        return text.find(part) != std::string::npos;
    }
} // namespace

// Row 1: a log is identified by its experiment and content, not by where it lies.
TEST(CampaignIntegrity, ACopiedFolderOrAnotherLogDirectoryNeverDuplicatesAnExperiment)
{
    const fs::path dir = campaignDir("moved");
    const std::string db = (dir / "f.db").string();
    ASSERT_EQ(runBench(dir, db).code, 0);
    const fs::path copy = dir.parent_path() / "moved_copy";
    fs::remove_all(copy);
    fs::copy(dir, copy, fs::copy_options::recursive);
    const Result again = runBench(copy, (copy / "f.db").string());
    EXPECT_EQ(again.code, 0) << again.out;
    // Other log directory, same database: the logs there are the same logs.
    fs::copy(dir / "f.db.logs", dir / "other.logs", fs::copy_options::recursive);
    const Result other = runBench(dir, db, {"--logs", (dir / "other.logs").string()});
    EXPECT_EQ(other.code, 0) << other.out;
    for (const std::string &file : {db, (copy / "f.db").string()})
    {
        test::Sql sql(file);
        EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2) << file;
        EXPECT_EQ(sql.count("SELECT count(*) FROM runs"), 4) << file;
        EXPECT_EQ(sql.count("SELECT count(*) FROM mhplan_logs"), 2) << file;
    }
}

// Row 4: only the campaign's own temporary files of dead processes on this host are removed.
TEST(CampaignIntegrity, OnlyItsOwnTemporaryFilesAreDeleted)
{
    const fs::path dir = campaignDir("temporaries");
    const fs::path logs = dir / "f.db.logs";
    fs::create_directories(logs);
    const std::string own = temporaryFilePrefix((logs / "w-a.log").string()) + "999999";
    const std::vector<fs::path> foreign{logs / "thesis.tmp424242", logs / "w-a.log.tmp999999",
                                        logs / "w-a.paths.mhplan-tmp.othernode.999999",
                                        logs / "someone-else.log.mhplan-tmp.x.999999"};
    for (const auto &f : foreign)
        std::ofstream(f) << "not mhplan's\n";
    std::ofstream(own) << "half a log\n";
    ASSERT_EQ(runBench(dir, (dir / "f.db").string()).code, 0);
    for (const auto &f : foreign)
        EXPECT_TRUE(fs::exists(f)) << f << " was deleted";
    EXPECT_FALSE(fs::exists(own)) << "its own stale temporary file is left";
}

// Row 5: a log is merged only with the side files it was written with; a truncated one is refused and the
// experiment runs again.
TEST(CampaignIntegrity, TruncatedSideFilesAreRefusedAndTheExperimentRunsAgain)
{
    const fs::path dir = campaignDir("sidefiles");
    const std::string db = (dir / "f.db").string();
    ASSERT_EQ(runBench(dir, db, {"--no-merge"}).code, 0);
    const fs::path paths = dir / "f.db.logs" / "w-a.paths";
    std::string text = readAll(paths);
    ASSERT_GT(text.size(), 40u);
    std::ofstream(paths, std::ios::trunc) << text.substr(0, text.size() - 30); // cut inside the last path
    const Result merge = runBench(dir, db, {"--merge-only"});
    EXPECT_EQ(merge.code, 3) << merge.out;
    EXPECT_TRUE(has(merge.out, "w-a: its side files")) << merge.out;
    EXPECT_TRUE(has(merge.out, "1 of 2 experiments have no complete log")) << merge.out;
    {
        test::Sql sql(db);
        EXPECT_EQ(sql.count("SELECT count(*) FROM experiments WHERE name = 'w-a'"), 0);
    }
    const Result rerun = runBench(dir, db);
    EXPECT_EQ(rerun.code, 0) << rerun.out;
    test::Sql sql(db);
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs"), 4);
    EXPECT_EQ(sql.count("SELECT count(*) FROM paths"),
              sql.count("SELECT count(*) FROM runs WHERE path_length IS NOT NULL"));
}

// Row 8: a merge names the experiments the database lacks and fails.
TEST(CampaignIntegrity, MergeOnlyNamesTheMissingExperiments)
{
    const fs::path dir = campaignDir("missing");
    const std::string db = (dir / "f.db").string();
    ASSERT_EQ(runBench(dir, db, {"--shard", "1/2"}).code, 0);
    const Result merge = runBench(dir, db, {"--merge-only"});
    EXPECT_EQ(merge.code, 3) << merge.out;
    EXPECT_TRUE(has(merge.out, "1 of 2 experiments have no complete log and are not in the database: w-b"))
        << merge.out;
}

// Row 20: two benches on one campaign: the second waits, saying so, and runs nothing twice.
TEST(CampaignIntegrity, ConcurrentBenchesOnOneCampaignRunEachExperimentOnce)
{
    const fs::path dir = campaignDir("concurrent");
    const std::string db = (dir / "f.db").string();
    const std::vector<std::string> args{"bench", (dir / "c.yaml").string(), "--no-progress", "--database",
                                        db};
    const std::string out1 = (dir / "first.txt").string(), out2 = (dir / "second.txt").string();
    const pid_t a = spawn(args, out1);
    const pid_t b = spawn(args, out2);
    const Result ra = finish(a, out1), rb = finish(b, out2);
    EXPECT_EQ(ra.code, 0) << ra.out;
    EXPECT_EQ(rb.code, 0) << rb.out;
    const std::string both = ra.out + rb.out;
    EXPECT_TRUE(has(both, "(2 run now, 0 already complete")) << both;
    EXPECT_TRUE(has(both, "(0 run now, 2 already complete")) << both;
    EXPECT_TRUE(has(both, "is running this campaign") && has(both, "waiting for it to finish")) << both;
    test::Sql sql(db);
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2);
}

// Row 2: what a run loaded is what its fingerprint says, checked again before merging.
TEST(CampaignIntegrity, AWorldEditedWhileTheCampaignRunsIsNeverMixedIn)
{
    const fs::path dir = campaignDir("edited");
    Campaign c = loadCampaign((dir / "c.yaml").string());
    c.database = (dir / "f.db").string();
    c.logDir = (dir / "f.db.logs").string();
    const auto resolve = [](const std::string &s) { return s; };
    const std::vector<Experiment> before = enumerateExperiments(c, resolve);
    ASSERT_EQ(before.size(), 2u);
    RunOptions o = test::options();
    o.merge = false;
    o.messages = nullptr;
    ASSERT_EQ(runCampaign(c, o).completed, 2u);
    // The world changes (one circle's radius) after the experiments were enumerated.
    std::string edited = kWorld;
    edited.replace(edited.find("radius: 1}"), 10, "radius: 1.5}");
    std::ofstream(dir / "w.yaml", std::ios::trunc) << edited;
    // An experiment process started now refuses to run on it ...
    detail::ExperimentSetup xs;
    xs.campaign = &c;
    xs.experiment = &before[0];
    xs.registry = &builtinPlanners();
    try
    {
        detail::prepareExperiment(xs);
        ADD_FAILURE() << "an experiment ran on a world other than the one fingerprinted";
    }
    catch (const std::runtime_error &e)
    {
        EXPECT_TRUE(has(e.what(), "changed after the campaign started")) << e.what();
    }
    // ... and the merge takes no log of the old world while the file says otherwise.
    std::vector<std::string> problems;
    EXPECT_EQ(mergeDatabase(c, before, "/usr/bin/ompl_benchmark_statistics", problems), 0u);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_TRUE(has(problems[0], "changed since the campaign started")) << problems[0];
}

// Row 14 and row 21 (database): the merge updates the file a link names, keeps its mode and hard links; a
// file that is not a usable SQLite database is refused before any run.
TEST(CampaignIntegrity, DatabaseLinkModeAndHardLinksAreKeptAndBadDatabasesRefusedFirst)
{
    const fs::path dir = campaignDir("links");
    const fs::path real = dir / "real.db";
    ASSERT_EQ(runBench(dir, real.string(), {"--shard", "1/2"}).code, 0);
    ASSERT_EQ(runBench(dir, real.string(), {"--merge-only"}).code, 3); // w-b is missing
    ASSERT_EQ(::chmod(real.c_str(), 0600), 0);
    fs::create_hard_link(real, dir / "hard.db");
    fs::create_symlink(real, dir / "link.db");
    const Result r = runBench(dir, (dir / "link.db").string(), {"--logs", (dir / "real.db.logs").string()});
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::is_symlink(dir / "link.db"));
    struct stat st
    {
    }, hard{};
    ASSERT_EQ(::stat(real.c_str(), &st), 0);
    ASSERT_EQ(::stat((dir / "hard.db").c_str(), &hard), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    EXPECT_EQ(st.st_ino, hard.st_ino);
    EXPECT_EQ(st.st_nlink, 2u);
    EXPECT_EQ(test::Sql((dir / "hard.db").string()).count("SELECT count(*) FROM experiments"), 2);

    const fs::path text = dir / "text.db";
    std::ofstream(text) << "experiments, not SQLite\n";
    const fs::path fresh = campaignDir("bad_database");
    const Result bad = runBench(fresh, text.string());
    EXPECT_EQ(bad.code, 1) << bad.out;
    EXPECT_TRUE(has(bad.out, "is not an SQLite database")) << bad.out;
    EXPECT_FALSE(fs::exists(text.string() + ".logs/w-a.log")) << "runs before the refusal";
    // A truncated database.
    const std::string bytes = readAll(real);
    std::ofstream(dir / "cut.db", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    const Result cut = runBench(fresh, (dir / "cut.db").string());
    EXPECT_EQ(cut.code, 1) << cut.out;
    EXPECT_TRUE(has(cut.out, "is damaged")) << cut.out;
}

namespace
{
    /** `mhplan ARGS` (its stdout and stderr). */
    Result runMhplan(const fs::path &dir, const std::vector<std::string> &args)
    {
        static int calls = 0;
        const std::string output = (dir / ("cli" + std::to_string(++calls) + ".txt")).string();
        return finish(spawn(args, output), output);
    }

    std::string lineOf(const std::string &text, const std::string &head)
    {
        const std::size_t at = text.find(head);
        return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
    }
} // namespace

// Row 17: start == goal is one problem for every command: a benchmark run and `mhplan plan` with its seed
// agree on the outcome (they did not: RRT* skips samples equal to their nearest tree state only when an
// intermediate-solution callback is registered, which only the benchmark did).
TEST(CampaignIntegrity, StartEqualToGoalIsOneProblemInBenchAndPlan)
{
    const fs::path dir = campaignDir("start_is_goal");
    std::ofstream(dir / "w.yaml", std::ios::trunc)
        << "name: w\nbounds: [0, 10, 0, 10]\nobstacles:\n  - circle: {center: [5, 5], radius: 1}\n"
           "queries:\n  - {name: a, start: [2, 2], goal: [2, 2]}\n";
    std::ofstream(dir / "c.yaml", std::ios::trunc)
        << "campaign: sg\ntime_limit: 0.05\nruns: 2\nseed: 5\nplanner_data: false\nworlds: [w.yaml]\n"
           "planners: [RRTstar]\n";
    const std::string db = (dir / "f.db").string();
    ASSERT_EQ(runBench(dir, db).code, 0);
    const auto runs = test::Sql(db).rows("SELECT run_seed, status FROM runs ORDER BY run_index");
    ASSERT_EQ(runs.size(), 2u);
    const std::map<std::string, std::string> statusName{{"5", "Approximate solution"},
                                                        {"6", "Exact solution"}};
    for (const auto &run : runs)
    {
        const Result plan = runMhplan(dir, {"plan", (dir / "w.yaml").string(), "--planner", "RRTstar",
                                            "--time", "0.05", "--seed", run[0]});
        ASSERT_TRUE(statusName.count(run[1])) << run[1];
        EXPECT_EQ(lineOf(plan.out, "status:"), "status:    " + statusName.at(run[1])) << plan.out;
    }
}

// Row 22: a population planner that cannot reach the goal reports a collision-free approximate path (the
// best valid prefix), as OMPL's planners do, never one through walls.
TEST(CampaignIntegrity, ApproximateSolutionsOfPopulationPlannersAreCollisionFree)
{
    const fs::path dir = campaignDir("enclosed");
    // The goal is walled in: no planner reaches it.
    std::ofstream(dir / "e.yaml") << "name: enclosed\nbounds: [0, 10, 0, 10]\nobstacles:\n"
                                     "  - polygon: {points: [[6, 6], [9, 6], [9, 6.5], [6, 6.5]]}\n"
                                     "  - polygon: {points: [[6, 8.5], [9, 8.5], [9, 9], [6, 9]]}\n"
                                     "  - polygon: {points: [[6, 6.4], [6.5, 6.4], [6.5, 8.6], [6, 8.6]]}\n"
                                     "  - polygon: {points: [[8.5, 6.4], [9, 6.4], [9, 8.6], [8.5, 8.6]]}\n"
                                     "queries:\n  - {name: q, start: [1, 1], goal: [7.5, 7.5]}\n";
    for (const std::string planner : {"GA", "SMA", "MGO", "LRSMA"})
    {
        const Result plan = runMhplan(dir, {"plan", (dir / "e.yaml").string(), "--planner", planner, "--seed",
                                            "3", "--set", "population_size=10", "--set", "max_iterations=5"});
        EXPECT_EQ(lineOf(plan.out, "status:"), "status:    Approximate solution") << planner << "\n"
                                                                                  << plan.out;
        EXPECT_TRUE(has(lineOf(plan.out, "valid:"), "valid:     yes")) << planner << "\n" << plan.out;
    }
}
