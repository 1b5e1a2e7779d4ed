// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the time-stepped multi-robot simulator (see Simulation.h). */
#include "src/sim/Simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mhplan
{
    namespace
    {
        double wrapAngle(double a)
        {
            a = std::fmod(a + kPi, 2.0 * kPi);
            if (a < 0.0)
                a += 2.0 * kPi;
            return a - kPi;
        }

        double wallSeconds()
        {
            using clock = std::chrono::steady_clock;
            return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
        }

        /** \brief Contact episode bookkeeping: returns true when a new episode starts. */
        bool enterContact(std::uint8_t &flag, bool inContact)
        {
            const bool started = inContact && flag == 0;
            flag = inContact ? 1 : 0;
            return started;
        }
    } // namespace

    Vec2 Motion::positionAt(double t) const
    {
        switch (kind)
        {
        case Kind::Fixed:
            return from;
        case Kind::Line:
        {
            const double length = distance(from, to);
            if (length <= 0.0 || speed <= 0.0)
                return from;
            const Vec2 dir = (to - from) / length;
            const double s = std::fmod(t * speed, 2.0 * length);
            return s <= length ? from + dir * s : to - dir * (s - length);
        }
        case Kind::Circle:
        {
            const double a = phase + angularSpeed * t;
            return center + Vec2(std::cos(a), std::sin(a)) * radius;
        }
        }
        return from;
    }

    Vec2 Motion::velocityAt(double t) const
    {
        switch (kind)
        {
        case Kind::Fixed:
            return {};
        case Kind::Line:
        {
            const double length = distance(from, to);
            if (length <= 0.0 || speed <= 0.0)
                return {};
            const Vec2 dir = (to - from) / length;
            const double s = std::fmod(t * speed, 2.0 * length);
            return s < length ? dir * speed : dir * -speed;
        }
        case Kind::Circle:
        {
            const double a = phase + angularSpeed * t;
            return Vec2(-std::sin(a), std::cos(a)) * (radius * angularSpeed);
        }
        }
        return {};
    }

    Command unicycleCommand(const RobotSpec &spec, double heading, const Vec2 &v, double dt)
    {
        Command u;
        const double speed = std::min(norm(v), spec.maxSpeed);
        if (speed > 1e-12 && std::isfinite(speed))
        {
            const double error = wrapAngle(std::atan2(v.y, v.x) - heading);
            const double maxTurn = spec.maxTurnRate * dt;
            u.unicycle = true;
            u.turn = std::clamp(error, -maxTurn, maxTurn);
            u.forward = speed * std::max(0.0, std::cos(error - u.turn));
        }
        return u;
    }

    void Controller::setParameter(const std::string &name, const std::string &value)
    {
        throw InputError("controller '" + this->name() + "' has no parameter '" + name + "' (value '" +
                         value + "')");
    }

    std::string toString(RobotStatus status)
    {
        switch (status)
        {
        case RobotStatus::Waiting:
            return "waiting";
        case RobotStatus::Moving:
            return "moving";
        case RobotStatus::Done:
            return "done";
        case RobotStatus::Stuck:
            return "stuck";
        }
        return "unknown";
    }

    Simulation::Simulation(Scenario scenario, ControllerPtr controller, std::uint32_t seed)
        : scenario_(std::move(scenario)), controller_(std::move(controller)), seed_(seed), rng_(seed)
    {
        if (!controller_)
            throw std::invalid_argument("Simulation: controller must not be null");
        if (!(scenario_.settings.dt > 0.0))
            throw std::invalid_argument("Simulation: settings.dt must be > 0");
        if (scenario_.settings.recordEvery == 0)
            throw std::invalid_argument("Simulation: settings.recordEvery must be >= 1");
        World pointWorld = scenario_.world;
        pointWorld.robotRadius = 0.0;
        pointWorld.queries.clear();
        pointModel_ = makeCollisionModel(pointWorld);
    }

    bool Simulation::staticFree(const Vec2 &p, double r) const
    {
        const Box &b = scenario_.world.bounds;
        if (!(p.x >= b.xmin + r && p.x <= b.xmax - r && p.y >= b.ymin + r && p.y <= b.ymax - r))
            return false;
        return pointModel_->clearance(p) >= r;
    }

    bool Simulation::staticSegmentFree(const Vec2 &a, const Vec2 &c, double r) const
    {
        if (!staticFree(a, r) || !staticFree(c, r))
            return false; // the inner box is convex: both ends inside means the segment is
        return pointModel_->segmentClearance(a, c) >= r;
    }

    void Simulation::updateWorld()
    {
        const auto &obs = scenario_.movingObstacles;
        obstaclePos_.resize(obs.size());
        obstacleVel_.resize(obs.size());
        for (std::size_t j = 0; j < obs.size(); ++j)
        {
            obstaclePos_[j] = obs[j].motion.positionAt(time_);
            obstacleVel_[j] = obs[j].motion.velocityAt(time_);
        }
        for (std::size_t i = 0; i < robots_.size(); ++i)
        {
            const RobotSpec &s = scenario_.robots[i];
            RobotState &r = robots_[i];
            if (r.task < s.tasks.size())
                r.goal = s.tasks[r.task].goal.positionAt(time_);
        }
    }

    void Simulation::beginTask(std::size_t i)
    {
        RobotState &r = robots_[i];
        r.status = RobotStatus::Moving;
        r.goal = scenario_.robots[i].tasks[r.task].goal.positionAt(time_);
        progressBest_[i] = distance(r.position, r.goal);
        progressSince_[i] = time_;
        controller_->taskStarted(*this, i);
    }

    void Simulation::start()
    {
        started_ = true;
        wallStart_ = wallSeconds();
        const std::size_t n = scenario_.robots.size();
        robots_.assign(n, RobotState{});
        progressBest_.assign(n, 0.0);
        progressSince_.assign(n, 0.0);
        staticContact_.assign(n, 0);
        movingContact_.assign(n * scenario_.movingObstacles.size(), 0);
        robotContact_.assign(n * n, 0);
        result_ = SimulationResult{};
        result_.scenario = scenario_.name;
        result_.controller = controller_->name();
        result_.seed = seed_;
        result_.robots.resize(n);
        result_.obstaclePositions.assign(scenario_.movingObstacles.size(), {});
        result_.goalPositions.assign(n, {});
        for (std::size_t i = 0; i < n; ++i)
        {
            const RobotSpec &s = scenario_.robots[i];
            result_.robots[i].name = s.name;
            robots_[i].position = s.start;
            robots_[i].heading = s.heading;
            if (s.tasks.empty())
                throw std::invalid_argument("Simulation: robot '" + s.name + "' has no task");
        }
        time_ = 0.0;
        updateWorld();
        controller_->reset(*this, rng_);
        admit();
        measure();
        record();
    }

    void Simulation::admit()
    {
        constexpr double eps = 1e-9;
        for (std::size_t i = 0; i < robots_.size(); ++i)
        {
            const RobotSpec &s = scenario_.robots[i];
            RobotState &r = robots_[i];
            if (!r.joined)
            {
                if (s.joinTime > time_ + eps)
                    continue;
                r.joined = true;
                r.joinedAt = time_;
                r.position = s.start;
                r.heading = s.heading;
                r.status = RobotStatus::Waiting;
            }
            if (r.status == RobotStatus::Moving)
            {
                r.goal = s.tasks[r.task].goal.positionAt(time_);
                const double d = distance(r.position, r.goal);
                if (d <= scenario_.settings.goalTolerance)
                {
                    ++r.task;
                    r.status = RobotStatus::Waiting;
                    if (r.task == s.tasks.size())
                    {
                        r.status = RobotStatus::Done;
                        r.finishedAt = time_;
                        continue;
                    }
                }
                else if (d < progressBest_[i] - scenario_.settings.stuckDistance)
                {
                    progressBest_[i] = d;
                    progressSince_[i] = time_;
                }
                else if (time_ - progressSince_[i] >= scenario_.settings.stuckTimeout - eps)
                {
                    r.status = RobotStatus::Stuck;
                    r.finishedAt = time_;
                    continue;
                }
            }
            if (r.status == RobotStatus::Waiting && r.task < s.tasks.size() &&
                s.tasks[r.task].assignedAt <= time_ + eps)
                beginTask(i);
        }
    }

    void Simulation::measure()
    {
        const std::size_t n = robots_.size();
        const auto &obs = scenario_.movingObstacles;
        constexpr double contactEps = 1e-9;
        for (std::size_t i = 0; i < n; ++i)
        {
            if (!robots_[i].joined)
                continue;
            const RobotSpec &s = scenario_.robots[i];
            RobotResult &out = result_.robots[i];
            const Vec2 &p = robots_[i].position;
            double clearance = pointModel_->clearance(p) - s.radius;
            for (std::size_t j = 0; j < obs.size(); ++j)
            {
                const double d = distance(p, obstaclePos_[j]) - obs[j].radius - s.radius;
                clearance = std::min(clearance, d);
                if (enterContact(movingContact_[i * obs.size() + j], d < -contactEps))
                {
                    ++result_.movingCollisions;
                    ++out.collisions;
                }
            }
            out.minObstacleClearance = std::min(out.minObstacleClearance, clearance);
            result_.minObstacleClearance = std::min(result_.minObstacleClearance, clearance);
            for (std::size_t k = i + 1; k < n; ++k)
            {
                if (!robots_[k].joined)
                    continue;
                const double d = distance(p, robots_[k].position) - s.radius - scenario_.robots[k].radius;
                out.minRobotDistance = std::min(out.minRobotDistance, d);
                result_.robots[k].minRobotDistance = std::min(result_.robots[k].minRobotDistance, d);
                result_.minRobotDistance = std::min(result_.minRobotDistance, d);
                if (enterContact(robotContact_[i * n + k], d < -contactEps))
                {
                    ++result_.robotCollisions;
                    ++out.collisions;
                    ++result_.robots[k].collisions;
                }
            }
        }
    }

    void Simulation::record()
    {
        if (result_.steps % scenario_.settings.recordEvery != 0 && !ended_)
            return;
        if (!result_.times.empty() && result_.times.back() == time_)
            return;
        result_.times.push_back(time_);
        for (std::size_t j = 0; j < obstaclePos_.size(); ++j)
            result_.obstaclePositions[j].push_back(obstaclePos_[j]);
        for (std::size_t i = 0; i < robots_.size(); ++i)
        {
            result_.goalPositions[i].push_back(robots_[i].goal);
            if (!robots_[i].joined)
                continue;
            RobotResult &out = result_.robots[i];
            out.times.push_back(time_);
            out.positions.push_back(robots_[i].position);
            out.headings.push_back(robots_[i].heading);
        }
    }

    void Simulation::addTask(std::size_t i, const Task &task)
    {
        RobotSpec &s = scenario_.robots.at(i);
        s.tasks.push_back(task);
        if (started_ && robots_.at(i).status == RobotStatus::Done)
            robots_[i].status = RobotStatus::Waiting;
    }

    void Simulation::setJoinTime(std::size_t i, double t)
    {
        RobotSpec &s = scenario_.robots.at(i);
        if (started_ && robots_.at(i).joined)
            throw std::logic_error("Simulation::setJoinTime: robot '" + s.name + "' has joined already");
        s.joinTime = t;
    }

    void Simulation::observe(double time, const std::vector<RobotState> &robots,
                             const std::vector<Vec2> &obstaclePos, const std::vector<Vec2> &obstacleVel)
    {
        if (robots.size() != scenario_.robots.size() ||
            obstaclePos.size() != scenario_.movingObstacles.size() ||
            obstacleVel.size() != obstaclePos.size())
            throw std::invalid_argument(
                "Simulation::observe: expected " + std::to_string(scenario_.robots.size()) + " robots and " +
                std::to_string(scenario_.movingObstacles.size()) + " moving obstacles");
        time_ = time;
        robots_ = robots;
        obstaclePos_ = obstaclePos;
        obstacleVel_ = obstacleVel;
        if (!observed_)
        {
            observed_ = started_ = ended_ = true;
            result_ = SimulationResult{};
            result_.robots.resize(robots.size());
            controller_->reset(*this, rng_);
        }
    }

    bool Simulation::step()
    {
        if (observed_)
            return false;
        if (!started_)
            start();
        if (ended_)
            return false;
        const SimulationSettings &set = scenario_.settings;
        const double dt = set.dt;
        const std::size_t n = robots_.size();

        // Commands from the state at the start of the step (synchronous update).
        commands_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            if (robots_[i].status == RobotStatus::Moving)
                commands_[i] = controller_->command(*this, i);

        unsigned long moving = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            RobotState &r = robots_[i];
            if (r.status != RobotStatus::Moving)
            {
                r.velocity = {};
                continue;
            }
            ++moving;
            const RobotSpec &s = scenario_.robots[i];
            r.traversalTime += dt;
            const Command u = commands_[i].unicycle
                                  ? commands_[i]
                                  : unicycleCommand(s, r.heading, commands_[i].velocity, dt);
            Vec2 next = r.position;
            if (u.unicycle)
            {
                const double maxTurn = s.maxTurnRate * dt;
                const double turn = std::isfinite(u.turn) ? std::clamp(u.turn, -maxTurn, maxTurn) : 0.0;
                const double forward =
                    std::isfinite(u.forward) ? std::clamp(u.forward, 0.0, s.maxSpeed) : 0.0;
                r.heading = wrapAngle(r.heading + turn);
                next = r.position + Vec2(std::cos(r.heading), std::sin(r.heading)) * (forward * dt);
            }
            bool blocked = false;
            if (next != r.position && !staticSegmentFree(r.position, next, s.radius))
            {
                // Cut the step at the last free position (bisection on the exact segment check).
                double lo = 0.0, hi = 1.0;
                for (int it = 0; it < 40; ++it)
                {
                    const double mid = 0.5 * (lo + hi);
                    if (staticSegmentFree(r.position, r.position + (next - r.position) * mid, s.radius))
                        lo = mid;
                    else
                        hi = mid;
                }
                next = r.position + (next - r.position) * lo;
                blocked = true;
            }
            if (enterContact(staticContact_[i], blocked))
            {
                ++result_.staticCollisions;
                ++result_.robots[i].collisions;
            }
            r.pathLength += distance(r.position, next);
            r.velocity = (next - r.position) / dt;
            r.position = next;
        }

        ++result_.steps;
        result_.robotSteps += moving;
        time_ = static_cast<double>(result_.steps) * dt;
        updateWorld();
        admit();
        measure();

        bool allOver = true;
        for (std::size_t i = 0; i < n; ++i)
            if (robots_[i].status != RobotStatus::Done && robots_[i].status != RobotStatus::Stuck)
                allOver = false;
        if (allOver || time_ >= set.timeLimit - 1e-9)
            ended_ = true;
        record();
        return !ended_;
    }

    SimulationResult Simulation::run()
    {
        while (step())
        {
        }
        return result();
    }

    SimulationResult Simulation::result() const
    {
        SimulationResult out = result_;
        out.simulatedTime = time_;
        out.wallTime = started_ ? wallSeconds() - wallStart_ : 0.0;
        out.counters = controller_->counters();
        out.done = out.stuck = out.unfinished = 0;
        out.flowtime = out.makespan = 0.0;
        for (std::size_t i = 0; i < robots_.size(); ++i)
        {
            const RobotState &r = robots_[i];
            RobotResult &rr = out.robots[i];
            rr.status = r.status;
            rr.traversalTime = r.traversalTime;
            rr.pathLength = r.pathLength;
            if (r.status == RobotStatus::Done)
                ++out.done;
            else if (r.status == RobotStatus::Stuck)
                ++out.stuck;
            else
                ++out.unfinished;
            out.flowtime += r.traversalTime;
            out.makespan = std::max(out.makespan, r.status == RobotStatus::Done ? r.finishedAt : time_);
        }
        out.allDone = out.done == robots_.size();
        return out;
    }
} // namespace mhplan
