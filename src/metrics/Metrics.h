// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the definitions of the path metrics (docs/metrics.md), for planar paths and the paths of
   SE(2)-based worlds alike; the benchmark driver, the CLI and the tests use these. The curvature,
   angle-over-length and cusp metrics follow Bench-MR's definitions (Heiden et al., "Bench-MR: A Motion
   Planning Benchmark for Wheeled Mobile Robots", RA-L 2021); every deviation is stated where it is made. What
   a campaign stores is the registration list of MetricList.h. */
#ifndef MHPLAN_METRICS_H
#define MHPLAN_METRICS_H

#include "src/collision/Collision.h"
#include "src/collision/RigidBody.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstddef>
#include <vector>

namespace mhplan
{
    /** \brief Turning angle at the middle point: the absolute heading change from a->b to b->c, in [0, pi]
        (0 straight on, pi a full reversal). Zero when a segment has zero length. */
    double turningAngle(const Vec2 &a, const Vec2 &b, const Vec2 &c);

    /** \brief The path with consecutive duplicate points removed (Bench-MR skips them in every metric). */
    std::vector<Vec2> withoutDuplicates(const std::vector<Vec2> &points);

    /** \brief Maximum curvature (Bench-MR MaxCurvatureMetric, vector form): at every interior vertex both
        neighbours are moved along their segments to the mean of the two segment lengths L, and the Menger
        curvature (1 / circumradius) of the three points is taken; for a turning angle theta this is
        2 sin(theta / 2) / L. A full reversal gives 2 / L (Bench-MR skips the undefined case; mhplan takes the
        limit). 0 for fewer than three distinct points. */
    double maxCurvature(const std::vector<Vec2> &points);

    /** \brief Angle over length (Bench-MR AOLMetric): the sum of the absolute heading changes at the interior
        vertices divided by the path length. 0 for a straight path; NaN for a path of zero length. */
    double angleOverLength(const std::vector<Vec2> &points);

    /** \brief Bench-MR's default cusp threshold: 60 degrees. */
    constexpr double kDefaultCuspAngle = 60.0 * 3.14159265358979323846 / 180.0;

    /** \brief The one tolerance of the cusp definition (docs/metrics.md, "Cusps"): a piece of a Reeds-Shepp
        curve shorter than this many turning radii has no driving direction and is skipped. */
    constexpr double kCuspTolerance = 1e-9;

    /** \brief Cusps of a polyline (docs/metrics.md, "Cusps"; Bench-MR PathEvaluation::computeCusps): interior
        vertices whose heading change exceeds \e thresholdRadians (Bench-MR's default 60 degrees). The heading
        change is normalised to [0, pi] (Bench-MR's fmod leaves a wrap-around at +-pi counted as a cusp;
       mhplan does not). */
    std::size_t cuspCount(const std::vector<Vec2> &points, double thresholdRadians = kDefaultCuspAngle);

    /** \brief Cusps of a path of a car that can reverse (docs/metrics.md, "Cusps"): the changes of driving
        direction (forward / reverse) along the Reeds-Shepp curves between consecutive states, within one
       motion and across motions; pieces shorter than kCuspTolerance are skipped. 0 for any other space (a
       Dubins car never reverses). */
    std::size_t reedsSheppCusps(const ompl::base::StateSpace *space,
                                const ompl::geometric::PathGeometric &path);

    /** \brief Smoothness as Bench-MR reports it (OMPL's PathGeometric::smoothness, re-implemented): the sum
        over interior vertices of (2 theta / (a + b))^2, with theta the turning angle and a, b the lengths of
        the adjacent segments. 0 for a straight path. Evaluated on the waypoints as given (Bench-MR evaluates
        its interpolated path; mhplan does not resample, so the value is comparable with OMPL's own
        "solution smoothness" column). */
    double smoothness(const std::vector<Vec2> &points);

    /** \brief Points every at most \e step along the polyline (both ends and every vertex included). */
    std::vector<Vec2> resamplePath(const std::vector<Vec2> &points, double step);

    /** \brief Clearance along a path. */
    struct ClearanceStats
    {
        /** \brief Exact minimum of the clearance over the whole polyline (CollisionModel::segmentClearance).
         */
        double min{0.0};
        /** \brief Arc-length mean: the mean of the clearance at points spaced uniformly along the path. */
        double mean{0.0};
    };

    /** \brief Minimum (exact) and mean (sampled every \e step) clearance of the robot along the path; may be
        +infinity in a world without obstacles. Throws std::invalid_argument if step <= 0. */
    ClearanceStats clearanceStats(const std::vector<Vec2> &points, const CollisionModel &model, double step);

    /** \brief Independent dense collision check: every point spaced at most \e step apart along the path is
        valid (CollisionModel::isValid; does not use the exact segment test the planners' motion validator
        uses). Throws std::invalid_argument if step <= 0. */
    bool denseCollisionFree(const std::vector<Vec2> &points, const CollisionModel &model, double step);

    /** \brief Every metric of one path. */
    struct PathMetrics
    {
        double length{0.0};
        bool collisionFree{false};
        double minClearance{0.0};
        double meanClearance{0.0};
        double smoothness{0.0};
        double maxCurvature{0.0};
        double angleOverLength{0.0};
        std::size_t cusps{0};
    };

    /** \brief All metrics; the dense check and the mean clearance use \e step (see defaultMetricStep). */
    PathMetrics computePathMetrics(const std::vector<Vec2> &points, const CollisionModel &model, double step);

    /** \brief A sampling step fine enough for the dense check: a quarter of the robot radius, at most 1/2000
        of the bounds' diagonal (and never 0). */
    double defaultMetricStep(const World &world);

    /** \brief The metrics of one path in an SE(2)-based world (docs/spaces.md, "Rigid-body and car worlds").
     */
    struct RigidPathMetrics
    {
        /** \brief Length in the space's metric (OMPL's PathGeometric::length: the sum of the space's
            distances). */
        double length{0.0};
        /** \brief The independent dense check (independentPosesFree) of \e poses. */
        bool collisionFree{false};
        /** \brief Minimum and mean of RigidBodyModel::clearance over \e poses (+infinity without obstacles).
         */
        double minClearance{0.0};
        double meanClearance{0.0};
        /** \brief reedsSheppCusps (0 outside reeds_shepp). */
        std::size_t cusps{0};
        /** \brief The poses of densePathPoses at the given step. */
        std::vector<Pose2> poses;
    };

    /** \brief Every metric of a path of an SE(2)-based world, the dense poses \e step apart (in robot-point
        displacement). */
    RigidPathMetrics rigidPathMetrics(const World &world, const ompl::base::SpaceInformation &si,
                                      const ompl::geometric::PathGeometric &path, const RigidBodyModel &model,
                                      double step);

    /** \brief Optimality gap in percent: 100 (length - optimum) / optimum; NaN when the optimum is not
        positive and finite. */
    double optimalityGapPercent(double length, double optimum);
} // namespace mhplan

#endif
