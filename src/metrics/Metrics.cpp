// SPDX-License-Identifier: BSD-3-Clause
#include "src/metrics/Metrics.h"

#include "src/collision/RigidValidity.h"

#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    double turningAngle(const Vec2 &a, const Vec2 &b, const Vec2 &c)
    {
        const Vec2 u = b - a;
        const Vec2 v = c - b;
        if (squaredNorm(u) == 0.0 || squaredNorm(v) == 0.0)
            return 0.0;
        // atan2 of (cross, dot) is the signed angle between the two directions, in [-pi, pi].
        return std::abs(std::atan2(cross(u, v), dot(u, v)));
    }

    std::vector<Vec2> withoutDuplicates(const std::vector<Vec2> &points)
    {
        std::vector<Vec2> out;
        out.reserve(points.size());
        for (const Vec2 &p : points)
            if (out.empty() || out.back() != p)
                out.push_back(p);
        return out;
    }

    namespace
    {
        double polyLength(const std::vector<Vec2> &p)
        {
            double len = 0.0;
            for (std::size_t i = 1; i < p.size(); ++i)
                len += distance(p[i - 1], p[i]);
            return len;
        }
    } // namespace

    double maxCurvature(const std::vector<Vec2> &points)
    {
        const std::vector<Vec2> p = withoutDuplicates(points);
        double best = 0.0;
        for (std::size_t i = 1; i + 1 < p.size(); ++i)
        {
            const double meanLength = 0.5 * (distance(p[i - 1], p[i]) + distance(p[i], p[i + 1]));
            const double k = 2.0 * std::sin(0.5 * turningAngle(p[i - 1], p[i], p[i + 1])) / meanLength;
            best = std::max(best, k);
        }
        return best;
    }

    double angleOverLength(const std::vector<Vec2> &points)
    {
        const std::vector<Vec2> p = withoutDuplicates(points);
        const double length = polyLength(p);
        if (!(length > 0.0))
            return std::numeric_limits<double>::quiet_NaN();
        double total = 0.0;
        for (std::size_t i = 1; i + 1 < p.size(); ++i)
            total += turningAngle(p[i - 1], p[i], p[i + 1]);
        return total / length;
    }

    std::size_t cuspCount(const std::vector<Vec2> &points, double thresholdRadians)
    {
        const std::vector<Vec2> p = withoutDuplicates(points);
        std::size_t count = 0;
        for (std::size_t i = 1; i + 1 < p.size(); ++i)
            if (turningAngle(p[i - 1], p[i], p[i + 1]) > thresholdRadians)
                ++count;
        return count;
    }

    double smoothness(const std::vector<Vec2> &points)
    {
        const std::vector<Vec2> p = withoutDuplicates(points);
        double s = 0.0;
        for (std::size_t i = 1; i + 1 < p.size(); ++i)
        {
            const double a = distance(p[i - 1], p[i]);
            const double b = distance(p[i], p[i + 1]);
            const double k = 2.0 * turningAngle(p[i - 1], p[i], p[i + 1]) / (a + b);
            s += k * k;
        }
        return s;
    }

    namespace
    {
        void checkStep(double step, const char *function)
        {
            if (!(step > 0.0) || !std::isfinite(step))
                throw std::invalid_argument(std::string(function) + ": step must be > 0 and finite (got " +
                                            std::to_string(step) + ")");
        }
    } // namespace

    std::vector<Vec2> resamplePath(const std::vector<Vec2> &points, double step)
    {
        checkStep(step, "resamplePath");
        std::vector<Vec2> out;
        if (points.empty())
            return out;
        out.push_back(points.front());
        for (std::size_t i = 1; i < points.size(); ++i)
        {
            const Vec2 &a = points[i - 1];
            const Vec2 &b = points[i];
            const double len = distance(a, b);
            const auto pieces = static_cast<std::size_t>(std::ceil(len / step));
            for (std::size_t k = 1; k < pieces; ++k)
                out.push_back(a + (b - a) * (static_cast<double>(k) / static_cast<double>(pieces)));
            out.push_back(b);
        }
        return out;
    }

    ClearanceStats clearanceStats(const std::vector<Vec2> &points, const CollisionModel &model, double step)
    {
        checkStep(step, "clearanceStats");
        ClearanceStats stats;
        if (points.empty())
        {
            stats.min = stats.mean = std::numeric_limits<double>::quiet_NaN();
            return stats;
        }
        stats.min =
            points.size() == 1 ? model.clearance(points.front()) : std::numeric_limits<double>::infinity();
        for (std::size_t i = 1; i < points.size(); ++i)
            stats.min = std::min(stats.min, model.segmentClearance(points[i - 1], points[i]));
        // Arc-length mean: split every segment into equal pieces no longer than step and weight each piece's
        // midpoint clearance by its length (a path of zero length averages its points).
        double weighted = 0.0, total = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i)
        {
            const Vec2 &a = points[i - 1];
            const Vec2 &b = points[i];
            const double len = distance(a, b);
            const auto pieces = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / step)));
            for (std::size_t k = 0; k < pieces; ++k)
            {
                const double t = (static_cast<double>(k) + 0.5) / static_cast<double>(pieces);
                const double c = model.clearance(a + (b - a) * t);
                weighted += c * (len / static_cast<double>(pieces));
            }
            total += len;
        }
        if (total > 0.0)
            stats.mean = weighted / total;
        else
            stats.mean = model.clearance(points.front());
        return stats;
    }

    bool denseCollisionFree(const std::vector<Vec2> &points, const CollisionModel &model, double step)
    {
        checkStep(step, "denseCollisionFree");
        if (points.empty())
            return false;
        for (const Vec2 &p : resamplePath(points, step))
            if (!model.isValid(p))
                return false;
        return true;
    }

    PathMetrics computePathMetrics(const std::vector<Vec2> &points, const CollisionModel &model, double step)
    {
        PathMetrics m;
        m.length = polyLength(points);
        m.collisionFree = denseCollisionFree(points, model, step);
        const ClearanceStats c = clearanceStats(points, model, step);
        m.minClearance = c.min;
        m.meanClearance = c.mean;
        m.smoothness = smoothness(points);
        m.maxCurvature = maxCurvature(points);
        m.angleOverLength = angleOverLength(points);
        m.cusps = cuspCount(points);
        return m;
    }

    double defaultMetricStep(const World &world)
    {
        const double diagonal = std::hypot(world.bounds.width(), world.bounds.height());
        double step = diagonal / 2000.0;
        if (world.robotRadius > 0.0)
            step = std::min(step, 0.25 * world.robotRadius);
        return step > 0.0 ? step : 1e-3;
    }

    std::size_t reedsSheppCusps(const ob::StateSpace *space, const og::PathGeometric &path)
    {
        const auto *rs = dynamic_cast<const ob::ReedsSheppStateSpace *>(space);
        if (rs == nullptr)
            return 0;
        std::size_t cusps = 0;
        int last = 0; // driving direction of the last piece so far: +1 forward, -1 reverse, 0 none yet
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
        {
            const auto curve = rs->reedsShepp(path.getState(i), path.getState(i + 1));
            for (int k = 0; k < 5; ++k)
            {
                if (curve.type_[k] == ob::ReedsSheppStateSpace::RS_NOP ||
                    std::fabs(curve.length_[k]) < kCuspTolerance)
                    continue;
                const int sign = curve.length_[k] > 0.0 ? 1 : -1;
                if (last != 0 && sign != last)
                    ++cusps;
                last = sign;
            }
        }
        return cusps;
    }

    RigidPathMetrics rigidPathMetrics(const World &world, const ob::SpaceInformation &si,
                                      const og::PathGeometric &path, const RigidBodyModel &model, double step)
    {
        RigidPathMetrics m;
        m.length = path.length();
        m.poses = densePathPoses(world, si, path, step);
        m.collisionFree = !m.poses.empty() && independentPosesFree(world, m.poses);
        m.minClearance = std::numeric_limits<double>::infinity();
        double sum = 0.0;
        for (const Pose2 &p : m.poses)
        {
            const double c = model.clearance(p);
            m.minClearance = std::min(m.minClearance, c);
            sum += c;
        }
        m.meanClearance = m.poses.empty() ? 0.0 : sum / static_cast<double>(m.poses.size());
        m.cusps = reedsSheppCusps(si.getStateSpace().get(), path);
        return m;
    }

    double optimalityGapPercent(double length, double optimum)
    {
        if (!(optimum > 0.0) || !std::isfinite(optimum))
            return std::numeric_limits<double>::quiet_NaN();
        return 100.0 * (length - optimum) / optimum;
    }
} // namespace mhplan
