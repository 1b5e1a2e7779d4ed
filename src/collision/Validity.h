// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the OMPL validity checker and exact motion validator every planner shares. */
#ifndef MHPLAN_VALIDITY_H
#define MHPLAN_VALIDITY_H

#include "mhplan/collision/Collision.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

namespace mhplan
{
    /** \brief Position (first two coordinates) of a RealVectorStateSpace state. */
    Vec2 statePosition(const ompl::base::State *state);
    /** \brief Write a position into a RealVectorStateSpace state. */
    void setStatePosition(ompl::base::State *state, const Vec2 &p);

    /** \brief State validity from a CollisionModel: isValid and an exact signed clearance (robot radius
        included, bounds excluded; see CollisionModel). */
    class WorldValidityChecker : public ompl::base::StateValidityChecker
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
