// SPDX-License-Identifier: BSD-3-Clause
#include "src/metrics/MetricList.h"

#include "src/collision/RigidValidity.h"

#include <algorithm>
#include <regex>
#include <stdexcept>

namespace mhplan
{
    namespace
    {
        /** Cusps (docs/metrics.md, "Cusps"): a car's curve (dubins, reeds_shepp) by its driving direction,
           any other path by the turns of the polyline it follows. */
        std::optional<double> cusps(const MetricPath &p)
        {
            if (p.path != nullptr && p.world != nullptr && p.world->isRigid() &&
                p.world->space != SpaceType::SE2)
                return static_cast<double>(reedsSheppCusps(p.si->getStateSpace().get(), *p.path));
            return static_cast<double>(cuspCount(p.points));
        }

        /** The built-in metrics: the registration list. One line per metric (docs/metrics.md). */
        std::vector<PathMetric> builtInMetrics()
        {
            return {
                {"path length REAL", [](const MetricPath &p) { return p.length; }},
                {"collision free BOOLEAN", [](const MetricPath &p) { return p.collisionFree ? 1.0 : 0.0; }},
                {"min clearance REAL", [](const MetricPath &p) { return p.minClearance; }},
                {"mean clearance REAL", [](const MetricPath &p) { return p.meanClearance; }},
                {"smoothness REAL", [](const MetricPath &p) { return smoothness(p.points); }},
                {"max curvature REAL", [](const MetricPath &p) { return maxCurvature(p.points); }},
                {"angle over length REAL", [](const MetricPath &p) { return angleOverLength(p.points); }},
                {"cusps INTEGER", cusps},
                {"optimality gap REAL",
                 [](const MetricPath &p) -> std::optional<double>
                 {
                     if (!p.exact)
                         return std::nullopt;
                     return optimalityGapPercent(p.length, p.optimum);
                 }},
            };
        }

        std::vector<PathMetric> &registry()
        {
            static std::vector<PathMetric> metrics = builtInMetrics();
            return metrics;
        }
    } // namespace

    namespace
    {
        /** The fields both kinds of path fill alike. */
        template <typename Measured>
        MetricPath measuredPath(const World &world, const Measured &m, bool exact, double optimum)
        {
            MetricPath p;
            p.world = &world;
            p.length = m.length;
            p.collisionFree = m.collisionFree;
            p.minClearance = m.minClearance;
            p.meanClearance = m.meanClearance;
            p.exact = exact;
            p.optimum = optimum;
            return p;
        }
    } // namespace

    MetricPath planarMetricPath(const World &world, const std::vector<Vec2> &points,
                                const CollisionModel &model, double step, bool exact, double optimum)
    {
        MetricPath p = measuredPath(world, computePathMetrics(points, model, step), exact, optimum);
        p.points = points;
        return p;
    }

    MetricPath rigidMetricPath(const World &world, const ompl::base::SpaceInformation &si,
                               const ompl::geometric::PathGeometric &path, const RigidPathMetrics &m,
                               std::vector<Vec2> drawn, bool exact, double optimum)
    {
        MetricPath p = measuredPath(world, m, exact, optimum);
        p.si = &si;
        p.path = &path;
        p.points = std::move(drawn);
        return p;
    }

    MetricPath rigidRunMetricPath(const World &world, const ompl::base::SpaceInformation &si,
                                  const ompl::geometric::PathGeometric &path, double step, bool exact,
                                  double optimum, std::vector<Pose2> &poses, RigidPathMetrics *measured)
    {
        const RigidBodyModel model(world);
        const RigidPathMetrics m = rigidPathMetrics(world, si, path, model, step);
        poses.clear();
        if (world.space == SpaceType::SE2)
            for (std::size_t i = 0; i < path.getStateCount(); ++i)
                poses.push_back(statePose(path.getState(i)));
        else
        {
            const double spacing = world.turningRadius / 8.0;
            const std::size_t every = std::max<std::size_t>(1, static_cast<std::size_t>(spacing / step));
            for (std::size_t i = 0; i < m.poses.size(); i += every)
                poses.push_back(m.poses[i]);
            poses.push_back(m.poses.back());
        }
        std::vector<Vec2> drawn;
        for (const Pose2 &p : poses)
            drawn.emplace_back(p.x, p.y);
        MetricPath out = rigidMetricPath(world, si, path, m, withoutDuplicates(drawn), exact, optimum);
        if (measured != nullptr)
            *measured = m;
        return out;
    }

    std::string metricColumn(const std::string &property)
    {
        std::string name = property.substr(0, property.rfind(' '));
        std::replace(name.begin(), name.end(), ' ', '_');
        return name;
    }

    const std::vector<PathMetric> &pathMetrics()
    {
        return registry();
    }

    void registerPathMetric(PathMetric metric)
    {
        static const std::regex form("[a-z][a-z0-9 ]*[a-z0-9] (REAL|INTEGER|BOOLEAN)");
        if (!std::regex_match(metric.property, form))
            throw std::invalid_argument(
                "registerPathMetric: property '" + metric.property +
                "' must be 'name REAL', 'name INTEGER' or 'name BOOLEAN' (name: lower "
                "case letters, digits and blanks)");
        if (!metric.value)
            throw std::invalid_argument("registerPathMetric: metric '" + metric.property +
                                        "' has no function");
        std::vector<PathMetric> &metrics = registry();
        const std::string name = metric.property.substr(0, metric.property.rfind(' '));
        for (const PathMetric &m : metrics)
            if (m.property.substr(0, m.property.rfind(' ')) == name)
                throw std::invalid_argument("registerPathMetric: a metric named '" + name +
                                            "' is registered already (" + m.property + ")");
        metrics.push_back(std::move(metric));
    }

    bool unregisterPathMetric(const std::string &property)
    {
        std::vector<PathMetric> &metrics = registry();
        const std::size_t builtIn = builtInMetrics().size();
        for (std::size_t i = builtIn; i < metrics.size(); ++i)
            if (metrics[i].property == property)
            {
                metrics.erase(metrics.begin() + static_cast<std::ptrdiff_t>(i));
                return true;
            }
        return false;
    }

    std::vector<std::pair<std::string, std::optional<double>>> evaluatePathMetrics(const MetricPath &path)
    {
        std::vector<std::pair<std::string, std::optional<double>>> out;
        for (const PathMetric &m : pathMetrics())
            out.emplace_back(m.property, m.value(path));
        return out;
    }
} // namespace mhplan
