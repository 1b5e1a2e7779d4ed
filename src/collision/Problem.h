// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: one OMPL problem (state space, validity checker, motion validator, objective) per world query. */
#ifndef MHPLAN_PROBLEM_H
#define MHPLAN_PROBLEM_H

#include "mhplan/collision/Collision.h"

#include <ompl/geometric/SimpleSetup.h>

namespace mhplan
{
    /** \brief Throws InputError when the query's start or goal is out of the bounds or in collision. */
    void validateQuery(const World &world, const Query &query, const CollisionModel &model);

    /** \brief A 2D RealVectorStateSpace with the world's bounds. */
    ompl::base::StateSpacePtr makeStateSpace(const World &world);

    /** \brief A fully configured SimpleSetup: state space, WorldValidityChecker, ExactMotionValidator,
        start, goal (exact position, threshold 1e-9 of the bounds' diagonal), path-length objective. The
        query is validated first. Every planner that mhplan runs on this world gets this same setup. */
    ompl::geometric::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query,
                                                    const CollisionModelPtr &model);

    /** \brief Euclidean length of a polyline (independent of OMPL's distance function). */
    double polylineLength(const std::vector<Vec2> &points);

    /** \brief The waypoints of a geometric path. */
    std::vector<Vec2> pathPoints(const ompl::geometric::PathGeometric &path);
} // namespace mhplan

#endif
