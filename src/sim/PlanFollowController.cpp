// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: plan-then-follow with any registered planner (see Controllers.h). */
#include "src/sim/Controllers.h"

#include "src/sim/detail/Sensing.h"
#include "src/collision/Problem.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>

namespace mhplan
{
    using namespace detail;

    namespace
    {
        /** \brief The point \e ahead metres along \e path from the point \e along metres into segment
            \e segment (the path's end when beyond it); \e remaining (if not null) gets the path length left
            from that start point. */
        Vec2 pathPointAhead(const std::vector<Vec2> &path, std::size_t segment, double along, double ahead,
                            double *remaining)
        {
            Vec2 point = path.back();
            bool found = false;
            double left = -along;
            ahead += along;
            for (std::size_t k = segment; k + 1 < path.size(); ++k)
            {
                const double length = distance(path[k], path[k + 1]);
                left += length;
                if (!found && ahead <= length)
                {
                    point = length > 0.0 ? path[k] + (path[k + 1] - path[k]) * (ahead / length) : path[k + 1];
                    found = true;
                    if (remaining == nullptr)
                        break;
                }
                ahead -= length;
            }
            if (remaining != nullptr)
                *remaining = left;
            return point;
        }

        /** \brief Distance a disc added in a replan keeps from the robot at the start and at the goal (m). */
        constexpr double kRoomSlack = 1e-6;
    } // namespace

    // ---------------------------------------------------------------------------------------------------
    // plan:<PLANNER>

    PlanFollowController::PlanFollowController(std::string planner, const PlannerRegistry &registry)
        : planner_(std::move(planner)), registry_(&registry)
    {
        registry_->get(planner_); // InputError listing the planners for an unknown one
        params_.add("plan_time", &planTime_, 0.001, 600.0, false,
                    "planning budget per plan (s of wall clock)");
        params_.add("lookahead", &lookahead_, 0.01, 100.0, false,
                    "pure-pursuit lookahead along the path (m)");
        params_.add("slowdown", &slowdown_, 0.0, 100.0, false,
                    "slow down linearly within this distance of the path end (m)");
        params_.add("sense_range", &senseRange_, 0.0, 1000.0, false,
                    "moving obstacles and robots within this range can block the path (m)");
        params_.add("margin", &margin_, 0.0, 100.0, false, "inflation of a blocking disc in a replan (m)");
        params_.add("goal_tolerance", &goalTolerance_, 0.001, 1000.0, false,
                    "replan when the goal moved this far from the path end (m)");
        params_.add("replan_interval", &replanInterval_, 0.0, 1000.0, false,
                    "least time between two replans (s)");
        params_.add("clearance", &clearance_, 0.0, 100.0, false,
                    "extra radius when planning on the static world (m)");
        params_.add("predict_time", &predictTime_, 0.0, 100.0, false,
                    "how far ahead blocking discs are predicted (s)");
        params_.add("evade", &evade_, 0.0, 1.0, true,
                    "1 = each command evades sensed moving obstacles predicted to come within evade_margin");
        params_.add("evade_horizon", &evadeHorizon_, 0.01, 20.0, false,
                    "how far ahead the evasion rolls candidate velocities out (s)");
        params_.add("evade_margin", &evadeMargin_, 0.0, 10.0, false,
                    "least predicted gap to a moving obstacle for a candidate velocity to be safe (m)");
        params_.add("evade_headings", &evadeHeadings_, 4.0, 360.0, true,
                    "evasive headings at full speed among the evasion's candidates");
    }

    void PlanFollowController::setParameter(const std::string &name, const std::string &value)
    {
        const std::string prefix = "planner.";
        if (name.compare(0, prefix.size(), prefix) != 0)
        {
            ControllerBase::setParameter(name, value);
            return;
        }
        const std::string key = name.substr(prefix.size());
        // Check the value on a throwaway planner (applyPlannerParameters names the problem).
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ompl::base::SpaceInformation>(space);
        try
        {
            registry_->create(planner_, si, {{key, value}});
        }
        catch (const InputError &e)
        {
            throw InputError("controller '" + this->name() + "' parameter '" + name + "': " + e.what());
        }
        plannerParams_[key] = value;
    }

    std::map<std::string, std::string> PlanFollowController::parameters() const
    {
        std::map<std::string, std::string> out = ControllerBase::parameters();
        for (const auto &kv : plannerParams_)
            out["planner." + kv.first] = kv.second;
        return out;
    }

    void PlanFollowController::reset(const Simulation &sim, ompl::RNG &rng)
    {
        rng_ = &rng;
        tracks_.assign(sim.robotCount(), Track{});
        threats_.clear();
        threats_.reserve(sim.scenario().movingObstacles.size());
        plans_ = replans_ = evasions_ = 0.0;
    }

    std::map<std::string, double> PlanFollowController::counters() const
    {
        return {{"plans", plans_}, {"replans", replans_}, {"evasions", evasions_}};
    }

    void PlanFollowController::taskStarted(const Simulation &sim, std::size_t i)
    {
        plan(sim, i, false);
        plans_ += 1.0;
        tracks_[i].lastPlan = -kInf;
    }

    template <class F> void PlanFollowController::forEachPrediction(const SensedObstacle &o, F &&f) const
    {
        const double speed = norm(o.velocity);
        if (speed <= 0.0 || predictTime_ <= 0.0)
            return;
        const int n =
            static_cast<int>(std::ceil(std::min(speed * predictTime_ / std::max(o.radius, 1e-3), 1000.0)));
        for (int k = 1; k <= n; ++k)
            f(o.center + o.velocity * (predictTime_ * k / n));
    }

    void PlanFollowController::plan(const Simulation &sim, std::size_t i, bool withDiscs)
    {
        const RobotState &s = sim.state(i);
        const double r = sim.spec(i).radius;
        World bare = sim.scenario().world;
        bare.robotRadius = r;
        bare.queries.clear();
        World spaced = bare;
        spaced.robotRadius = r + clearance_;
        World withDiscsWorld = spaced;
        Query query;
        query.name = "sim";
        query.start = s.position;
        query.goal = s.goal;
        if (withDiscs)
        {
            std::shared_ptr<OccupancyGrid> grid;
            if (bare.isGrid())
                grid = std::make_shared<OccupancyGrid>(*bare.grid);
            // A disc inflated by the margin; by less when that would cover the start or the goal; dropped
            // when even the bare disc would. The room left keeps kRoomSlack from the start and the goal: a
            // disc that touched one exactly would make it invalid by rounding, the query would be refused
            // and the replan would fall back to the static world, blind to every sensed disc.
            auto addDisc = [&](const Vec2 &center, double bareRadius)
            {
                const double room = std::min(distance(center, query.start), distance(center, query.goal)) -
                                    spaced.robotRadius - kRoomSlack;
                const double radius = std::min(bareRadius + margin_, room);
                if (radius < bareRadius)
                    return;
                if (!grid)
                {
                    withDiscsWorld.circles.push_back(Circle{center, radius});
                    return;
                }
                for (int iy = grid->cellY(center.y - radius); iy <= grid->cellY(center.y + radius); ++iy)
                    for (int ix = grid->cellX(center.x - radius); ix <= grid->cellX(center.x + radius); ++ix)
                        if (grid->inside(ix, iy) && boxDistance(grid->cellBox(ix, iy), center) < radius)
                            grid->setBlocked(ix, iy, true);
            };
            forEachObstacle(sim, i, s.position, senseRange_, false,
                            [&](const SensedObstacle &o, double, const Vec2 &)
                            {
                                if (o.source == SensedObstacle::Source::Static)
                                    return;
                                addDisc(o.center, o.radius);
                                forEachPrediction(o, [&](const Vec2 &c) { addDisc(c, o.radius); });
                            });
            if (grid)
                withDiscsWorld.grid = grid;
        }
        // The first exact solution of: the world with the sensed discs (replans), the static world with the
        // clearance, the static world with the bare radius; else the first approximate one; else a straight
        // segment. A world whose setup is refused (the start or goal invalid there) is skipped.
        std::vector<Vec2> path;
        std::vector<const World *> worlds;
        if (withDiscs)
            worlds.push_back(&withDiscsWorld);
        worlds.push_back(&spaced);
        worlds.push_back(&bare);
        for (const World *w : worlds)
        {
            try
            {
                const ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(*w, query, makeCollisionModel(*w));
                const ompl::base::PlannerPtr planner =
                    registry_->create(planner_, ss->getSpaceInformation(), plannerParams_);
                if (planner->params().hasParam("seed") && plannerParams_.count("seed") == 0)
                    planner->params().setParam("seed", std::to_string(rng_->uniformInt(1, 1 << 30)));
                ss->setPlanner(planner);
                ss->solve(planTime_);
                if (!ss->haveSolutionPath())
                    continue;
                const bool exact = ss->haveExactSolutionPath();
                if (exact || path.empty())
                    path = pathPoints(ss->getSolutionPath());
                if (exact)
                    break;
            }
            catch (const InputError &)
            {
            }
        }
        if (path.size() < 2)
            path = {s.position, s.goal};
        Track &t = tracks_[i];
        t.path = std::move(path);
        t.segment = 0;
        t.along = 0.0;
    }

    void PlanFollowController::project(const Simulation &sim, std::size_t i)
    {
        Track &t = tracks_[i];
        const Vec2 p = sim.state(i).position;
        for (;;)
        {
            const Vec2 &a = t.path[t.segment];
            const Vec2 &b = t.path[t.segment + 1];
            const double length = distance(a, b);
            const double u = length > 0.0 ? std::clamp(dot(p - a, b - a) / (length * length), 0.0, 1.0) : 1.0;
            t.along = u * length;
            if (t.segment + 2 >= t.path.size())
                return;
            if (u >= 1.0 || pointSegmentDistance(p, b, t.path[t.segment + 2]) < pointSegmentDistance(p, a, b))
            {
                ++t.segment;
                continue;
            }
            return;
        }
    }

    double PlanFollowController::blockedAt(const Simulation &sim, std::size_t i, bool &byRobot) const
    {
        const Track &t = tracks_[i];
        const Vec2 p = sim.state(i).position;
        const double r = sim.spec(i).radius;
        double blocked = kInf;
        byRobot = false;
        auto check = [&](const Vec2 &center, double radius, bool robot)
        {
            double walked = -t.along;
            for (std::size_t k = t.segment; k + 1 < t.path.size() && walked < senseRange_; ++k)
            {
                const Vec2 &a = t.path[k];
                const Vec2 &b = t.path[k + 1];
                const double length = distance(a, b);
                const Vec2 from = k == t.segment && length > 0.0 ? a + (b - a) * (t.along / length) : a;
                if (pointSegmentDistance(center, from, b) < radius + r)
                {
                    const double at =
                        std::max(0.0, walked + distance(a, from) + distance(from, center) - radius - r);
                    if (at < blocked)
                    {
                        blocked = at;
                        byRobot = robot;
                    }
                    return;
                }
                walked += length;
            }
        };
        forEachObstacle(sim, i, p, senseRange_, false,
                        [&](const SensedObstacle &o, double, const Vec2 &)
                        {
                            if (o.source == SensedObstacle::Source::Static)
                                return;
                            const bool robot = o.source == SensedObstacle::Source::Robot;
                            check(o.center, o.radius, robot);
                            forEachPrediction(o, [&](const Vec2 &c) { check(c, o.radius, robot); });
                        });
        return blocked;
    }

    Command PlanFollowController::command(const Simulation &sim, std::size_t i)
    {
        const RobotState &s = sim.state(i);
        const double vmax = sim.spec(i).maxSpeed;
        Track &t = tracks_[i];
        project(sim, i);
        bool byRobot = false;
        double blocked = blockedAt(sim, i, byRobot);
        const bool goalMoved = distance(t.path.back(), s.goal) > goalTolerance_;
        const bool mayReplan = sim.time() - t.lastPlan >= replanInterval_ - 1e-9;
        if ((blocked < kInf || goalMoved) && mayReplan)
        {
            plan(sim, i, true);
            replans_ += 1.0;
            t.lastPlan = sim.time();
            project(sim, i);
            blocked = blockedAt(sim, i, byRobot);
        }
        // While a robot blocks the path within the lookahead and no replan is allowed yet, the follower
        // waits (a zero command; the evasion still moves it out of a moving obstacle's way).
        const bool wait = byRobot && blocked <= lookahead_ && !mayReplan;

        // Pure pursuit toward the point lookahead further along the path, pulled back (halving) while the
        // straight way there is not free; the speed follows the path length left.
        const double r = sim.spec(i).radius;
        double remaining = 0.0, ahead = lookahead_;
        Vec2 target = pathPointAhead(t.path, t.segment, t.along, ahead, &remaining);
        for (int k = 0; k < 6 && !sim.staticSegmentFree(s.position, target, r); ++k)
        {
            ahead *= 0.5;
            target = pathPointAhead(t.path, t.segment, t.along, ahead, nullptr);
        }
        if (remaining <= lookahead_ && sim.staticSegmentFree(s.position, s.goal, r))
        {
            target = s.goal;
            remaining = distance(s.position, s.goal);
        }
        const double speed = slowdown_ > 0.0 ? vmax * std::min(1.0, remaining / slowdown_) : vmax;
        const Vec2 toward = unit(target - s.position);
        const Vec2 follow = wait ? Vec2() : toward * speed;
        return {brake(sim, i, evade(sim, i, follow, toward))};
    }

    PlanFollowController::Rollout PlanFollowController::rollout(const Simulation &sim, std::size_t i,
                                                                const Vec2 &v, const Vec2 &toward,
                                                                int steps) const
    {
        const RobotSpec &spec = sim.spec(i);
        const RobotState &s = sim.state(i);
        const double dt = sim.dt();
        Vec2 p = s.position;
        double heading = s.heading;
        bool stopped = false;
        double gap = kInf;
        for (int k = 1; k <= steps; ++k)
        {
            // The simulator's step from the world-frame command (Simulation.h, Command); a step that would
            // leave the static free space is not made (the brake and the simulator stop the robot there).
            if (!stopped)
            {
                const Command u = unicycleCommand(spec, heading, v, dt);
                if (u.unicycle)
                {
                    const double h = heading + u.turn;
                    const Vec2 next = p + Vec2(std::cos(h), std::sin(h)) * (u.forward * dt);
                    if (sim.staticFree(next, spec.radius))
                    {
                        p = next;
                        heading = h;
                    }
                    else
                        stopped = true;
                }
            }
            const double time = k * dt;
            for (const SensedObstacle &o : threats_)
                gap = std::min(gap, distance(p, o.center + o.velocity * time) - o.radius - spec.radius);
        }
        return {gap, dot(p - s.position, toward)};
    }

    Vec2 PlanFollowController::evade(const Simulation &sim, std::size_t i, const Vec2 &follow,
                                     const Vec2 &toward)
    {
        if (evade_ == 0.0)
            return follow;
        const RobotSpec &spec = sim.spec(i);
        const RobotState &s = sim.state(i);
        const int steps = std::max(1, static_cast<int>(std::ceil(evadeHorizon_ / sim.dt() - 1e-9)));
        const double horizon = steps * sim.dt();
        // The sensed moving obstacles (what the replanning sees) that can come within the margin of anywhere
        // the robot can reach within the horizon: the disc's centre sweeps c + v t, the robot stays within
        // maxSpeed t of its position.
        threats_.clear();
        forEachObstacle(sim, i, s.position, senseRange_, false,
                        [&](const SensedObstacle &o, double, const Vec2 &)
                        {
                            if (o.source != SensedObstacle::Source::Moving)
                                return;
                            const double closest =
                                pointSegmentDistance(s.position, o.center, o.center + o.velocity * horizon) -
                                o.radius - spec.radius;
                            if (closest - spec.maxSpeed * horizon < evadeMargin_)
                                threats_.push_back(o); // within the capacity reserved in reset()
                        });
        if (threats_.empty())
            return follow;
        const Rollout kept = rollout(sim, i, follow, toward, steps);
        if (kept.gap >= evadeMargin_)
            return follow;

        // a is better than b: safe before unsafe; among safe ones more progress (then the larger gap); among
        // unsafe ones the larger gap (then more progress).
        auto better = [&](const Rollout &a, const Rollout &b)
        {
            const bool safeA = a.gap >= evadeMargin_, safeB = b.gap >= evadeMargin_;
            if (safeA != safeB)
                return safeA;
            const double first = safeA ? a.progress - b.progress : a.gap - b.gap;
            const double second = safeA ? a.gap - b.gap : a.progress - b.progress;
            constexpr double tie = 1e-9;
            return first > tie || (first >= -tie && second > tie);
        };
        Vec2 best = follow;
        Rollout bestRollout = kept;
        auto consider = [&](const Vec2 &v)
        {
            const Rollout candidate = rollout(sim, i, v, toward, steps);
            if (better(candidate, bestRollout))
            {
                best = v;
                bestRollout = candidate;
            }
        };
        consider(follow * 0.5);
        consider(follow * 0.25);
        consider(Vec2());
        const int headings = static_cast<int>(evadeHeadings_);
        for (int k = 0; k < headings; ++k)
        {
            const double angle = s.heading + 2.0 * kPi * k / headings;
            consider(Vec2(std::cos(angle), std::sin(angle)) * spec.maxSpeed);
        }
        if (best != follow)
            evasions_ += 1.0;
        return best;
    }
} // namespace mhplan
