// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the registration list of the path metrics a campaign stores (docs/metrics.md). A solution path is
   prepared once (MetricPath: the costly dense check and clearance done there), then every registered metric
   is evaluated on it and stored under its OMPL run property ("name TYPE", so the database column is the
   name with blanks as underscores). A new metric is one function of a MetricPath, one line in
   builtInMetrics() (MetricList.cpp) and its test. */
#ifndef MHPLAN_METRIC_LIST_H
#define MHPLAN_METRIC_LIST_H

#include "src/metrics/Metrics.h"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mhplan
{
    /** \brief One solution path, prepared once for every registered metric. */
    struct MetricPath
    {
        /** \brief The world the path was planned in. */
        const World *world{nullptr};
        /** \brief The path as the planner reported it and its space information; null for a polyline given
            without OMPL (tests). */
        const ompl::base::SpaceInformation *si{nullptr};
        const ompl::geometric::PathGeometric *path{nullptr};
        /** \brief The polyline the robot's reference point follows: the waypoints (planar worlds, se2), the
            driven curve sampled (dubins, reeds_shepp). The shape metrics are taken on it. */
        std::vector<Vec2> points;
        /** \brief Length: of the polyline (planar worlds), in the space's metric (SE(2)-based worlds). */
        double length{0.0};
        /** \brief The independent dense check (denseCollisionFree, independentPosesFree). */
        bool collisionFree{false};
        /** \brief Minimum and mean clearance along the path (clearanceStats, rigidPathMetrics). */
        double minClearance{0.0};
        double meanClearance{0.0};
        /** \brief Whether the planner reported the path as an exact solution, and the problem's exact optimum
            (NaN when there is none). */
        bool exact{false};
        double optimum{std::numeric_limits<double>::quiet_NaN()};
    };

    /** \brief A planar path's MetricPath: the dense check and clearance over \e model every \e step. */
    MetricPath planarMetricPath(const World &world, const std::vector<Vec2> &points,
                                const CollisionModel &model, double step, bool exact, double optimum);

    /** \brief An SE(2)-based path's MetricPath from its rigidPathMetrics \e m and the polyline \e drawn the
        robot's reference point follows. */
    MetricPath rigidMetricPath(const World &world, const ompl::base::SpaceInformation &si,
                               const ompl::geometric::PathGeometric &path, const RigidPathMetrics &m,
                               std::vector<Vec2> drawn, bool exact, double optimum);

    /** \brief An SE(2)-based path's MetricPath as every program prepares it (docs/spaces.md, "Rigid-body and
        car worlds"): rigidPathMetrics every \e step (the length in the space's metric, the independent dense
        check along the space's interpolation, the FCL clearance); the shape metrics are taken on the
        waypoints (se2) or on the driven curve sampled every eighth of the turning radius (cars), which
        \e poses receives with the robot's heading (the path a campaign stores). \e measured, when given,
        receives rigidPathMetrics' result. */
    MetricPath rigidRunMetricPath(const World &world, const ompl::base::SpaceInformation &si,
                                  const ompl::geometric::PathGeometric &path, double step, bool exact,
                                  double optimum, std::vector<Pose2> &poses,
                                  RigidPathMetrics *measured = nullptr);

    /** \brief The name of a metric's property ("path length REAL"): its database column, "path_length". */
    std::string metricColumn(const std::string &property);

    /** \brief One registered metric: its OMPL run property ("name REAL", "name INTEGER" or "name BOOLEAN")
       and its value on a path (no value: nothing is stored for that run). */
    struct PathMetric
    {
        std::string property;
        std::function<std::optional<double>(const MetricPath &)> value;
    };

    /** \brief Every registered metric, the built-in ones first (builtInMetrics), in registration order. */
    const std::vector<PathMetric> &pathMetrics();

    /** \brief Register one more metric (a program's or a test's own). Throws std::invalid_argument when the
        property is not "name REAL|INTEGER|BOOLEAN" or is registered already. */
    void registerPathMetric(PathMetric metric);

    /** \brief Remove a metric registered by registerPathMetric (tests); false when there is none of that
        property or it is a built-in one. */
    bool unregisterPathMetric(const std::string &property);

    /** \brief Every registered metric of \e path: (property, value), in registration order. */
    std::vector<std::pair<std::string, std::optional<double>>> evaluatePathMetrics(const MetricPath &path);
} // namespace mhplan

#endif
