// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: one OMPL problem (state space, validity checker, motion validator, objective) per world query. */
#ifndef MHPLAN_PROBLEM_H
#define MHPLAN_PROBLEM_H

#include "src/collision/Collision.h"

#include <ompl/geometric/SimpleSetup.h>

#include <functional>
#include <string>

namespace mhplan
{
    class RigidBodyModel;

    /** \brief How a problem checks validity (docs/setups.md). Exact (the default): mhplan's
        WorldValidityChecker and ExactMotionValidator over the world's collision model (SE(2)-based worlds:
        RigidValidityChecker and CertifiedMotionValidator). App: as a user's OMPL program would, a plain point
        checker (PointValidityChecker: the world's geometry queried point by point, no clearance, no segment
        model) and OMPL's DiscreteMotionValidator at \c resolution, the space's longest-valid-segment
        fraction (SpaceInformation::setStateValidityCheckingResolution). */
    struct ValiditySetup
    {
        enum class Kind
        {
            Exact,
            App
        };
        Kind kind{Kind::Exact};
        /** \brief App only: the validity-checking resolution, a fraction of the space's maximum extent. */
        double resolution{0.002};

        bool app() const { return kind == Kind::App; }
        /** \brief "exact" or "app". */
        std::string name() const { return app() ? "app" : "exact"; }
        /** \brief "exact" or "app (point checker, DiscreteMotionValidator at resolution R)". */
        std::string describe() const;
        bool operator==(const ValiditySetup &o) const
        {
            return kind == o.kind && (kind == Kind::Exact || resolution == o.resolution);
        }
        bool operator!=(const ValiditySetup &o) const { return !(*this == o); }
    };

    /** \brief The app set-up's default resolution: the one of OMPL's optimizing-planner tests. */
    constexpr double kDefaultAppResolution = 0.002;
    /** \brief Accepted app resolutions: [kMinAppResolution, kMaxAppResolution]. Finer than 1e-5 makes one
        motion along the diagonal 10^5 checks; coarser than 0.5 checks little more than the end states. */
    constexpr double kMinAppResolution = 1e-5;
    constexpr double kMaxAppResolution = 0.5;

    /** \brief The set-up named \e kind ("exact" or "app") with \e resolution (app only; NaN: the
        default). Throws InputError naming what is accepted: an unknown kind, a resolution out of range, or a
        resolution given with "exact". */
    ValiditySetup makeValiditySetup(const std::string &kind, double resolution);

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
                                                    const CollisionModelPtr &model,
                                                    const ValiditySetup &setup = {});

    /** \brief Makes the SimpleSetup object (a subclass of it) over a state space. */
    using SimpleSetupFactory =
        std::function<ompl::geometric::SimpleSetupPtr(const ompl::base::StateSpacePtr &space)>;

    /** \brief makeSimpleSetup, configuring the object \e make returns (the benchmark's runs use a subclass,
        benchmarks/README.md "Overhead"). */
    ompl::geometric::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query,
                                                    const CollisionModelPtr &model,
                                                    const SimpleSetupFactory &make,
                                                    const ValiditySetup &setup = {});

    /** \brief Euclidean length of a polyline (independent of OMPL's distance function). */
    double polylineLength(const std::vector<Vec2> &points);

    /** \brief The waypoints' positions of a geometric path (RealVector or SE(2)-based). */
    std::vector<Vec2> pathPoints(const ompl::geometric::PathGeometric &path);
} // namespace mhplan

#endif
