// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: one OMPL problem (state space, validity checker, motion validator, objective) per world query. */
#ifndef MHPLAN_PROBLEM_H
#define MHPLAN_PROBLEM_H

#include "mhplan/collision/Collision.h"

#include <ompl/geometric/SimpleSetup.h>

#include <functional>

namespace mhplan
{
    class RigidBodyModel;

    /** \brief Throws InputError when the query's start or goal is out of the bounds or in collision (in an
        SE(2)-based world: the robot at the query's poses, checked by a RigidBodyModel built here; \e model is
        not used then). */
    void validateQuery(const World &world, const Query &query, const CollisionModel &model);

    /** \brief validateQuery for an SE(2)-based world with its rigid-body model. */
    void validateRigidQuery(const World &world, const Query &query, const RigidBodyModel &model);

    /** \brief The certified motion validator's resolution in an SE(2)-based world: 1e-4 of the bounds'
        diagonal (docs/spaces.md, "Rigid-body and car worlds"). */
    double motionResolution(const World &world);

    /** \brief The world's state space: a 2D RealVectorStateSpace with the world's bounds (r2), or an
        SE2StateSpace, DubinsStateSpace or ReedsSheppStateSpace (turning radius from the world) whose position
        bounds are the world's. */
    ompl::base::StateSpacePtr makeStateSpace(const World &world);

    /** \brief A fully configured SimpleSetup: state space, WorldValidityChecker, ExactMotionValidator,
        start, goal (exact position, threshold 1e-9 of the bounds' diagonal), path-length objective. The
        query is validated first. Every planner that mhplan runs on this world gets this same setup.
        SE(2)-based worlds: the world's space, a RigidValidityChecker and a CertifiedMotionValidator over a
        RigidBodyModel built here (\e model is not used), start and goal poses with their headings, and the
        path-length objective in the space's own metric (SE(2): |dxy| + 0.5 |dtheta|, OMPL's weights; the
        cars: the length of the car's path). A no-op intermediate-solution callback is registered, as every
        benchmark run registers its own: the problem definition, and so what OMPL's planners do, is the same
        in every command (RRT* skips samples equal to their nearest tree state only with a callback). */
    ompl::geometric::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query,
                                                    const CollisionModelPtr &model);

    /** \brief Makes the SimpleSetup object (a subclass of it) over a state space. */
    using SimpleSetupFactory =
        std::function<ompl::geometric::SimpleSetupPtr(const ompl::base::StateSpacePtr &space)>;

    /** \brief makeSimpleSetup, configuring the object \e make returns (the benchmark's runs use a subclass,
        benchmarks/README.md "Overhead"). */
    ompl::geometric::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query,
                                                    const CollisionModelPtr &model,
                                                    const SimpleSetupFactory &make);

    /** \brief Euclidean length of a polyline (independent of OMPL's distance function). */
    double polylineLength(const std::vector<Vec2> &points);

    /** \brief The waypoints' positions of a geometric path (RealVector or SE(2)-based). */
    std::vector<Vec2> pathPoints(const ompl::geometric::PathGeometric &path);
} // namespace mhplan

#endif
