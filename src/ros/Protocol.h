// SPDX-License-Identifier: BSD-3-Clause
/* mhplan ROS 1 component: the topics and messages between the world node (the simulator as the physics) and
   the per-robot controller nodes, and their conversions. The protocol is described in docs/ros.md. */
#ifndef MHPLAN_ROS_PROTOCOL_H
#define MHPLAN_ROS_PROTOCOL_H

#include "src/sim/Simulation.h"

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <std_msgs/Header.h>

#include <string>
#include <vector>

namespace mhplan::ros1
{
    /** \brief Topic names (global). Per robot NAME: /NAME/odom (nav_msgs/Odometry, world node), /NAME/goal
        (geometry_msgs/PoseStamped, world node: the robot's current goal), /NAME/cmd_vel (geometry_msgs/Twist,
        robot node). Per moving obstacle NAME: /obstacles/NAME/odom. */
    std::string odomTopic(const std::string &robot);
    std::string goalTopic(const std::string &robot);
    std::string cmdTopic(const std::string &robot);
    std::string obstacleTopic(const std::string &obstacle);
    /** \brief The step tick (std_msgs/Header), published by the world after a step's odometry; the robot
        nodes answer it. */
    inline const char *stepTopic()
    {
        return "/mhplan/step";
    }
    /** \brief Robot nodes announce themselves here (std_msgs/String: the robot name; latched). */
    inline const char *joinTopic()
    {
        return "/mhplan/join";
    }
    /** \brief The task assignment topic (geometry_msgs/PoseStamped: header.frame_id = robot name, the
        position = the goal, header.stamp = the assignment time, 0 = as soon as received). */
    inline const char *assignTopic()
    {
        return "/mhplan/assign";
    }
    /** \brief The moving obstacles' names as the topics use them (the scenario's name, or "o<index>"). */
    std::vector<std::string> obstacleNames(const Scenario &scenario);

    /** \brief The stamp of simulation time \e t (the /clock time). */
    ::ros::Time stampOf(double t);

    /** \brief What a step tick says: the step index (time = step * dt exactly, as in Simulation), every
        robot's presence, status and task index, and whether the run has ended. */
    struct Tick
    {
        unsigned long step{0};
        bool end{false};
        struct Robot
        {
            bool joined{false};
            RobotStatus status{RobotStatus::Waiting};
            std::size_t task{0};
        };
        std::vector<Robot> robots;
    };
    /** \brief The tick of the simulation's current state, and its decoding (header.frame_id carries
        "k=STEP end=0|1 NAME=STATUS:TASK ..." with STATUS one of w m d s, or NAME=- before joining). */
    std_msgs::Header encodeTick(const Simulation &sim, bool end);
    /** \brief Throws std::runtime_error naming the text on a malformed tick or one for other robots. */
    Tick decodeTick(const std_msgs::Header &msg, const Scenario &scenario);

    /** \brief Odometry of robot \e i at the simulation's time: pose (heading as a quaternion about z) in
        frame "map", twist in the body frame (child_frame_id NAME/base_link): the velocity of the last step.
     */
    nav_msgs::Odometry robotOdometry(const Simulation &sim, std::size_t i, const ::ros::Time &stamp);
    /** \brief Odometry of moving obstacle \e j (twist in the map frame: child_frame_id NAME, no rotation). */
    nav_msgs::Odometry obstacleOdometry(const Simulation &sim, std::size_t j, const std::string &name,
                                        const ::ros::Time &stamp);
    /** \brief Decoded odometry: position, heading, world-frame velocity. */
    void readOdometry(const nav_msgs::Odometry &msg, Vec2 &position, double &heading, Vec2 &velocity);

    /** \brief A unicycle Command as a Twist (linear.x forward m/s, angular.z = turn / dt rad/s) and back. */
    geometry_msgs::Twist toTwist(const Command &u, double dt);
    Command fromTwist(const geometry_msgs::Twist &twist, double dt);

    /** \brief A scenario argument: an existing file, or the name of a shipped scenario
        (environments/scenarios/NAME.yaml); throws InputError otherwise. */
    std::string resolveScenario(const std::string &arg);
    /** \brief Index of the robot called \e name; throws InputError listing the robots. */
    std::size_t robotIndex(const Scenario &scenario, const std::string &name);
} // namespace mhplan::ros1

#endif
