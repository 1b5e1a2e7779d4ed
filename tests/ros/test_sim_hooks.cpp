// SPDX-License-Identifier: BSD-3-Clause
/* The simulator hooks the ROS nodes rely on (docs/ros.md), without ROS: a controller run on observed states
   in a mirror (Simulation::observe) and handed to the world as a unicycle command gives the in-process run
   exactly; tasks added during a run and join times moved before a robot joins. */
#include "src/sim/Controllers.h"
#include "src/sim/ScenarioIO.h"
#include "src/sim/Simulation.h"

#include <gtest/gtest.h>

#include <limits>

using namespace mhplan;

namespace
{
    Scenario scenario(const std::string &name)
    {
        return loadScenario(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/scenarios/" + name + ".yaml");
    }

    /** The world's side as in src/ros: each robot's command comes from its own controller instance running on
        a mirror that only sees the observed states (as a robot node does), as a unicycle command. */
    class Relay : public Controller
    {
      public:
        Relay(const Scenario &s, const std::string &controller)
        {
            for (std::size_t i = 0; i < s.robots.size(); ++i)
            {
                controllers_.push_back(makeController(controller));
                mirrors_.push_back(std::make_unique<Simulation>(s, controllers_.back(), 1));
            }
            lastTask_.assign(s.robots.size(), std::numeric_limits<std::size_t>::max());
        }
        std::string name() const override { return "relay"; }
        void reset(const Simulation &, ompl::RNG &) override {}
        void taskStarted(const Simulation &, std::size_t) override {}
        Command command(const Simulation &sim, std::size_t i) override
        {
            std::vector<RobotState> states;
            for (std::size_t k = 0; k < sim.robotCount(); ++k)
            {
                RobotState s;
                s.joined = sim.state(k).joined;
                s.status = sim.state(k).status;
                s.task = sim.state(k).task;
                s.position = sim.state(k).position;
                s.heading = sim.state(k).heading;
                s.velocity = sim.state(k).velocity;
                if (k == i)
                    s.goal = sim.state(k).goal;
                states.push_back(s);
            }
            Simulation &m = *mirrors_[i];
            m.observe(sim.time(), states, sim.obstaclePositions(), sim.obstacleVelocities());
            if (lastTask_[i] != states[i].task)
                controllers_[i]->taskStarted(m, i);
            lastTask_[i] = states[i].task;
            const Command c = controllers_[i]->command(m, i);
            return unicycleCommand(sim.spec(i), sim.state(i).heading, c.velocity, sim.dt());
        }

      private:
        std::vector<ControllerPtr> controllers_;
        std::vector<std::unique_ptr<Simulation>> mirrors_;
        std::vector<std::size_t> lastTask_;
    };
} // namespace

TEST(SimHooks, MirroredControllersGiveTheInProcessRun)
{
    for (const char *name : {"mapf_2robots", "mapf_joining"})
        for (const char *controller : {"aapf", "dapf"})
        {
            const Scenario s = scenario(name);
            const SimulationResult a = Simulation(s, makeController(controller), 1).run();
            const SimulationResult b = Simulation(s, std::make_shared<Relay>(s, controller), 1).run();
            SCOPED_TRACE(std::string(name) + " " + controller);
            ASSERT_TRUE(a.allDone);
            EXPECT_EQ(a.makespan, b.makespan);
            EXPECT_EQ(a.flowtime, b.flowtime);
            EXPECT_EQ(a.collisions(), b.collisions());
            ASSERT_EQ(a.robots.size(), b.robots.size());
            for (std::size_t i = 0; i < a.robots.size(); ++i)
            {
                ASSERT_EQ(a.robots[i].positions.size(), b.robots[i].positions.size());
                for (std::size_t k = 0; k < a.robots[i].positions.size(); ++k)
                {
                    EXPECT_EQ(a.robots[i].positions[k].x, b.robots[i].positions[k].x);
                    EXPECT_EQ(a.robots[i].positions[k].y, b.robots[i].positions[k].y);
                }
            }
        }
}

TEST(SimHooks, ObservedSimulationDoesNotStep)
{
    const Scenario s = scenario("mapf_2robots");
    Simulation m(s, makeController("aapf"), 1);
    m.observe(1.0, std::vector<RobotState>(2), {}, {});
    EXPECT_FALSE(m.step());
    EXPECT_EQ(m.time(), 1.0);
    EXPECT_THROW(m.observe(1.0, std::vector<RobotState>(3), {}, {}), std::invalid_argument);
}

TEST(SimHooks, TaskAddedToADoneRobotAndLateJoin)
{
    Scenario s = scenario("mapf_2robots");
    Simulation sim(s, makeController("aapf"), 1);
    sim.setJoinTime(1, 5.0); // r2 appears at t = 5 s
    bool added = false;
    while (sim.step())
    {
        if (!added && sim.state(0).status == RobotStatus::Done)
        {
            Task t;
            t.goal.from = Vec2(3.0, 5.5);
            t.assignedAt = sim.time() + 1.0;
            sim.addTask(0, t);
            EXPECT_EQ(sim.state(0).status, RobotStatus::Waiting);
            added = true;
        }
        if (sim.state(1).joined)
        {
            EXPECT_THROW(sim.setJoinTime(1, 0.0), std::logic_error);
        }
    }
    const SimulationResult r = sim.result();
    ASSERT_TRUE(added);
    ASSERT_TRUE(r.allDone);
    EXPECT_EQ(r.collisions(), 0u);
    EXPECT_NEAR(r.robots[1].times.front(), 5.0, 1e-9);
    EXPECT_LE(distance(r.robots[0].positions.back(), Vec2(3.0, 5.5)), s.settings.goalTolerance);
    EXPECT_THROW(sim.addTask(7, Task{}), std::out_of_range);
}
