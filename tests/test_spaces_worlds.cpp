// SPDX-License-Identifier: BSD-3-Clause
/* SE(2)-based worlds (docs/spaces.md, "Rigid-body and car worlds"): the world file's new fields and their
   errors (file:line:field), the YAML round trip, the shipped worlds solved by RRT* within an iteration
   budget (paths checked independently), the CLI (plan, worlds --json, optimum refused), and the small
   campaign benchmarks/spaces_smoke.yaml end to end with its report. */
#include "CliSupport.h"

#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "src/metrics/Metrics.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidValidity.h"
#include "src/io/WorldIO.h"
#include "src/optimum/Optimum.h"
#include "src/registry/Registry.h"

#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace mhplan;
using namespace mhplan::test;
namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace fs = std::filesystem;

namespace
{
    std::string parseError(const std::string &text)
    {
        try
        {
            parseWorldYaml(text, "test.yaml");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }

    const std::string kBox = "bounds: [0, 10, 0, 10]\n";
    const std::string kBar = "robot: {polygon: [[-1, -0.2], [1, -0.2], [1, 0.2], [-1, 0.2]]}\n";

    std::string sql(const std::string &db, const std::string &query)
    {
        sqlite3 *h = nullptr;
        sqlite3_open_v2(db.c_str(), &h, SQLITE_OPEN_READONLY, nullptr);
        sqlite3_stmt *st = nullptr;
        std::string out;
        if (sqlite3_prepare_v2(h, query.c_str(), -1, &st, nullptr) == SQLITE_OK &&
            sqlite3_step(st) == SQLITE_ROW)
        {
            const unsigned char *t = sqlite3_column_text(st, 0);
            out = t ? reinterpret_cast<const char *>(t) : "NULL";
        }
        else
            ADD_FAILURE() << sqlite3_errmsg(h) << " in " << query;
        sqlite3_finalize(st);
        sqlite3_close(h);
        return out;
    }
} // namespace

TEST(SpacesWorlds, ReadsTheNewFields)
{
    const World w = parseWorldYaml("space: reeds_shepp\nturning_radius: 1.5\n" + kBox + kBar +
                                       "queries: [{start: [2, 2, 0.5], goal: [8, 8]}]\n",
                                   "ok.yaml");
    EXPECT_EQ(w.space, SpaceType::ReedsShepp);
    EXPECT_DOUBLE_EQ(w.turningRadius, 1.5);
    ASSERT_EQ(w.robotPolygon.size(), 4u);
    EXPECT_NEAR(w.robotReach(), std::hypot(1.0, 0.2), 1e-12);
    EXPECT_DOUBLE_EQ(w.queries[0].startYaw, 0.5);
    EXPECT_DOUBLE_EQ(w.queries[0].goalYaw, 0.0); // optional, default 0
    // A disc robot in SE(2); r2 stays the default.
    const World d = parseWorldYaml("space: se2\nrobot: {radius: 0.3}\n" + kBox, "disc.yaml");
    EXPECT_TRUE(d.robotPolygon.empty());
    EXPECT_EQ(parseWorldYaml(kBox, "r2.yaml").space, SpaceType::R2);
    // The round trip keeps every field.
    const World again = parseWorldYaml(worldToYaml(w), "again.yaml");
    EXPECT_EQ(again.space, w.space);
    EXPECT_DOUBLE_EQ(again.turningRadius, w.turningRadius);
    EXPECT_EQ(again.robotPolygon, w.robotPolygon);
    EXPECT_DOUBLE_EQ(again.queries[0].startYaw, 0.5);
}

TEST(SpacesWorlds, RefusesBadFieldsWithFileLineAndField)
{
    struct Case
    {
        std::string text;
        std::string expect; // '|'-separated parts the message must contain
    };
    const std::vector<Case> cases = {
        {"space: se3\n" + kBox,
         "test.yaml:1: field 'space'|unknown space 'se3'|r2, se2, dubins, reeds_shepp"},
        {"space: [se2]\n" + kBox, "test.yaml:1: field 'space'"},
        {"space: dubins\n" + kBox, "field 'turning_radius'|needs 'turning_radius: R'"},
        {"space: dubins\nturning_radius: 0\n" + kBox, "test.yaml:2: field 'turning_radius'|must be > 0"},
        {"space: reeds_shepp\nturning_radius: -1\n" + kBox,
         "test.yaml:2: field 'turning_radius'|must be > 0"},
        {"space: dubins\nturning_radius: wide\n" + kBox, "test.yaml:2: field 'turning_radius'"},
        {"space: se2\nturning_radius: 1\n" + kBox, "test.yaml:2: field 'turning_radius'|applies only to"},
        {kBox + "turning_radius: 1\n", "field 'turning_radius'|applies only to"},
        {"space: se2\n" + kBox + "robot: {radius: 0.2, polygon: [[0, 0], [1, 0], [0, 1]]}\n",
         "test.yaml:3: field 'robot'|not both"},
        {kBox + kBar, "test.yaml:2: field 'robot.polygon'|needs 'space: se2'"},
        {"space: se2\n" + kBox + "robot: {polygon: [[0, 0], [1, 1], [1, 0], [0, 1]]}\n",
         "test.yaml:3: field 'robot.polygon'|not simple"},
        {"space: se2\n" + kBox + "robot: {polygon: [[0, 0], [1, 0]]}\n", "field 'robot.polygon'|at least 3"},
        {"space: se2\n" + kBox + "robot: {polygon: [[0, 0], [1, 0], [1]]}\n", "field 'robot.polygon[2]'"},
        {"space: se2\n" + kBox + "robot: {shape: [[0, 0]]}\n", "field 'robot.shape'|unknown key"},
        {kBox + "queries: [{start: [1, 1, 0.5], goal: [2, 2]}]\n",
         "test.yaml:2: field 'queries[0].start'|heading [x, y, yaw] needs 'space: se2'"},
        {"space: se2\n" + kBox + "queries: [{start: [1, 1, 0, 3], goal: [2, 2]}]\n",
         "field 'queries[0].start'|expected a pose [x, y, yaw]"},
        {"space: se2\n" + kBox + "queries: [{start: [1, 1, north], goal: [2, 2]}]\n",
         "field 'queries[0].start[2]'"},
        {"space: se2\nspace: se2\n" + kBox, "space"},
        // Valid as a point, but the bar at this heading overlaps the wall / leaves the bounds.
        {"space: se2\n" + kBox + kBar + "obstacles: [{rectangle: {min: [4, 0], max: [5, 10]}}]\n" +
             "queries: [{start: [3.5, 5, 0], goal: [8, 5, 1.5707963]}]\n",
         "test.yaml:5: field 'queries[0].start'|(3.5, 5, yaw 0) is in collision"},
        {"space: se2\n" + kBox + kBar + "queries: [{start: [5, 0.1, 0], goal: [8, 5]}]\n",
         "field 'queries[0].start'|out of bounds"},
    };
    for (const Case &c : cases)
    {
        const std::string msg = parseError(c.text);
        ASSERT_FALSE(msg.empty()) << "accepted:\n" << c.text;
        std::stringstream parts(c.expect);
        std::string part;
        while (std::getline(parts, part, '|'))
            EXPECT_NE(msg.find(part), std::string::npos) << "message '" << msg << "' lacks '" << part << "'";
    }
}

TEST(SpacesWorlds, ShippedWorldsAreSolvedByRrtStar)
{
    // Iteration-bounded, fixed seed (one process per test under CTest).
    ompl::RNG::setSeed(17);
    const unsigned int kIterations = 1000;
    for (const std::string name : {"se2_narrow_passage", "reeds_shepp_parking", "dubins_circles"})
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
        ASSERT_TRUE(w.isRigid()) << name;
        const og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
        ss->setPlanner(builtinPlanners().create("RRTstar", ss->getSpaceInformation(), {}));
        const ob::PlannerStatus status = ss->solve(ob::IterationTerminationCondition(kIterations));
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << name;
        const og::PathGeometric &path = ss->getSolutionPath();
        const RigidPathMetrics m =
            rigidPathMetrics(w, *ss->getSpaceInformation(), path, RigidBodyModel(w), defaultMetricStep(w));
        EXPECT_TRUE(m.collisionFree) << name;
        EXPECT_GT(m.minClearance, 0.0) << name;
        // The reported cost is the objective's, in the space's metric.
        EXPECT_NEAR(
            m.length,
            ss->getProblemDefinition()->getSolutionPath()->cost(ss->getOptimizationObjective()).value(),
            1e-9 * m.length)
            << name;
        const Pose2 end = statePose(path.getState(path.getStateCount() - 1));
        EXPECT_NEAR(end.yaw, w.queries[0].goalYaw, 1e-6) << name;
    }
}

TEST(SpacesWorlds, CliPlansShowsAndRefusesTheOptimum)
{
    const auto plan = runCli("plan se2_narrow_passage --planner RRTstar --time 2 --seed 3 --quiet");
    EXPECT_EQ(plan.code, 0) << plan.out;
    EXPECT_TRUE(contains(plan.out, "space:     se2")) << plan.out;
    EXPECT_TRUE(contains(plan.out, "cost:      ")) << plan.out;
    EXPECT_TRUE(contains(plan.out, "yaw 1.5708")) << plan.out;
    EXPECT_TRUE(contains(plan.out, "valid:     yes")) << plan.out;
    const auto rs = runCli("plan reeds_shepp_parking --planner RRTstar --time 2 --seed 3 --quiet");
    EXPECT_TRUE(contains(rs.out, "cusps:     ")) << rs.out;
    EXPECT_TRUE(contains(rs.out, "space:     reeds_shepp (turning radius 1.2)")) << rs.out;
    // OMPL warns that RRT* wants a symmetric space (on stderr, which runCliStdout's "2>/dev/null 2>&1" still
    // merges): the document starts at its first brace.
    const auto json = runCliStdout("plan dubins_circles --planner RRTstar --time 1 --seed 3 --json");
    EXPECT_EQ(pyJson(json.out.substr(std::min(json.out.find('{'), json.out.size())),
                     "(d['space'], d['world']['turning_radius'], len(d['poses'][0]), d['optimum'])"),
              "('dubins', 1, 3, None)");

    const auto worlds =
        runCliStdout("worlds " + std::string(MHPLAN_ENVIRONMENTS_DIR) + "/reeds_shepp_parking.yaml --json");
    ASSERT_EQ(worlds.code, 0);
    EXPECT_EQ(pyJson(worlds.out,
                     "(d['worlds'][0]['space'], d['worlds'][0]['turning_radius'], "
                     "len(d['worlds'][0]['robot_polygon']), d['worlds'][0]['queries'][0]['start_yaw'])"),
              "('reeds_shepp', 1.2, 4, 0)");
    // r2 worlds keep their fields: no space fields.
    const auto r2 = runCliStdout("worlds bfo_case1 --json");
    EXPECT_EQ(pyJson(r2.out, "'space' in d['worlds'][0]"), "False");

    const auto opt = runCli("optimum se2_narrow_passage");
    EXPECT_EQ(opt.code, 1);
    EXPECT_TRUE(contains(opt.out, "no exact optimum for space se2: ")) << opt.out;
    EXPECT_THROW(
        computeOptimum(loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/dubins_circles.yaml"), Query{}),
        InputError);
}

TEST(SpacesWorlds, SmokeCampaignAndReport)
{
    bench::Campaign c = bench::loadCampaign(std::string(MHPLAN_SOURCE_DIR) + "/benchmarks/spaces_smoke.yaml");
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_spaces_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    c.database = (dir / "spaces.db").string();
    c.logDir = (dir / "logs").string();
    bench::RunOptions opt;
    opt.jobs = 2;
    opt.progressBar = false;
    opt.resolveWorld = [](const std::string &name)
    { return std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml"; };
    const bench::CampaignSummary s = bench::runCampaign(c, opt);
    EXPECT_EQ(s.experiments, 3u);
    EXPECT_EQ(s.failed, 0u) << (s.errors.empty() ? "" : s.errors[0]);
    const std::string db = c.database;
    EXPECT_EQ(sql(db, "SELECT group_concat(space, ',') FROM (SELECT space FROM experiments ORDER BY space)"),
              "dubins,reeds_shepp,se2");
    // No exact optimum: the optimum columns are empty.
    EXPECT_EQ(sql(db,
                  "SELECT count(*) FROM runs WHERE exact_optimum_length IS NOT NULL OR optimality_gap IS NOT "
                  "NULL"),
              "0");
    EXPECT_EQ(sql(db, "SELECT count(*) FROM runs"), "12");
    // RRT* checks its motions in their direction: every path it returns passes the independent check. (PRM*
    // joins milestones both ways after checking one direction: in the asymmetric Dubins space its paths may
    // fail the check, and the database says so.)
    EXPECT_EQ(sql(db,
                  "SELECT count(*) FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id WHERE p.name = "
                  "'geometric_RRTstar' AND r.status = 6 AND r.collision_free = 0"),
              "0");
    EXPECT_NE(sql(db, "SELECT count(*) FROM runs WHERE status = 6 AND collision_free = 1"), "0");
    EXPECT_EQ(sql(db,
                  "SELECT count(*) FROM runs r JOIN experiments e ON r.experimentid = e.id WHERE e.space = "
                  "'reeds_shepp' AND r.status = 6 AND r.cusps IS NULL"),
              "0");
    // The path length is the objective's cost (the last improvement's). Not for PRM* in the Dubins space: it
    // reports the cost of its undirected roadmap, whose edges it checked and costed in one direction only.
    EXPECT_EQ(
        sql(db,
            "SELECT count(*) FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p "
            "ON r.plannerid = p.id WHERE r.status = 6 AND NOT (e.space = 'dubins' AND p.name = "
            "'geometric_PRMstar') AND abs((SELECT cost FROM improvements WHERE runid = r.id ORDER BY time "
            "DESC, cost ASC LIMIT 1) - r.path_length) > 1e-9 * r.path_length"),
        "0");

    // The machine's load while each experiment ran (benchmarks/README.md), stated by the report.
    EXPECT_EQ(
        sql(db,
            "SELECT count(*) FROM experiments WHERE cpu_share > 0 AND cpu_share < 2 AND load_average >= 0 "
            "AND cores_available >= 1"),
        "3");
    // Paths with the robot's heading: three numbers per point ("x y yaw;").
    EXPECT_EQ(sql(db, "SELECT count(*) FROM paths WHERE length(substr(points, 1, instr(points, ';'))) - "
                      "length(replace(substr(points, 1, instr(points, ';')), ' ', '')) != 2"),
              "0");
    EXPECT_NE(sql(db, "SELECT count(*) FROM paths"), "0");
    const auto report = runCli("report " + db + " -o " + (dir / "report").string());
    ASSERT_EQ(report.code, 0) << report.out;
    std::ifstream in(dir / "report" / "index.html");
    std::stringstream html;
    html << in.rdbuf();
    EXPECT_TRUE(contains(html.str(), "gaps are to the best found cost")) << "the ranking names its reference";
    EXPECT_TRUE(contains(html.str(), "median gap to best found"));
    EXPECT_TRUE(contains(html.str(), "Machine load recorded by the campaign: the planners had "));
    EXPECT_TRUE(contains(html.str(), "The robot's footprint is drawn along each planner's best path"));
    EXPECT_TRUE(fs::exists(dir / "report" / "box_reeds_shepp_parking-default.png"));
    fs::remove_all(dir);
}
