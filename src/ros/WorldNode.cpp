// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_ros_world: mhplan's simulator as the physics of a ROS 1 run (docs/ros.md). Every step it publishes
   the robots' odometry and goals, the moving obstacles' odometry, /clock and the step tick, then waits for
   the Twist of every moving robot's controller node and integrates them (unicycle commands, Command). Robots
   join when their node announces itself; goals are assigned on /mhplan/assign at any time. At the end it
   prints the same per-robot results as `mhplan sim`. */
#include "NodeSupport.h"
#include "Protocol.h"

#include "src/draw/SimRender.h"
#include "src/sim/ScenarioIO.h"
#include "src/sim/SimulationReport.h"

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/String.h>

#include <cmath>
#include <deque>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <thread>

namespace mhplan::ros1
{
    namespace
    {
        constexpr double kNotYet = std::numeric_limits<double>::max();
        /** \brief Wall seconds without the command of a moving robot after which the step is sent again. */
        constexpr double kResend = 0.5;

        /** \brief The world's side of the run: publishes states, collects commands, admits robots and
            tasks. It is also the controller of the world's Simulation: command() returns the Twist that
            robot i's node sent for the current step (waiting for it). */
        class World : public Controller
        {
          public:
            World(const Scenario &scenario, std::string label, double commandTimeout)
                : scenario_(scenario), label_(std::move(label)), commandTimeout_(commandTimeout),
                  names_(obstacleNames(scenario)), commands_(scenario.robots.size()),
                  fresh_(scenario.robots.size(), 0), announced_(scenario.robots.size(), 0),
                  admitted_(scenario.robots.size(), 0)
            {
                for (const auto &r : scenario.robots)
                    joinTimes_.push_back(r.joinTime);
            }

            std::string name() const override { return label_; }
            void reset(const Simulation &, ompl::RNG &) override {}
            void taskStarted(const Simulation &, std::size_t) override {}
            std::map<std::string, double> counters() const override
            {
                return {{"ros_commands", static_cast<double>(commandsReceived_)},
                        {"ros_state_messages", static_cast<double>(published_)},
                        {"ros_steps_resent", static_cast<double>(resent_)}};
            }

            Command command(const Simulation &sim, std::size_t i) override
            {
                publish(sim, false);
                const double t0 = wallNow();
                double lastSent = t0;
                while (!fresh_[i])
                {
                    // A node whose subscription was still being set up when the state went out missed a
                    // message of this step: send the step again (a node answers each step once).
                    if (wallNow() - lastSent > kResend)
                    {
                        publish(sim, false, true);
                        lastSent = wallNow();
                        ++resent_;
                    }
                    if (!::ros::ok())
                        throw std::runtime_error("interrupted");
                    if (wallNow() - t0 > commandTimeout_)
                        throw std::runtime_error("no command from robot '" + scenario_.robots[i].name +
                                                 "' for t = " + std::to_string(sim.time()) + " s within " +
                                                 std::to_string(commandTimeout_) + " s (did its node die?)");
                    ::ros::getGlobalCallbackQueue()->callAvailable(::ros::WallDuration(0.01));
                }
                fresh_[i] = 0;
                return commands_[i];
            }

            void connect(::ros::NodeHandle &nh)
            {
                const ::ros::TransportHints hints = ::ros::TransportHints().tcpNoDelay();
                for (std::size_t i = 0; i < scenario_.robots.size(); ++i)
                {
                    const std::string &n = scenario_.robots[i].name;
                    odom_.push_back(nh.advertise<nav_msgs::Odometry>(odomTopic(n), 16));
                    goal_.push_back(nh.advertise<geometry_msgs::PoseStamped>(goalTopic(n), 16));
                    cmd_.push_back(nh.subscribe<geometry_msgs::Twist>(
                        cmdTopic(n), 4,
                        [this, i](const geometry_msgs::Twist::ConstPtr &m)
                        {
                            commands_[i] = fromTwist(*m, scenario_.settings.dt);
                            fresh_[i] = 1;
                            ++commandsReceived_;
                        },
                        ::ros::VoidConstPtr(), hints));
                }
                for (const auto &n : names_)
                    obstacles_.push_back(nh.advertise<nav_msgs::Odometry>(obstacleTopic(n), 16));
                tick_ = nh.advertise<std_msgs::Header>(stepTopic(), 16);
                clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 16);
                join_ = nh.subscribe<std_msgs::String>(
                    joinTopic(), 64,
                    [this](const std_msgs::String::ConstPtr &m)
                    {
                        for (std::size_t i = 0; i < scenario_.robots.size(); ++i)
                            if (scenario_.robots[i].name == m->data && !announced_[i])
                            {
                                announced_[i] = 1;
                                std::cout << "world: robot " << m->data << " announced" << std::endl;
                            }
                    });
                assign_ = nh.subscribe<geometry_msgs::PoseStamped>(
                    assignTopic(), 64,
                    [this](const geometry_msgs::PoseStamped::ConstPtr &m) { tasks_.push_back(*m); });
            }

            bool announced(std::size_t i) const { return announced_[i] != 0; }
            double scenarioJoinTime(std::size_t i) const { return joinTimes_[i]; }

            /** \brief Robots that announced join at max(their scenario join time, now); tasks received are
                appended (refused with a message when the robot is unknown or the goal not free). */
            void admit(Simulation &sim)
            {
                for (std::size_t i = 0; i < announced_.size(); ++i)
                    if (announced_[i] && !admitted_[i])
                    {
                        sim.setJoinTime(i, std::max(joinTimes_[i], sim.time()));
                        admitted_[i] = 1;
                    }
                while (!tasks_.empty())
                {
                    const geometry_msgs::PoseStamped m = tasks_.front();
                    tasks_.pop_front();
                    std::size_t i = 0;
                    try
                    {
                        i = robotIndex(scenario_, m.header.frame_id);
                    }
                    catch (const InputError &e)
                    {
                        ROS_ERROR("world: task refused: %s", e.what());
                        continue;
                    }
                    Task task;
                    task.goal.kind = Motion::Kind::Fixed;
                    task.goal.from = Vec2(m.pose.position.x, m.pose.position.y);
                    task.assignedAt = std::max(m.header.stamp.toSec(), sim.time());
                    if (!sim.staticFree(task.goal.from, scenario_.robots[i].radius))
                    {
                        ROS_ERROR("world: task for %s refused: goal (%g, %g) is out of bounds or in a static "
                                  "obstacle",
                                  m.header.frame_id.c_str(), task.goal.from.x, task.goal.from.y);
                        continue;
                    }
                    sim.addTask(i, task);
                    ++tasksAssigned_;
                    std::cout << "world: task " << sim.spec(i).tasks.size() << " for " << m.header.frame_id
                              << ": goal (" << task.goal.from.x << ", " << task.goal.from.y
                              << ") from t = " << task.assignedAt << " s (received at t = " << sim.time()
                              << " s)" << std::endl;
                }
            }

            /** \brief Publish the state at the simulation's time (once per time), the tick last. */
            void publish(const Simulation &sim, bool end, bool again = false)
            {
                const auto step = static_cast<long>(std::llround(sim.time() / sim.dt()));
                if (step == publishedStep_ && !end && !again)
                    return;
                publishedStep_ = step;
                const ::ros::Time stamp = stampOf(sim.time());
                rosgraph_msgs::Clock c;
                c.clock = stamp;
                clock_.publish(c);
                for (std::size_t i = 0; i < sim.robotCount(); ++i)
                {
                    if (!sim.present(i))
                        continue;
                    odom_[i].publish(robotOdometry(sim, i, stamp));
                    geometry_msgs::PoseStamped g;
                    g.header.stamp = stamp;
                    g.header.frame_id = "map";
                    g.pose.position.x = sim.state(i).goal.x;
                    g.pose.position.y = sim.state(i).goal.y;
                    g.pose.orientation.w = 1.0;
                    goal_[i].publish(g);
                    published_ += 2;
                }
                for (std::size_t j = 0; j < names_.size(); ++j)
                    obstacles_[j].publish(obstacleOdometry(sim, j, names_[j], stamp));
                tick_.publish(encodeTick(sim, end));
                published_ += names_.size() + 2;
            }

            unsigned long published() const { return published_; }
            unsigned long commandsReceived() const { return commandsReceived_; }
            unsigned long tasksAssigned() const { return tasksAssigned_; }

          private:
            const Scenario &scenario_;
            std::string label_;
            double commandTimeout_;
            std::vector<std::string> names_;
            std::vector<Command> commands_;
            std::vector<std::uint8_t> fresh_, announced_, admitted_;
            std::vector<double> joinTimes_;
            std::deque<geometry_msgs::PoseStamped> tasks_;
            std::vector<::ros::Publisher> odom_, goal_, obstacles_;
            std::vector<::ros::Subscriber> cmd_;
            ::ros::Publisher tick_, clock_;
            ::ros::Subscriber join_, assign_;
            long publishedStep_{-1};
            unsigned long published_{0}, commandsReceived_{0}, tasksAssigned_{0}, resent_{0};
        };

        /** \brief Spin until \e done or \e timeout wall seconds; false on timeout. */
        template <typename F> bool spinUntil(F done, double timeout)
        {
            const double t0 = wallNow();
            while (::ros::ok() && !done())
            {
                if (wallNow() - t0 > timeout)
                    return false;
                ::ros::getGlobalCallbackQueue()->callAvailable(::ros::WallDuration(0.01));
            }
            return ::ros::ok();
        }

        int runWorld(int argc, char **argv)
        {
            const cli::Args args = nodeArgs("mhplan_ros_world", argc, argv,
                                            {{"scenario", "controller", "seed", "realtime", "startup-timeout",
                                              "command-timeout", "results", "csv", "time-limit"},
                                             {"late"},
                                             {"wait-join"}});
            if (!args.has("scenario"))
                throw InputError(
                    "mhplan_ros_world: --scenario SCENARIO is required (a scenario file or the name "
                    "of a shipped scenario, e.g. mapf_2robots)");
            const std::uint32_t seed = applySeed(args);
            Scenario scenario = loadScenario(resolveScenario(args.get("scenario")));
            if (args.has("time-limit"))
            {
                const double limit = args.number("time-limit", 0.0);
                if (!(limit > 0.0) || limit / scenario.settings.dt > 1e7)
                    throw InputError(
                        "mhplan_ros_world: --time-limit must be > 0 s and at most 10^7 steps (got " +
                        args.get("time-limit") + ")");
                scenario.settings.timeLimit = limit;
            }
            const double realtime = args.number("realtime", 0.0);
            if (!(realtime >= 0.0) || std::isinf(realtime))
                throw InputError(
                    "mhplan_ros_world: --realtime must be >= 0 (0 = as fast as the nodes answer; "
                    "1 = simulated time runs at wall time; got " +
                    args.get("realtime") + ")");
            const double startupTimeout = args.number("startup-timeout", 60.0);
            const double commandTimeout = args.number("command-timeout", 10.0);
            std::set<std::string> late;
            for (const auto &n : args.all("late"))
            {
                robotIndex(scenario, n);
                late.insert(n);
            }
            const bool waitJoin = args.has("wait-join");

            ::ros::init(argc, argv, "mhplan_world");
            ::ros::NodeHandle nh;
            const Scenario original = scenario;
            for (auto &r : scenario.robots)
                r.joinTime = kNotYet; // a robot joins when its node announces itself (World::admit)
            auto world = std::make_shared<World>(original, args.get("controller", "ros"), commandTimeout);
            world->connect(nh);
            Simulation sim(scenario, world, seed);

            std::cout << "scenario:   " << original.name << " (" << original.file << ")\n"
                      << "controller: " << world->name() << " (one mhplan_ros_robot node per robot)\n"
                      << "seed:       " << seed << "\n"
                      << std::flush;
            // Start once every robot that is there from the beginning has announced itself.
            const auto startupReady = [&]()
            {
                for (std::size_t i = 0; i < original.robots.size(); ++i)
                    if (!late.count(original.robots[i].name) && original.robots[i].joinTime <= 0.0 &&
                        !world->announced(i))
                        return false;
                return true;
            };
            const double wallStart = wallNow();
            if (!spinUntil(startupReady, startupTimeout))
                throw std::runtime_error("not every robot node announced itself within " +
                                         std::to_string(startupTimeout) +
                                         " s (start one mhplan_ros_robot per robot)");
            const double wallRun = wallNow();
            bool more = true;
            while (more && ::ros::ok())
            {
                ::ros::getGlobalCallbackQueue()->callAvailable();
                const double next = sim.time() + sim.dt();
                if (waitJoin)
                    for (std::size_t i = 0; i < original.robots.size(); ++i)
                        if (!world->announced(i) && world->scenarioJoinTime(i) <= next + 1e-9 &&
                            !spinUntil([&]() { return world->announced(i); }, startupTimeout))
                            throw std::runtime_error("robot '" + original.robots[i].name +
                                                     "' did not announce itself by its join time");
                world->admit(sim);
                if (realtime > 0.0)
                {
                    const double due = wallRun + sim.time() / realtime;
                    const double now = wallNow();
                    if (due > now)
                        std::this_thread::sleep_for(std::chrono::duration<double>(due - now));
                }
                more = sim.step();
                world->publish(sim, !more);
            }
            const double wallEnd = wallNow();
            const SimulationResult r = sim.result();
            std::ostringstream report;
            printSimulationReport(report, r);
            const double wall = wallEnd - wallRun;
            report << "ros:        " << r.steps << " steps in " << wall << " s wall ("
                   << r.steps / std::max(wall, 1e-9) << " steps/s), startup " << (wallRun - wallStart)
                   << " s; " << world->published() << " state messages published ("
                   << world->published() / std::max(wall, 1e-9) << "/s), " << world->commandsReceived()
                   << " commands received (" << world->commandsReceived() / std::max(wall, 1e-9) << "/s), "
                   << world->tasksAssigned() << " tasks assigned\n";
            std::cout << report.str() << std::flush;
            if (args.has("results"))
            {
                std::ofstream out(args.get("results"));
                out << "scenario:   " << original.name << "\ncontroller: " << world->name()
                    << "\nseed:       " << seed << "\n"
                    << report.str();
                if (!out)
                    throw std::runtime_error("cannot write " + args.get("results"));
            }
            if (args.has("csv"))
            {
                std::ofstream out(args.get("csv"));
                out << trajectoryCsv(r);
                if (!out)
                    throw std::runtime_error("cannot write " + args.get("csv"));
            }
            // Give the robot nodes the final tick before the publishers go away.
            ::ros::WallDuration(0.2).sleep();
            return r.allDone ? 0 : 3;
        }
    } // namespace
} // namespace mhplan::ros1

int main(int argc, char **argv)
{
    return mhplan::ros1::runNode("mhplan_ros_world", [&]() { return mhplan::ros1::runWorld(argc, argv); });
}
