// SPDX-License-Identifier: BSD-3-Clause
/* Tests of the simulator's controllers (src/sim/Controllers.h): names and parameters, an independent check
   that no trajectory overlaps a static obstacle, determinism per seed, robots joining and tasks assigned
   during a run, the U-shaped trap, 15 robots crossing, BFO on a static world, plan-then-follow replanning. */
#include "mhplan/planners/lattice/ThetaStar.h"
#include "mhplan/sim/Controllers.h"
#include "mhplan/sim/ScenarioIO.h"

#include <ompl/util/Console.h>

#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

using namespace mhplan;

namespace
{
    /** \brief Quiet OMPL's informational messages (the planners log every solve). */
    const bool kQuiet = []
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        return true;
    }();

    std::string errorOf(const std::function<void()> &f)
    {
        try
        {
            f();
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        ADD_FAILURE() << "no InputError";
        return "";
    }

    SimulationResult run(const Scenario &scenario, const std::string &controller, std::uint32_t seed = 1,
                         const std::map<std::string, std::string> &params = {})
    {
        ControllerPtr c = makeController(controller);
        for (const auto &kv : params)
            c->setParameter(kv.first, kv.second);
        Simulation sim(scenario, c, seed);
        return sim.run();
    }

    /** \brief The independent oracle: every recorded segment of every robot is valid for a fresh analytic
        model of the static world with that robot's radius; a completed run has no contact at all. */
    void expectSafe(const Scenario &scenario, const SimulationResult &result, bool contactFree = true)
    {
        for (std::size_t i = 0; i < result.robots.size(); ++i)
        {
            World world = scenario.world;
            world.robotRadius = scenario.robots[i].radius;
            world.queries.clear();
            const AnalyticCollisionModel model(world);
            const auto &pos = result.robots[i].positions;
            for (std::size_t k = 0; k + 1 < pos.size(); ++k)
                ASSERT_TRUE(model.segmentValid(pos[k], pos[k + 1]))
                    << result.controller << ": robot " << i << " overlaps a static obstacle between ("
                    << pos[k].x << ", " << pos[k].y << ") and (" << pos[k + 1].x << ", " << pos[k + 1].y
                    << ") at t = " << result.robots[i].times[k];
        }
        if (result.allDone && contactFree)
        {
            EXPECT_EQ(result.collisions(), 0u) << result.controller;
        }
    }

    /** \brief Two robots cross a pillar field while a disc moves across; a circle in the middle. */
    Scenario smallScenario()
    {
        return parseScenarioYaml(R"(
name: small
bounds: {xmin: 0, xmax: 6, ymin: 0, ymax: 6}
obstacles:
  - circle: {center: [3, 3.4], radius: 0.3}
  - rectangle: {min: [1.4, 4.4], max: [2.0, 5.0]}
moving_obstacles:
  - {name: m1, radius: 0.25, motion: {line: {from: [4.5, 0.5], to: [4.5, 5.5], speed: 0.15}}}
robots:
  - {name: a, start: [0.5, 3], heading: 0, goal: [5.5, 3]}
  - {name: b, start: [5.5, 2.5], heading: 180, goal: [0.5, 2.6]}
  - {name: c, start: [3, 0.5], heading: 90, goal: [3, 5.5]}
simulation: {dt: 0.05, time_limit: 80, stuck_timeout: 20, goal_tolerance: 0.05}
)",
                                 "small.yaml");
    }

    /** \brief Robot a has a second goal assigned at t = 30 s; robot b joins at t = 8 s. */
    Scenario joiningScenario()
    {
        return parseScenarioYaml(R"(
name: joining
bounds: {xmin: 0, xmax: 6, ymin: 0, ymax: 6}
obstacles:
  - circle: {center: [3, 1.6], radius: 0.3}
  - circle: {center: [3, 4.0], radius: 0.3}
robots:
  - name: a
    start: [0.5, 0.5]
    heading: 0
    tasks:
      - {goal: [5.5, 0.7], at: 0}
      - {goal: [5.4, 5.4], at: 30}
  - {name: b, start: [0.6, 5.4], heading: -90, join_time: 8, goal: [0.6, 2.5]}
simulation: {dt: 0.05, time_limit: 120, stuck_timeout: 20, goal_tolerance: 0.05}
)",
                                 "joining.yaml");
    }

    /** \brief 15 TurtleBots on a circle of radius 3 about (4, 4) swap to the antipodal points; a few
        static circles off the centre. */
    Scenario fifteenRobots()
    {
        std::ostringstream yaml;
        yaml << "name: fifteen\nbounds: {xmin: 0, xmax: 8, ymin: 0, ymax: 8}\nobstacles:\n"
             << "  - circle: {center: [5.2, 4.6], radius: 0.25}\n"
             << "  - circle: {center: [2.9, 3.1], radius: 0.25}\n"
             << "  - circle: {center: [3.8, 5.5], radius: 0.2}\nrobots:\n";
        yaml.precision(10);
        for (int k = 0; k < 15; ++k)
        {
            const double a = 2.0 * kPi * k / 15.0;
            const double x = 4.0 + 3.0 * std::cos(a), y = 4.0 + 3.0 * std::sin(a);
            yaml << "  - {name: r" << k << ", start: [" << x << ", " << y
                 << "], heading: " << a * 180.0 / kPi - 180.0 << ", goal: [" << 8.0 - x << ", " << 8.0 - y
                 << "]}\n";
        }
        yaml << "simulation: {dt: 0.05, time_limit: 200, stuck_timeout: 30, goal_tolerance: 0.05}\n";
        return parseScenarioYaml(yaml.str(), "fifteen.yaml");
    }
} // namespace

TEST(ControllerNames, KnownAndUnknown)
{
    const std::vector<std::string> names = controllerNames();
    for (const std::string n : {"dapf", "aapf", "bfo", "atbfo", "plan:ThetaStar", "plan:RRTConnect"})
    {
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
        EXPECT_EQ(makeController(n)->name(), n);
    }
    for (const std::string bad : {"apf", "plan:", "plan:Nope", "PLAN:ThetaStar", ""})
    {
        const std::string msg = errorOf([&] { makeController(bad); });
        EXPECT_NE(msg.find("'" + bad + "'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("dapf"), std::string::npos) << msg;
        EXPECT_NE(msg.find("plan:ThetaStar"), std::string::npos) << msg;
    }
}

TEST(ControllerNames, PlanDrawsFromTheRegistryItIsHanded)
{
    // A planner only this registry knows, counting its allocations.
    static int allocations = 0;
    PlannerRegistry registry = builtinPlanners();
    registry.add({"OnlyHere", "test", "Theta* under a name the built-in registry does not know",
                  [](const ompl::base::SpaceInformationPtr &si) -> ompl::base::PlannerPtr
                  {
                      ++allocations;
                      return std::make_shared<ThetaStar>(si);
                  }});
    const std::vector<std::string> names = controllerNames(registry);
    EXPECT_NE(std::find(names.begin(), names.end(), "plan:OnlyHere"), names.end());
    const std::vector<std::string> builtinNames = controllerNames();
    EXPECT_EQ(std::find(builtinNames.begin(), builtinNames.end(), "plan:OnlyHere"), builtinNames.end());
    EXPECT_NE(errorOf([] { makeController("plan:OnlyHere"); }).find("'plan:OnlyHere'"), std::string::npos);

    ControllerPtr c = makeController("plan:OnlyHere", registry);
    EXPECT_EQ(c->name(), "plan:OnlyHere");
    allocations = 0;
    c->setParameter("planner.resolution", "0.05"); // checked on a planner of the handed registry
    EXPECT_EQ(allocations, 1);
    EXPECT_NE(errorOf([&] { c->setParameter("planner.nope", "1"); }).find("nope"), std::string::npos);

    allocations = 0;
    const Scenario scenario = smallScenario();
    Simulation sim(scenario, c, 1);
    const SimulationResult r = sim.run();
    expectSafe(scenario, r, false);
    const double plans = c->counters().at("plans");
    EXPECT_GE(plans, static_cast<double>(scenario.robots.size()));
    EXPECT_GE(allocations, static_cast<int>(plans)) << "every plan allocates from the handed registry";
    EXPECT_TRUE(r.allDone);
}

TEST(ControllerParameters, SetListedAndRefused)
{
    ControllerPtr aapf = makeController("aapf");
    for (const std::string p : {"C_a", "C_o", "C_r", "rho", "phi_M", "k_a", "horizon", "safety_brake"})
        EXPECT_EQ(aapf->parameters().count(p), 1u) << p;
    aapf->setParameter("rho", "0.7");
    EXPECT_EQ(aapf->parameters().at("rho"), "0.7");

    std::string msg = errorOf([&] { aapf->setParameter("nope", "1"); });
    EXPECT_NE(msg.find("'nope'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("phi_M"), std::string::npos) << msg;
    msg = errorOf([&] { aapf->setParameter("rho", "-1"); });
    EXPECT_NE(msg.find("'rho'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[0.01, 100]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'-1'"), std::string::npos) << msg;
    errorOf([&] { aapf->setParameter("phi_M", "abc"); });
    errorOf([&] { aapf->setParameter("horizon", "nan"); });
    EXPECT_EQ(aapf->parameters().at("rho"), "0.7"); // unchanged by the refusals

    EXPECT_EQ(makeController("dapf")->parameters().count("phi_M"), 0u);
    errorOf([&] { makeController("dapf")->setParameter("phi_M", "30"); });

    ControllerPtr bfo = makeController("atbfo");
    bfo->setParameter("S", "20");
    msg = errorOf([&] { bfo->setParameter("S", "2.5"); });
    EXPECT_NE(msg.find("integer"), std::string::npos) << msg;
    errorOf([&] { bfo->setParameter("Ped", "1.5"); });
    errorOf([&] { bfo->setParameter("safety_brake", "2"); });

    ControllerPtr plan = makeController("plan:ThetaStar");
    plan->setParameter("planner.resolution", "0.05");
    plan->setParameter("plan_time", "2");
    EXPECT_EQ(plan->parameters().at("planner.resolution"), "0.05");
    EXPECT_EQ(plan->parameters().at("plan_time"), "2");
    msg = errorOf([&] { plan->setParameter("planner.nope", "1"); });
    EXPECT_NE(msg.find("nope"), std::string::npos) << msg;
    errorOf([&] { plan->setParameter("planner.resolution", "-3"); });
    errorOf([&] { plan->setParameter("plan_time", "0"); });
}

TEST(Controllers, DeterministicPerSeedAndSafe)
{
    const Scenario scenario = smallScenario();
    for (const std::string name : {"dapf", "aapf", "bfo", "plan:ThetaStar"})
    {
        // ThetaStar's searches end by themselves (far within the default plan_time of 0.5 s of wall clock,
        // but a slow or loaded machine could cut one there and change the path): 60 s is only a safety
        // net, so the two runs compared bit for bit do not depend on the machine's speed.
        std::map<std::string, std::string> params;
        if (name == "plan:ThetaStar")
            params["plan_time"] = "60";
        const SimulationResult a = run(scenario, name, 7, params);
        const SimulationResult b = run(scenario, name, 7, params);
        // Measured: plan:ThetaStar grazes the moving disc once in this scenario (its prediction is linear
        // and its detours tight); the static world is never touched by anyone.
        expectSafe(scenario, a, name != "plan:ThetaStar");
        ASSERT_EQ(a.robots.size(), b.robots.size());
        for (std::size_t i = 0; i < a.robots.size(); ++i)
        {
            ASSERT_EQ(a.robots[i].positions.size(), b.robots[i].positions.size()) << name;
            for (std::size_t k = 0; k < a.robots[i].positions.size(); ++k)
                ASSERT_EQ(a.robots[i].positions[k], b.robots[i].positions[k]) << name << " robot " << i;
        }
        EXPECT_EQ(a.counters, b.counters) << name;
        EXPECT_TRUE(a.allDone) << name;
    }
    // BFO draws from the seed: another seed walks another path.
    const SimulationResult c = run(scenario, "bfo", 8), d = run(scenario, "bfo", 7);
    EXPECT_NE(c.robots[0].positions, d.robots[0].positions);
    EXPECT_GT(d.counters.at("evaluations"), 0.0);
}

class JoinAndLateTask : public ::testing::TestWithParam<std::string>
{
};

TEST_P(JoinAndLateTask, DrivenToTheirGoals)
{
    const Scenario scenario = joiningScenario();
    const SimulationResult r = run(scenario, GetParam(), 3);
    expectSafe(scenario, r);
    ASSERT_TRUE(r.allDone) << GetParam() << ": done " << r.done << " stuck " << r.stuck;
    // Robot b appears at t = 8 s and is driven from there.
    EXPECT_DOUBLE_EQ(r.robots[1].times.front(), 8.0);
    EXPECT_LT(distance(r.robots[1].positions.back(), Vec2(0.6, 2.5)), 0.05 + 1e-9);
    // Robot a finished its first goal, waited for the second (assigned at 30 s) and reached it.
    EXPECT_LT(distance(r.robots[0].positions.back(), Vec2(5.4, 5.4)), 0.05 + 1e-9);
    EXPECT_LT(r.robots[0].traversalTime, r.makespan - 1.0); // the wait is not traversal time
    EXPECT_GT(r.makespan, 30.0);
}

INSTANTIATE_TEST_SUITE_P(Controllers, JoinAndLateTask,
                         ::testing::Values("dapf", "aapf", "bfo", "atbfo", "plan:ThetaStar"),
                         [](const auto &info)
                         {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), ':', '_');
                             return n;
                         });

TEST(Controllers, UTrapCatchesBothPotentialFields)
{
    const Scenario scenario =
        loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/mapf_u_trap.yaml");
    // Inside the U: between its arms (y 1.2 .. 2.8) and in front of its back wall (x 2.4 .. 3.6).
    auto insideU = [](const Vec2 &p) { return p.x > 2.4 && p.x < 3.6 && p.y > 1.2 && p.y < 2.8; };
    // Classic APF: the known local minimum in front of the back wall.
    const SimulationResult dapf = run(scenario, "dapf");
    expectSafe(scenario, dapf);
    EXPECT_EQ(dapf.robots[0].status, RobotStatus::Stuck);
    EXPECT_TRUE(insideU(dapf.robots[0].positions.back()));
    // Adaptive APF, measured: the rotated repulsion slides the robot along the back wall, but the side
    // "facing the target" flips when it crosses the U's axis, so it settles on the axis: trapped too.
    const SimulationResult aapf = run(scenario, "aapf");
    expectSafe(scenario, aapf);
    EXPECT_EQ(aapf.robots[0].status, RobotStatus::Stuck);
    EXPECT_TRUE(insideU(aapf.robots[0].positions.back()));
    EXPECT_NEAR(aapf.robots[0].positions.back().y, 2.0, 0.1);
    // A planner is not fooled.
    const SimulationResult plan = run(scenario, "plan:ThetaStar");
    expectSafe(scenario, plan);
    EXPECT_TRUE(plan.allDone);
}

TEST(Controllers, FifteenRobotsCrossAnOpenWorld)
{
    const Scenario scenario = fifteenRobots();
    const SimulationResult aapf = run(scenario, "aapf");
    expectSafe(scenario, aapf);
    EXPECT_TRUE(aapf.allDone) << "done " << aapf.done << " stuck " << aapf.stuck;
    EXPECT_EQ(aapf.collisions(), 0u);
    // Measured for the classic field: it finishes too in this open world, more slowly.
    const SimulationResult dapf = run(scenario, "dapf");
    expectSafe(scenario, dapf);
    EXPECT_TRUE(dapf.allDone) << "done " << dapf.done << " stuck " << dapf.stuck;
    EXPECT_LT(aapf.flowtime, dapf.flowtime);
    RecordProperty("aapf_flowtime", std::to_string(aapf.flowtime));
    RecordProperty("dapf_flowtime", std::to_string(dapf.flowtime));
}

TEST(Controllers, BfoReachesTheGoalOnAStaticWorld)
{
    // [BFO] case 1 (docs/algorithms.md 9), a point robot at 1 m/s as in the case-3 scenarios.
    const Scenario scenario = parseScenarioYaml(R"(
name: bfo_static
bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}
obstacles:
  - circle: {center: [2, 2], radius: 0.7}
  - circle: {center: [4, 4.1], radius: 0.7}
  - circle: {center: [7.2, 7], radius: 0.7}
  - circle: {center: [9, 8], radius: 0.7}
robots:
  - {name: robot, start: [0, 0], heading: 45, goal: [10, 10], radius: 0, max_speed: 1.0, max_turn_rate: 10}
simulation: {dt: 0.05, time_limit: 60, stuck_timeout: 20, goal_tolerance: 0.2}
)",
                                                "bfo_static.yaml");
    for (const std::string name : {"bfo", "atbfo"})
    {
        const SimulationResult r = run(scenario, name, 5);
        expectSafe(scenario, r);
        EXPECT_TRUE(r.allDone) << name;
        EXPECT_LT(r.robots[0].pathLength, 1.15 * std::sqrt(200.0)) << name;
        EXPECT_GT(r.counters.at("decisions"), 10.0) << name;
    }
}

TEST(Controllers, PlanReplansAroundACrossingObstacle)
{
    // The straight path (y = 2) is crossed by a disc moving down x = 3 just when the robot gets there.
    const Scenario scenario = parseScenarioYaml(R"(
name: cross
bounds: {xmin: 0, xmax: 6, ymin: 0, ymax: 4}
obstacles:
  - circle: {center: [1.5, 3.2], radius: 0.3}
moving_obstacles:
  - {name: m1, radius: 0.3, motion: {line: {from: [3, 3.7], to: [3, 0.3], speed: 0.12}}}
robots:
  - {name: a, start: [0.5, 2], heading: 0, goal: [5.5, 2]}
simulation: {dt: 0.05, time_limit: 100, stuck_timeout: 20, goal_tolerance: 0.05}
)",
                                                "cross.yaml");
    const SimulationResult r = run(scenario, "plan:ThetaStar");
    expectSafe(scenario, r);
    EXPECT_TRUE(r.allDone);
    EXPECT_EQ(r.collisions(), 0u);
    EXPECT_GE(r.counters.at("replans"), 1.0);
    EXPECT_EQ(r.counters.at("plans"), 1.0);
    // The robot left the straight line to let the disc pass.
    double deviation = 0.0;
    for (const Vec2 &p : r.robots[0].positions)
        deviation = std::max(deviation, std::abs(p.y - 2.0));
    EXPECT_GT(deviation, 0.05);
    // Without sensing (no replanning) it drives into the disc.
    const SimulationResult blind =
        run(scenario, "plan:ThetaStar", 1, {{"sense_range", "0"}, {"predict_time", "0"}});
    EXPECT_GT(blind.movingCollisions, 0u);
}

TEST(Controllers, CommandsAllocateNothingOnceWarm)
{
    Scenario scenario = smallScenario();
    scenario.settings.recordEvery = 1000000;
    for (const std::string name : {"dapf", "aapf", "bfo", "atbfo"})
    {
        const ControllerPtr c = makeController(name);
        Simulation sim(scenario, c, 3);
        for (int k = 0; k < 40; ++k)
            ASSERT_TRUE(sim.step());
        const unsigned long before = test::heapAllocations();
        for (int k = 0; k < 50; ++k)
            for (std::size_t i = 0; i < sim.robotCount(); ++i)
                if (sim.state(i).status == RobotStatus::Moving)
                    c->command(sim, i);
        EXPECT_EQ(test::heapAllocations() - before, 0u) << name;
    }
}

TEST(Controllers, BrakeMarginIsKeptFromRobotsAndObstacles)
{
    // Default margin (1e-6 m): robots may come arbitrarily close; with 0.1 m the brake keeps every robot at
    // least that far from every other robot and every static obstacle it approaches (robots then stall in
    // the crowded centre: the margin is a safety property, not a planner).
    const Scenario scenario =
        loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/mapf_15robots.yaml");
    for (const std::string controller : {"dapf", "aapf"})
    {
        const SimulationResult r = run(scenario, controller, 1, {{"brake_margin", "0.1"}});
        EXPECT_EQ(r.collisions(), 0u) << controller;
        EXPECT_GE(r.minRobotDistance, 0.1 - 1e-9) << controller;
        EXPECT_GE(r.minObstacleClearance, 0.1 - 1e-9) << controller;
    }
    ControllerPtr c = makeController("aapf");
    EXPECT_EQ(c->parameters().at("brake_margin"), "1e-06");
    EXPECT_THROW(c->setParameter("brake_margin", "2"), InputError);
}
