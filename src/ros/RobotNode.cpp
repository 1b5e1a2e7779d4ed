// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_ros_robot: the controller node of one robot (docs/ros.md). It subscribes to every robot's
   odometry, the moving obstacles' odometry, its own goal and the world's step tick; for every tick in which
   its robot is moving it rebuilds the observed state in a mirror of the scenario (Simulation::observe), runs
   the controller for its robot only, and publishes the unicycle command as geometry_msgs/Twist on
   /NAME/cmd_vel. It joins the run by announcing itself on /mhplan/join once it is connected. */
#include "NodeSupport.h"
#include "Protocol.h"

#include "src/sim/Controllers.h"
#include "src/sim/ScenarioIO.h"

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace mhplan::ros1
{
    namespace
    {
        class RobotNode
        {
          public:
            RobotNode(Scenario scenario, std::size_t self, ControllerPtr controller, std::uint32_t seed)
                : scenario_(std::move(scenario)), self_(self), controller_(std::move(controller)),
                  mirror_(scenario_, controller_, seed), odom_(scenario_.robots.size()),
                  obstacles_(scenario_.movingObstacles.size())
            {
            }

            int run(double connectTimeout)
            {
                ::ros::NodeHandle nh;
                const std::string &name = scenario_.robots[self_].name;
                for (std::size_t i = 0; i < scenario_.robots.size(); ++i)
                    subs_.push_back(nh.subscribe<nav_msgs::Odometry>(
                        odomTopic(scenario_.robots[i].name), 4,
                        [this, i](const nav_msgs::Odometry::ConstPtr &m)
                        {
                            odom_[i] = *m;
                            ++received_;
                            answer();
                        },
                        ::ros::VoidConstPtr(), ::ros::TransportHints().tcpNoDelay()));
                const auto names = obstacleNames(scenario_);
                for (std::size_t j = 0; j < names.size(); ++j)
                    subs_.push_back(nh.subscribe<nav_msgs::Odometry>(
                        obstacleTopic(names[j]), 4,
                        [this, j](const nav_msgs::Odometry::ConstPtr &m)
                        {
                            obstacles_[j] = *m;
                            ++received_;
                            answer();
                        },
                        ::ros::VoidConstPtr(), ::ros::TransportHints().tcpNoDelay()));
                subs_.push_back(nh.subscribe<geometry_msgs::PoseStamped>(
                    goalTopic(name), 4,
                    [this](const geometry_msgs::PoseStamped::ConstPtr &m)
                    {
                        goal_ = *m;
                        ++received_;
                        answer();
                    },
                    ::ros::VoidConstPtr(), ::ros::TransportHints().tcpNoDelay()));
                subs_.push_back(nh.subscribe<std_msgs::Header>(
                    stepTopic(), 16,
                    [this](const std_msgs::Header::ConstPtr &m)
                    {
                        tick_ = decodeTick(*m, scenario_);
                        tickStamp_ = m->stamp;
                        ++ticks_;
                        if (tick_->end)
                            ended_ = true;
                        answer();
                    },
                    ::ros::VoidConstPtr(), ::ros::TransportHints().tcpNoDelay()));
                cmd_ = nh.advertise<geometry_msgs::Twist>(cmdTopic(name), 4);
                ::ros::Publisher join = nh.advertise<std_msgs::String>(joinTopic(), 1, true);

                // Join only once every subscription has its publisher (the world) and the world listens to
                // the commands: from then on no message of a step can be missed.
                const double t0 = wallNow();
                while (::ros::ok() && !connected(join))
                {
                    if (wallNow() - t0 > connectTimeout)
                        throw std::runtime_error("robot '" + name + "': no world node connected within " +
                                                 std::to_string(connectTimeout) +
                                                 " s (is mhplan_ros_world running?)");
                    ::ros::WallDuration(0.01).sleep();
                    ::ros::spinOnce();
                }
                std_msgs::String hello;
                hello.data = name;
                join.publish(hello);
                std::cout << "robot " << name << " (" << controller_->name() << ") joined after "
                          << wallNow() - t0 << " s" << std::endl;
                const double start = wallNow();
                while (::ros::ok() && !ended_)
                    ::ros::getGlobalCallbackQueue()->callAvailable(::ros::WallDuration(0.1));
                const double wall = wallNow() - start;
                std::cout << "robot " << name << ": " << answered_ << " commands for " << ticks_ << " ticks, "
                          << received_ << " state messages, " << wall << " s wall ("
                          << (wall > 0 ? answered_ / wall : 0.0) << " commands/s)" << std::endl;
                return 0;
            }

          private:
            bool connected(const ::ros::Publisher &join) const
            {
                for (const auto &s : subs_)
                    if (s.getNumPublishers() == 0)
                        return false;
                return cmd_.getNumSubscribers() > 0 && join.getNumSubscribers() > 0;
            }

            /** \brief Answer the last tick once its state is complete (every present robot's odometry,
                every obstacle's and the own goal, all of the tick's stamp) and the robot moves in it. */
            void answer()
            {
                if (!tick_ || answeredStep_ == static_cast<long>(tick_->step))
                    return;
                const Tick &t = *tick_;
                const Tick::Robot &me = t.robots[self_];
                if (!me.joined || me.status != RobotStatus::Moving)
                {
                    lastStatus_ = me.joined ? me.status : RobotStatus::Waiting;
                    return;
                }
                for (std::size_t i = 0; i < t.robots.size(); ++i)
                    if (t.robots[i].joined && odom_[i].header.stamp != tickStamp_)
                        return;
                for (const auto &o : obstacles_)
                    if (o.header.stamp != tickStamp_)
                        return;
                if (goal_.header.stamp != tickStamp_)
                    return;

                std::vector<RobotState> states(t.robots.size());
                for (std::size_t i = 0; i < t.robots.size(); ++i)
                {
                    RobotState &s = states[i];
                    s.joined = t.robots[i].joined;
                    s.status = t.robots[i].status;
                    s.task = t.robots[i].task;
                    if (s.joined)
                        readOdometry(odom_[i], s.position, s.heading, s.velocity);
                }
                states[self_].goal = Vec2(goal_.pose.position.x, goal_.pose.position.y);
                std::vector<Vec2> obsPos(obstacles_.size()), obsVel(obstacles_.size());
                for (std::size_t j = 0; j < obstacles_.size(); ++j)
                {
                    double heading = 0.0;
                    readOdometry(obstacles_[j], obsPos[j], heading, obsVel[j]);
                }
                const double time = static_cast<double>(t.step) * mirror_.dt();
                mirror_.observe(time, states, obsPos, obsVel);
                if (lastStatus_ != RobotStatus::Moving || lastTask_ != me.task)
                    controller_->taskStarted(mirror_, self_);
                lastStatus_ = RobotStatus::Moving;
                lastTask_ = me.task;
                const Command c = controller_->command(mirror_, self_);
                const Command u = c.unicycle ? c
                                             : unicycleCommand(scenario_.robots[self_], states[self_].heading,
                                                               c.velocity, mirror_.dt());
                cmd_.publish(toTwist(u, mirror_.dt()));
                answeredStep_ = static_cast<long>(t.step);
                ++answered_;
            }

            Scenario scenario_;
            std::size_t self_;
            ControllerPtr controller_;
            Simulation mirror_;
            std::vector<::ros::Subscriber> subs_;
            ::ros::Publisher cmd_;
            std::vector<nav_msgs::Odometry> odom_, obstacles_;
            geometry_msgs::PoseStamped goal_;
            std::optional<Tick> tick_;
            ::ros::Time tickStamp_;
            long answeredStep_{-1};
            RobotStatus lastStatus_{RobotStatus::Waiting};
            std::size_t lastTask_{0};
            bool ended_{false};
            unsigned long answered_{0}, ticks_{0}, received_{0};
        };
    } // namespace
} // namespace mhplan::ros1

int main(int argc, char **argv)
{
    using namespace mhplan;
    return ros1::runNode(
        "mhplan_ros_robot",
        [&]()
        {
            const cli::Args args =
                ros1::nodeArgs("mhplan_ros_robot", argc, argv,
                               {{"scenario", "robot", "controller", "seed", "connect-timeout"}, {"set"}, {}});
            for (const char *required : {"scenario", "robot", "controller"})
                if (!args.has(required))
                    throw InputError(
                        std::string("mhplan_ros_robot: --") + required +
                        " is required (usage: mhplan_ros_robot --scenario SCENARIO --robot NAME "
                        "--controller dapf|aapf|bfo|atbfo|plan:PLANNER [--set KEY=VALUE]... [--seed N])");
            const std::uint32_t seed = ros1::applySeed(args);
            Scenario scenario = loadScenario(ros1::resolveScenario(args.get("scenario")));
            const std::size_t self = ros1::robotIndex(scenario, args.get("robot"));
            const ControllerPtr controller = makeController(args.get("controller"));
            std::map<std::string, std::string> params;
            for (const auto &kv : args.all("set"))
                parseKeyValue(kv, params);
            for (const auto &kv : params)
                controller->setParameter(kv.first, kv.second);
            const double connectTimeout = args.number("connect-timeout", 30.0);
            ::ros::init(argc, argv, "mhplan_robot_" + scenario.robots[self].name);
            ros1::RobotNode node(std::move(scenario), self, controller, seed);
            return node.run(connectTimeout);
        });
}
