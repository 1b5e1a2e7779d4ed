// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_ros_task: assign a goal to a robot of a running ROS run (docs/ros.md): publishes one
   geometry_msgs/PoseStamped on /mhplan/assign (frame_id = the robot, position = the goal, stamp = the
   assignment's simulation time; 0 = as soon as the world receives it) once the world node listens. */
#include "NodeSupport.h"
#include "Protocol.h"

#include <ros/ros.h>

#include <cmath>

int main(int argc, char **argv)
{
    using namespace mhplan;
    return ros1::runNode(
        "mhplan_ros_task",
        [&]()
        {
            const cli::Args args =
                ros1::nodeArgs("mhplan_ros_task", argc, argv, {{"robot", "goal", "at", "timeout"}, {}, {}});
            if (!args.has("robot") || !args.has("goal"))
                throw InputError(
                    "mhplan_ros_task: usage: mhplan_ros_task --robot NAME --goal X,Y [--at SECONDS] "
                    "[--timeout SECONDS]");
            const Vec2 goal = args.point("goal");
            const double at = args.number("at", 0.0);
            if (!(at >= 0.0) || std::isinf(at))
                throw InputError("mhplan_ros_task: --at must be a simulation time >= 0 s (got " +
                                 args.get("at") + ")");
            const double timeout = args.number("timeout", 10.0);
            ::ros::init(argc, argv, "mhplan_task", ::ros::init_options::AnonymousName);
            ::ros::NodeHandle nh;
            ::ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>(ros1::assignTopic(), 1, true);
            const double t0 = ros1::wallNow();
            while (::ros::ok() && pub.getNumSubscribers() == 0)
            {
                if (ros1::wallNow() - t0 > timeout)
                    throw std::runtime_error("no world node listens on " + std::string(ros1::assignTopic()) +
                                             " within " + std::to_string(timeout) + " s");
                ::ros::WallDuration(0.01).sleep();
            }
            geometry_msgs::PoseStamped m;
            m.header.frame_id = args.get("robot");
            m.header.stamp = ros1::stampOf(at);
            m.pose.position.x = goal.x;
            m.pose.position.y = goal.y;
            m.pose.orientation.w = 1.0;
            pub.publish(m);
            // The message is on its way once published to a connected subscriber; let the transport flush it.
            ::ros::WallDuration(0.3).sleep();
            return 0;
        });
}
