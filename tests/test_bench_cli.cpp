// SPDX-License-Identifier: BSD-3-Clause
/* The mhplan program's bench and report commands on a campaign it runs: arguments refused, the databases it
   writes and the report's numbers recomputed from them (split from test_bench.cpp). */
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

namespace
{
    /** \e v as the report's Python writes it ("%.Nf" and a suffix; "&ndash;" for no value, NaN here). */
    std::string reportNumber(double v, int digits, const std::string &suffix = "")
    {
        if (std::isnan(v))
            return "&ndash;";
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
        return buf + suffix;
    }

    /** The median as numpy computes it (the mean of the middle two of an even count); NaN when empty. */
    double median(std::vector<double> v)
    {
        if (v.empty())
            return std::nan("");
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
    }

    std::string readText(const fs::path &file)
    {
        std::ifstream in(file);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }

    /** The table row of \e html that starts with \e head (empty when there is none). */
    std::string rowStartingWith(const std::string &html, const std::string &head)
    {
        const std::size_t at = html.find(head);
        if (at == std::string::npos)
            return "";
        const std::size_t end = html.find("</tr>", at);
        return html.substr(at, end == std::string::npos ? std::string::npos : end + 5 - at);
    }
} // namespace

TEST(BenchCli, ReportsOnTheDatabasesTheProgramWrote)
{
    // The whole way a user goes: `mhplan bench` (the program) on a tiny plane campaign, one r2 world with an
    // exact optimum (bfo_case1: the optimum and gap columns), GA (iteration-bounded) and RRT*, and one
    // simulation experiment (mapf_2robots, dapf and aapf from perturbed starts); then `mhplan report` on each
    // of the two databases it wrote. The reports name the experiments, planners and controllers of their
    // database only, and their counts and medians are the ones computed here from the database.
    using mhplan::test::contains;
    using mhplan::test::runCli;
    const fs::path dir =
        fs::temp_directory_path() / ("mhplan_test_bench_report_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string campaign = (dir / "plane.yaml").string();
    std::ofstream(campaign) << "campaign: plane\n"
                               "time_limit: 0.2\n"
                               "runs: 2\n"
                               "seed: 3\n"
                               "progress_interval: 0.01\n"
                               "planner_data: false\n"
                               "worlds: [bfo_case1]\n"
                               "planners:\n"
                               "  - planner: GA\n"
                               "    params: {population_size: 10, iterations: 5, max_iterations: 5}\n"
                               "  - RRTstar\n"
                               "simulations:\n"
                               "  - scenario: mapf_2robots\n"
                               "    runs: 2\n"
                               "    start_jitter: 0.05\n"
                               "    controllers: [dapf, aapf]\n";
    const std::string db = (dir / "plane.db").string(), simDb = (dir / "plane-sim.db").string();
    auto r = runCli("bench " + campaign + " --no-progress --database " + db);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "experiments: 2 (2 run now, 0 already complete, 0 failed)")) << r.out;
    EXPECT_TRUE(contains(r.out, "runs:        8 (0 recorded as Crash)")) << r.out;
    ASSERT_TRUE(fs::exists(db));
    ASSERT_TRUE(fs::exists(simDb));

    // The planning database and its report.
    r = runCli("report " + db + " -o " + (dir / "report").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, (dir / "report" / "index.html").string())) << r.out;
    const std::string html = readText(dir / "report" / "index.html");
    {
        const Sql sql(db);
        EXPECT_TRUE(
            contains(html, "<p>Database <code>" + db + "</code>: 1 experiments, 2 planners, 4 runs.</p>"))
            << html.substr(0, 2000);
        const std::vector<double> optimum = sql.numbers("SELECT exact_optimum FROM experiments");
        ASSERT_EQ(optimum.size(), 1u);
        ASSERT_FALSE(std::isnan(optimum[0]));
        EXPECT_TRUE(contains(
            html, "<h3>bfo_case1-default</h3><p>exact optimum: " + reportNumber(optimum[0], 4) + "</p>"));
        for (const std::string planner : {"GA", "RRTstar"})
        {
            const std::string runs = "FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                                     "WHERE plannerConfigs.name = 'geometric_" +
                                     planner + "'";
            const long long n = sql.count("SELECT count(*) " + runs),
                            exact = sql.count("SELECT count(*) " + runs + " AND runs.status = 6"),
                            approximate = sql.count("SELECT count(*) " + runs + " AND runs.status = 5"),
                            crashed = sql.count("SELECT count(*) " + runs + " AND runs.status = 7");
            EXPECT_EQ(n, 2) << planner;
            EXPECT_GT(exact, 0) << planner;
            const std::vector<double> lengths =
                sql.numbers("SELECT runs.path_length " + runs + " AND runs.status = 6 ORDER BY runs.id");
            const std::vector<double> gaps =
                sql.numbers("SELECT runs.optimality_gap " + runs + " AND runs.status = 6 ORDER BY runs.id");
            ASSERT_EQ(lengths.size(), gaps.size());
            for (std::size_t i = 0; i < gaps.size(); ++i)
                EXPECT_NEAR(gaps[i], 100.0 * (lengths[i] - optimum[0]) / optimum[0],
                            1e-9 * std::max(1.0, std::abs(gaps[i])))
                    << planner;
            // Ranking per problem: success rate and median gap.
            EXPECT_TRUE(contains(html, "<tr><td>" + planner + "</td><td>" +
                                           reportNumber(100.0 * exact / n, 0, "%") + "</td><td>" +
                                           reportNumber(median(gaps), 2, "%") + "</td>"))
                << planner;
            // The problem's table: runs, outcomes, shortest and median length of the exact runs.
            const std::string row = "<tr><td>" + planner + "</td><td>" + std::to_string(n) + "</td><td>" +
                                    std::to_string(exact) + "</td><td>" + std::to_string(approximate) +
                                    "</td><td>" + std::to_string(n - exact - approximate - crashed) +
                                    "</td><td>" + std::to_string(crashed) + "</td><td>" +
                                    reportNumber(*std::min_element(lengths.begin(), lengths.end()), 4) +
                                    "</td><td>" + reportNumber(median(lengths), 4) + "</td>";
            EXPECT_TRUE(contains(html, row)) << row;
        }
        EXPECT_FALSE(contains(html, "mapf_2robots")) << "a simulation in the planning report";
        for (const char *figure : {"success.png", "box_bfo_case1-default.png",
                                   "convergence_bfo_case1-default.png", "paths_bfo_case1-default.png"})
        {
            EXPECT_TRUE(contains(html, std::string("src='") + figure + "'")) << figure;
            EXPECT_GT(fs::file_size(dir / "report" / figure), 1000u) << figure;
        }
    }

    // The simulation database and its report.
    r = runCli("report " + simDb + " -o " + (dir / "report-sim").string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::string simHtml = readText(dir / "report-sim" / "index.html");
    {
        const Sql sql(simDb);
        EXPECT_TRUE(contains(simHtml, "<p>Database <code>" + simDb +
                                          "</code>: 1 experiments, 2 planners, 4 runs.</p>"))
            << simHtml.substr(0, 2000);
        EXPECT_TRUE(contains(simHtml, "<h3>mapf_2robots-sim</h3>"));
        for (const std::string controller : {"dapf", "aapf"})
        {
            const std::string runs = "FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                                     "WHERE plannerConfigs.name = 'sim:" +
                                     controller + "'";
            const long long n = sql.count("SELECT count(*) " + runs),
                            done = sql.count("SELECT count(*) " + runs + " AND runs.status = 6"),
                            crashed = sql.count("SELECT count(*) " + runs + " AND runs.status = 7");
            EXPECT_EQ(n, 2) << controller;
            // Medians with the runs that did not bring every robot home at +infinity (censored).
            const auto censoredMedian = [&](const std::string &column)
            {
                std::vector<double> v =
                    sql.numbers("SELECT CASE WHEN runs.status = 6 THEN runs." + column + " END " + runs);
                for (double &x : v)
                    x = std::isnan(x) ? std::numeric_limits<double>::infinity() : x;
                const double m = median(v);
                return std::isinf(m) ? std::string("unfinished") : reportNumber(m, 2);
            };
            const std::string row = rowStartingWith(
                simHtml, "<tr><td>" + controller + "</td><td>" + std::to_string(n) + "</td><td>" +
                             std::to_string(done) + " (" + reportNumber(100.0 * done / n, 0) + "%)</td><td>" +
                             std::to_string(crashed) + "</td>");
            ASSERT_FALSE(row.empty()) << controller << "\n" << simHtml;
            EXPECT_TRUE(contains(row, "<td>" + censoredMedian("makespan") + "</td><td>" +
                                          censoredMedian("flowtime") + "</td>"))
                << row;
        }
        EXPECT_FALSE(contains(simHtml, "bfo_case1-default"))
            << "a planning experiment in the simulation report";
        EXPECT_GT(fs::file_size(dir / "report-sim" / "sim_box_mapf_2robots-sim.png"), 1000u);
    }
    fs::remove_all(dir);
}
