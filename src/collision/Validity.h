// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the OMPL validity checker and exact motion validator every planner shares. */
#ifndef MHPLAN_VALIDITY_H
#define MHPLAN_VALIDITY_H

#include "src/collision/Collision.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include <atomic>
#include <cstdint>
#include <functional>

namespace mhplan
{
    /** \brief Position (first two coordinates) of a RealVectorStateSpace state. */
    Vec2 statePosition(const ompl::base::State *state);
    /** \brief Write a position into a RealVectorStateSpace state. */
    void setStatePosition(ompl::base::State *state, const Vec2 &p);

    /** \brief A state validity checker that counts its isValid calls (docs/setups.md, "Checks counted"): the
        benchmark's runs store the count per run. Every checker mhplan installs derives from it, so that the
        planners' own type tests (dynamic_cast to the concrete checker) still see the checker they know. */
    class CountingStateValidityChecker : public ompl::base::StateValidityChecker
    {
      public:
        using ompl::base::StateValidityChecker::StateValidityChecker;
        /** \brief isValid calls (both overloads) since construction. */
        std::uint64_t checkCount() const { return checks_.load(std::memory_order_relaxed); }

      protected:
        void countCheck() const { checks_.fetch_add(1, std::memory_order_relaxed); }

      private:
        mutable std::atomic<std::uint64_t> checks_{0};
    };

    /** \brief Validity-checker and motion-validator calls so far (docs/setups.md, "Checks counted"). */
    struct CheckCounts
    {
        std::uint64_t state{0};
        std::uint64_t motion{0};
        /** \brief False when the checker does not count (not a CountingStateValidityChecker). */
        bool haveState{false};
        CheckCounts operator-(const CheckCounts &o) const
        {
            return {state - o.state, motion - o.motion, haveState && o.haveState};
        }
    };

    /** \brief The counts of \e si's checker (CountingStateValidityChecker) and motion validator (OMPL's
        MotionValidator counts its valid and invalid motions itself). */
    CheckCounts checkCounts(const ompl::base::SpaceInformation &si);

    /** \brief State validity from a CollisionModel: isValid and an exact signed clearance (robot radius
        included, bounds excluded; see CollisionModel). */
    class WorldValidityChecker : public CountingStateValidityChecker
    {
      public:
        WorldValidityChecker(const ompl::base::SpaceInformationPtr &si, CollisionModelPtr model);

        bool isValid(const ompl::base::State *state) const override;
        bool isValid(const ompl::base::State *state, double &dist) const override;
        double clearance(const ompl::base::State *state) const override;

        const CollisionModelPtr &model() const { return model_; }

      private:
        CollisionModelPtr model_;
    };

    /** \brief The plain point checker of an OMPL app's set-up (docs/setups.md): a position is valid when the
        world's geometry says so at that point (CollisionModel::isValid), nothing more: no clearance, no
        segment model. Deliberately not a WorldValidityChecker, so that no planner finds the exact model
        behind it. */
    class PointValidityChecker : public CountingStateValidityChecker
    {
      public:
        PointValidityChecker(const ompl::base::SpaceInformationPtr &si, CollisionModelPtr model);
        bool isValid(const ompl::base::State *state) const override;

      private:
        CollisionModelPtr model_;
    };

    /** \brief State validity from any function (an SE(2)-based app set-up's pose checker), counted. */
    class FunctionValidityChecker : public CountingStateValidityChecker
    {
      public:
        FunctionValidityChecker(const ompl::base::SpaceInformationPtr &si,
                                std::function<bool(const ompl::base::State *)> fn);
        bool isValid(const ompl::base::State *state) const override;

      private:
        std::function<bool(const ompl::base::State *)> fn_;
    };

    /** \brief Exact straight-segment motion validator: a motion is valid when every point of the segment is
        (no sampling resolution; CollisionModel::segmentValid). The lastValid variant locates the first
        contact by bisection to 1e-9 of the segment's length. */
    class ExactMotionValidator : public ompl::base::MotionValidator
    {
      public:
        ExactMotionValidator(const ompl::base::SpaceInformationPtr &si, CollisionModelPtr model);

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

      private:
        CollisionModelPtr model_;
    };
} // namespace mhplan

#endif
