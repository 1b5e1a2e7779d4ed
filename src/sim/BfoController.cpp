// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the bfo / atbfo controllers (see Controllers.h). */
#include "src/sim/Controllers.h"

#include "src/sim/detail/Sensing.h"

#include <algorithm>
#include <cmath>

namespace mhplan
{
    using namespace detail;

    // ---------------------------------------------------------------------------------------------------
    // bfo / atbfo

    BfoController::BfoController(bool adaptiveTumble) : adaptive_(adaptiveTumble)
    {
        params_.add("S", &colonySize_, 2.0, 100000.0, true, "S, bacteria per decision");
        params_.add("Nc", &chemotactic_, 1.0, 100000.0, true, "Nc, chemotactic steps per reproduction");
        params_.add("Ns", &swim_, 0.0, 100000.0, true, "Ns, maximal swim length");
        params_.add("Nre", &reproduction_, 1.0, 100000.0, true,
                    "Nre, reproductions per elimination-dispersal event");
        params_.add("Ned", &elimination_, 1.0, 100000.0, true,
                    "Ned, elimination-dispersal events per decision");
        params_.add("Ped", &dispersal_, 0.0, 1.0, false,
                    "Ped, dispersal probability per bacterium and event");
        params_.add("C", &stepSize_, 1e-6, 1e6, false, "C, chemotactic step (m)");
        params_.add("xi", &xi_, 0.0, 1e6, false, "xi, attraction weight of J");
        params_.add("eta", &eta_, 0.0, 1e6, false, "eta, repulsion weight of J");
        params_.add("d0", &d0_, 1e-6, 1e6, false, "d0, range of the repulsion in J (m)");
        params_.add("lambda", &lambda_, 1e-6, 1e6, false,
                    "lambda, the robot step toward the best bacterium (m)");
        params_.add("D_sense", &sensing_, 1e-6, 1e6, false,
                    "D_sense, sensing range: obstacles sensed and bacteria confined (m)");
        params_.add("F_improv", &improvement_, 0.0, 100000.0, true,
                    "F_improv, improvements that keep a direction (atbfo)");
        params_.add("sector_angle", &sectorDegrees_, 0.0, 180.0, false,
                    "half angle of the sector the bacteria start in (degrees)");
        params_.add("predict", &predict_, 0.0, 1.0, true,
                    "1 = grow moving discs by their travel while the robot drives lambda (segment tests)");
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
} // namespace mhplan
