// SPDX-License-Identifier: BSD-3-Clause
/* Benchmark campaigns end to end: a tiny campaign (two worlds, GA twice under distinct names, RRT*, and three
   deliberately crashing planners: abort, throw, segfault) is run, merged into an OMPL database and checked
   for its experiments, planners, runs and columns; the optimality gap is recomputed from the stored values;
   sharded runs merge to the unsharded row count with identical results; a re-run resumes (skips finished
   experiments). A planner that hangs (ignores its termination condition) is killed after the campaign's
   wall_limit and recorded as Crash. Simulation experiments are in test_bench_sim.cpp. */
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "CliSupport.h"
#include "BenchSupport.h"
#include "TimeScale.h"
#include "src/sim/Controllers.h"
#include "ompl_planners/lattice/ThetaStar.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"
#include "src/sim/Simulation.h"
#include "src/base/World.h"
#include "benchmarks/Improvements.h"
#include "benchmarks/ExperimentRuns.h"
#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "src/metrics/MetricList.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
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
        c.planners.push_back({"CrashSegv", "CrashTest", {{"mode", "segfault"}}, {}});
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

    constexpr int kRunsPerExperiment = 6 * 3; // planners x runs

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
    // wall_limit, the planning runs' watchdog: by default (0) 2 x time limit + 20 s; never at or below the
    // time limit, which would kill every run.
    EXPECT_DOUBLE_EQ(c.wallLimit, 0.0);
    EXPECT_DOUBLE_EQ(
        parseCampaign("worlds: [a]\nplanners: [RRT]\nwall_limit: 5\ntime_limit: 2\n", "w.yaml").wallLimit,
        5.0);
    const std::string low = error("worlds: [a]\nplanners: [RRT]\nwall_limit: 2\ntime_limit: 2\n");
    EXPECT_NE(low.find("field 'wall_limit'"), std::string::npos) << low;
    EXPECT_NE(low.find("must exceed time_limit (2 s)"), std::string::npos) << low;
    EXPECT_NE(error("worlds: [a]\nplanners: [RRT]\nwall_limit: 0\n").find("field 'wall_limit'"),
              std::string::npos);
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

// A benchmark run's RunSetup leaves OMPL's measuring out of the setup print before every run and takes as
// many seeds instead (benchmarks/README.md, "Overhead"): every generator made after it, so every random
// number of the run, is the same as under OMPL's own print, on every kind of space and with the planner set
// as OMPL's Benchmark sets it. One seed more or less would change them.
TEST(RunSetup, TakesTheSeedsOfOmplsPrint)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const PlannerRegistry &registry = builtinPlanners();
    for (const char *file :
         {"bfo_case2", "gms_grid10", "se2_narrow_passage", "dubins_circles", "reeds_shepp_parking"})
    {
        const World world = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + file + ".yaml");
        const Query query = world.queries.front();
        const CollisionModelPtr model = makeCollisionModel(world);
        const auto runSetup = [](const ob::StateSpacePtr &space)
        { return std::make_shared<detail::RunSetup>(space); };
        // Measured as a run process does: on a fresh setup, before the run's seed.
        std::optional<std::size_t> seeds;
        {
            const auto ss = makeSimpleSetup(world, query, model, runSetup);
            ss->getSpaceInformation()->setup();
            seeds = static_cast<detail::RunSetup &>(*ss).measurePrintSeeds();
        }
        ASSERT_TRUE(seeds.has_value()) << file;
        EXPECT_GT(*seeds, 0u) << file;
        for (const char *planner : {"RRTConnect", "RRTstar", "PRMstar"})
        {
            // The seed of the first generator made after the print, as in OMPL's Benchmark::benchmark: the
            // planner set up, the print, the setup (its path simplifier's generator), then the next one.
            const auto next = [&](std::optional<std::size_t> take)
            {
                detail::seedRunProcess(4711);
                const auto ss = take ? makeSimpleSetup(world, query, model, runSetup)
                                     : makeSimpleSetup(world, query, model);
                const ob::PlannerPtr p = registry.create(planner, ss->getSpaceInformation());
                ss->setPlanner(p);
                ss->getSpaceInformation()->setup();
                p->setProblemDefinition(ss->getProblemDefinition());
                p->setup();
                if (take)
                    static_cast<detail::RunSetup &>(*ss).printSeeds(*take);
                std::ostringstream out;
                ss->print(out);
                ss->setup();
                return ompl::RNG().getLocalSeed();
            };
            const auto ompls = next(std::nullopt);
            EXPECT_EQ(next(*seeds), ompls) << file << " " << planner;
            EXPECT_NE(next(*seeds + 1), ompls) << file << " " << planner;
            EXPECT_NE(next(*seeds - 1), ompls) << file << " " << planner;
        }
    }
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
    d = c;
    d.wallLimit = 30.0; // a run killed sooner is another result
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
    // A time limit raised past the wall limit after the file was read (mhplan bench --time).
    c.planners.pop_back();
    c.wallLimit = 0.4;
    try
    {
        runCampaign(c, options());
        ADD_FAILURE() << "expected InputError";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("wall_limit (0.4 s) must exceed the time limit (0.5 s)"),
                  std::string::npos)
            << e.what();
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
            // A metric of the test's own (docs/conventions.md, "Adding a metric"): registered here, stored by
            // the campaign like the built-in ones (RegisteredMetricIsStored).
            if (std::none_of(pathMetrics().begin(), pathMetrics().end(),
                             [](const PathMetric &m) { return m.property == "waypoints INTEGER"; }))
                registerPathMetric({"waypoints INTEGER", [](const MetricPath &p)
                                    { return static_cast<double>(p.points.size()); }});
            // What the experiment processes say about crashed runs (CrashingPlanners... reads it).
            StderrToFile capture(campaign_->logDir + ".stderr.txt");
            summary_ = new CampaignSummary(runCampaign(*campaign_, options(2)));
            stderr_ = new std::string(capture.text());
        }
        ASSERT_NE(summary_, nullptr) << "the tiny campaign failed (reported by the first test)";
    }
    static void TearDownTestSuite()
    {
        delete campaign_;
        delete summary_;
        delete stderr_;
        fs::remove_all(fs::temp_directory_path() / ("mhplan_test_bench_" + std::to_string(::getpid())));
    }
    static Campaign *campaign_;
    static CampaignSummary *summary_;
    /** Everything the campaign wrote to stderr. */
    static std::string *stderr_;
};
Campaign *TinyCampaign::campaign_ = nullptr;
CampaignSummary *TinyCampaign::summary_ = nullptr;
std::string *TinyCampaign::stderr_ = nullptr;

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
    EXPECT_EQ(planners,
              (std::set<std::string>{"geometric_RRTstar", "geometric_GA", "geometric_GA_small",
                                     "geometric_CrashAbort", "geometric_CrashThrow", "geometric_CrashSegv"}));
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
    // Every run of each crashing planner (3 planners x 2 experiments x 3 runs), and no other run.
    for (const char *planner : {"CrashAbort", "CrashThrow", "CrashSegv"})
        EXPECT_EQ(sql.count("SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = "
                            "plannerConfigs.id WHERE plannerConfigs.name = 'geometric_" +
                            std::string(planner) + "' AND runs.status = " + crash + " AND runs.solved = 0"),
                  2 * 3)
            << planner;
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs WHERE status = " + crash), 3 * 2 * 3);
    EXPECT_EQ(summary_->crashes, 3u * 2 * 3);
    // The campaign says why each run whose process died crashed: SIGABRT, SIGSEGV (under AddressSanitizer,
    // whose handler catches SIGSEGV, exit code 1 and its report). A throwing solve() ends its run normally
    // (OMPL's benchmark catches the exception, the run process records the crash): no such line.
    for (const auto &e : enumerateExperiments(*campaign_, resolveShipped))
        for (std::size_t k = 0; k < 3; ++k)
        {
            EXPECT_EQ(crashReason(*stderr_, e.name, "CrashAbort", k), "signal 6 (Aborted)") << e.name << k;
            EXPECT_TRUE(segfaulted(crashReason(*stderr_, e.name, "CrashSegv", k), *stderr_)) << e.name << k;
            EXPECT_EQ(crashReason(*stderr_, e.name, "CrashThrow", k), "") << e.name << k;
        }
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

TEST_F(TinyCampaign, RegisteredMetricIsStored)
{
    // Every run with a path stores the test's metric: the number of points of the path it saved.
    const Sql sql(campaign_->database);
    ASSERT_TRUE(sql.columns("runs").count("waypoints"));
    const auto rows =
        sql.rows("SELECT paths.points, runs.waypoints FROM paths JOIN runs ON paths.runid = runs.id");
    ASSERT_FALSE(rows.empty());
    for (const auto &r : rows)
        EXPECT_EQ(std::to_string(std::count(r[0].begin(), r[0].end(), ';')), r[1]) << r[0];
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs WHERE path_length IS NULL AND waypoints IS NOT NULL"), 0);
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

TEST(CrashCampaign, HangingAndSegfaultingPlannersAreRecordedAsCrashAndTheCampaignGoesOn)
{
    // One experiment: GA_small, a planner that hangs (sleeps in small steps and never looks at its
    // termination condition), one that segfaults, then GA. The hanging run is killed once it has been
    // silent for the campaign's wall_limit, far sooner than the default 2 x time limit + 20 s, and recorded
    // as Crash with that time; the runs after it go on. The limit is the GA runs' safety net too (they take
    // milliseconds), scaled in slower builds.
    Campaign c = tinyCampaign("hang");
    c.worlds.resize(1);
    const PlannerSpec gaSmall = c.planners[2], ga = c.planners[1];
    c.planners = {gaSmall,
                  {"CrashHang", "CrashTest", {{"mode", "hang"}}, {}, 1},
                  {"CrashSegv", "CrashTest", {{"mode", "segfault"}}, {}, 2},
                  ga};
    c.wallLimit = 1.5 * timeScale();
    StderrToFile capture(c.logDir + ".stderr.txt");
    const CampaignSummary s = runCampaign(c, options());
    const std::string text = capture.text();
    EXPECT_EQ(s.completed, 1u);
    EXPECT_EQ(s.failed, 0u) << (s.errors.empty() ? "" : s.errors[0]);
    EXPECT_EQ(s.runs, 3u + 1 + 2 + 3);
    EXPECT_EQ(s.crashes, 3u);
    EXPECT_LT(s.wallSeconds, 2.0 * c.timeLimit + 20.0) << "the hanging run waited for the default limit";

    const Sql sql(c.database);
    const std::string crash =
        sql.rows("SELECT value FROM enums WHERE name = 'status' AND description = 'Crash'").at(0).at(0);
    const auto rows =
        sql.rows("SELECT plannerConfigs.name, runs.run_index, runs.status, runs.solved, runs.time "
                 "FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                 "WHERE plannerConfigs.name LIKE 'geometric_Crash%' "
                 "ORDER BY plannerConfigs.name, runs.run_index");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"geometric_CrashHang", "0", crash, "0", rows[0][4]}));
    EXPECT_NEAR(std::atof(rows[0][4].c_str()), c.wallLimit, 1e-9) << "a killed run's time is the limit";
    for (std::size_t i = 1; i < 3; ++i)
    {
        EXPECT_EQ(rows[i], (std::vector<std::string>{"geometric_CrashSegv", std::to_string(i - 1), crash, "0",
                                                     rows[i][4]}));
        EXPECT_LT(std::atof(rows[i][4].c_str()), c.wallLimit) << "a dead run is not waited for";
    }
    // The planners before and after the crashes ran every run to their iteration bound and solved.
    EXPECT_EQ(gaIterationsShort(sql), 0);
    EXPECT_EQ(sql.count("SELECT count(*) FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                        "WHERE plannerConfigs.name LIKE 'geometric_GA%' AND runs.status = 6"),
              6);

    const std::string experiment = enumerateExperiments(c, resolveShipped).at(0).name;
    std::ostringstream killed;
    killed << "killed after " << c.wallLimit << " s without progress";
    EXPECT_EQ(crashReason(text, experiment, "CrashHang", 0), killed.str()) << text;
    for (std::size_t k = 0; k < 2; ++k)
        EXPECT_TRUE(segfaulted(crashReason(text, experiment, "CrashSegv", k), text)) << text;
    fs::remove_all(fs::path(c.database).parent_path());
}
