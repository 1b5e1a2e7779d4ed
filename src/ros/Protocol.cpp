// SPDX-License-Identifier: BSD-3-Clause
/* mhplan ROS 1 component: topics and message conversions (see Protocol.h). */
#include "Protocol.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace mhplan::ros1
{
    std::string odomTopic(const std::string &robot)
    {
        return "/" + robot + "/odom";
    }
    std::string goalTopic(const std::string &robot)
    {
        return "/" + robot + "/goal";
    }
    std::string cmdTopic(const std::string &robot)
    {
        return "/" + robot + "/cmd_vel";
    }
    std::string obstacleTopic(const std::string &obstacle)
    {
        return "/obstacles/" + obstacle + "/odom";
    }

    std::vector<std::string> obstacleNames(const Scenario &scenario)
    {
        std::vector<std::string> names;
        for (std::size_t j = 0; j < scenario.movingObstacles.size(); ++j)
            names.push_back(scenario.movingObstacles[j].name.empty() ? "o" + std::to_string(j)
                                                                     : scenario.movingObstacles[j].name);
        return names;
    }

    ::ros::Time stampOf(double t)
    {
        return ::ros::Time(t);
    }

    namespace
    {
        char statusLetter(RobotStatus s)
        {
            switch (s)
            {
            case RobotStatus::Waiting:
                return 'w';
            case RobotStatus::Moving:
                return 'm';
            case RobotStatus::Done:
                return 'd';
            case RobotStatus::Stuck:
                return 's';
            }
            return '?';
        }
    } // namespace

    std_msgs::Header encodeTick(const Simulation &sim, bool end)
    {
        std_msgs::Header h;
        const auto step = static_cast<unsigned long>(std::llround(sim.time() / sim.dt()));
        h.seq = static_cast<std::uint32_t>(step);
        h.stamp = stampOf(sim.time());
        std::ostringstream s;
        s << "k=" << step << " end=" << (end ? 1 : 0);
        for (std::size_t i = 0; i < sim.robotCount(); ++i)
        {
            s << " " << sim.spec(i).name << "=";
            if (!sim.present(i))
                s << "-";
            else
                s << statusLetter(sim.state(i).status) << ":" << sim.state(i).task;
        }
        h.frame_id = s.str();
        return h;
    }

    Tick decodeTick(const std_msgs::Header &msg, const Scenario &scenario)
    {
        const auto bad = [&](const std::string &why)
        { return std::runtime_error("malformed step tick '" + msg.frame_id + "': " + why); };
        std::istringstream in(msg.frame_id);
        std::string word;
        Tick t;
        if (!(in >> word) || word.rfind("k=", 0) != 0)
            throw bad("expected k=STEP first");
        t.step = std::stoul(word.substr(2));
        if (!(in >> word) || (word != "end=0" && word != "end=1"))
            throw bad("expected end=0|1 second");
        t.end = word == "end=1";
        t.robots.resize(scenario.robots.size());
        std::size_t i = 0;
        for (; in >> word; ++i)
        {
            if (i >= scenario.robots.size())
                throw bad("more robots than the scenario's " + std::to_string(scenario.robots.size()));
            const std::string prefix = scenario.robots[i].name + "=";
            if (word.rfind(prefix, 0) != 0)
                throw bad("robot " + std::to_string(i) + " should be '" + scenario.robots[i].name + "'");
            const std::string v = word.substr(prefix.size());
            if (v == "-")
                continue;
            if (v.size() < 3 || v[1] != ':')
                throw bad("status of '" + scenario.robots[i].name + "'");
            Tick::Robot &r = t.robots[i];
            r.joined = true;
            switch (v[0])
            {
            case 'w':
                r.status = RobotStatus::Waiting;
                break;
            case 'm':
                r.status = RobotStatus::Moving;
                break;
            case 'd':
                r.status = RobotStatus::Done;
                break;
            case 's':
                r.status = RobotStatus::Stuck;
                break;
            default:
                throw bad("status letter of '" + scenario.robots[i].name + "'");
            }
            r.task = std::stoul(v.substr(2));
        }
        if (i != scenario.robots.size())
            throw bad("expected " + std::to_string(scenario.robots.size()) + " robots");
        return t;
    }

    namespace
    {
        /** \brief The angle in (-pi, pi]. */
        double wrap(double a)
        {
            return std::atan2(std::sin(a), std::cos(a));
        }

        void setPose(nav_msgs::Odometry &o, const Vec2 &p, double heading)
        {
            o.pose.pose.position.x = p.x;
            o.pose.pose.position.y = p.y;
            o.pose.pose.orientation.z = std::sin(0.5 * heading);
            o.pose.pose.orientation.w = std::cos(0.5 * heading);
        }
    } // namespace

    nav_msgs::Odometry robotOdometry(const Simulation &sim, std::size_t i, const ::ros::Time &stamp)
    {
        const RobotState &s = sim.state(i);
        nav_msgs::Odometry o;
        o.header.stamp = stamp;
        o.header.frame_id = "map";
        o.child_frame_id = sim.spec(i).name + "/base_link";
        setPose(o, s.position, s.heading);
        const double c = std::cos(s.heading), sn = std::sin(s.heading);
        o.twist.twist.linear.x = c * s.velocity.x + sn * s.velocity.y;
        o.twist.twist.linear.y = -sn * s.velocity.x + c * s.velocity.y;
        return o;
    }

    nav_msgs::Odometry obstacleOdometry(const Simulation &sim, std::size_t j, const std::string &name,
                                        const ::ros::Time &stamp)
    {
        nav_msgs::Odometry o;
        o.header.stamp = stamp;
        o.header.frame_id = "map";
        o.child_frame_id = name;
        setPose(o, sim.obstaclePositions()[j], 0.0);
        o.twist.twist.linear.x = sim.obstacleVelocities()[j].x;
        o.twist.twist.linear.y = sim.obstacleVelocities()[j].y;
        return o;
    }

    void readOdometry(const nav_msgs::Odometry &msg, Vec2 &position, double &heading, Vec2 &velocity)
    {
        position = Vec2(msg.pose.pose.position.x, msg.pose.pose.position.y);
        heading = wrap(2.0 * std::atan2(msg.pose.pose.orientation.z, msg.pose.pose.orientation.w));
        const double c = std::cos(heading), s = std::sin(heading);
        const double bx = msg.twist.twist.linear.x, by = msg.twist.twist.linear.y;
        velocity = Vec2(c * bx - s * by, s * bx + c * by);
    }

    geometry_msgs::Twist toTwist(const Command &u, double dt)
    {
        geometry_msgs::Twist t;
        if (u.unicycle)
        {
            t.linear.x = u.forward;
            t.angular.z = u.turn / dt;
        }
        return t;
    }

    Command fromTwist(const geometry_msgs::Twist &twist, double dt)
    {
        Command u;
        u.unicycle = true;
        u.forward = twist.linear.x;
        u.turn = twist.angular.z * dt;
        return u;
    }

    std::string resolveScenario(const std::string &arg)
    {
        if (fs::exists(arg))
            return arg;
        const char *env = std::getenv("MHPLAN_ENVIRONMENTS");
        const fs::path root = env ? fs::path(env) : fs::path(MHPLAN_ENVIRONMENTS_DIR);
        for (const char *ext : {".yaml", ".yml"})
            if (fs::exists(root / "scenarios" / (arg + ext)))
                return (root / "scenarios" / (arg + ext)).string();
        throw InputError("scenario '" + arg + "': no such file, and no shipped scenario of that name in " +
                         (root / "scenarios").string());
    }

    std::size_t robotIndex(const Scenario &scenario, const std::string &name)
    {
        std::string names;
        for (std::size_t i = 0; i < scenario.robots.size(); ++i)
        {
            if (scenario.robots[i].name == name)
                return i;
            names += (names.empty() ? "" : ", ") + scenario.robots[i].name;
        }
        throw InputError("scenario '" + scenario.name + "' has no robot '" + name + "' (robots: " + names +
                         ")");
    }
} // namespace mhplan::ros1
