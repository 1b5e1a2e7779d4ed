// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/Validity.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace ob = ompl::base;

namespace mhplan
{
    Vec2 statePosition(const ob::State *state)
    {
        const auto *s = state->as<ob::RealVectorStateSpace::StateType>();
        return {s->values[0], s->values[1]};
    }

    void setStatePosition(ob::State *state, const Vec2 &p)
    {
        auto *s = state->as<ob::RealVectorStateSpace::StateType>();
        s->values[0] = p.x;
        s->values[1] = p.y;
    }

    CheckCounts checkCounts(const ob::SpaceInformation &si)
    {
        CheckCounts c;
        if (const auto *counting =
                dynamic_cast<const CountingStateValidityChecker *>(si.getStateValidityChecker().get()))
        {
            c.state = counting->checkCount();
            c.haveState = true;
        }
        if (const ob::MotionValidatorPtr &mv = si.getMotionValidator())
            c.motion = mv->getCheckedMotionCount();
        return c;
    }

    WorldValidityChecker::WorldValidityChecker(const ob::SpaceInformationPtr &si, CollisionModelPtr model)
        : CountingStateValidityChecker(si), model_(std::move(model))
    {
        specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
        specs_.hasValidDirectionComputation = false;
    }

    bool WorldValidityChecker::isValid(const ob::State *state) const
    {
        countCheck();
        return model_->isValid(statePosition(state));
    }

    bool WorldValidityChecker::isValid(const ob::State *state, double &dist) const
    {
        countCheck();
        const Vec2 p = statePosition(state);
        dist = model_->clearance(p);
        return model_->inBounds(p) && dist >= 0.0;
    }

    double WorldValidityChecker::clearance(const ob::State *state) const
    {
        return model_->clearance(statePosition(state));
    }

    PointValidityChecker::PointValidityChecker(const ob::SpaceInformationPtr &si, CollisionModelPtr model)
        : CountingStateValidityChecker(si), model_(std::move(model))
    {
    }

    bool PointValidityChecker::isValid(const ob::State *state) const
    {
        countCheck();
        return model_->isValid(statePosition(state));
    }

    FunctionValidityChecker::FunctionValidityChecker(const ob::SpaceInformationPtr &si,
                                                     std::function<bool(const ob::State *)> fn)
        : CountingStateValidityChecker(si), fn_(std::move(fn))
    {
    }

    bool FunctionValidityChecker::isValid(const ob::State *state) const
    {
        countCheck();
        return fn_(state);
    }

    ExactMotionValidator::ExactMotionValidator(const ob::SpaceInformationPtr &si, CollisionModelPtr model)
        : ob::MotionValidator(si), model_(std::move(model))
    {
    }

    bool ExactMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2) const
    {
        const bool ok = model_->segmentValid(statePosition(s1), statePosition(s2));
        if (ok)
            ++valid_;
        else
            ++invalid_;
        return ok;
    }

    bool ExactMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2,
                                           std::pair<ob::State *, double> &lastValid) const
    {
        const Vec2 a = statePosition(s1);
        const Vec2 b = statePosition(s2);
        if (model_->segmentValid(a, b))
        {
            ++valid_;
            return true;
        }
        ++invalid_;
        // Bisection on the prefix [a, a + t (b - a)]: lo is always a valid prefix (or the invalid start).
        double lo = 0.0;
        double hi = 1.0;
        if (!model_->isValid(a))
            hi = 0.0;
        const double tol = 1e-9;
        while (hi - lo > tol)
        {
            const double mid = 0.5 * (lo + hi);
            if (model_->segmentValid(a, a + (b - a) * mid))
                lo = mid;
            else
                hi = mid;
        }
        if (lastValid.first != nullptr)
            setStatePosition(lastValid.first, a + (b - a) * lo);
        lastValid.second = lo;
        return false;
    }
} // namespace mhplan
