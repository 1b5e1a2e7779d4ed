// SPDX-License-Identifier: BSD-3-Clause
/* The scaling suite's machinery: world families (disjoint obstacles at 20-35 % coverage in a square growing
   with the count, checked independently; deterministic per seed), random queries (valid, connected, at least
   the requested share of the diagonal apart), generated campaign worlds (refused with file:line and field
   for bad entries; written once and reused), benchmarks/scaling.yaml parses (and issue 31's targets campaigns
   are a subset of it), and the smoke campaign
   (benchmarks/scaling_smoke.yaml) runs end to end into a database with optima and improvements. */
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "src/collision/Collision.h"
#include "src/optimum/Optimum.h"
#include "benchmarks/WorldFamilies.h"
#include "src/io/WorldIO.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <unistd.h>

using namespace mhplan;
using namespace mhplan::bench;
namespace fs = std::filesystem;

namespace
{

    double area(const World &w)
    {
        double a = 0.0;
        for (const auto &c : w.circles)
            a += kPi * c.radius * c.radius;
        for (const auto &p : w.polygons)
            a += 0.5 * std::abs(signedArea2(p.vertices));
        return a;
    }

    /** True when the two polygons share a point (an edge crossing or one inside the other). */
    bool polygonsMeet(const std::vector<Vec2> &a, const std::vector<Vec2> &b)
    {
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j)
                if (segmentsIntersect(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]))
                    return true;
        return pointInPolygon(a[0], b) || pointInPolygon(b[0], a);
    }

    long long sqlCount(const std::string &db, const std::string &sql)
    {
        sqlite3 *h = nullptr;
        sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr);
        sqlite3_stmt *st = nullptr;
        long long n = -1;
        if (sqlite3_prepare_v2(h, sql.c_str(), -1, &st, nullptr) == SQLITE_OK &&
            sqlite3_step(st) == SQLITE_ROW)
            n = sqlite3_column_int64(st, 0);
        else
            ADD_FAILURE() << sqlite3_errmsg(h) << " in " << sql;
        sqlite3_finalize(st);
        sqlite3_close(h);
        return n;
    }

    std::string parseError(const std::string &yaml)
    {
        try
        {
            parseCampaign(yaml, "bad.yaml");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }
} // namespace

TEST(WorldFamilies, GeometricFamiliesAreDisjointCoverTheTargetShareAndGrow)
{
    for (const std::string kind : {"circles", "rectangles", "polygons"})
    {
        double previousSide = 0.0;
        for (std::size_t count : {10u, 300u})
            for (double radius : {0.0, 0.25})
            {
                if (count < 100 && radius > 0.0)
                    continue; // gaps of 2 r in a box of a few obstacles across leave no room at 30 %
                FamilyOptions o;
                o.kind = kind;
                o.count = count;
                o.coverage = 0.3;
                o.robotRadius = radius;
                o.seed = 3;
                const World w = generateFamilyWorld(o);
                ASSERT_EQ(w.obstacleCount(), count) << kind;
                const double side = w.bounds.width();
                const double share = area(w) / (side * side);
                EXPECT_GE(share, 0.20) << kind << count;
                EXPECT_LE(share, 0.35) << kind << count;
                if (radius == 0.0)
                {
                    EXPECT_GT(side, previousSide * 3.0) << "the square grows with sqrt(count)";
                    previousSide = side;
                }
                // Pairwise disjoint, at least 2 r apart (the disc passes between any two), inside the bounds.
                const AnalyticCollisionModel model(w);
                for (std::size_t i = 0; i < w.circles.size(); ++i)
                {
                    const Circle &a = w.circles[i];
                    EXPECT_GE(a.center.x - a.radius, 2.0 * radius);
                    EXPECT_LE(a.center.y + a.radius, side - 2.0 * radius);
                    for (std::size_t j = i + 1; j < w.circles.size(); ++j)
                        ASSERT_GT(distance(a.center, w.circles[j].center) - a.radius - w.circles[j].radius,
                                  2.0 * radius)
                            << kind << " " << i << " " << j;
                }
                for (std::size_t i = 0; i < w.polygons.size(); ++i)
                {
                    EXPECT_GE(w.polygons[i].bbox.xmin, 2.0 * radius);
                    EXPECT_LE(w.polygons[i].bbox.ymax, side - 2.0 * radius);
                    EXPECT_EQ(kind == "rectangles", w.polygons[i].convex);
                    for (std::size_t j = i + 1; j < w.polygons.size(); ++j)
                        if (w.polygons[i].bbox.inflated(radius).overlaps(w.polygons[j].bbox.inflated(radius)))
                        {
                            ASSERT_FALSE(polygonsMeet(w.polygons[i].vertices, w.polygons[j].vertices));
                            double d = std::numeric_limits<double>::infinity();
                            for (const Vec2 &v : w.polygons[i].vertices)
                                d = std::min(d, pointPolygonSignedDistance(v, w.polygons[j].vertices));
                            EXPECT_GT(d, 2.0 * radius) << kind << " " << i << " " << j;
                        }
                }
            }
    }
}

TEST(WorldFamilies, SameSeedSameWorldAndGridKinds)
{
    FamilyOptions o;
    o.kind = "polygons";
    o.count = 50;
    o.seed = 9;
    EXPECT_EQ(worldToYaml(generateFamilyWorld(o)), worldToYaml(generateFamilyWorld(o)));
    o.seed = 10;
    const std::string other = worldToYaml(generateFamilyWorld(o));
    o.seed = 9;
    EXPECT_NE(worldToYaml(generateFamilyWorld(o)), other);
    o.kind = "maze";
    o.cells = 33;
    const World maze = generateFamilyWorld(o);
    ASSERT_TRUE(maze.isGrid());
    EXPECT_EQ(maze.grid->width(), 33);
    o.kind = "grid";
    o.cells = 64;
    o.density = 0.25;
    const World grid = generateFamilyWorld(o);
    EXPECT_EQ(grid.grid->width(), 64);
    EXPECT_NEAR(static_cast<double>(grid.grid->blockedCount()) / (64.0 * 64.0), 0.25, 0.05);
    o.kind = "hexagons";
    EXPECT_THROW(generateFamilyWorld(o), InputError);
    o.kind = "circles";
    o.coverage = 0.39;
    o.count = 400;
    o.robotRadius = 3.0; // gaps of 6 m between obstacles of 1-3 m at 39 %: cannot fit
    EXPECT_THROW(generateFamilyWorld(o), InputError);
}

TEST(WorldFamilies, QueriesAreValidConnectedAndFarApart)
{
    for (const std::string kind : {"circles", "maze", "grid"})
    {
        FamilyOptions o;
        o.kind = kind;
        o.count = 60;
        o.cells = 40;
        o.robotRadius = kind == "circles" ? 0.5 : 0.0;
        o.seed = 4;
        World w = generateFamilyWorld(o);
        QueryOptions q;
        q.count = 10;
        q.minSeparation = 0.5;
        q.seed = 5;
        addRandomQueries(w, q);
        ASSERT_EQ(w.queries.size(), 10u);
        const CollisionModelPtr model = makeCollisionModel(w);
        const double diagonal = std::hypot(w.bounds.width(), w.bounds.height());
        for (std::size_t i = 0; i < w.queries.size(); ++i)
        {
            const Query &qq = w.queries[i];
            EXPECT_EQ(qq.name, "q" + std::to_string(i));
            EXPECT_TRUE(model->isValid(qq.start));
            EXPECT_TRUE(model->isValid(qq.goal));
            EXPECT_GE(distance(qq.start, qq.goal), 0.5 * diagonal);
            const OptimumResult opt = computeOptimum(w, qq);
            EXPECT_TRUE(opt.found) << kind << " " << qq.name;
            EXPECT_GE(opt.length, distance(qq.start, qq.goal) * (1.0 - 1e-12));
        }
        // The written world reads back with the same queries.
        const fs::path file =
            fs::temp_directory_path() / ("mhplan_test_scaling_q_" + std::to_string(::getpid()) + ".yaml");
        {
            std::ofstream out(file);
            out << worldToYaml(w);
        }
        const World back = loadWorld(file.string());
        fs::remove(file);
        ASSERT_EQ(back.queries.size(), w.queries.size());
        EXPECT_EQ(back.queries[3].goal.x, w.queries[3].goal.x);
    }
}

TEST(GeneratedWorlds, BadEntriesAreRefusedWithFileLineAndField)
{
    const std::string head = "planners: [RRTstar]\nworlds:\n";
    const std::string ok =
        "  - {generate: {kind: circles, count: 10, seed: 1}, queries: {count: 2, seed: 1}}\n";
    EXPECT_EQ(parseError(head + ok), "");
    const auto expectError = [&](const std::string &entry, const std::string &what)
    {
        const std::string e = parseError(head + ok + entry);
        EXPECT_NE(e.find("bad.yaml:4"), std::string::npos) << e;
        EXPECT_NE(e.find(what), std::string::npos) << e;
    };
    expectError("  - {generate: {kind: hexagons, count: 10, seed: 1}, queries: {count: 2, seed: 1}}\n",
                "worlds[1].generate.kind");
    expectError("  - {generate: {kind: circles, count: 0, seed: 1}, queries: {count: 2, seed: 1}}\n",
                "worlds[1].generate.count");
    expectError("  - {generate: {kind: circles, count: 10, seed: 1}}\n", "worlds[1].queries");
    expectError(
        "  - {generate: {kind: circles, count: 10, cells: 4, seed: 1}, queries: {count: 2, seed: 1}}\n",
        "worlds[1].generate.cells");
    expectError("  - {generate: {kind: maze, seed: 1}, queries: {count: 2, seed: 1}}\n", "cells");
    expectError(
        "  - {generate: {kind: circles, count: 10, seed: 1, colour: red}, queries: {count: 2, seed: 1}}\n",
        "colour");
    expectError("  - {generate: {kind: circles, count: 10, seed: 1}, queries: {count: 2, seed: 1, "
                "min_separation: 2}}\n",
                "worlds[1].queries.min_separation");
    expectError(
        "  - {generate: {kind: circles, count: 10, coverage: 0.9, seed: 1}, queries: {count: 2, seed: 1}}\n",
        "worlds[1].generate.coverage");
    expectError("  - {world: bfo_case1, generate: {kind: circles, count: 10, seed: 1}, queries: {count: 2, "
                "seed: 1}}\n",
                "either world or generate");
}

TEST(GeneratedWorlds, TheScalingSuiteParses)
{
    const Campaign c = loadCampaign(std::string(MHPLAN_SOURCE_DIR) + "/benchmarks/scaling.yaml");
    EXPECT_GE(c.worlds.size(), 20u);
    for (const auto &w : c.worlds)
    {
        ASSERT_TRUE(w.generated.present);
        EXPECT_GE(w.generated.queries.count, 10u);
        EXPECT_GE(w.generated.queries.minSeparation, 0.5);
    }
    EXPECT_DOUBLE_EQ(c.timeLimit, 5.0);
    EXPECT_GE(c.planners.size(), 22u);
    // Issue 31: the memetic planners beside OMPL's optimizing planners, ABIT* and AIT* included.
    for (const char *name :
         {"GA-MEM", "SMA-MEM", "LRSMA-MEM", "MGO-MEM", "InformedRRTstar", "BITstar", "ABITstar", "AITstar"})
        EXPECT_TRUE(std::any_of(c.planners.begin(), c.planners.end(),
                                [&](const PlannerSpec &p) { return p.displayName == name; }))
            << name;
}

TEST(GeneratedWorlds, TheTargetsCampaignsAreASubsetOfTheSuite)
{
    // benchmarks/scaling_targets.yaml (1 s) and scaling_targets_5s.yaml (benchmarks/README.md, "Issue 31's
    // targets"): every world is one of the suite's recipes with fewer queries (drawn in order, so the suite's
    // first ones), both set-ups, every planner one of the suite's lines with the same settings.
    const std::string dir = std::string(MHPLAN_SOURCE_DIR) + "/benchmarks/";
    const Campaign suite = loadCampaign(dir + "scaling.yaml");
    for (const auto &[file, limit, planners] :
         {std::tuple<std::string, double, std::size_t>{"scaling_targets.yaml", 1.0, 8},
          std::tuple<std::string, double, std::size_t>{"scaling_targets_5s.yaml", 5.0, 6}})
    {
        SCOPED_TRACE(file);
        const Campaign c = loadCampaign(dir + file);
        EXPECT_DOUBLE_EQ(c.timeLimit, limit);
        EXPECT_EQ(c.seed, suite.seed);
        ASSERT_EQ(c.setups.size(), 2u);
        EXPECT_FALSE(c.setups[0].app());
        EXPECT_TRUE(c.setups[1].app());
        EXPECT_DOUBLE_EQ(c.setups[1].resolution, 0.002);
        EXPECT_GE(c.worlds.size(), 7u);
        for (const auto &w : c.worlds)
        {
            ASSERT_TRUE(w.generated.present);
            EXPECT_TRUE(w.setups.empty());
            // The same recipe (kind, sizes, seeds, query seed and separation) but for the query count.
            const auto sameRecipe = [&](const WorldSpec &s)
            {
                GeneratedWorldSpec same = w.generated;
                same.queries.count = s.generated.queries.count;
                return s.generated.present && same.recipe() == s.generated.recipe();
            };
            const auto it = std::find_if(suite.worlds.begin(), suite.worlds.end(), sameRecipe);
            ASSERT_NE(it, suite.worlds.end()) << w.generated.recipe();
            EXPECT_LE(w.generated.queries.count, it->generated.queries.count);
        }
        ASSERT_EQ(c.planners.size(), planners);
        unsigned memetic = 0;
        for (const auto &p : c.planners)
        {
            const auto it =
                std::find_if(suite.planners.begin(), suite.planners.end(),
                             [&](const PlannerSpec &s) { return s.displayName == p.displayName; });
            ASSERT_NE(it, suite.planners.end()) << p.displayName;
            EXPECT_EQ(p.planner, it->planner);
            EXPECT_EQ(p.params, it->params);
            EXPECT_EQ(p.progress, it->progress);
            memetic += p.displayName.size() > 4 && p.displayName.substr(p.displayName.size() - 4) == "-MEM";
        }
        EXPECT_GE(memetic, 2u);
    }
}

TEST(GeneratedWorlds, SmokeCampaignRunsEndToEnd)
{
    Campaign c = loadCampaign(std::string(MHPLAN_SOURCE_DIR) + "/benchmarks/scaling_smoke.yaml");
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_scaling_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    c.database = (dir / "smoke.db").string();
    c.logDir = (dir / "logs").string();
    RunOptions opt;
    opt.jobs = 2;
    opt.progressBar = false;
    opt.resolveWorld = [](const std::string &name) { return name; };
    const CampaignSummary s = runCampaign(c, opt);
    EXPECT_EQ(s.experiments, 6u);
    EXPECT_EQ(s.completed, 6u);
    EXPECT_EQ(s.failed, 0u) << (s.errors.empty() ? "" : s.errors[0]);
    EXPECT_EQ(sqlCount(c.database, "SELECT count(*) FROM experiments WHERE exact_optimum > 0"), 6);
    EXPECT_EQ(sqlCount(c.database, "SELECT count(DISTINCT collision_backend) FROM experiments"), 3)
        << "analytic (10 circles), hash (80 rectangles), grid (maze)";
    EXPECT_EQ(sqlCount(c.database, "SELECT count(*) FROM runs"), 6 * 4);
    // Every exact run has improvement rows, and its last one is the run's path length.
    EXPECT_EQ(
        sqlCount(c.database,
                 "SELECT count(*) FROM runs WHERE status = 6 AND NOT EXISTS (SELECT 1 FROM improvements "
                 "WHERE runid = runs.id)"),
        0);
    EXPECT_GT(sqlCount(c.database, "SELECT count(*) FROM runs WHERE status = 6"), 12);
    EXPECT_EQ(
        sqlCount(c.database,
                 "SELECT count(*) FROM runs WHERE status = 6 AND abs((SELECT cost FROM improvements WHERE "
                 "runid = runs.id ORDER BY time DESC, cost ASC LIMIT 1) - path_length) > 1e-9 * path_length"),
        0);
    // The generated worlds are written once; a second run skips everything and keeps them.
    const fs::path world = dir / "logs" / "worlds" / "circles_10_s1.yaml";
    ASSERT_TRUE(fs::exists(world));
    const auto written = fs::last_write_time(world);
    const CampaignSummary again = runCampaign(c, opt);
    EXPECT_EQ(again.skipped, 6u);
    EXPECT_EQ(fs::last_write_time(world), written);
    fs::remove_all(dir);
}
