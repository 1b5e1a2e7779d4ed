// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/StatePathFitness.h"

#include <algorithm>
#include <utility>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief As Fitness.cpp: f2 of a path whose samples are free but which fails the motion validator,
            and the 1 m scale of the clearance penetration (docs/algorithms.md 1.2). */
        constexpr double kHiddenCollisionViolation = 1e-3;
        constexpr double kPenetrationScale = 1.0;
    } // namespace

    StatePathFitness::StatePathFitness(ob::SpaceInformationPtr si, const StateParametrisation &param)
        : si_(std::move(si)), param_(param), guard_(si_->getStateSpace().get())
    {
    }

    StatePathFitness::~StatePathFitness()
    {
        freeStates();
    }

    void StatePathFitness::freeStates()
    {
        for (ob::State *s : path_)
            si_->freeState(s);
        path_.clear();
        if (sample_ != nullptr)
            si_->freeState(sample_);
        sample_ = nullptr;
    }

    void StatePathFitness::configure(const ob::State *start, const ob::State *goal, unsigned int waypoints,
                                     unsigned int samples, const FitnessWeights &weights)
    {
        freeStates();
        path_.resize(waypoints + 2);
        for (ob::State *&s : path_)
            s = si_->allocState();
        sample_ = si_->allocState();
        si_->copyState(path_.front(), start);
        si_->copyState(path_.back(), goal);
        samples_ = std::max(2u, samples);
        weights_ = weights;
        dubins_ = dynamic_cast<const ob::DubinsStateSpace *>(si_->getStateSpace().get());
        reedsShepp_ = dynamic_cast<const ob::ReedsSheppStateSpace *>(si_->getStateSpace().get());
        const ob::StateValidityCheckerPtr &checker = si_->getStateValidityChecker();
        mode_ = checker && checker->getSpecs().clearanceComputationType != ob::StateValidityCheckerSpecs::NONE
                    ? PenaltyMode::Clearance
                    : PenaltyMode::ValidityOnly;
    }

    void StatePathFitness::decode(const double *x)
    {
        const unsigned int n = param_.dimension();
        for (std::size_t w = 1; w + 1 < path_.size(); ++w)
            param_.fromVector(x + (w - 1) * n, path_[w]);
    }

    FitnessResult StatePathFitness::evaluate(const double *x)
    {
        decode(x);
        FitnessResult r;
        const std::size_t segments = path_.size() - 1;
        safe_.resize(segments);
        for (std::size_t i = 0; i < segments; ++i)
        {
            safe_[i] = guard_.safe(path_[i], path_[i + 1]) ? 1 : 0;
            r.length += guard_.distance(*si_, path_[i], path_[i + 1], safe_[i] != 0);
        }

        const ob::StateSpacePtr &space = si_->getStateSpace();
        const ob::StateValidityCheckerPtr &checker = si_->getStateValidityChecker();
        const double tmax = static_cast<double>(segments);
        double sum = 0.0;
        std::size_t current = segments;
        bool firstTime = true;
        for (unsigned int s = 0; s < samples_; ++s)
        {
            const double t = tmax * s / (samples_ - 1);
            const std::size_t i = std::min(static_cast<std::size_t>(t), segments - 1);
            const double u = std::min(1.0, t - static_cast<double>(i));
            if (i != current)
            {
                current = i;
                firstTime = true; // a new segment: its curve is computed at its first inner sample
            }
            if (safe_[i] == 0)
                guard_.interpolate(*si_, path_[i], path_[i + 1], u, sample_, false);
            else if (dubins_ != nullptr)
                dubins_->interpolate(path_[i], path_[i + 1], u, firstTime, dubinsPath_, sample_);
            else if (reedsShepp_ != nullptr)
                reedsShepp_->interpolate(path_[i], path_[i + 1], u, firstTime, reedsSheppPath_, sample_);
            else
                space->interpolate(path_[i], path_[i + 1], u, sample_);
            if (!si_->satisfiesBounds(sample_))
                sum += 1.0;
            if (mode_ == PenaltyMode::Clearance)
            {
                const double c = checker->clearance(sample_);
                if (c < 0.0)
                    sum += std::min(-c / kPenetrationScale, 1.0);
            }
            else if (!si_->isValid(sample_))
                sum += 1.0;
        }
        r.violation = sum / samples_;
        r.feasible = r.violation == 0.0;
        for (std::size_t i = 0; r.feasible && i < segments; ++i)
            r.feasible = safe_[i] != 0 && si_->checkMotion(path_[i], path_[i + 1]);
        if (!r.feasible && r.violation == 0.0)
            r.violation = kHiddenCollisionViolation;
        r.fitness = weights_.lengthWeight * r.length + weights_.penaltyWeight * r.violation;
        return r;
    }
} // namespace mhplan
