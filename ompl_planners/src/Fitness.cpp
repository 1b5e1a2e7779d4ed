#include "Fitness.h"

#include "Validity.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

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
        /** \brief The robot-scale of the clearance-based penetration term (1 m, ALGORITHMS.md 1.2). */
        constexpr double kPenetrationScale = 1.0;
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
        const auto *space = si_->getStateSpace()->as<ob::RealVectorStateSpace>();
        const ob::RealVectorBounds &b = space->getBounds();
        box_ = {b.low[0], b.high[0], b.low[1], b.high[1]};
        model_.reset();
        exactCircles_ = false;
        circles_.clear();
        if (const auto *checker =
                dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get()))
        {
            model_ = checker->model();
            box_ = model_->bounds().inflated(-model_->robotRadius());
            if (const auto *analytic = dynamic_cast<const AnalyticCollisionModel *>(model_.get()))
                if (analytic->polygons().empty())
                {
                    exactCircles_ = true;
                    for (const Circle &c : analytic->circles())
                        if (c.radius + model_->robotRadius() > 0.0)
                            circles_.push_back({c.center, c.radius + model_->robotRadius()});
                }
        }
        resolution_ = std::max(1e-6, si_->getStateValidityCheckingResolution() * si_->getMaximumExtent());
        infeasibleOffset_ = 10.0 * 2.0 * (box_.width() + box_.height());
    }

    bool PathFitness::pointValid(const Vec2 &p) const
    {
        if (model_)
            return model_->isValid(p);
        setStatePosition(s1_, p);
        return si_->isValid(s1_);
    }

    double PathFitness::clearance(const Vec2 &p) const
    {
        if (model_)
            return model_->clearance(p);
        setStatePosition(s1_, p);
        return si_->getStateValidityChecker()->clearance(s1_);
    }

    bool PathFitness::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        setStatePosition(s1_, a);
        setStatePosition(s2_, b);
        return si_->checkMotion(s1_, s2_);
    }

    bool PathFitness::pathValid(const std::vector<Vec2> &path) const
    {
        for (std::size_t i = 1; i < path.size(); ++i)
            if (!segmentValid(path[i - 1], path[i]))
                return false;
        return true;
    }

    double PathFitness::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        if (model_)
            return model_->segmentClearance(a, b);
        const double len = distance(a, b);
        const auto steps = static_cast<unsigned int>(std::ceil(len / resolution_));
        double best = std::numeric_limits<double>::infinity();
        for (unsigned int k = 0; k <= steps; ++k)
            best = std::min(best, clearance(a + (b - a) * (steps == 0 ? 0.0 : double(k) / steps)));
        return best;
    }

    double PathFitness::outOfBounds(const Vec2 &p) const
    {
        const double dx = std::max({box_.xmin - p.x, p.x - box_.xmax, 0.0});
        const double dy = std::max({box_.ymin - p.y, p.y - box_.ymax, 0.0});
        return std::min(std::hypot(dx, dy) / kPenetrationScale, 1.0);
    }

    double PathFitness::collisionViolation(const std::vector<Vec2> &samples) const
    {
        if (samples.empty())
            return 0.0;
        double sum = 0.0;
        if (exactCircles_)
        {
            for (const Vec2 &q : samples)
            {
                for (const Circle &c : circles_)
                {
                    const double d2 = squaredNorm(q - c.center);
                    if (d2 < c.radius * c.radius)
                        sum += 1.0 - std::sqrt(d2) / c.radius;
                }
                sum += outOfBounds(q);
            }
        }
        else
        {
            for (const Vec2 &q : samples)
            {
                const double cl = clearance(q);
                if (cl < 0.0)
                    sum += std::min(-cl / kPenetrationScale, 1.0);
                sum += outOfBounds(q);
            }
        }
        return sum / static_cast<double>(samples.size());
    }

    FitnessResult PathFitness::evaluate(const std::vector<Vec2> &path, const std::vector<Vec2> &samples)
    {
        return kind_ == FitnessKind::LengthPenalty ? evaluateLengthPenalty(path, samples) : evaluateGms(path);
    }

    FitnessResult PathFitness::evaluateLengthPenalty(const std::vector<Vec2> &path,
                                                     const std::vector<Vec2> &samples)
    {
        FitnessResult r;
        for (std::size_t i = 1; i < path.size(); ++i)
            r.length += distance(path[i - 1], path[i]);
        r.violation = collisionViolation(samples);
        r.feasible = r.violation == 0.0 && pathValid(path);
        if (!r.feasible && r.violation == 0.0)
            r.violation = kHiddenCollisionViolation;
        r.fitness = weights_.lengthWeight * r.length + weights_.penaltyWeight * r.violation;
        return r;
    }

    double PathFitness::gmsFeasibleFitness(const std::vector<Vec2> &path) const
    {
        double dis = 0.0, saf = 0.0, smo = 0.0;
        Vec2 prevDir;
        bool havePrev = false;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            const Vec2 d = path[i] - path[i - 1];
            const double len = norm(d);
            dis += len;
            if (weights_.safetyWeight != 0.0)
                saf += std::max(0.0, 1.0 - segmentClearance(path[i - 1], path[i]) / weights_.safeDistance);
            if (len <= 0.0)
                continue;
            if (havePrev)
                smo += std::atan2(std::abs(cross(prevDir, d)), dot(prevDir, d));
            prevDir = d;
            havePrev = true;
        }
        return weights_.distanceWeight * dis + weights_.safetyWeight * saf + weights_.smoothnessWeight * smo;
    }

    FitnessResult PathFitness::evaluateGms(const std::vector<Vec2> &path)
    {
        FitnessResult r;
        for (std::size_t i = 1; i < path.size(); ++i)
            r.length += distance(path[i - 1], path[i]);
        r.feasible = pathValid(path);
        if (r.feasible)
        {
            r.fitness = gmsFeasibleFitness(path);
            return r;
        }
        double inside = 0.0;
        unsigned int crossings = 0;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            const Vec2 a = path[i - 1], b = path[i];
            const double len = distance(a, b);
            const auto steps = std::max(1u, static_cast<unsigned int>(std::ceil(len / resolution_)));
            bool wasInvalid = false;
            unsigned int invalid = 0;
            for (unsigned int k = 0; k <= steps; ++k)
            {
                const bool bad = !pointValid(a + (b - a) * (double(k) / steps));
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
        r.fitness = infeasibleOffset_ + r.violation;
        return r;
    }
} // namespace mhplan
