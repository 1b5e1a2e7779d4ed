// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: scenario files (format: environments/README.md, "Scenario files"). */
#include "src/sim/ScenarioIO.h"

#include "src/io/InputFile.h"

#include "src/io/WorldIO.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

namespace mhplan
{
    namespace
    {
        /** \brief Samples per period when checking that a moving goal stays in free space. */
        constexpr int kMotionSamples = 72;

        std::string directoryOf(const std::string &path)
        {
            const auto slash = path.find_last_of('/');
            return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
        }

        std::string formatPoint(const Vec2 &p)
        {
            std::ostringstream s;
            s << "(" << p.x << ", " << p.y << ")";
            return s.str();
        }

        /** \brief A point [x, y], or a mapping with exactly one of `line` and `circle`. */
        Motion readMotion(const YamlReader &r, const YAML::Node &n, const std::string &field)
        {
            Motion m;
            if (n.IsSequence())
            {
                m.kind = Motion::Kind::Fixed;
                m.from = r.point(n, field);
                return m;
            }
            if (!n.IsMap())
                r.fail(n, field, "expected a point [x, y] or {line: {...}} or {circle: {...}}");
            r.allowKeys(n, field, {"line", "circle"});
            if (n["line"].IsDefined() == n["circle"].IsDefined())
                r.fail(n, field, "give exactly one of 'line' and 'circle'");
            if (n["line"].IsDefined())
            {
                const YAML::Node l = n["line"];
                const std::string f = field + ".line";
                r.allowKeys(l, f, {"from", "to", "speed"});
                m.kind = Motion::Kind::Line;
                m.from = r.point(r.require(l, "from", f), f + ".from");
                m.to = r.point(r.require(l, "to", f), f + ".to");
                m.speed = r.number(r.require(l, "speed", f), f + ".speed", 0.0, 1e3);
                if (!(m.speed > 0.0))
                    r.fail(l["speed"], f + ".speed", "must be > 0 (got " + l["speed"].Scalar() + ")");
                if (m.from == m.to)
                    r.fail(l, f, "'from' and 'to' must differ");
                return m;
            }
            const YAML::Node c = n["circle"];
            const std::string f = field + ".circle";
            r.allowKeys(c, f, {"center", "radius", "angular_speed", "period", "phase"});
            m.kind = Motion::Kind::Circle;
            m.center = r.point(r.require(c, "center", f), f + ".center");
            m.radius = r.number(r.require(c, "radius", f), f + ".radius", 0.0, 1e6);
            if (!(m.radius > 0.0))
                r.fail(c["radius"], f + ".radius", "must be > 0 (got " + c["radius"].Scalar() + ")");
            if (c["angular_speed"].IsDefined() == c["period"].IsDefined())
                r.fail(c, f,
                       "give exactly one of 'angular_speed' (rad/s, sign = direction) and 'period' (s)");
            if (c["angular_speed"].IsDefined())
                m.angularSpeed = r.number(c["angular_speed"], f + ".angular_speed", -1e3, 1e3);
            else
            {
                const double period = r.number(c["period"], f + ".period");
                if (period == 0.0)
                    r.fail(c["period"], f + ".period", "must not be 0 (negative = clockwise)");
                m.angularSpeed = 2.0 * kPi / period;
            }
            if (c["phase"].IsDefined())
                m.phase = r.number(c["phase"], f + ".phase", -360.0, 360.0) * kPi / 180.0;
            return m;
        }

        /** \brief One period of a motion (or a single instant for a fixed point), sampled. */
        std::vector<Vec2> motionSamples(const Motion &m)
        {
            double period = 0.0;
            if (m.kind == Motion::Kind::Line)
                period = 2.0 * distance(m.from, m.to) / m.speed;
            else if (m.kind == Motion::Kind::Circle && m.angularSpeed != 0.0)
                period = 2.0 * kPi / std::abs(m.angularSpeed);
            std::vector<Vec2> out;
            const int n = period > 0.0 ? kMotionSamples : 1;
            for (int k = 0; k < n; ++k)
                out.push_back(m.positionAt(period * k / n));
            return out;
        }

        /** \brief The smallest time step and the most steps one simulation may take (time_limit / dt). */
        constexpr double kMinDt = 1e-4;
        constexpr double kMaxSteps = 1e7;

        void readSettings(const YamlReader &r, const YAML::Node &n, SimulationSettings &s)
        {
            r.allowKeys(
                n, "simulation",
                {"dt", "time_limit", "stuck_timeout", "stuck_distance", "goal_tolerance", "record_every"});
            auto positive = [&](const char *key, double lo, double hi, double &out)
            {
                if (!n[key].IsDefined())
                    return;
                const std::string f = std::string("simulation.") + key;
                out = r.number(n[key], f, lo, hi);
                if (!(out > 0.0))
                    r.fail(n[key], f, "must be > 0 (got " + n[key].Scalar() + ")");
            };
            positive("dt", 0.0, 10.0, s.dt);
            positive("time_limit", 0.0, 1e7, s.timeLimit);
            positive("stuck_timeout", 0.0, 1e7, s.stuckTimeout);
            positive("stuck_distance", 0.0, 1e6, s.stuckDistance);
            positive("goal_tolerance", 0.0, 1e6, s.goalTolerance);
            if (n["record_every"].IsDefined())
                s.recordEvery = static_cast<unsigned int>(
                    r.integer(n["record_every"], "simulation.record_every", 1, 1000000));
            if (s.dt < kMinDt)
                r.fail(n["dt"], "simulation.dt",
                       "must be at least " + std::to_string(kMinDt) + " s (got " + n["dt"].Scalar() + ")");
            if (s.dt > s.timeLimit)
                r.fail(n, "simulation.dt", "must not exceed time_limit");
            if (s.timeLimit / s.dt > kMaxSteps)
                r.fail(n["dt"].IsDefined() ? n["dt"] : n, "simulation.dt",
                       "time_limit / dt is " + std::to_string(static_cast<long long>(s.timeLimit / s.dt)) +
                           " steps; at most " + std::to_string(static_cast<long long>(kMaxSteps)) +
                           " are allowed (raise dt or lower time_limit)");
        }

        struct RobotLimits
        {
            double radius{0.105}, maxSpeed{0.22}, maxTurnRate{2.84};
        };

        void readLimits(const YamlReader &r, const YAML::Node &n, const std::string &field, RobotLimits &l)
        {
            if (n["radius"].IsDefined())
                l.radius = r.number(n["radius"], field + ".radius", 0.0, 1e6);
            if (n["max_speed"].IsDefined())
            {
                l.maxSpeed = r.number(n["max_speed"], field + ".max_speed", 0.0, 1e6);
                if (!(l.maxSpeed > 0.0))
                    r.fail(n["max_speed"], field + ".max_speed",
                           "must be > 0 (got " + n["max_speed"].Scalar() + ")");
            }
            if (n["max_turn_rate"].IsDefined())
            {
                l.maxTurnRate = r.number(n["max_turn_rate"], field + ".max_turn_rate", 0.0, 1e6);
                if (!(l.maxTurnRate > 0.0))
                    r.fail(n["max_turn_rate"], field + ".max_turn_rate",
                           "must be > 0 (got " + n["max_turn_rate"].Scalar() + ")");
            }
        }
    } // namespace

    Scenario parseScenarioYaml(const std::string &text, const std::string &fileName)
    {
        const YAML::Node root = loadYamlMapping(text, fileName, "scenario file", "environments/README.md");
        const YamlReader r(fileName);
        const std::set<std::string> scenarioKeys{"world",  "moving_obstacles", "robot_defaults",
                                                 "robots", "simulation",       "reference"};

        Scenario sc;
        sc.file = fileName;
        if (root["world"].IsDefined())
        {
            // The static world comes from a world file; the scenario file holds only scenario keys.
            r.allowKeys(root, "",
                        {"name", "description", "source", "assumptions", "world", "moving_obstacles",
                         "robot_defaults", "robots", "simulation", "reference"});
            std::string path = r.nonEmptyText(root["world"], "world");
            if (path.front() != '/')
                path = directoryOf(fileName) + path;
            try
            {
                sc.world = loadWorld(path);
            }
            catch (const InputError &e)
            {
                r.fail(root["world"], "world", std::string("cannot load the world: ") + e.what());
            }
        }
        else
        {
            if (root["queries"].IsDefined())
                r.fail(root["queries"], "queries", "a scenario's robots carry their own starts and goals");
            sc.world = readWorldNode(r, root, scenarioKeys);
        }
        sc.name = root["name"].IsDefined() ? r.text(root["name"], "name") : sc.world.name;
        if (root["description"].IsDefined())
            sc.description = r.text(root["description"], "description");
        if (root["source"].IsDefined())
            sc.source = r.text(root["source"], "source");
        if (root["assumptions"].IsDefined())
            sc.assumptions = r.text(root["assumptions"], "assumptions");
        sc.world.queries.clear();
        sc.world.robotRadius = 0.0;

        if (root["simulation"].IsDefined())
            readSettings(r, root["simulation"], sc.settings);

        if (root["reference"].IsDefined())
        {
            const YAML::Node ref = root["reference"];
            if (!ref.IsMap())
                r.fail(ref, "reference", "expected a mapping of names to numbers");
            r.uniqueKeys(ref, "reference");
            for (const auto &kv : ref)
            {
                const std::string key = r.key(kv.first, "reference");
                sc.reference[key] = r.number(kv.second, "reference." + key);
            }
        }

        // A point-robot model of the static world for the placement checks below.
        World pointWorld = sc.world;
        const CollisionModelPtr model = makeCollisionModel(pointWorld);
        const Box &b = sc.world.bounds;
        auto freeFor = [&](const Vec2 &p, double radius)
        {
            return p.x >= b.xmin + radius && p.x <= b.xmax - radius && p.y >= b.ymin + radius &&
                   p.y <= b.ymax - radius && model->clearance(p) >= radius;
        };

        if (root["moving_obstacles"].IsDefined() && !root["moving_obstacles"].IsNull())
        {
            const YAML::Node list = root["moving_obstacles"];
            if (!list.IsSequence())
                r.fail(list, "moving_obstacles", "expected a list");
            std::set<std::string> names;
            for (std::size_t j = 0; j < list.size(); ++j)
            {
                const YAML::Node n = list[j];
                const std::string field = "moving_obstacles[" + std::to_string(j) + "]";
                r.allowKeys(n, field, {"name", "radius", "motion"});
                MovingObstacle o;
                o.name = n["name"].IsDefined() ? r.nonEmptyText(n["name"], field + ".name")
                                               : "m" + std::to_string(j + 1);
                if (!names.insert(o.name).second)
                    r.fail(n["name"], field + ".name", "duplicate moving obstacle name '" + o.name + "'");
                o.radius = r.number(r.require(n, "radius", field), field + ".radius", 0.0, 1e6);
                if (!(o.radius > 0.0))
                    r.fail(n["radius"], field + ".radius", "must be > 0 (got " + n["radius"].Scalar() + ")");
                o.motion = readMotion(r, r.require(n, "motion", field), field + ".motion");
                sc.movingObstacles.push_back(o);
            }
        }

        RobotLimits defaults;
        if (root["robot_defaults"].IsDefined())
        {
            r.allowKeys(root["robot_defaults"], "robot_defaults", {"radius", "max_speed", "max_turn_rate"});
            readLimits(r, root["robot_defaults"], "robot_defaults", defaults);
        }

        const YAML::Node robots = r.require(root, "robots", "");
        if (!robots.IsSequence() || robots.size() == 0)
            r.fail(robots, "robots", "expected a non-empty list of robots");
        std::set<std::string> names;
        for (std::size_t i = 0; i < robots.size(); ++i)
        {
            const YAML::Node n = robots[i];
            const std::string field = "robots[" + std::to_string(i) + "]";
            r.allowKeys(n, field,
                        {"name", "start", "heading", "join_time", "goal", "tasks", "radius", "max_speed",
                         "max_turn_rate"});
            RobotSpec s;
            s.name = n["name"].IsDefined() ? r.nonEmptyText(n["name"], field + ".name")
                                           : "r" + std::to_string(i + 1);
            if (!names.insert(s.name).second)
                r.fail(n["name"], field + ".name", "duplicate robot name '" + s.name + "'");
            RobotLimits limits = defaults;
            readLimits(r, n, field, limits);
            s.radius = limits.radius;
            s.maxSpeed = limits.maxSpeed;
            s.maxTurnRate = limits.maxTurnRate;
            s.start = r.point(r.require(n, "start", field), field + ".start");
            if (n["heading"].IsDefined())
                s.heading = r.number(n["heading"], field + ".heading", -360.0, 360.0) * kPi / 180.0;
            if (n["join_time"].IsDefined())
                s.joinTime = r.number(n["join_time"], field + ".join_time", 0.0, 1e7);
            if (!freeFor(s.start, s.radius))
            {
                std::ostringstream c;
                c << std::setprecision(6) << model->clearance(s.start) - s.radius;
                r.fail(n["start"], field + ".start",
                       formatPoint(s.start) + " is out of bounds or in collision for a robot of radius " +
                           std::to_string(s.radius) + " (clearance " + c.str() + ")");
            }
            if (n["goal"].IsDefined() == n["tasks"].IsDefined())
                r.fail(n, field, "give exactly one of 'goal' (one task from the join time) and 'tasks'");
            std::vector<std::pair<YAML::Node, std::string>> goalNodes;
            if (n["goal"].IsDefined())
            {
                Task t;
                t.goal = readMotion(r, n["goal"], field + ".goal");
                t.assignedAt = s.joinTime;
                s.tasks.push_back(t);
                goalNodes.emplace_back(n["goal"], field + ".goal");
            }
            else
            {
                const YAML::Node tasks = n["tasks"];
                if (!tasks.IsSequence() || tasks.size() == 0)
                    r.fail(tasks, field + ".tasks", "expected a non-empty list of {goal, at}");
                for (std::size_t k = 0; k < tasks.size(); ++k)
                {
                    const std::string tf = field + ".tasks[" + std::to_string(k) + "]";
                    r.allowKeys(tasks[k], tf, {"goal", "at"});
                    Task t;
                    t.goal = readMotion(r, r.require(tasks[k], "goal", tf), tf + ".goal");
                    t.assignedAt = tasks[k]["at"].IsDefined() ? r.number(tasks[k]["at"], tf + ".at", 0.0, 1e7)
                                                              : s.joinTime;
                    if (t.assignedAt < s.joinTime)
                        r.fail(tasks[k]["at"], tf + ".at",
                               "the task is assigned before the robot joins (join_time " +
                                   std::to_string(s.joinTime) + ")");
                    if (k > 0 && t.assignedAt < s.tasks.back().assignedAt)
                        r.fail(tasks[k]["at"], tf + ".at",
                               "tasks must be listed in the order they are assigned");
                    s.tasks.push_back(t);
                    goalNodes.emplace_back(tasks[k]["goal"], tf + ".goal");
                }
            }
            for (std::size_t k = 0; k < s.tasks.size(); ++k)
                for (const Vec2 &p : motionSamples(s.tasks[k].goal))
                    if (!freeFor(p, s.radius))
                        r.fail(goalNodes[k].first, goalNodes[k].second,
                               "the goal " + formatPoint(p) +
                                   " is out of bounds or in collision for a robot of radius " +
                                   std::to_string(s.radius));
            sc.robots.push_back(s);
        }

        // Robots present together at the start must not overlap.
        for (std::size_t i = 0; i < sc.robots.size(); ++i)
            for (std::size_t k = i + 1; k < sc.robots.size(); ++k)
            {
                const RobotSpec &a = sc.robots[i], &c = sc.robots[k];
                if (a.joinTime == 0.0 && c.joinTime == 0.0 &&
                    distance(a.start, c.start) < a.radius + c.radius)
                    r.fail(robots[k]["start"], "robots[" + std::to_string(k) + "].start",
                           "robot '" + c.name + "' overlaps robot '" + a.name + "' at the start");
            }
        return sc;
    }

    Scenario loadScenario(const std::string &path)
    {
        return parseScenarioYaml(readInputFile(path, kMaxYamlBytes, "scenario file"), path);
    }
} // namespace mhplan
