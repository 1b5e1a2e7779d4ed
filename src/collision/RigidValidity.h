// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the OMPL validity checker and the certified conservative motion validator of the SE(2)-based
   spaces (se2, dubins, reeds_shepp), and the path helpers that follow a motion the way the space interpolates
   it (docs/spaces.md, "Rigid-body and car worlds"). */
#ifndef MHPLAN_RIGID_VALIDITY_H
#define MHPLAN_RIGID_VALIDITY_H

#include "src/collision/RigidBody.h"
#include "src/collision/Validity.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstddef>
#include <vector>

namespace mhplan
{
    /** \brief The pose of an SE2StateSpace state (also Dubins and Reeds-Shepp states). */
    Pose2 statePose(const ompl::base::State *state);
    /** \brief Write a pose into an SE2StateSpace state. */
    void setStatePose(ompl::base::State *state, const Pose2 &p);

    /** \brief One motion of an SE(2)-based space between two states, followed as the space interpolates it,
        with a bound on how far any robot point moves along it:
        - se2: OMPL interpolates position linearly and heading the shorter way round, so a robot point at
          distance r from the origin moves at most L_xy + r |dtheta| (L_xy the Euclidean distance of the
          positions, dtheta the heading change);
        - dubins, reeds_shepp: the position moves at unit speed along the car's path of length L (the space's
          distance) and the heading turns at a rate of at most 1 / turning radius, so a point moves at most
          L (1 + r / turning radius).
        r is the robot's rotation reach (RigidBodyModel::rotationReach: 0 for a disc). Interpolation is
        uniform in the path parameter, so the piece [ta, tb] of the motion has the bound (tb - ta) bound().
        The car's path is computed once per motion. */
    class SpaceMotion
    {
      public:
        SpaceMotion(const ompl::base::StateSpace *space, SpaceType type, double rotationReach,
                    double turningRadius, const ompl::base::State *from, const ompl::base::State *to);

        /** \brief The motion's length in the space's metric (its distance). */
        double length() const { return length_; }
        /** \brief The bound on any robot point's displacement over the whole motion. */
        double bound() const { return bound_; }
        /** \brief The state at path parameter t in [0, 1]. */
        void at(double t, ompl::base::State *out) const;

      private:
        const ompl::base::StateSpace *space_;
        SpaceType type_;
        const ompl::base::State *from_;
        const ompl::base::State *to_;
        mutable ompl::base::DubinsStateSpace::DubinsPath dubins_;
        mutable ompl::base::ReedsSheppStateSpace::ReedsSheppPath reedsShepp_;
        double length_{0.0};
        double bound_{0.0};
    };

    /** \brief State validity of an SE(2)-based space from a RigidBodyModel: isValid (bounds and FCL's
       collision test) and clearance (FCL's distance minus the model's margin; bounds excluded, as
       CollisionModel). */
    class RigidValidityChecker : public CountingStateValidityChecker
    {
      public:
        RigidValidityChecker(const ompl::base::SpaceInformationPtr &si, RigidBodyModelPtr model);

        bool isValid(const ompl::base::State *state) const override;
        bool isValid(const ompl::base::State *state, double &dist) const override;
        double clearance(const ompl::base::State *state) const override;

        const RigidBodyModelPtr &model() const { return model_; }

      private:
        RigidBodyModelPtr model_;
    };

    /** \brief The certified conservative motion validator: a motion is accepted only when it is split into
        pieces each of whose displacement bound (SpaceMotion) is below the free distance
        (RigidBodyModel::freeDistance: obstacles and bounds) at one of its ends; then every robot point of
        every pose of the piece lies within that distance of the robot at that end, so no pose of an accepted
        motion touches an obstacle or leaves the bounds. Pieces are halved until certified; a motion whose
        uncertified pieces fall below \e resolution (in metres of displacement) is refused (conservative:
        it passes within about the resolution of an obstacle). Both end states must have a positive free
        distance. The lastValid variant returns the end of the certified prefix. */
    class CertifiedMotionValidator : public ompl::base::MotionValidator
    {
      public:
        CertifiedMotionValidator(const ompl::base::SpaceInformationPtr &si, RigidBodyModelPtr model,
                                 SpaceType type, double turningRadius, double resolution);

        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;

        double resolution() const { return resolution_; }
        /** \brief Free-distance evaluations since construction (for the measurements of docs/spaces.md). */
        std::size_t evaluations() const { return evaluations_; }

      private:
        /** Certify [0, 1]; returns the certified prefix's end (1 when the whole motion is). Without \e prefix
            it stops at the first pose found in collision (the prefix returned is then a safe underestimate);
            with it, it goes on certifying the part before that pose. */
        double certify(const ompl::base::State *s1, const ompl::base::State *s2, bool prefix) const;

        RigidBodyModelPtr model_;
        SpaceType type_;
        double turningRadius_;
        double resolution_;
        mutable std::size_t evaluations_{0};
    };

    /** \brief The poses along a path as its space interpolates it, spaced so that no robot point moves more
        than \e step between two consecutive ones (SpaceMotion's bound); every waypoint included. */
    std::vector<Pose2> densePathPoses(const World &world, const ompl::base::SpaceInformation &si,
                                      const ompl::geometric::PathGeometric &path, double step);

    /** \brief Independent dense check of a sampled path (independentPoseFree at every pose). */
    bool independentPosesFree(const World &world, const std::vector<Pose2> &poses);
} // namespace mhplan

#endif
