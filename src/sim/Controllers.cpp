// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the simulator's controllers (see Controllers.h). */
#include "mhplan/sim/Controllers.h"

#include "mhplan/collision/Problem.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        /** \brief Smallest speed a braked command keeps (the simulator turns only for a nonzero speed). */
        constexpr double kCreepSpeed = 1e-11;

        Vec2 unit(const Vec2 &v)
        {
            const double n = norm(v);
            return n > 0.0 ? v / n : Vec2();
        }

        Vec2 capped(const Vec2 &v, double limit)
        {
            const double n = norm(v);
            return n > limit ? v * (limit / n) : v;
        }

        /** \brief Distance from \e p to the surface of \e o (negative inside); the nearest surface point in
            \e nearest when it is not null (for the grid: from the clearance's numerical gradient). */
        double surfaceDistance(const Simulation &sim, const SensedObstacle &o, const Vec2 &p, Vec2 *nearest)
        {
            using Shape = SensedObstacle::Shape;
            switch (o.shape)
            {
            case Shape::Disc:
            {
                const double d = distance(p, o.center);
                if (nearest != nullptr)
                    *nearest = o.center + unit(p - o.center) * o.radius;
                return d - o.radius;
            }
            case Shape::Wall:
            {
                const double d = dot(p - o.center, o.normal);
                if (nearest != nullptr)
                    *nearest = p - o.normal * d;
                return d;
            }
            case Shape::Polygon:
            {
                const std::vector<Vec2> &v = o.polygon->vertices;
                double best = kInf;
                Vec2 bestPoint = p;
                for (std::size_t k = 0; k < v.size(); ++k)
                {
                    const Vec2 q = closestPointOnSegment(p, v[k], v[(k + 1) % v.size()]);
                    const double d = distance(p, q);
                    if (d < best)
                    {
                        best = d;
                        bestPoint = q;
                    }
                }
                if (nearest != nullptr)
                    *nearest = bestPoint;
                return pointInPolygon(p, v) ? -best : best;
            }
            case Shape::Grid:
            {
                const CollisionModel &model = sim.staticModel();
                const double c = model.clearance(p);
                if (nearest != nullptr)
                {
                    const double h = sim.scenario().world.grid->cellSize() / 20.0;
                    const Vec2 g(model.clearance(p + Vec2(h, 0.0)) - model.clearance(p - Vec2(h, 0.0)),
                                 model.clearance(p + Vec2(0.0, h)) - model.clearance(p - Vec2(0.0, h)));
                    *nearest = p - unit(g) * c;
                }
                return c;
            }
            }
            return kInf;
        }

        /** \brief Distance from \e p to the box (0 inside). */
        double boxDistance(const Box &b, const Vec2 &p)
        {
            const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax});
            const double dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
            return std::hypot(dx, dy);
        }

        /** \brief Calls f(obstacle, gap, nearest) for every obstacle whose surface is within \e range of the
            surface of robot \e self's disc placed at \e p (gap = surface distance minus the robot's radius):
            static circles and polygons (the nearest blocked cell in grid worlds), the walls when \e walls,
            moving obstacles and the other present robots. Allocates nothing. */
        template <class F>
        void forEachObstacle(const Simulation &sim, std::size_t self, const Vec2 &p, double range, bool walls,
                             F &&f)
        {
            using Shape = SensedObstacle::Shape;
            using Source = SensedObstacle::Source;
            const double r = sim.spec(self).radius;
            const World &world = sim.scenario().world;
            SensedObstacle o;
            Vec2 nearest;
            auto visit = [&]()
            {
                const double gap = surfaceDistance(sim, o, p, &nearest) - r;
                if (gap <= range)
                    f(o, gap, nearest);
            };
            o.source = Source::Static;
            if (world.isGrid())
            {
                o.shape = Shape::Grid;
                if (sim.staticModel().clearance(p) - r <= range)
                    visit();
            }
            o.shape = Shape::Disc;
            for (const Circle &c : world.circles)
            {
                o.center = c.center;
                o.radius = c.radius;
                visit();
            }
            o.shape = Shape::Polygon;
            for (const Polygon &poly : world.polygons)
            {
                if (boxDistance(poly.bbox, p) - r > range)
                    continue;
                o.polygon = &poly;
                visit();
            }
            if (walls)
            {
                const Box &b = world.bounds;
                o.shape = Shape::Wall;
                const Vec2 points[4] = {{b.xmin, p.y}, {b.xmax, p.y}, {p.x, b.ymin}, {p.x, b.ymax}};
                const Vec2 normals[4] = {{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}};
                for (int k = 0; k < 4; ++k)
                {
                    o.center = points[k];
                    o.normal = normals[k];
                    visit();
                }
            }
            o.shape = Shape::Disc;
            o.source = Source::Moving;
            const auto &moving = sim.scenario().movingObstacles;
            for (std::size_t j = 0; j < moving.size(); ++j)
            {
                o.center = sim.obstaclePositions()[j];
                o.radius = moving[j].radius;
                o.velocity = sim.obstacleVelocities()[j];
                visit();
            }
            o.source = Source::Robot;
            for (std::size_t k = 0; k < sim.robotCount(); ++k)
            {
                if (k == self || !sim.present(k))
                    continue;
                o.center = sim.state(k).position;
                o.radius = sim.spec(k).radius;
                o.velocity = sim.state(k).velocity;
                visit();
            }
        }

        /** \brief True when the robot disc (radius \e r) sweeping [a, b] stays off the disc obstacles of
            \e obstacles (moving obstacles and robots), each grown by the distance it travels in \e time at
            its current speed. */
        bool clearOfDiscs(const std::vector<SensedObstacle> &obstacles, const Vec2 &a, const Vec2 &b,
                          double r, double time)
        {
            for (const SensedObstacle &o : obstacles)
                if (o.shape == SensedObstacle::Shape::Disc && o.source != SensedObstacle::Source::Static &&
                    pointSegmentDistance(o.center, a, b) < o.radius + r + norm(o.velocity) * time)
                    return false;
            return true;
        }

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

        std::string formatNumber(double v)
        {
            std::ostringstream out;
            out.precision(12);
            out << v;
            return out.str();
        }
    } // namespace

    // ---------------------------------------------------------------------------------------------------
    // Parameters and the shared base

    void ControllerParameters::add(const std::string &name, double *value, double lo, double hi, bool integer)
    {
        entries_[name] = Entry{value, lo, hi, integer};
    }

    std::string ControllerParameters::list() const
    {
        std::string out;
        for (const auto &kv : entries_)
            out += (out.empty() ? "" : ", ") + kv.first;
        return out;
    }

    void ControllerParameters::set(const std::string &controller, const std::string &name,
                                   const std::string &value)
    {
        const auto it = entries_.find(name);
        if (it == entries_.end())
            throw InputError("controller '" + controller + "' has no parameter '" + name + "' (value '" +
                             value + "'); its parameters: " + list());
        const Entry &e = it->second;
        char *end = nullptr;
        const double v = value.empty() ? std::nan("") : std::strtod(value.c_str(), &end);
        const bool parsed = end != nullptr && *end == '\0' && std::isfinite(v);
        if (!parsed || v < e.lo || v > e.hi || (e.integer && v != std::floor(v)))
            throw InputError("controller '" + controller + "' parameter '" + name + "': value '" + value +
                             "' is out of range; expected " + (e.integer ? "an integer" : "a number") +
                             " in [" + formatNumber(e.lo) + ", " + formatNumber(e.hi) + "]");
        *e.value = v;
    }

    std::map<std::string, std::string> ControllerParameters::values() const
    {
        std::map<std::string, std::string> out;
        for (const auto &kv : entries_)
            out[kv.first] = formatNumber(*kv.second.value);
        return out;
    }

    ControllerBase::ControllerBase()
    {
        params_.add("safety_brake", &safetyBrake_, 0.0, 1.0, true);
        params_.add("brake_margin", &brakeMargin_, 0.0, 1.0);
    }

    void ControllerBase::setParameter(const std::string &name, const std::string &value)
    {
        params_.set(this->name(), name, value);
    }

    Vec2 ControllerBase::brake(const Simulation &sim, std::size_t i, const Vec2 &v, bool *limited) const
    {
        const RobotSpec &spec = sim.spec(i);
        const double speed = std::min(norm(v), spec.maxSpeed);
        if (safetyBrake_ == 0.0 || !(speed > 0.0))
            return v;
        const double dt = sim.dt();
        const RobotState &s = sim.state(i);
        // The step the simulator makes per unit of speed (Command): turn toward v by at most maxTurnRate dt,
        // then drive along the new heading, scaled by the cosine of the heading error left.
        const double error = std::remainder(std::atan2(v.y, v.x) - s.heading, 2.0 * kPi);
        const double turn = std::clamp(error, -spec.maxTurnRate * dt, spec.maxTurnRate * dt);
        const Vec2 step = Vec2(std::cos(s.heading + turn), std::sin(s.heading + turn)) *
                          (std::max(0.0, std::cos(error - turn)) * dt);
        double limit = speed;
        forEachObstacle(sim, i, s.position, speed * dt / 0.45 + brakeMargin_, true,
                        [&](const SensedObstacle &o, double gap, const Vec2 &nearest)
                        {
                            using Source = SensedObstacle::Source;
                            if (o.source == Source::Moving)
                                return;
                            // Toward a convex obstacle only the step's component along the direction of its
                            // nearest point counts (the supporting half-plane bounds the distance); the grid
                            // and non-convex polygons are braked for in every direction.
                            const bool convex = o.shape != SensedObstacle::Shape::Grid &&
                                                (o.polygon == nullptr || o.polygon->convex);
                            const double approach =
                                convex ? dot(step, unit(nearest - s.position)) : norm(step);
                            if (approach <= 0.0)
                                return;
                            const double share = o.source == Source::Robot ? 0.45 : 0.9;
                            limit = std::min(limit, share * std::max(gap - brakeMargin_, 0.0) / approach);
                        });
        if (limited != nullptr)
            *limited = limit < speed;
        if (limit >= speed)
            return v;
        return unit(v) * std::max(limit, kCreepSpeed);
    }

    // ---------------------------------------------------------------------------------------------------
    // dapf / aapf

    ApfController::ApfController(bool adaptive) : adaptive_(adaptive)
    {
        params_.add("C_a", &attraction_, 0.0, 100.0);
        params_.add("C_o", &obstacleGain_, 0.0, 100.0);
        params_.add("C_r", &robotGain_, 0.0, 100.0);
        params_.add("rho", &rho_, 0.01, 100.0);
        if (adaptive_)
        {
            params_.add("phi_M", &coneDegrees_, 0.0, 180.0);
            params_.add("k_a", &adaptiveGain_, 0.0, 100.0);
            params_.add("horizon", &horizon_, 0.0, 100.0);
        }
    }

    void ApfController::reset(const Simulation & /*sim*/, ompl::RNG & /*rng*/) {}

    void ApfController::taskStarted(const Simulation & /*sim*/, std::size_t /*i*/) {}

    unsigned int ApfController::crowding(const Simulation &sim, std::size_t i) const
    {
        const RobotState &me = sim.state(i);
        const double ri = sim.spec(i).radius;
        const Vec2 next = me.position + me.velocity * horizon_;
        unsigned int n = 0;
        for (std::size_t k = 0; k < sim.robotCount(); ++k)
        {
            if (k == i || !sim.present(k))
                continue;
            const RobotState &other = sim.state(k);
            const double rk = sim.spec(k).radius;
            if (norm(other.velocity) <= 1e-3 || distance(me.position, other.position) - ri - rk > 2.0 * rho_)
                continue;
            if (pointSegmentDistance(next, other.position, other.position + other.velocity * horizon_) <
                ri + rk + rho_)
                ++n;
        }
        return n;
    }

    Command ApfController::command(const Simulation &sim, std::size_t i)
    {
        const RobotState &s = sim.state(i);
        const double vmax = sim.spec(i).maxSpeed;
        const Vec2 p = s.position;
        const Vec2 toGoal = s.goal - p;
        Vec2 v = capped(toGoal * attraction_, vmax);
        const Vec2 heading(std::cos(s.heading), std::sin(s.heading));
        const double cosCone = std::cos(coneDegrees_ * kPi / 180.0);
        const double robotGain =
            adaptive_ ? robotGain_ * (1.0 + adaptiveGain_ * crowding(sim, i)) : robotGain_;
        forEachObstacle(sim, i, p, rho_, true,
                        [&](const SensedObstacle &o, double gap, const Vec2 &nearest)
                        {
                            if (gap >= rho_)
                                return;
                            const bool robot = o.source == SensedObstacle::Source::Robot;
                            const double d = std::max(gap, 1e-3);
                            const double magnitude =
                                (robot ? robotGain : obstacleGain_) * (1.0 / d - 1.0 / rho_);
                            const Vec2 to =
                                o.shape == SensedObstacle::Shape::Disc ? o.center - p : nearest - p;
                            Vec2 n = unit(Vec2() - to);
                            if (adaptive_ && dot(to, heading) >= cosCone * norm(to))
                            {
                                // Rotated by 90 degrees: counter-clockwise pushes the robot to its right of
                                // the obstacle.
                                const bool counterClockwise = robot || cross(toGoal, to) >= 0.0;
                                n = counterClockwise ? Vec2(-n.y, n.x) : Vec2(n.y, -n.x);
                            }
                            v = v + n * magnitude;
                        });
        return {brake(sim, i, capped(v, vmax))};
    }

    // ---------------------------------------------------------------------------------------------------
    // bfo / atbfo

    BfoController::BfoController(bool adaptiveTumble) : adaptive_(adaptiveTumble)
    {
        params_.add("S", &colonySize_, 2.0, 100000.0, true);
        params_.add("Nc", &chemotactic_, 1.0, 100000.0, true);
        params_.add("Ns", &swim_, 0.0, 100000.0, true);
        params_.add("Nre", &reproduction_, 1.0, 100000.0, true);
        params_.add("Ned", &elimination_, 1.0, 100000.0, true);
        params_.add("Ped", &dispersal_, 0.0, 1.0);
        params_.add("C", &stepSize_, 1e-6, 1e6);
        params_.add("xi", &xi_, 0.0, 1e6);
        params_.add("eta", &eta_, 0.0, 1e6);
        params_.add("d0", &d0_, 1e-6, 1e6);
        params_.add("lambda", &lambda_, 1e-6, 1e6);
        params_.add("D_sense", &sensing_, 1e-6, 1e6);
        params_.add("F_improv", &improvement_, 0.0, 100000.0, true);
        params_.add("sector_angle", &sectorDegrees_, 0.0, 180.0);
        params_.add("predict", &predict_, 0.0, 1.0, true);
    }

    void BfoController::reset(const Simulation &sim, ompl::RNG &rng)
    {
        rng_ = &rng;
        const std::size_t n = sim.robotCount();
        waypoint_.assign(n, Vec2());
        hasWaypoint_.assign(n, 0);
        const World &world = sim.scenario().world;
        sensed_.clear();
        sensed_.reserve(world.circles.size() + world.polygons.size() + sim.scenario().movingObstacles.size() +
                        n + 1);
        colony_.reserve(2, static_cast<unsigned int>(colonySize_));
        evaluations_ = decisions_ = 0.0;
    }

    void BfoController::taskStarted(const Simulation & /*sim*/, std::size_t i)
    {
        hasWaypoint_[i] = 0;
    }

    std::map<std::string, double> BfoController::counters() const
    {
        return {{"evaluations", evaluations_}, {"decisions", decisions_}};
    }

    void BfoController::sense(const Simulation &sim, std::size_t i)
    {
        sensed_.clear();
        forEachObstacle(sim, i, robot_, sensing_, false,
                        [this](const SensedObstacle &o, double, const Vec2 &) { sensed_.push_back(o); });
    }

    bool BfoController::segmentFree(const Simulation &sim, const Vec2 &a, const Vec2 &b) const
    {
        return sim.staticSegmentFree(a, b, radius_) && clearOfDiscs(sensed_, a, b, radius_, travelTime_);
    }

    double BfoController::cost(const Simulation &sim, const Vec2 &p)
    {
        evaluations_ += 1.0;
        double j = 0.5 * xi_ * squaredNorm(p - goal_);
        for (const SensedObstacle &o : sensed_)
        {
            const double d = surfaceDistance(sim, o, p, nullptr) - radius_;
            if (d <= 0.0)
                return kInf;
            if (d < d0_)
                j += 0.5 * eta_ * (1.0 / d - 1.0 / d0_);
        }
        if (!segmentFree(sim, robot_, p))
            return kInf;
        if (!bestKnown_ || j < bestJ_)
        {
            bestKnown_ = true;
            bestJ_ = j;
            best_ = p;
        }
        return j;
    }

    Vec2 BfoController::constrain(const Vec2 &x) const
    {
        Vec2 y = x;
        const double d = distance(x, robot_);
        if (d > sensing_)
            y = robot_ + (x - robot_) * (sensing_ / d);
        const Box &b = inner_;
        y.x = std::clamp(y.x, b.xmin, b.xmax);
        y.y = std::clamp(y.y, b.ymin, b.ymax);
        return y;
    }

    Vec2 BfoController::randomBacterium()
    {
        const Vec2 toGoal = goal_ - robot_;
        const double heading = squaredNorm(toGoal) > 0.0 ? std::atan2(toGoal.y, toGoal.x) : 0.0;
        const double half = sectorDegrees_ * kPi / 180.0;
        const double angle = heading + rng_->uniformReal(-half, half);
        const double r = sensing_ * std::sqrt(rng_->uniform01()); // uniform by area
        return constrain(robot_ + Vec2(std::cos(angle), std::sin(angle)) * r);
    }

    /** \brief The colony's view of a decision: J, the sector, the sensing disc and bounds. */
    class BfoController::Adapter : public ColonyProblem
    {
      public:
        explicit Adapter(BfoController &c) : c_(c) {}
        double cost(const double *x) override { return c_.cost(*c_.sim_, Vec2(x[0], x[1])); }
        void randomPosition(double *x) override { store(c_.randomBacterium(), x); }
        void constrain(double *x) override { store(c_.constrain(Vec2(x[0], x[1])), x); }
        /** \brief Delta ~ U(-1, 1)^2 drawn y first, then x (the order this controller has always drawn in,
            as GCC evaluated its constructor arguments), redrawn while |Delta|^2 < 1e-24; Delta / |Delta|. */
        void randomDirection(double *phi, unsigned int /*dim*/, ompl::RNG &rng) override
        {
            Vec2 delta;
            while (squaredNorm(delta) < 1e-24)
            {
                const double y = rng.uniformReal(-1.0, 1.0);
                const double x = rng.uniformReal(-1.0, 1.0);
                delta = Vec2(x, y);
            }
            store(unit(delta), phi);
        }

      private:
        static void store(const Vec2 &v, double *x)
        {
            x[0] = v.x;
            x[1] = v.y;
        }
        BfoController &c_;
    };

    void BfoController::runColony(const Simulation &sim)
    {
        ColonySettings &cs = colonySettings_;
        cs.chemotacticSteps = static_cast<unsigned int>(chemotactic_);
        cs.swimLength = static_cast<unsigned int>(swim_);
        cs.reproductionSteps = static_cast<unsigned int>(reproduction_);
        cs.eliminationEvents = static_cast<unsigned int>(elimination_);
        cs.eliminationProbability = dispersal_;
        cs.stepSize = stepSize_;
        cs.adaptiveTumble = adaptive_;
        cs.improvementThreshold = static_cast<unsigned int>(improvement_);
        cs.cellToCell = false;
        sim_ = &sim;
        bestKnown_ = false;
        Adapter adapter(*this);
        // Every bacterium is evaluated where it starts; a dispersed one when it next moves.
        colony_.start(2, static_cast<unsigned int>(colonySize_), adapter);
        colony_.evaluateAll(adapter);
        while (colony_.step(adapter, *rng_) != BacterialColony::Step::RunComplete)
        {
        }
        sim_ = nullptr;
    }

    void BfoController::decide(const Simulation &sim, std::size_t i)
    {
        decisions_ += 1.0;
        const RobotState &s = sim.state(i);
        robot_ = s.position;
        goal_ = s.goal;
        radius_ = sim.spec(i).radius;
        travelTime_ = predict_ != 0.0 ? lambda_ / sim.spec(i).maxSpeed : 0.0;
        const Box &b = sim.scenario().world.bounds;
        inner_ = Box{b.xmin + radius_, b.xmax - radius_, b.ymin + radius_, b.ymax - radius_};
        sense(sim, i);
        hasWaypoint_[i] = 0;
        if (distance(robot_, goal_) <= lambda_ && segmentFree(sim, robot_, goal_))
        {
            waypoint_[i] = goal_;
            hasWaypoint_[i] = 1;
            return;
        }
        runColony(sim);
        Vec2 direction = unit((bestKnown_ ? best_ : goal_) - robot_);
        if (squaredNorm(direction) == 0.0)
            direction = unit(goal_ - robot_);
        double step = lambda_;
        for (int attempt = 0; attempt <= 3; ++attempt, step *= 0.5)
        {
            const Vec2 w = robot_ + direction * step;
            if (segmentFree(sim, robot_, w))
            {
                waypoint_[i] = w;
                hasWaypoint_[i] = 1;
                return;
            }
        }
    }

    Command BfoController::command(const Simulation &sim, std::size_t i)
    {
        const RobotState &s = sim.state(i);
        const RobotSpec &spec = sim.spec(i);
        const double reach = spec.maxSpeed * sim.dt();
        bool decideNow = !hasWaypoint_[i] || distance(s.position, waypoint_[i]) <= reach;
        if (!decideNow)
        {
            // A moving obstacle or robot now on the way to the waypoint makes it invalid.
            forEachObstacle(sim, i, s.position, distance(s.position, waypoint_[i]), false,
                            [&](const SensedObstacle &o, double, const Vec2 &)
                            {
                                if (o.source != SensedObstacle::Source::Static &&
                                    pointSegmentDistance(o.center, s.position, waypoint_[i]) <
                                        o.radius + spec.radius)
                                    decideNow = true;
                            });
        }
        if (decideNow)
            decide(sim, i);
        if (!hasWaypoint_[i])
            return {};
        const Vec2 d = waypoint_[i] - s.position;
        const double n = norm(d);
        const Vec2 v = n <= reach ? d / sim.dt() : d * (spec.maxSpeed / n);
        bool limited = false;
        const Vec2 braked = brake(sim, i, v, &limited);
        if (limited)
            hasWaypoint_[i] = 0; // the way to the waypoint grazes something: decide again at the next step
        return {braked};
    }

    // ---------------------------------------------------------------------------------------------------
    // plan:<PLANNER>

    PlanFollowController::PlanFollowController(std::string planner, const PlannerRegistry &registry)
        : planner_(std::move(planner)), registry_(&registry)
    {
        registry_->get(planner_); // InputError listing the planners for an unknown one
        params_.add("plan_time", &planTime_, 0.001, 600.0);
        params_.add("lookahead", &lookahead_, 0.01, 100.0);
        params_.add("slowdown", &slowdown_, 0.0, 100.0);
        params_.add("sense_range", &senseRange_, 0.0, 1000.0);
        params_.add("margin", &margin_, 0.0, 100.0);
        params_.add("goal_tolerance", &goalTolerance_, 0.001, 1000.0);
        params_.add("replan_interval", &replanInterval_, 0.0, 1000.0);
        params_.add("clearance", &clearance_, 0.0, 100.0);
        params_.add("predict_time", &predictTime_, 0.0, 100.0);
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
        plans_ = replans_ = 0.0;
    }

    std::map<std::string, double> PlanFollowController::counters() const
    {
        return {{"plans", plans_}, {"replans", replans_}};
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
            // when even the bare disc would.
            auto addDisc = [&](const Vec2 &center, double bareRadius)
            {
                const double room = std::min(distance(center, query.start), distance(center, query.goal)) -
                                    spaced.robotRadius;
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
        if (byRobot && blocked <= lookahead_ && !mayReplan)
            return {};

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
        return {brake(sim, i, unit(target - s.position) * speed)};
    }

    // ---------------------------------------------------------------------------------------------------
    // Names

    namespace
    {
        const std::map<std::string, std::function<ControllerPtr()>> &fieldControllers()
        {
            static const std::map<std::string, std::function<ControllerPtr()>> table = {
                {"dapf", [] { return std::make_shared<ApfController>(false); }},
                {"aapf", [] { return std::make_shared<ApfController>(true); }},
                {"bfo", [] { return std::make_shared<BfoController>(false); }},
                {"atbfo", [] { return std::make_shared<BfoController>(true); }}};
            return table;
        }

        const std::string kPlanPrefix = "plan:";
    } // namespace

    std::vector<std::string> controllerNames(const PlannerRegistry &registry)
    {
        std::vector<std::string> names = {"dapf", "aapf", "bfo", "atbfo"};
        for (const std::string &p : registry.names())
            names.push_back(kPlanPrefix + p);
        return names;
    }

    ControllerPtr makeController(const std::string &name, const PlannerRegistry &registry)
    {
        const auto it = fieldControllers().find(name);
        if (it != fieldControllers().end())
            return it->second();
        if (name.compare(0, kPlanPrefix.size(), kPlanPrefix) == 0 &&
            registry.has(name.substr(kPlanPrefix.size())))
            return std::make_shared<PlanFollowController>(name.substr(kPlanPrefix.size()), registry);
        std::string known;
        for (const std::string &n : controllerNames(registry))
            known += (known.empty() ? "" : ", ") + n;
        throw InputError("unknown controller '" + name + "'; known controllers: " + known);
    }
} // namespace mhplan
