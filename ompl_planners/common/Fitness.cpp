// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/Fitness.h"

#include "src/collision/Validity.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief f2 given to a path whose samples are all free but which fails the motion validator. */
        constexpr double kHiddenCollisionViolation = 1e-3;
        /** \brief The robot-scale of the clearance-based penetration term (1 m, docs/algorithms.md 1.2). */
        constexpr double kPenetrationScale = 1.0;

        /** \brief |b - a| in R^k (std::hypot in the plane, as Geometry's distance()). */
        double pointDistance(const double *a, const double *b, unsigned int k)
        {
            if (k == 2)
                return std::hypot(a[0] - b[0], a[1] - b[1]);
            double s = 0.0;
            for (unsigned int c = 0; c < k; ++c)
                s += (b[c] - a[c]) * (b[c] - a[c]);
            return std::sqrt(s);
        }

        /** \brief Angle in [0, pi] between the directions of segments (a, b) and (b, c), both non-degenerate:
            atan2(|u x v|, u . v) in the plane, Kahan's 2 atan2(|u |v| - v |u||, |u |v| + v |u||) in R^k. */
        double turningAngle(const double *a, const double *b, const double *c, unsigned int k)
        {
            if (k == 2)
            {
                const Vec2 u(b[0] - a[0], b[1] - a[1]), v(c[0] - b[0], c[1] - b[1]);
                return std::atan2(std::abs(cross(u, v)), dot(u, v));
            }
            const double lu = pointDistance(a, b, k), lv = pointDistance(b, c, k);
            double minus = 0.0, plus = 0.0;
            for (unsigned int j = 0; j < k; ++j)
            {
                const double p = (b[j] - a[j]) * lv, q = (c[j] - b[j]) * lu;
                minus += (p - q) * (p - q);
                plus += (p + q) * (p + q);
            }
            return 2.0 * std::atan2(std::sqrt(minus), std::sqrt(plus));
        }
    } // namespace

    FitnessKind parseFitnessKind(const std::string &name)
    {
        if (name == "lrsma")
            return FitnessKind::LengthPenalty;
        if (name == "gms")
            return FitnessKind::FeasibleInfeasible;
        throw std::invalid_argument("parameter 'fitness' must be one of {auto, lrsma, gms}; got '" + name +
                                    "'");
    }

    std::string toString(FitnessKind kind)
    {
        return kind == FitnessKind::LengthPenalty ? "lrsma" : "gms";
    }

    PathFitness::PathFitness(ob::SpaceInformationPtr si) : si_(std::move(si))
    {
        s1_ = si_->allocState();
        s2_ = si_->allocState();
    }

    PathFitness::~PathFitness()
    {
        si_->freeState(s1_);
        si_->freeState(s2_);
    }

    void PathFitness::configure(FitnessKind kind, const FitnessWeights &weights)
    {
        kind_ = kind;
        weights_ = weights;
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si_->getStateSpace().get());
        if (space == nullptr)
            throw std::invalid_argument("PathFitness: needs an ompl::base::RealVectorStateSpace; got state "
                                        "space '" +
                                        si_->getStateSpace()->getName() + "'");
        dim_ = space->getDimension();
        const ob::RealVectorBounds &b = space->getBounds();
        low_ = b.low;
        high_ = b.high;
        model_.reset();
        mode_ = PenaltyMode::Clearance;
        circles_.clear();
        const ob::StateValidityCheckerPtr &checker = si_->getStateValidityChecker();
        const auto *world = dynamic_cast<const WorldValidityChecker *>(checker.get());
        if (world != nullptr && dim_ == 2)
        {
            model_ = world->model();
            const Box box = model_->bounds().inflated(-model_->robotRadius());
            low_ = {box.xmin, box.ymin};
            high_ = {box.xmax, box.ymax};
            if (const auto *analytic = dynamic_cast<const AnalyticCollisionModel *>(model_.get()))
                if (analytic->polygons().empty())
                {
                    mode_ = PenaltyMode::ExactCircles;
                    for (const Circle &c : analytic->circles())
                        if (c.radius + model_->robotRadius() > 0.0)
                            circles_.push_back({c.center, c.radius + model_->robotRadius()});
                }
        }
        else if (!checker ||
                 checker->getSpecs().clearanceComputationType == ob::StateValidityCheckerSpecs::NONE)
            mode_ = PenaltyMode::ValidityOnly;
        resolution_ = std::max(1e-6, si_->getStateValidityCheckingResolution() * si_->getMaximumExtent());
        double sides = 0.0;
        for (unsigned int c = 0; c < dim_; ++c)
            sides += high_[c] - low_[c];
        infeasibleConstant_ = 20.0 * sides;
        point_.assign(dim_, 0.0);
    }

    void PathFitness::requirePlanar(const char *what) const
    {
        if (dim_ != 2)
            throw std::logic_error(std::string("PathFitness::") + what + ": planar (Vec2) call on a " +
                                   std::to_string(dim_) + "-dimensional space");
    }

    PointsView PathFitness::planar(const std::vector<Vec2> &points, std::vector<double> &buffer)
    {
        buffer.resize(2 * points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
        {
            buffer[2 * i] = points[i].x;
            buffer[2 * i + 1] = points[i].y;
        }
        return {buffer.data(), points.size(), 2};
    }

    void PathFitness::toState(ob::State *s, const double *p) const
    {
        double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
        std::copy(p, p + dim_, v);
    }

    bool PathFitness::inBounds(const double *p) const
    {
        for (unsigned int c = 0; c < dim_; ++c)
            if (!(p[c] >= low_[c] && p[c] <= high_[c]))
                return false;
        return true;
    }

    bool PathFitness::checkerValid(const double *p) const
    {
        toState(s1_, p);
        return si_->isValid(s1_);
    }

    bool PathFitness::pointValid(const double *p) const
    {
        if (model_)
            return model_->isValid(Vec2(p[0], p[1])); // the model checks its box
        return inBounds(p) && checkerValid(p);
    }

    double PathFitness::clearance(const double *p) const
    {
        if (model_)
            return model_->clearance(Vec2(p[0], p[1]));
        // A user's checker is never asked about a state outside the space's bounds (OMPL's planners keep
        // their states inside; a checker indexing a map would read outside it): no clearance there.
        if (!inBounds(p))
            return 0.0;
        toState(s1_, p);
        return si_->getStateValidityChecker()->clearance(s1_);
    }

    bool PathFitness::segmentValid(const double *a, const double *b) const
    {
        // The box is convex: a segment between points inside it stays inside.
        if (!model_ && (!inBounds(a) || !inBounds(b)))
            return false;
        toState(s1_, a);
        toState(s2_, b);
        return si_->checkMotion(s1_, s2_);
    }

    bool PathFitness::pathValid(const PointsView &path) const
    {
        for (std::size_t i = 1; i < path.size(); ++i)
            if (!segmentValid(path[i - 1], path[i]))
                return false;
        return true;
    }

    double PathFitness::segmentClearance(const double *a, const double *b) const
    {
        if (model_)
            return model_->segmentClearance(Vec2(a[0], a[1]), Vec2(b[0], b[1]));
        const double len = pointDistance(a, b, dim_);
        const auto steps = static_cast<unsigned int>(std::ceil(len / resolution_));
        double best = std::numeric_limits<double>::infinity();
        double *q = point_.data();
        for (unsigned int k = 0; k <= steps; ++k)
        {
            const double u = steps == 0 ? 0.0 : double(k) / steps;
            for (unsigned int c = 0; c < dim_; ++c)
                q[c] = a[c] + (b[c] - a[c]) * u;
            best = std::min(best, clearance(q));
        }
        return best;
    }

    double PathFitness::outOfBounds(const double *p) const
    {
        if (dim_ == 2)
        {
            const double dx = std::max({low_[0] - p[0], p[0] - high_[0], 0.0});
            const double dy = std::max({low_[1] - p[1], p[1] - high_[1], 0.0});
            return std::min(std::hypot(dx, dy) / kPenetrationScale, 1.0);
        }
        double s = 0.0;
        for (unsigned int c = 0; c < dim_; ++c)
        {
            const double d = std::max({low_[c] - p[c], p[c] - high_[c], 0.0});
            s += d * d;
        }
        return std::min(std::sqrt(s) / kPenetrationScale, 1.0);
    }

    double PathFitness::collisionViolation(const PointsView &samples) const
    {
        if (samples.size() == 0)
            return 0.0;
        double sum = 0.0;
        switch (mode_)
        {
        case PenaltyMode::ExactCircles:
            for (std::size_t i = 0; i < samples.size(); ++i)
            {
                const Vec2 q(samples[i][0], samples[i][1]);
                for (const Circle &c : circles_)
                {
                    const double d2 = squaredNorm(q - c.center);
                    if (d2 < c.radius * c.radius)
                        sum += 1.0 - std::sqrt(d2) / c.radius;
                }
                sum += outOfBounds(samples[i]);
            }
            break;
        case PenaltyMode::Clearance:
            for (std::size_t i = 0; i < samples.size(); ++i)
            {
                const double cl = clearance(samples[i]);
                if (cl < 0.0)
                    sum += std::min(-cl / kPenetrationScale, 1.0);
                sum += outOfBounds(samples[i]);
            }
            break;
        case PenaltyMode::ValidityOnly:
            for (std::size_t i = 0; i < samples.size(); ++i)
            {
                // Outside the bounds the penalty is outOfBounds()'s depth alone, and the checker is not asked
                // (a user's checker may read a map there).
                const double out = outOfBounds(samples[i]);
                sum += out == 0.0 && !checkerValid(samples[i]) ? 1.0 : out;
            }
            break;
        }
        return sum / static_cast<double>(samples.size());
    }

    FitnessResult PathFitness::evaluate(const PointsView &path, const PointsView &samples)
    {
        return kind_ == FitnessKind::LengthPenalty ? evaluateLengthPenalty(path, samples) : evaluateGms(path);
    }

    FitnessResult PathFitness::evaluateLengthPenalty(const PointsView &path, const PointsView &samples)
    {
        FitnessResult r;
        for (std::size_t i = 1; i < path.size(); ++i)
            r.length += pointDistance(path[i - 1], path[i], dim_);
        r.violation = collisionViolation(samples);
        r.feasible = r.violation == 0.0 && pathValid(path);
        if (!r.feasible && r.violation == 0.0)
            r.violation = kHiddenCollisionViolation;
        r.fitness = weights_.lengthWeight * r.length + weights_.penaltyWeight * r.violation;
        return r;
    }

    double PathFitness::gmsFeasibleFitness(const PointsView &path) const
    {
        double dis = 0.0, saf = 0.0, smo = 0.0;
        const double *prevA = nullptr, *prevB = nullptr;
        const bool danger = weights_.safetyWeight != 0.0 && mode_ != PenaltyMode::ValidityOnly;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            const double len = pointDistance(path[i - 1], path[i], dim_);
            dis += len;
            if (danger) // alpha in [0, 1]: a segment in collision (negative clearance) counts 1
                saf += std::min(
                    1.0, std::max(0.0, 1.0 - segmentClearance(path[i - 1], path[i]) / weights_.safeDistance));
            if (len <= 0.0)
                continue;
            // After a zero-length segment prevB has the coordinates of path[i - 1]: the angle between the
            // last two non-degenerate directions, as before.
            if (prevA != nullptr)
                smo += turningAngle(prevA, prevB, path[i], dim_);
            prevA = path[i - 1];
            prevB = path[i];
        }
        return weights_.distanceWeight * dis + weights_.safetyWeight * saf + weights_.smoothnessWeight * smo;
    }

    FitnessResult PathFitness::evaluateGms(const PointsView &path)
    {
        FitnessResult r;
        for (std::size_t i = 1; i < path.size(); ++i)
            r.length += pointDistance(path[i - 1], path[i], dim_);
        r.feasible = pathValid(path);
        // Denominator of f1 (w_d dis + w_s saf + w_sm smo), kept away from 0 (start = goal).
        const double base = std::max(gmsFeasibleFitness(path), 1e-12);
        if (r.feasible)
        {
            r.gmsValue = 1.0 / base; // f1, maximised
            r.fitness = -r.gmsValue;
            return r;
        }
        double inside = 0.0;
        unsigned int crossings = 0;
        double *q = point_.data();
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            const double *a = path[i - 1], *b = path[i];
            const double len = pointDistance(a, b, dim_);
            const auto steps = std::max(1u, static_cast<unsigned int>(std::ceil(len / resolution_)));
            bool wasInvalid = false;
            unsigned int invalid = 0;
            for (unsigned int k = 0; k <= steps; ++k)
            {
                const double u = double(k) / steps;
                for (unsigned int c = 0; c < dim_; ++c)
                    q[c] = a[c] + (b[c] - a[c]) * u;
                const bool bad = !pointValid(q);
                if (bad && !wasInvalid)
                    ++crossings;
                invalid += bad ? 1u : 0u;
                wasInvalid = bad;
            }
            inside += len * invalid / (steps + 1.0);
        }
        const double lin = r.length > 0.0 ? inside / r.length : 1.0;
        const double cro = r.length > 0.0 ? crossings / r.length : 1.0;
        r.violation = weights_.infeasibleLengthWeight * lin + weights_.crossingWeight * cro;
        // f2 = 1 / (D + w_l lin + w_c cro) with D = f1's denominator of the same path (docs/algorithms.md
        // 1.3): the key is f2's denominator, positive, so every feasible path (negative key) ranks first.
        r.fitness = (weights_.infeasibleBaseIsPath ? base : infeasibleConstant_) + r.violation;
        r.gmsValue = 1.0 / r.fitness;
        return r;
    }

    // Planar (Vec2) overloads: copy into reused buffers and forward.

    FitnessResult PathFitness::evaluate(const std::vector<Vec2> &path, const std::vector<Vec2> &samples)
    {
        requirePlanar("evaluate");
        const PointsView p = planar(path, planarA_);
        const PointsView s = &samples == &path ? p : planar(samples, planarB_);
        return evaluate(p, s);
    }

    bool PathFitness::pointValid(const Vec2 &p) const
    {
        requirePlanar("pointValid");
        const double q[2] = {p.x, p.y};
        return pointValid(q);
    }

    double PathFitness::clearance(const Vec2 &p) const
    {
        requirePlanar("clearance");
        const double q[2] = {p.x, p.y};
        return clearance(q);
    }

    bool PathFitness::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        requirePlanar("segmentValid");
        const double p[2] = {a.x, a.y}, q[2] = {b.x, b.y};
        return segmentValid(p, q);
    }

    double PathFitness::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        requirePlanar("segmentClearance");
        const double p[2] = {a.x, a.y}, q[2] = {b.x, b.y};
        return segmentClearance(p, q);
    }

    bool PathFitness::pathValid(const std::vector<Vec2> &path) const
    {
        requirePlanar("pathValid");
        return pathValid(planar(path, planarA_));
    }

    double PathFitness::gmsFeasibleFitness(const std::vector<Vec2> &path) const
    {
        requirePlanar("gmsFeasibleFitness");
        return gmsFeasibleFitness(planar(path, planarB_));
    }
} // namespace mhplan
