// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the exact optimum's entry point (one solver per kind of world: TangentGraph.cpp, GridAnyAngle.cpp,
   GridDiscRobot.cpp; the 8-connected grid optimum in Octile.cpp), the polyline of a piecewise path and the
   optimality gap. */
#include "src/optimum/Optimum.h"

#include "src/collision/Collision.h"
#include "src/collision/GridCollision.h"
#include "src/collision/Problem.h"
#include "src/optimum/detail/ArcGeometry.h"
#include "src/optimum/detail/OptimumInternal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    using optimum_detail::gridAnyAngleOptimum;
    using optimum_detail::gridDiscRobotOptimum;
    using optimum_detail::polar;
    using optimum_detail::secondsSince;
    using optimum_detail::tangentGraphOptimum;

    std::vector<Vec2> piecesToPolyline(const std::vector<OptimumPiece> &pieces, double maxDeviation,
                                       double push)
    {
        std::vector<Vec2> out;
        if (pieces.empty())
            return out;
        auto pushed = [&](const OptimumPiece &p, const Vec2 &x)
        {
            const Vec2 v = x - p.center;
            const double d = norm(v);
            return d > 0.0 ? p.center + v * ((p.radius + push) / d) : x;
        };
        out.push_back(pieces.front().from);
        for (const auto &p : pieces)
        {
            if (!p.arc || p.radius <= 0.0)
            {
                out.push_back(p.to);
                continue;
            }
            const Vec2 a = pushed(p, p.from);
            if (distance(out.back(), p.from) <= 1e-9 * (1.0 + p.radius))
                out.back() = a;
            else
                out.push_back(a);
            if (p.sweep != 0.0)
            {
                const double ratio = (p.radius + push) / (p.radius + std::max(maxDeviation, 2.0 * push));
                const double hmax = std::max(2.0 * std::acos(std::min(1.0, ratio)), 1e-6);
                const double th0 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x);
                const double th1 = th0 + p.sweep;
                // Split at the axis directions, where the arc reaches its extreme coordinates: there the
                // polyline has a vertex on the (pushed) circle, so an arc that touches the bounds keeps its
                // polyline inside them once clamped.
                std::vector<double> cuts{th0};
                const double quarter = 0.5 * kPi;
                const double margin = 1e-9;
                if (p.sweep > 0.0)
                    for (double a = (std::floor(th0 / quarter) + 1.0) * quarter; a < th1 - margin;
                         a += quarter)
                    {
                        if (a > th0 + margin)
                            cuts.push_back(a);
                    }
                else
                    for (double a = (std::ceil(th0 / quarter) - 1.0) * quarter; a > th1 + margin;
                         a -= quarter)
                    {
                        if (a < th0 - margin)
                            cuts.push_back(a);
                    }
                cuts.push_back(th1);
                for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
                {
                    const double span = cuts[c + 1] - cuts[c];
                    const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(span) / hmax)));
                    const double h = span / n;
                    const double R = (p.radius + push) / std::cos(0.5 * h);
                    for (int k = 1; k <= n; ++k)
                        out.push_back(polar(p.center, R, cuts[c] + (k - 0.5) * h));
                    out.push_back(c + 2 < cuts.size() ? polar(p.center, p.radius + push, cuts[c + 1])
                                                      : pushed(p, p.to));
                }
            }
        }
        return out;
    }

    double optimalityGap(double pathLength, const OptimumResult &optimum)
    {
        if (!optimum.found)
            return std::numeric_limits<double>::quiet_NaN();
        if (optimum.length == 0.0)
            return 0.0;
        return (pathLength - optimum.length) / optimum.length;
    }

    void requirePlanarSpace(const World &world)
    {
        if (world.isRigid())
            throw InputError(
                "no exact optimum for space " + toString(world.space) + ": '" + world.name +
                "' is an SE(2)-based world (a rigid body or a car); the exact solvers cover a disc "
                "or point robot translating in the plane (space r2) only (docs/spaces.md)");
    }

    OptimumResult computeOptimum(const World &world, const Query &query, const OptimumOptions &options)
    {
        if (!(options.arcDeviation > 0.0 && options.arcDeviation <= 0.1))
        {
            std::ostringstream m;
            m << "computeOptimum: options.arcDeviation must be in (0, 0.1], got " << options.arcDeviation;
            throw std::invalid_argument(m.str());
        }
        requirePlanarSpace(world);
        const auto t0 = std::chrono::steady_clock::now();
        if (world.isGrid())
        {
            GridCollisionModel model(world);
            validateQuery(world, query, model);
            if (world.robotRadius > 0.0)
            {
                OptimumResult res = gridDiscRobotOptimum(world, query, options);
                res.seconds = secondsSince(t0);
                return res;
            }
            OptimumResult res = gridAnyAngleOptimum(world, query, model, options);
            res.seconds = secondsSince(t0);
            return res;
        }
        {
            AnalyticCollisionModel model(world);
            validateQuery(world, query, model);
        }
        OptimumResult res = tangentGraphOptimum(world, query, options);
        res.seconds = secondsSince(t0);
        return res;
    }
} // namespace mhplan
