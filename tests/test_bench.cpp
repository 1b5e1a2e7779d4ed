// SPDX-License-Identifier: BSD-3-Clause
/* Benchmark campaigns end to end: a tiny campaign (two worlds, GA twice under distinct names, RRT*, and two
   deliberately crashing planners) is run, merged into an OMPL database and checked for its experiments,
   planners, runs and columns; the optimality gap is recomputed from the stored values; sharded runs merge
   to the unsharded row count with identical results; a re-run resumes (skips finished experiments).
   Simulation experiments are in test_bench_sim.cpp. */
#include "mhplan/bench/Campaign.h"
#include "mhplan/bench/CampaignRunner.h"
#include "CliSupport.h"
#include "BenchSupport.h"
#include "mhplan/sim/Controllers.h"
#include "mhplan/planners/lattice/ThetaStar.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/sim/ScenarioIO.h"
#include "mhplan/sim/Simulation.h"
#include "mhplan/base/World.h"
#include "mhplan/bench/Improvements.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

using namespace mhplan;
using namespace mhplan::bench;
namespace ob = ompl::base;
namespace fs = std::filesystem;

using namespace mhplan::test;

namespace
{
    /** The tiny campaign with its database under a fresh directory \e tag. */
    Campaign tinyCampaign(const std::string &tag)
    {
        Campaign c = loadCampaign(std::string(MHPLAN_TEST_DATA_DIR) + "/bench_tiny.yaml");
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_bench_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir);
        c.database = (dir / "tiny.db").string();
        c.logDir = (dir / "logs").string();
        // The GA runs are compared (solved, lengths across shards): they must end by their iteration bound
        // (5 and 3), never by the clock. bench_tiny.yaml's 0.05 s did not always fit 5 GA iterations
        // (measured up to 15 ms in a release build on a loaded machine, 3-5 times more with the
        // sanitizers); 0.5 s is RRT*'s budget and the GA's safety net, and gaIterationsShort() checks that
        // the net never caught a GA run.
        c.timeLimit = 0.5;
        c.planners.push_back({"CrashAbort", "CrashTest", {{"mode", "abort"}}, {}});
        c.planners.push_back({"CrashThrow", "CrashTest", {{"mode", "throw"}}, {}});
        return c;
    }

    /** path_length of every run keyed by (experiment, planner, run index). */
    std::map<std::string, std::string> lengthsByRun(const Sql &sql)
    {
        std::map<std::string, std::string> out;
        for (const auto &r :
             sql.rows("SELECT experiments.name, plannerConfigs.name, runs.run_index, "
                      "runs.path_length FROM runs JOIN experiments ON runs.experimentid = "
                      "experiments.id JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id"))
            out[r[0] + "|" + r[1] + "|" + r[2]] = r[3];
        return out;
    }

    constexpr int kRunsPerExperiment = 5 * 3; // planners x runs

    /** GA runs of a tiny campaign's database that stopped before their max_iterations (5 for GA, 3 for
        GA_small): the time limit, not the iteration bound, ended them. */
    long long gaIterationsShort(const Sql &sql)
    {
        return sql.count(
            "SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
            "WHERE (plannerConfigs.name = 'geometric_GA' AND runs.iterations != 5) OR "
            "(plannerConfigs.name = 'geometric_GA_small' AND runs.iterations != 3)");
    }
} // namespace

TEST(Campaign, ParsesAndRefusesBadInput)
{
    const Campaign c = loadCampaign(std::string(MHPLAN_TEST_DATA_DIR) + "/bench_tiny.yaml");
    EXPECT_EQ(c.name, "tiny");
    EXPECT_EQ(c.runs, 3u);
    EXPECT_DOUBLE_EQ(c.timeLimit, 0.05);
    ASSERT_EQ(c.planners.size(), 3u);
    EXPECT_EQ(c.planners[1].displayName, "GA");
    EXPECT_EQ(c.planners[2].displayName, "GA_small");
    EXPECT_EQ(c.planners[2].planner, "GA");
    EXPECT_EQ(c.planners[2].params.at("max_iterations"), "3");
    EXPECT_EQ(c.logDir, "tiny.db.logs");

    const auto error = [](const std::string &text)
    {
        try
        {
            parseCampaign(text, "bad.yaml");
        }
        catch (const InputError &e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error("worlds: [a]\nplanners: [RRT]\nrunz: 3\n").find("unknown key 'runz'"), std::string::npos);
    EXPECT_NE(error("worlds: [a]\nplanners: [GA, GA]\n").find("duplicate planner name 'GA'"),
              std::string::npos);
    EXPECT_NE(error("worlds: [a]\nplanners: [RRT]\nruns: 0\n").find("field 'runs'"), std::string::npos);
    EXPECT_NE(error("worlds: [a]\nplanners: [RRT]\ntime_limit: x\n").find("field 'time_limit'"),
              std::string::npos);
    EXPECT_NE(error("planners: [RRT]\n").find("field 'worlds': missing"), std::string::npos);
    EXPECT_NE(
        error("worlds: [a]\nplanners:\n  - {planner: RRT, progress: best}\n").find("planners[0].progress"),
        std::string::npos);
    const Campaign p =
        parseCampaign("worlds: [a]\nplanners:\n  - {planner: BITstar, progress: [best cost]}\n", "p.yaml");
    EXPECT_EQ(p.planners[0].progress, std::vector<std::string>{"best cost"});
    EXPECT_NE(error("worlds: [a]\nplanners:\n  - {planner: RRT, name: 'a b'}\n").find("blanks"),
              std::string::npos);
}

TEST(Campaign, SeedsAndShardsAreDeterministic)
{
    EXPECT_EQ(deriveSeed(1, "bfo_case1-default", 0), deriveSeed(1, "bfo_case1-default", 0));
    EXPECT_NE(deriveSeed(1, "bfo_case1-default", 0), deriveSeed(2, "bfo_case1-default", 0));
    EXPECT_NE(deriveSeed(1, "bfo_case1-default", 0), deriveSeed(1, "bfo_case1-default", 1));
    EXPECT_NE(deriveSeed(1, "GA", 0), 0u);
    Campaign c = tinyCampaign("enumerate");
    const auto all = enumerateExperiments(c, resolveShipped);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].name, "bfo_case1-default");
    EXPECT_EQ(all[1].name, "lrsma_scenario1-default");
    const auto a = shardExperiments(all, 1, 2), b = shardExperiments(all, 2, 2);
    ASSERT_EQ(a.size() + b.size(), all.size());
    EXPECT_EQ(a[0].name, all[0].name);
    EXPECT_EQ(b[0].name, all[1].name);
    EXPECT_THROW(shardExperiments(all, 0, 2), InputError);
    EXPECT_THROW(shardExperiments(all, 3, 2), InputError);
    // The fingerprint follows the configuration.
    Campaign d = c;
    d.runs = 4;
    EXPECT_NE(enumerateExperiments(d, resolveShipped)[0].configHash, all[0].configHash);
}

TEST(Campaign, RefusesUnknownPlannersAndParametersBeforeRunning)
{
    Campaign c = tinyCampaign("refuse");
    c.planners.push_back({"X", "NoSuchPlanner", {}, {}});
    EXPECT_THROW(runCampaign(c, options()), InputError);
    c.planners.back() = {"X", "GA", {{"no_such_parameter", "1"}}, {}};
    try
    {
        runCampaign(c, options());
        ADD_FAILURE() << "expected InputError";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("no_such_parameter"), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(c.database));
}

class TinyCampaign : public ::testing::Test
{
  protected:
    /** The campaign runs once per test process, in the first test's SetUp: googletest reports every test of
        a suite whose SetUpTestSuite fails (or throws) as skipped, which CTest shows as "Skipped". */
    void SetUp() override
    {
        if (campaign_ == nullptr)
        {
            campaign_ = new Campaign(tinyCampaign("full"));
            summary_ = new CampaignSummary(runCampaign(*campaign_, options(2)));
        }
        ASSERT_NE(summary_, nullptr) << "the tiny campaign failed (reported by the first test)";
    }
    static void TearDownTestSuite()
    {
        delete campaign_;
        delete summary_;
        fs::remove_all(fs::temp_directory_path() / ("mhplan_test_bench_" + std::to_string(::getpid())));
    }
    static Campaign *campaign_;
    static CampaignSummary *summary_;
};
Campaign *TinyCampaign::campaign_ = nullptr;
CampaignSummary *TinyCampaign::summary_ = nullptr;

TEST_F(TinyCampaign, DatabaseHasExpectedExperimentsPlannersRunsAndColumns)
{
    EXPECT_EQ(summary_->experiments, 2u);
    EXPECT_EQ(summary_->completed, 2u);
    EXPECT_EQ(summary_->failed, 0u) << (summary_->errors.empty() ? "" : summary_->errors[0]);
    EXPECT_EQ(summary_->runs, 2u * kRunsPerExperiment);
    EXPECT_EQ(summary_->mergedLogs, 2u);
    const Sql sql(campaign_->database);
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs"), 2 * kRunsPerExperiment);
    std::set<std::string> planners;
    for (const auto &r : sql.rows("SELECT DISTINCT name FROM plannerConfigs"))
        planners.insert(r[0]);
    EXPECT_EQ(planners, (std::set<std::string>{"geometric_RRTstar", "geometric_GA", "geometric_GA_small",
                                               "geometric_CrashAbort", "geometric_CrashThrow"}));
    // The two GA configurations are distinct planner configurations with their own settings.
    const auto settings =
        sql.rows("SELECT DISTINCT plannerConfigs.name, plannerConfigs.settings FROM runs JOIN "
                 "plannerConfigs ON runs.plannerid = plannerConfigs.id WHERE runs.experimentid = "
                 "(SELECT min(id) FROM experiments) AND plannerConfigs.name LIKE 'geometric_GA%'");
    ASSERT_EQ(settings.size(), 2u);
    EXPECT_NE(settings[0][1], settings[1][1]);
    EXPECT_NE(settings[0][1].find("max_iterations = "), std::string::npos);
    // A real version line (Debian's OMPL leaves it empty).
    for (const auto &r : sql.rows("SELECT version FROM experiments"))
        EXPECT_EQ(r[0].rfind("OMPL 1.", 0), 0u) << r[0];
    const std::set<std::string> exp = sql.columns("experiments");
    for (const char *c :
         {"world", "world_type", "world_file", "obstacle_count", "robot_radius", "query", "config_hash"})
        EXPECT_TRUE(exp.count(c)) << "experiments." << c;
    const std::set<std::string> runs = sql.columns("runs");
    for (const char *c :
         {"time", "status", "solved", "path_length", "exact_optimum_length", "optimality_gap",
          "collision_free", "min_clearance", "mean_clearance", "smoothness", "max_curvature",
          "angle_over_length", "cusps", "iterations", "fitness_evaluations", "run_index", "run_seed"})
        EXPECT_TRUE(runs.count(c)) << "runs." << c;
    // Planner Arena joins runs with experiments: no run property may repeat an experiment column.
    for (const std::string &c : runs)
    {
        if (c != "id")
        {
            EXPECT_EQ(exp.count(c), 0u) << "runs." << c << " repeats an experiments column";
        }
    }
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments WHERE world = 'bfo_case1' AND obstacle_count > 0"),
              1);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                        "WHERE plannerConfigs.name LIKE 'geometric_GA%'"),
              2 * 2 * 3);
    EXPECT_EQ(gaIterationsShort(sql), 0);
    // Every run index 0..2 of every planner and experiment is present once.
    EXPECT_EQ(
        sql.count("SELECT count(DISTINCT experimentid || '/' || plannerid || '/' || run_index) FROM runs"),
        2 * kRunsPerExperiment);
}

TEST_F(TinyCampaign, GapEqualsRecomputedFromStoredLengthAndOptimum)
{
    const Sql sql(campaign_->database);
    if (sql.columns("experiments").count("exact_optimum") == 0)
        GTEST_SKIP() << "no exact optimum in this build (src/optimum/Optimum.cpp not in mhplan_core)";
    const auto rows = sql.rows("SELECT runs.path_length, runs.exact_optimum_length, runs.optimality_gap, "
                               "experiments.exact_optimum FROM runs JOIN experiments ON runs.experimentid = "
                               "experiments.id WHERE runs.optimality_gap IS NOT NULL");
    EXPECT_GE(rows.size(), 6u); // at least the GA runs have exact solutions
    for (const auto &r : rows)
    {
        const double length = std::atof(r[0].c_str()), optimum = std::atof(r[1].c_str()),
                     gap = std::atof(r[2].c_str());
        EXPECT_EQ(r[1], r[3]); // the run's optimum is the experiment's
        ASSERT_GT(optimum, 0.0);
        EXPECT_NEAR(gap, 100.0 * (length - optimum) / optimum, 1e-9 * std::max(1.0, std::abs(gap)));
        EXPECT_GE(gap, -1e-6); // no valid path beats the exact optimum
    }
}

TEST_F(TinyCampaign, CrashingPlannersAreRecordedAsCrashAndTheRestRuns)
{
    const Sql sql(campaign_->database);
    const std::string crash =
        sql.rows("SELECT value FROM enums WHERE name = 'status' AND description = 'Crash'").at(0).at(0);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                        "WHERE plannerConfigs.name LIKE 'geometric_Crash%' AND runs.status = " +
                        crash),
              2 * 2 * 3);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs WHERE status = " + crash), 2 * 2 * 3);
    EXPECT_EQ(summary_->crashes, 2u * 2 * 3);
    // The planners after and before the crashing ones solved their problems.
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                        "WHERE plannerConfigs.name = 'geometric_GA' AND runs.solved = 1"),
              6);
}

TEST_F(TinyCampaign, SolutionPathsAreSavedPerRun)
{
    const Sql sql(campaign_->database);
    const long long withPath = sql.count("SELECT count(*) FROM runs WHERE path_length IS NOT NULL");
    EXPECT_GT(withPath, 0);
    EXPECT_EQ(sql.count("SELECT count(*) FROM paths"), withPath);
    // A stored path starts at the query's start and its length is the run's path_length.
    for (const auto &r :
         sql.rows("SELECT paths.points, runs.path_length FROM paths JOIN runs ON paths.runid = "
                  "runs.id JOIN experiments ON runs.experimentid = experiments.id WHERE "
                  "experiments.world = 'bfo_case1'"))
    {
        std::vector<std::pair<double, double>> pts;
        std::size_t pos = 0;
        while (pos < r[0].size())
        {
            const std::size_t end = r[0].find(';', pos);
            double x = 0, y = 0;
            if (std::sscanf(r[0].substr(pos, end - pos).c_str(), "%lf %lf", &x, &y) == 2)
                pts.emplace_back(x, y);
            pos = end == std::string::npos ? r[0].size() : end + 1;
        }
        ASSERT_GE(pts.size(), 2u);
        EXPECT_DOUBLE_EQ(pts.front().first, 0.0);
        EXPECT_DOUBLE_EQ(pts.front().second, 0.0);
        double length = 0.0;
        for (std::size_t i = 1; i < pts.size(); ++i)
            length += std::hypot(pts[i].first - pts[i - 1].first, pts[i].second - pts[i - 1].second);
        EXPECT_NEAR(length, std::atof(r[1].c_str()), 1e-9 * length);
    }
    // Progress samples of the optimizing planners carry the best cost.
    EXPECT_TRUE(sql.columns("progress").count("best_cost"));
    EXPECT_GT(sql.count("SELECT count(*) FROM progress WHERE best_cost IS NOT NULL"), 0);
    // Every progress series ends with a sample at the end of solve(): for the GA the last best cost is the
    // length of the path it returned.
    const auto last = sql.rows(
        "SELECT runs.path_length, progress.best_cost FROM runs JOIN plannerConfigs ON runs.plannerid = "
        "plannerConfigs.id JOIN progress ON progress.runid = runs.id WHERE plannerConfigs.name = "
        "'geometric_GA' "
        "AND runs.solved = 1 AND progress.time = (SELECT max(time) FROM progress WHERE runid = runs.id)");
    EXPECT_EQ(last.size(), 6u);
    for (const auto &r : last)
        EXPECT_NEAR(std::atof(r[1].c_str()), std::atof(r[0].c_str()), 1e-9 * std::atof(r[0].c_str()));
}

TEST_F(TinyCampaign, EveryImprovementIsStoredPerRunAndEndsAtTheSolution)
{
    const Sql sql(campaign_->database);
    ASSERT_EQ(sql.columns("improvements"), (std::set<std::string>{"runid", "time", "cost", "source"}));
    // Every exact run has rows; the last row's cost is the returned path's length (path-length objective),
    // no row is later than the run's time, and costs strictly decrease.
    const auto runs =
        sql.rows("SELECT runs.id, runs.path_length, runs.time, plannerConfigs.name, runs.improvements "
                 "FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                 "WHERE runs.status = 6");
    ASSERT_FALSE(runs.empty());
    std::set<std::string> sources;
    for (const auto &r : runs)
    {
        const auto rows = sql.rows("SELECT time, cost, source FROM improvements WHERE runid = " + r[0] +
                                   " ORDER BY time, cost DESC");
        ASSERT_FALSE(rows.empty()) << r[3];
        EXPECT_EQ(std::to_string(rows.size()), r[4]) << "run property 'improvements' counts the rows";
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            sources.insert(r[3] + ":" + rows[i][2]);
            EXPECT_LE(std::atof(rows[i][0].c_str()), std::atof(r[2].c_str()) + 1e-3);
            if (i > 0)
            {
                EXPECT_LT(std::atof(rows[i][1].c_str()), std::atof(rows[i - 1][1].c_str()));
            }
        }
        const double length = std::atof(r[1].c_str());
        EXPECT_NEAR(std::atof(rows.back()[1].c_str()), length, 1e-9 * length) << r[3];
    }
    // RRT* reports through the callback.
    EXPECT_TRUE(sources.count("geometric_RRTstar:callback"));
    // The side file next to each log holds the same rows.
    const auto all = enumerateExperiments(*campaign_, resolveShipped);
    for (const auto &e : all)
        EXPECT_TRUE(fs::exists(improvementsFile(*campaign_, e))) << e.name;
    // No rows for runs that do not exist (crashed runs have none either).
    EXPECT_EQ(sql.count("SELECT count(*) FROM improvements WHERE runid NOT IN (SELECT id FROM runs)"), 0);
    EXPECT_EQ(sql.count("SELECT count(*) FROM improvements JOIN runs ON improvements.runid = runs.id "
                        "WHERE runs.status = 7"),
              0);
}

TEST_F(TinyCampaign, ShardedRunsMergeToTheSameRows)
{
    Campaign c = tinyCampaign("sharded");
    RunOptions o = options();
    o.merge = false;
    o.shardIndex = 1;
    o.shardCount = 2;
    const CampaignSummary s1 = runCampaign(c, o);
    o.shardIndex = 2;
    const CampaignSummary s2 = runCampaign(c, o);
    EXPECT_EQ(s1.completed + s2.completed, 2u);
    EXPECT_FALSE(fs::exists(c.database));
    RunOptions m = options();
    m.run = false;
    const CampaignSummary merged = runCampaign(c, m);
    EXPECT_EQ(merged.mergedLogs, 2u);
    const Sql sharded(c.database), whole(campaign_->database);
    EXPECT_EQ(sharded.count("SELECT count(*) FROM runs"), whole.count("SELECT count(*) FROM runs"));
    EXPECT_EQ(sharded.count("SELECT count(*) FROM experiments"), 2);
    // Seeds derive from names, not from the process layout: the GA runs (iteration-bounded) are identical.
    EXPECT_EQ(gaIterationsShort(sharded), 0);
    EXPECT_EQ(gaIterationsShort(whole), 0);
    const auto a = lengthsByRun(sharded), b = lengthsByRun(whole);
    std::size_t compared = 0;
    for (const auto &kv : a)
        if (kv.first.find("|geometric_GA") != std::string::npos)
        {
            ASSERT_TRUE(b.count(kv.first)) << kv.first;
            EXPECT_EQ(kv.second, b.at(kv.first)) << kv.first;
            ++compared;
        }
    EXPECT_EQ(compared, 2u * 2 * 3);
}

TEST_F(TinyCampaign, ReRunResumesAndDoesNotDuplicate)
{
    Campaign c = tinyCampaign("resume");
    const CampaignSummary first = runCampaign(c, options());
    ASSERT_EQ(first.completed, 2u);
    const CampaignSummary again = runCampaign(c, options());
    EXPECT_EQ(again.skipped, 2u);
    EXPECT_EQ(again.completed, 0u);
    EXPECT_EQ(again.runs, 0u);
    EXPECT_EQ(again.mergedLogs, 0u);
    {
        const Sql sql(c.database);
        EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2);
    }
    // Lose one experiment (as if killed while it ran): only that one runs again, and its rows are replaced.
    const auto exps = enumerateExperiments(c, resolveShipped);
    fs::remove(logFile(c, exps[1]));
    const CampaignSummary third = runCampaign(c, options());
    EXPECT_EQ(third.skipped, 1u);
    EXPECT_EQ(third.completed, 1u);
    EXPECT_EQ(third.runs, static_cast<std::size_t>(kRunsPerExperiment));
    EXPECT_EQ(third.mergedLogs, 1u);
    const Sql sql(c.database);
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 2);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs"), 2 * kRunsPerExperiment);
    // A changed configuration is not mistaken for finished work.
    c.runs = 2;
    EXPECT_FALSE(logIsComplete(logFile(c, enumerateExperiments(c, resolveShipped)[0]),
                               enumerateExperiments(c, resolveShipped)[0].configHash));
}

TEST(BenchCli, RunsACampaignAndRefusesBadArguments)
{
    using mhplan::test::contains;
    using mhplan::test::runCli;
    const std::string data = std::string(MHPLAN_TEST_DATA_DIR) + "/bench_tiny.yaml";
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_bench_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const std::string db = (dir / "cli.db").string();

    auto r = runCli("bench");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "expected one CAMPAIGN")) << r.out;
    r = runCli("bench " + data + " --shard 3/2");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "--shard")) << r.out;
    r = runCli("bench " + data + " --jobs 0");
    EXPECT_EQ(r.code, 1) << r.out;
    r = runCli("bench " + data + " --merge-only --no-merge");
    EXPECT_EQ(r.code, 1) << r.out;

    r = runCli("bench " + data + " --list --database " + db);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "bfo_case1-default\tto do")) << r.out;
    r = runCli("bench " + data + " --runs 1 --time 0.02 --no-progress --database " + db);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "experiments: 2 (2 run now, 0 already complete, 0 failed)")) << r.out;
    EXPECT_TRUE(contains(r.out, "runs:        6 (0 recorded as Crash)")) << r.out;
    EXPECT_TRUE(contains(r.out, "2 log(s) appended")) << r.out;
    r = runCli("bench " + data + " --runs 1 --time 0.02 --list --database " + db);
    EXPECT_TRUE(contains(r.out, "bfo_case1-default\tcomplete")) << r.out;
    // Other settings make other experiments: the logs of 1 run are not taken for 3.
    r = runCli("bench " + data + " --list --database " + db);
    EXPECT_TRUE(contains(r.out, "bfo_case1-default\tto do")) << r.out;
    fs::remove_all(dir);
}
