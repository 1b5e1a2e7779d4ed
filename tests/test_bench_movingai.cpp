// SPDX-License-Identifier: BSD-3-Clause
/* MovingAI benchmark sets as campaign worlds: selection by bucket, the .scen optimum checked against mhplan's
   octile optimum (LF and CRLF files, full-precision and 6-significant-digit optima), a disagreement refused
   with file:line, both optima recorded, A*'s lengths equal to them. Data: tests/data/movingai/
   (make_scen.py). */
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "BenchSupport.h"
#include "CliSupport.h"
#include "src/io/ScenIO.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

using namespace mhplan;
using namespace mhplan::bench;
using namespace mhplan::test;
namespace fs = std::filesystem;

namespace
{
    const std::string kData = std::string(MHPLAN_TEST_DATA_DIR) + "/movingai/";

    Campaign movingai(const std::string &entry, const std::string &planners = "[AStar]")
    {
        return parseCampaign("campaign: mai\ntime_limit: 0.5\nruns: 1\nseed: 3\nplanner_data: false\n"
                             "worlds:\n  - " +
                                 entry + "\nplanners: " + planners + "\n",
                             kData + "campaign.yaml");
    }

    std::string errorOf(const Campaign &c)
    {
        try
        {
            enumerateExperiments(c, resolveShipped);
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }
} // namespace

TEST(MovingAICampaign, SelectsProblemsByBucketEveryAndCount)
{
    // rooms.map.scen: buckets 0 (2 problems), 1 (3), 2 (2), 3 (1), 4 (2), LF, full precision.
    auto all = enumerateExperiments(movingai("{map: rooms.map, scen: rooms.map.scen}"), resolveShipped);
    ASSERT_EQ(all.size(), 10u);
    EXPECT_EQ(all[0].name, "rooms-b0-l2");
    EXPECT_EQ(all[0].scenLine, 2);
    for (const Experiment &e : all)
    {
        EXPECT_TRUE(scenOptimumMatches(e.scenOptimum, e.octileOptimum)) << e.name;
        EXPECT_NEAR(e.scenOptimum, e.octileOptimum, 1e-9) << e.name; // full precision: equal
    }
    const auto one = enumerateExperiments(
        movingai("{map: rooms.map, scen: rooms.map.scen, problems_per_bucket: 1}"), resolveShipped);
    ASSERT_EQ(one.size(), 5u);
    for (std::size_t k = 0; k < one.size(); ++k)
        EXPECT_EQ(one[k].scenBucket, static_cast<int>(k));
    EXPECT_EQ(one[1].scenLine, 4); // the first problem of bucket 1
    const auto some = enumerateExperiments(
        movingai("{map: rooms.map, scen: rooms.map.scen, buckets: [1, 4], every: 2}"), resolveShipped);
    ASSERT_EQ(some.size(), 3u); // bucket 1: its 1st and 3rd problem; bucket 4: its 1st
    EXPECT_EQ(some[0].scenLine, 4);
    EXPECT_EQ(some[1].scenLine, 6);
    EXPECT_EQ(some[2].scenLine, 10);
}

TEST(MovingAICampaign, AcceptsCrlfAndSixDigitOptimaAndRefusesAWrongOne)
{
    const auto crlf =
        enumerateExperiments(movingai("{map: rooms.map, scen: rooms_crlf.map.scen}"), resolveShipped);
    ASSERT_EQ(crlf.size(), 10u);
    EXPECT_DOUBLE_EQ(crlf[1].scenOptimum, 3.41421); // as written: 6 significant digits
    EXPECT_NEAR(crlf[1].octileOptimum, 2.0 + std::sqrt(2.0), 1e-12);

    std::string e = errorOf(movingai("{map: rooms.map, scen: rooms_wrong.map.scen}"));
    EXPECT_TRUE(contains(e, "rooms_wrong.map.scen:4: field 'optimal-length': the .scen optimum 6.01 differs "
                            "from mhplan's octile optimum 6"))
        << e;
    EXPECT_TRUE(contains(e, "campaign.yaml:")) << e;
    e = errorOf(movingai("{map: rooms.map, scen: rooms.map.scen, buckets: [9]}"));
    EXPECT_TRUE(contains(e, "no problem of")) << e;
    e = errorOf(movingai("{map: rooms.map, scen: no_such.scen}"));
    EXPECT_TRUE(contains(e, "no_such.scen")) << e;
    for (const std::string bad : {"{map: rooms.map}", "{map: rooms.map, scen: rooms.map.scen, every: 0}",
                                  "{map: rooms.map, scen: rooms.map.scen, buckets: []}",
                                  "{map: rooms.map, scen: rooms.map.scen, queries: [default]}"})
        EXPECT_THROW(movingai(bad), InputError) << bad;
}

TEST(MovingAICampaign, RecordsBothOptimaAndAStarMatchesThem)
{
    Campaign c =
        movingai("{map: rooms.map, scen: rooms_crlf.map.scen, problems_per_bucket: 1, buckets: [1, 4]}",
                 "[AStar, ThetaStar]");
    const fs::path dir =
        fs::temp_directory_path() / ("mhplan_test_bench_movingai_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    c.database = (dir / "mai.db").string();
    c.logDir = (dir / "logs").string();
    const CampaignSummary s = runCampaign(c, options(2));
    ASSERT_EQ(s.failed, 0u) << (s.errors.empty() ? "" : s.errors[0]);
    const Sql sql(c.database);
    const auto rows =
        sql.rows("SELECT experiments.name, scen_bucket, scen_line, scen_optimum, octile_optimum, "
                 "exact_optimum, plannerConfigs.name, runs.solution_length FROM runs JOIN "
                 "experiments ON runs.experimentid = experiments.id JOIN plannerConfigs ON "
                 "runs.plannerid = plannerConfigs.id ORDER BY experiments.id, plannerConfigs.name");
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[0][0], "rooms-b1-l4");
    EXPECT_EQ(rows[0][1], "1");
    EXPECT_EQ(rows[2][0], "rooms-b4-l10");
    for (const auto &r : rows)
    {
        const double scen = std::atof(r[3].c_str()), octile = std::atof(r[4].c_str());
        const double anyAngle = std::atof(r[5].c_str()), length = std::atof(r[7].c_str());
        EXPECT_TRUE(scenOptimumMatches(scen, octile)) << r[0];
        EXPECT_LE(anyAngle, octile + 1e-9) << r[0]; // the any-angle optimum is never longer (1 m cells)
        // OMPL's log holds the run's length with 6 significant digits.
        const double tol = 1e-5 * octile;
        if (r[6] == "geometric_AStar")
            EXPECT_NEAR(length, octile, tol) << r[0];
        else // Theta*: any-angle, between the two optima
            EXPECT_TRUE(length >= anyAngle - tol && length <= octile + tol) << r[0] << " " << length;
    }
    fs::remove_all(dir);
}
