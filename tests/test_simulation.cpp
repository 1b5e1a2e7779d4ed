// SPDX-License-Identifier: BSD-3-Clause
/* Tests of the simulator core and scenario files (src/sim/Simulation.h, src/sim/ScenarioIO.h), with
   controllers defined here so that the physics is tested independently of mhplan's controllers. */
#include "src/sim/ScenarioIO.h"
#include "src/sim/Simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace mhplan;

namespace
{
    /** \brief Heads straight for the goal at full speed (optionally with a random perturbation). */
    class StraightController : public Controller
    {
      public:
        explicit StraightController(double noise = 0.0) : noise_(noise) {}
        std::string name() const override { return "straight"; }
        void reset(const Simulation &, ompl::RNG &rng) override
        {
            rng_ = &rng;
            started.clear();
        }
        void taskStarted(const Simulation &sim, std::size_t i) override
        {
            started.emplace_back(i, sim.time());
        }
        Command command(const Simulation &sim, std::size_t i) override
        {
            const Vec2 d = sim.state(i).goal - sim.state(i).position;
            const double n = norm(d);
            Vec2 v = n > 0 ? d / n * sim.spec(i).maxSpeed : Vec2();
            if (noise_ > 0.0)
                v = v + Vec2(rng_->uniformReal(-noise_, noise_), rng_->uniformReal(-noise_, noise_));
            return {v};
        }
        std::vector<std::pair<std::size_t, double>> started;

      private:
        double noise_;
        ompl::RNG *rng_{nullptr};
    };

    Scenario openScenario()
    {
        return parseScenarioYaml(R"(
name: open
bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}
robots:
  - {name: a, start: [1, 1], heading: 0, goal: [9, 1]}
simulation: {dt: 0.05, time_limit: 100}
)",
                                 "open.yaml");
    }

    std::string expectError(const std::string &text)
    {
        try
        {
            parseScenarioYaml(text, "bad.yaml");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        ADD_FAILURE() << "no InputError for:\n" << text;
        return "";
    }
} // namespace

TEST(Motion, LinePingPongAndCircle)
{
    Motion line;
    line.kind = Motion::Kind::Line;
    line.from = {0, 0};
    line.to = {2, 0};
    line.speed = 0.5;
    EXPECT_NEAR(line.positionAt(1.0).x, 0.5, 1e-12);
    EXPECT_NEAR(line.positionAt(4.0).x, 2.0, 1e-12);
    EXPECT_NEAR(line.positionAt(5.0).x, 1.5, 1e-12); // on the way back
    EXPECT_NEAR(line.positionAt(8.0).x, 0.0, 1e-12);
    EXPECT_NEAR(line.velocityAt(5.0).x, -0.5, 1e-12);

    Motion c;
    c.kind = Motion::Kind::Circle;
    c.center = {9.5, 9.5};
    c.radius = 1.0;
    c.angularSpeed = 0.2;
    for (double t : {0.0, 1.3, 7.7, 31.0})
    {
        EXPECT_NEAR(distance(c.positionAt(t), c.center), 1.0, 1e-12);
        // The velocity is the derivative of the position.
        const Vec2 numeric = (c.positionAt(t + 1e-6) - c.positionAt(t - 1e-6)) / 2e-6;
        EXPECT_NEAR(numeric.x, c.velocityAt(t).x, 1e-6);
        EXPECT_NEAR(numeric.y, c.velocityAt(t).y, 1e-6);
    }
}

TEST(ScenarioIO, ShippedScenariosLoad)
{
    std::size_t count = 0;
    for (const auto &e :
         std::filesystem::directory_iterator(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios"))
    {
        if (e.path().extension() != ".yaml")
            continue;
        ++count;
        Scenario s;
        ASSERT_NO_THROW(s = loadScenario(e.path().string())) << e.path();
        EXPECT_FALSE(s.robots.empty());
        EXPECT_FALSE(s.source.empty()) << e.path() << " must say where it comes from";
        EXPECT_FALSE(s.assumptions.empty()) << e.path() << " must state its assumptions";
    }
    EXPECT_GE(count, 7u);
    const Scenario m15 = loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/mapf_15robots.yaml");
    EXPECT_EQ(m15.robots.size(), 15u);
    EXPECT_DOUBLE_EQ(m15.robots[0].maxSpeed, 0.22);
    EXPECT_DOUBLE_EQ(m15.robots[0].maxTurnRate, 2.84);
    EXPECT_DOUBLE_EQ(m15.robots[0].radius, 0.105);
    EXPECT_DOUBLE_EQ(m15.reference.at("traversal_time_reduction_percent"), 50.0);
    const Scenario c3 =
        loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/bfo_case3_lines.yaml");
    ASSERT_EQ(c3.movingObstacles.size(), 6u);
    // The paper's initial positions.
    const Vec2 initial[] = {{1.5, 1}, {3, 3}, {5.5, 4.1}, {6, 5}, {8, 6}, {11, 10}};
    for (std::size_t j = 0; j < 6; ++j)
    {
        EXPECT_NEAR(c3.movingObstacles[j].motion.positionAt(0).x, initial[j].x, 1e-12) << j;
        EXPECT_NEAR(c3.movingObstacles[j].motion.positionAt(0).y, initial[j].y, 1e-12) << j;
        EXPECT_DOUBLE_EQ(c3.movingObstacles[j].radius, 0.4);
    }
}

TEST(ScenarioIO, WorldFromAFile)
{
    const std::string dir = ::testing::TempDir();
    const Scenario s = parseScenarioYaml(
        "world: " + std::string(MHPLAN_ENVIRONMENTS_DIR) +
            "/bfo_case1.yaml\nrobots:\n  - {start: [0.5, 0.5], goal: [9.5, 9.5], radius: 0.1}\n",
        dir + "/s.yaml");
    EXPECT_EQ(s.world.circles.size(), 4u);
    EXPECT_TRUE(s.world.queries.empty());
    EXPECT_EQ(s.robots[0].name, "r1");
}

TEST(ScenarioIO, BadInputIsRefusedWithFileLineAndField)
{
    const std::string head = "bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\n"
                             "obstacles:\n  - circle: {center: [5, 5], radius: 1}\n";
    std::string e = expectError(head + "robots:\n  - {start: [1, 1], goal: [9, 9], colour: red}\n");
    EXPECT_NE(e.find("bad.yaml:5"), std::string::npos) << e;
    EXPECT_NE(e.find("colour"), std::string::npos) << e;
    e = expectError(head + "robots:\n  - {start: [5, 5.5], goal: [9, 9]}\n");
    EXPECT_NE(e.find("robots[0].start"), std::string::npos) << e;
    EXPECT_NE(e.find("collision"), std::string::npos) << e;
    e = expectError(
        head + "robots:\n  - {start: [1, 1], goal: {circle: {center: [5, 5], radius: 1.05, period: 10}}}\n");
    EXPECT_NE(e.find("robots[0].goal"), std::string::npos) << e;
    e = expectError(head + "robots:\n  - {start: [1, 1], join_time: 5, tasks: [{goal: [9, 9], at: 2}]}\n");
    EXPECT_NE(e.find("assigned before the robot joins"), std::string::npos) << e;
    e = expectError(head +
                    "robots:\n  - {start: [1, 1], goal: [9, 9]}\n  - {start: [1.1, 1], goal: [9, 8]}\n");
    EXPECT_NE(e.find("overlaps"), std::string::npos) << e;
    e = expectError(head + "robots:\n  - {start: [1, 1], goal: [9, 9], tasks: [{goal: [2, 2]}]}\n");
    EXPECT_NE(e.find("exactly one of 'goal'"), std::string::npos) << e;
    e = expectError(
        head + "moving_obstacles:\n  - {radius: 0.3, motion: {line: {from: [1, 1], to: [2, 2], speed: -1}}}\n"
               "robots:\n  - {start: [1, 1], goal: [9, 9]}\n");
    EXPECT_NE(e.find("moving_obstacles[0].motion.line.speed"), std::string::npos) << e;
    e = expectError(head + "robots:\n  - {start: [1, 1], goal: [9, 9]}\nsimulation: {dt: 0}\n");
    EXPECT_NE(e.find("simulation.dt"), std::string::npos) << e;
    e = expectError(head + "robots: []\n");
    EXPECT_NE(e.find("robots"), std::string::npos) << e;
    e = expectError(
        head + "queries:\n  - {start: [1, 1], goal: [9, 9]}\nrobots:\n  - {start: [1, 1], goal: [9, 9]}\n");
    EXPECT_NE(e.find("queries"), std::string::npos) << e;
    EXPECT_THROW(loadScenario("/nonexistent/scenario.yaml"), InputError);
}

TEST(Simulation, KinematicLimitsAndArrival)
{
    const Scenario sc = openScenario();
    auto ctrl = std::make_shared<StraightController>();
    Simulation sim(sc, ctrl, 1);
    const SimulationResult r = sim.run();
    ASSERT_TRUE(r.allDone);
    const RobotResult &a = r.robots[0];
    EXPECT_EQ(a.status, RobotStatus::Done);
    // 8 m less the goal tolerance (0.05) at 0.22 m/s, heading already right, within one step.
    EXPECT_NEAR(a.traversalTime, 7.95 / 0.22, 0.051);
    EXPECT_NEAR(a.pathLength, 7.95, 0.012);
    EXPECT_NEAR(r.makespan, a.traversalTime, 1e-9);
    EXPECT_NEAR(r.flowtime, a.traversalTime, 1e-9);
    for (std::size_t k = 1; k < a.positions.size(); ++k)
        EXPECT_LE(distance(a.positions[k], a.positions[k - 1]), 0.22 * 0.05 + 1e-12);
    EXPECT_EQ(r.collisions(), 0u);
    EXPECT_EQ(r.robotSteps, r.steps);
}

TEST(Simulation, TurnRateIsLimited)
{
    Scenario sc = openScenario();
    sc.robots[0].heading = kPi; // facing away from the goal
    Simulation sim(sc, std::make_shared<StraightController>(), 1);
    const SimulationResult r = sim.run();
    ASSERT_TRUE(r.allDone);
    const RobotResult &a = r.robots[0];
    for (std::size_t k = 1; k < a.headings.size(); ++k)
    {
        double d = std::abs(a.headings[k] - a.headings[k - 1]);
        d = std::min(d, 2 * kPi - d);
        EXPECT_LE(d, 2.84 * 0.05 + 1e-9);
    }
    // Turning 180 degrees takes pi / 2.84 s, during which it cannot drive toward the goal.
    EXPECT_GT(a.traversalTime, 8.0 / 0.22 + 0.5);
}

TEST(Simulation, WallsStopTheRobotAndCountOneCollision)
{
    Scenario sc = parseScenarioYaml(R"(
bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 4}
obstacles:
  - rectangle: {min: [4, 0], max: [5, 4]}
robots:
  - {start: [1, 2], heading: 0, goal: [9, 2]}
simulation: {dt: 0.05, time_limit: 200, stuck_timeout: 10}
)",
                                    "wall.yaml");
    Simulation sim(sc, std::make_shared<StraightController>(), 1);
    const SimulationResult r = sim.run();
    EXPECT_FALSE(r.allDone);
    EXPECT_EQ(r.stuck, 1u);
    EXPECT_EQ(r.staticCollisions, 1u); // one contact episode, however long it lasts
    const RobotResult &a = r.robots[0];
    // Independent check: the robot's disc never overlaps the wall.
    for (const Vec2 &p : a.positions)
        EXPECT_LE(p.x, 4.0 - 0.105 + 1e-9);
    EXPECT_NEAR(a.positions.back().x, 4.0 - 0.105, 1e-6);
    EXPECT_LT(r.simulatedTime, 200.0);
}

TEST(Simulation, RobotAndMovingObstacleContactsAreCounted)
{
    Scenario sc = parseScenarioYaml(R"(
bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}
moving_obstacles:
  - {name: crosser, radius: 0.3, motion: {line: {from: [5, 0.5], to: [5, 9.5], speed: 0.25}}}
robots:
  - {name: a, start: [1, 3.2], heading: 0, goal: [9, 3.2]}
  - {name: b, start: [9, 3.25], heading: 180, goal: [1, 3.25]}
simulation: {dt: 0.05, time_limit: 100}
)",
                                    "cross.yaml");
    Simulation sim(sc, std::make_shared<StraightController>(), 1);
    const SimulationResult r = sim.run();
    // The straight controller ignores everything: the two robots pass through each other once, and the
    // crossing obstacle (at y = 3.2 around t = 10.8 s, when the robots are at x = 3.4 and 6.6) misses them.
    EXPECT_EQ(r.robotCollisions, 1u);
    EXPECT_LT(r.minRobotDistance, 0.0);
    EXPECT_TRUE(r.allDone);
    EXPECT_EQ(r.robots[0].collisions, 1u);

    // Now time the obstacle to meet robot a: at x = 5 when a gets there (t = 4 / 0.22 = 18.2 s).
    sc.movingObstacles[0].motion.from = {5, 3.2 - 0.25 * 4.0 / 0.22};
    sc.robots.pop_back();
    Simulation hit(sc, std::make_shared<StraightController>(), 1);
    const SimulationResult h = hit.run();
    EXPECT_GE(h.movingCollisions, 1u);
    EXPECT_LT(h.minObstacleClearance, 0.0);
}

TEST(Simulation, JoiningRobotsAndLateTasks)
{
    Scenario sc = parseScenarioYaml(R"(
bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}
robots:
  - name: a
    start: [1, 1]
    heading: 0
    tasks:
      - {goal: [3, 1], at: 0}
      - {goal: [3, 3], at: 30}
  - {name: b, start: [1, 5], heading: 0, join_time: 12, goal: [4, 5]}
simulation: {dt: 0.05, time_limit: 100}
)",
                                    "join.yaml");
    auto ctrl = std::make_shared<StraightController>();
    Simulation sim(sc, ctrl, 1);
    while (sim.time() < 11.0)
        sim.step();
    EXPECT_FALSE(sim.present(1));
    EXPECT_EQ(sim.state(0).status, RobotStatus::Waiting); // first task done after 9.1 s, next at 30 s
    const SimulationResult r = sim.run();
    ASSERT_TRUE(r.allDone);
    // taskStarted: a at 0, b when it joins at 12, a's second task at 30.
    ASSERT_EQ(ctrl->started.size(), 3u);
    EXPECT_EQ(ctrl->started[1].first, 1u);
    EXPECT_NEAR(ctrl->started[1].second, 12.0, 1e-9);
    EXPECT_EQ(ctrl->started[2].first, 0u);
    EXPECT_NEAR(ctrl->started[2].second, 30.0, 1e-9);
    // b's trajectory starts when it joins; waiting is not traversal time.
    EXPECT_NEAR(r.robots[1].times.front(), 12.0, 1e-9);
    EXPECT_NEAR(r.robots[1].traversalTime, 2.95 / 0.22, 0.051);
    EXPECT_LT(r.robots[0].traversalTime, 4.0 / 0.22 + 2.0);
    EXPECT_GT(r.makespan, 30.0 + 2.0 / 0.22 - 0.1);
}

TEST(Simulation, MovingTargetIsReached)
{
    const Scenario sc =
        loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/bfo_case3_moving_target.yaml");
    Scenario free = sc;
    free.movingObstacles.clear();
    Simulation sim(free, std::make_shared<StraightController>(), 1);
    const SimulationResult r = sim.run();
    ASSERT_TRUE(r.allDone);
    const Vec2 end = r.robots[0].positions.back();
    const Vec2 target = free.robots[0].tasks[0].goal.positionAt(r.robots[0].times.back());
    EXPECT_LE(distance(end, target), free.settings.goalTolerance + 1e-9);
    EXPECT_GT(distance(target, free.robots[0].tasks[0].goal.positionAt(0)), 0.1); // it did move
}

TEST(Simulation, DeterministicPerSeed)
{
    const Scenario sc = openScenario();
    auto run = [&](std::uint32_t seed)
    {
        Simulation sim(sc, std::make_shared<StraightController>(0.1), seed);
        return sim.run();
    };
    const SimulationResult a = run(7), b = run(7), c = run(8);
    ASSERT_EQ(a.robots[0].positions.size(), b.robots[0].positions.size());
    for (std::size_t k = 0; k < a.robots[0].positions.size(); ++k)
        ASSERT_EQ(a.robots[0].positions[k], b.robots[0].positions[k]);
    bool differs = a.robots[0].positions.size() != c.robots[0].positions.size();
    for (std::size_t k = 0; !differs && k < a.robots[0].positions.size(); ++k)
        differs = a.robots[0].positions[k] != c.robots[0].positions[k];
    EXPECT_TRUE(differs);
    EXPECT_EQ(a.seed, 7u);
}

TEST(Simulation, TimeLimitLeavesRobotsUnfinished)
{
    Scenario sc = openScenario();
    sc.settings.timeLimit = 10.0;
    Simulation sim(sc, std::make_shared<StraightController>(), 1);
    const SimulationResult r = sim.run();
    EXPECT_FALSE(r.allDone);
    EXPECT_EQ(r.unfinished, 1u);
    EXPECT_NEAR(r.makespan, 10.0, 1e-9);
    EXPECT_NEAR(r.simulatedTime, 10.0, 1e-9);
    EXPECT_FALSE(sim.step()); // the run has ended
}
