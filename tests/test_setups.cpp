// SPDX-License-Identifier: BSD-3-Clause
/* Validity set-ups (docs/setups.md) and the contact rule (docs/contact.md): the campaign key setup and
   plan's --setup/--resolution round trip and refuse bad values with file:line:field or the option; an app
   set-up installs a plain point checker and OMPL's DiscreteMotionValidator at its resolution and counts
   checks; a campaign with both set-ups of a world records both in its database, with the checks per run; a
   path touching obstacles (zero clearance) is accepted by the exact models and passes the independent dense
   check, and one penetrating beyond the contact tolerance fails both. */
#include "BenchSupport.h"
#include "CliSupport.h"

#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "src/collision/Collision.h"
#include "src/metrics/Metrics.h"
#include "src/collision/Problem.h"
#include "src/collision/Validity.h"
#include "src/io/WorldIO.h"

#include <ompl/base/DiscreteMotionValidator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

using namespace mhplan;
using namespace mhplan::bench;
using namespace mhplan::test;
namespace ob = ompl::base;
namespace fs = std::filesystem;

namespace
{
    std::string refusal(const std::string &text)
    {
        try
        {
            parseCampaign(text, "c.yaml");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "(accepted)";
    }
} // namespace

TEST(Setups, CampaignKeyRoundTripsAndRefusesBadValues)
{
    const Campaign c = parseCampaign("setup: [exact, {app: {resolution: 0.004}}]\nworlds:\n  - bfo_case1\n"
                                     "  - {world: bfo_case2, setup: app}\nplanners: [RRTConnect]\n",
                                     "c.yaml");
    ASSERT_EQ(c.setups.size(), 2u);
    EXPECT_FALSE(c.setups[0].app());
    EXPECT_TRUE(c.setups[1].app());
    EXPECT_EQ(c.setups[1].resolution, 0.004);
    ASSERT_EQ(c.worlds[1].setups.size(), 1u);
    EXPECT_EQ(c.worlds[1].setups[0].resolution, kDefaultAppResolution);
    EXPECT_TRUE(c.worlds[0].setups.empty()); // the campaign's
    EXPECT_EQ(parseCampaign("worlds: [a]\nplanners: [RRTConnect]\n", "c.yaml").setups.size(), 1u);

    const std::string pre = "worlds: [a]\nplanners: [RRTConnect]\n";
    EXPECT_NE(refusal(pre + "setup: fast\n").find("c.yaml:3: field 'setup'"), std::string::npos)
        << refusal(pre + "setup: fast\n");
    EXPECT_NE(refusal(pre + "setup: fast\n").find("accepted: exact"), std::string::npos);
    EXPECT_NE(refusal(pre + "setup: {app: {resolution: 2}}\n").find("field 'setup.app.resolution'"),
              std::string::npos)
        << refusal(pre + "setup: {app: {resolution: 2}}\n");
    EXPECT_NE(refusal(pre + "setup: {app: {res: 0.1}}\n").find("res"), std::string::npos);
    EXPECT_NE(refusal(pre + "setup: [app, app]\n").find("listed twice"), std::string::npos);
    EXPECT_NE(refusal(pre + "setup: {exact: {resolution: 0.1}}\n").find("exact takes no settings"),
              std::string::npos);
    EXPECT_NE(refusal("worlds:\n  - {world: a, setup: []}\nplanners: [RRTConnect]\n").find("worlds[0].setup"),
              std::string::npos);
}

TEST(Setups, BothSetUpsOfAWorldAreTwoExperimentsWithTheirOwnFingerprints)
{
    const auto resolve = [](const std::string &n) { return resolveShipped(n); };
    const Campaign plain = parseCampaign("worlds: [bfo_case1]\nplanners: [RRTConnect]\n", "c.yaml");
    const Campaign both =
        parseCampaign("setup: [exact, app, {app: {resolution: 0.01}}]\nworlds: [bfo_case1]\n"
                      "planners: [RRTConnect]\n",
                      "c.yaml");
    const auto p = enumerateExperiments(plain, resolve);
    const auto b = enumerateExperiments(both, resolve);
    ASSERT_EQ(b.size(), 3 * p.size());
    EXPECT_EQ(b[0].name, p[0].name);
    EXPECT_EQ(b[0].configHash, p[0].configHash); // the exact set-up keeps its old fingerprint
    EXPECT_EQ(b[1].name, p[0].name + "-app");
    EXPECT_EQ(b[2].name, p[0].name + "-app0.01");
    EXPECT_NE(b[1].configHash, b[0].configHash);
    EXPECT_NE(b[2].configHash, b[1].configHash);
    EXPECT_EQ(b[1].seed, b[0].seed); // paired runs
    EXPECT_TRUE(b[2].setup.app());
}

TEST(Setups, AppSetUpIsAPointCheckerAndOmplsDiscreteValidatorAndCountsChecks)
{
    const World world = loadWorld(resolveShipped("bfo_case1"));
    const CollisionModelPtr model = makeCollisionModel(world);
    const auto ss = makeSimpleSetup(world, world.queries.front(), model, makeValiditySetup("app", 0.01));
    ss->setup();
    const auto &si = ss->getSpaceInformation();
    EXPECT_NE(dynamic_cast<const PointValidityChecker *>(si->getStateValidityChecker().get()), nullptr);
    EXPECT_EQ(dynamic_cast<const WorldValidityChecker *>(si->getStateValidityChecker().get()), nullptr);
    EXPECT_NE(dynamic_cast<const ob::DiscreteMotionValidator *>(si->getMotionValidator().get()), nullptr);
    EXPECT_DOUBLE_EQ(si->getStateValidityCheckingResolution(), 0.01);
    const CheckCounts before = checkCounts(*si);
    ob::ScopedState<> a(si), b(si);
    a[0] = world.queries.front().start.x;
    a[1] = world.queries.front().start.y;
    b[0] = a[0] + 0.01;
    b[1] = a[1];
    si->checkMotion(a.get(), b.get());
    const CheckCounts after = checkCounts(*si) - before;
    EXPECT_TRUE(after.haveState);
    EXPECT_EQ(after.motion, 1u);
    EXPECT_GE(after.state, 1u);

    const auto exact = makeSimpleSetup(world, world.queries.front(), model);
    EXPECT_NE(dynamic_cast<const WorldValidityChecker *>(
                  exact->getSpaceInformation()->getStateValidityChecker().get()),
              nullptr);
    EXPECT_THROW(makeValiditySetup("app", 0.9), InputError);
    EXPECT_THROW(makeValiditySetup("exact", 0.01), InputError);
    EXPECT_THROW(makeValiditySetup("fast", std::nan("")), InputError);
}

TEST(Setups, PlanOptionsRoundTripAndRefuse)
{
    const CliResult ok = runCliStdout(
        "plan bfo_case1 --planner RRTConnect --time 0.05 --seed 3 --setup app --resolution 0.004 "
        "--json --quiet");
    EXPECT_EQ(pyJson(ok.out, "d['setup'], d['resolution'], d['motion_checks'] > 0", "setup"),
              "app 0.004 True")
        << ok.out;
    const CliResult exact = runCliStdout("plan bfo_case1 --planner RRTConnect --time 0.05 --seed 3 --json");
    EXPECT_EQ(pyJson(exact.out, "d['setup'], d['resolution']", "setup"), "exact None") << exact.out;
    const CliResult bad = runCli("plan bfo_case1 --setup fast");
    EXPECT_EQ(bad.code, 1);
    EXPECT_NE(bad.out.find("--setup"), std::string::npos) << bad.out;
    const CliResult lone = runCli("plan bfo_case1 --resolution 0.01");
    EXPECT_EQ(lone.code, 1);
    EXPECT_NE(lone.out.find("--resolution belongs to --setup app"), std::string::npos) << lone.out;
    const CliResult range = runCli("compare bfo_case1 --planners RRTConnect --setup app --resolution 3");
    EXPECT_EQ(range.code, 1);
    EXPECT_NE(range.out.find("out of range"), std::string::npos) << range.out;
}

TEST(Setups, TheDatabaseRecordsEachExperimentsSetUpAndItsChecks)
{
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_setups_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    Campaign c = parseCampaign("time_limit: 0.05\nruns: 1\nplanner_data: false\nworlds:\n"
                               "  - {world: bfo_case1, setup: [exact, {app: {resolution: 0.005}}]}\n"
                               "planners: [RRTConnect]\n",
                               (dir / "c.yaml").string());
    c.database = (dir / "c.db").string();
    c.logDir = (dir / "logs").string();
    runCampaign(c, options());
    const Sql sql(c.database);
    const auto rows =
        sql.rows("SELECT experiments.validity_setup, experiments.validity_resolution, "
                 "runs.state_checks > 0, runs.motion_checks > 0, runs.collision_free IS NOT NULL "
                 "FROM runs JOIN experiments ON runs.experimentid = experiments.id ORDER BY "
                 "experiments.name");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"exact", "NULL", "1", "1", "1"}));
    EXPECT_EQ(rows[1][0], "app");
    EXPECT_NEAR(std::atof(rows[1][1].c_str()), 0.005, 1e-12);
    EXPECT_EQ(rows[1][2], "1");
    EXPECT_EQ(rows[1][3], "1");
    fs::remove_all(dir);
}

/* The zero-clearance disagreement (issue 31): a path pulled tight against a grid corner or a circle touches
   it; points computed along an accepted segment land up to an ulp inside. The exact models accept such a
   segment and the independent dense check (denseCollisionFree, isValid at points along it) must accept it
   too; a segment that really enters (beyond the contact tolerance) is refused by both. */
TEST(ContactRule, TouchingPathsPassTheDenseCheckAndPenetratingOnesFailBoth)
{
    World grid;
    grid.name = "contact";
    grid.bounds = {0.0, 10.0, 0.0, 10.0};
    auto cells = std::make_shared<OccupancyGrid>(10, 10, 1.0, Vec2{0.0, 0.0});
    cells->setBlocked(4, 4, true); // the wall [4, 6] x [4, 5]
    cells->setBlocked(5, 4, true);
    grid.grid = cells;
    World discs;
    discs.name = "discs";
    discs.bounds = {0.0, 10.0, 0.0, 10.0};
    discs.circles.push_back({{5.0, 5.0}, 1.3});
    for (const World *w : {&grid, &discs})
    {
        const CollisionModelPtr m = makeCollisionModel(*w);
        int touching = 0;
        for (int k = 0; k < 400; ++k)
        {
            // Lines through a contact point c, tangent to the obstacle there, with irrational-ish ends.
            const double u = 0.1 + 0.8 * k / 400.0;
            Vec2 c, dir;
            if (w == &grid)
            {
                // Lines touching the wall [4, 6] x [4, 5] at a bottom corner only, the wall on one side.
                c = k % 2 ? Vec2{4.0, 4.0} : Vec2{6.0, 4.0};
                dir = k % 2 ? Vec2{1.0, -0.2 - 2.0 * u} : Vec2{1.0, 0.2 + 2.0 * u};
            }
            else
            {
                const double t = 6.283185307179586 * u;
                c = Vec2{5.0, 5.0} + Vec2{std::cos(t), std::sin(t)} * 1.3;
                dir = {-std::sin(t), std::cos(t)};
            }
            const Vec2 a = c - dir * (1.1 + 0.3 * u), b = c + dir * (0.7 + 0.9 * u);
            if (!m->isValid(a) || !m->isValid(b))
                continue;
            ASSERT_TRUE(m->segmentValid(a, b)) << w->name << " k " << k;
            ++touching;
            // A waypoint at the contact, computed along the segment (as planners do): within rounding.
            const Vec2 cc = a + (b - a) * (distance(a, c) / distance(a, b));
            EXPECT_TRUE(m->segmentValid(a, cc) && m->segmentValid(cc, b)) << w->name << " k " << k;
            EXPECT_TRUE(denseCollisionFree({a, cc, b}, *m, 1e-3)) << w->name << " k " << k;
            EXPECT_TRUE(denseCollisionFree({a, c, b}, *m, 7e-4)) << w->name << " k " << k;
            // Pushed into the obstacle by 1e-6 (beyond the tolerance, 1e-8 here): refused by both.
            const Vec2 n = w == &grid ? (k % 2 ? Vec2{1.0, 1.0} : Vec2{-1.0, 1.0}) * std::sqrt(0.5)
                                      : (Vec2{5.0, 5.0} - c) * (1.0 / 1.3);
            const Vec2 in = c + n * 1e-6;
            EXPECT_FALSE(m->segmentValid(a + n * 1e-6, b + n * 1e-6)) << w->name << " k " << k;
            EXPECT_FALSE(m->isValid(in)) << w->name << " k " << k;
            EXPECT_FALSE(denseCollisionFree({a + n * 1e-6, in, b + n * 1e-6}, *m, 1e-3));
        }
        EXPECT_GT(touching, 100) << w->name;
    }
}
