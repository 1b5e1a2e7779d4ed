// SPDX-License-Identifier: BSD-3-Clause
#include "src/optimum/detail/ArcGeometry.h"

#include <algorithm>
#include <cmath>

namespace mhplan
{
    namespace optimum_detail
    {
        double pointArcDistance(const Vec2 &p, const Arc &arc)
        {
            const Vec2 v = p - arc.c;
            const double d = norm(v);
            if (d == 0.0)
                return arc.rho;
            if (arc.contains(std::atan2(v.y, v.x)))
                return std::fabs(d - arc.rho);
            return std::min(distance(p, arc.at(0.0)), distance(p, arc.at(1.0)));
        }

        /** Exact distance between an arc and a segment: end points against the other piece, the arc points
            whose normal is perpendicular to the segment, and intersections. */
        double arcSegmentDistance(const Arc &arc, const Vec2 &a, const Vec2 &b)
        {
            double best = std::min(pointArcDistance(a, arc), pointArcDistance(b, arc));
            best = std::min(best, pointSegmentDistance(arc.at(0.0), a, b));
            best = std::min(best, pointSegmentDistance(arc.at(1.0), a, b));
            const Vec2 d = b - a;
            const double len2 = squaredNorm(d);
            if (len2 == 0.0)
                return best;
            const double base = std::atan2(d.y, d.x) + 0.5 * kPi;
            for (double ang : {base, base + kPi})
                if (arc.contains(ang))
                    best = std::min(best, pointSegmentDistance(polar(arc.c, arc.rho, ang), a, b));
            // Intersections of the segment with the circle.
            const Vec2 f = a - arc.c;
            const double bq = dot(f, d);
            const double cq = squaredNorm(f) - arc.rho * arc.rho;
            const double disc = bq * bq - len2 * cq;
            if (disc >= 0.0)
            {
                const double sq = std::sqrt(disc);
                for (double t : {(-bq - sq) / len2, (-bq + sq) / len2})
                    if (t >= 0.0 && t <= 1.0)
                    {
                        const Vec2 x = a + d * t - arc.c;
                        if (arc.contains(std::atan2(x.y, x.x)))
                            return 0.0;
                    }
            }
            return best;
        }

        namespace
        {
            /** Appends the parameter t in (0, 1) at which the segment a + t d crosses the polygon edge
                [p, q], if it does. */
            void segmentCrossing(const Vec2 &a, const Vec2 &d, const Vec2 &p, const Vec2 &q,
                                 std::vector<double> &ts)
            {
                const Vec2 e = q - p;
                const double den = cross(d, e);
                if (den == 0.0)
                    return;
                const Vec2 w = p - a;
                const double t = cross(w, e) / den;
                const double s = cross(w, d) / den;
                if (t > 0.0 && t < 1.0 && s >= -1e-12 && s <= 1.0 + 1e-12)
                    ts.push_back(t);
            }

            /** Appends the arc parameters in [0, 1) at which the arc meets the polygon edge [a, b]. */
            void arcCrossing(const Arc &arc, const Vec2 &a, const Vec2 &b, std::vector<double> &ts)
            {
                const Vec2 d = b - a;
                const double len2 = squaredNorm(d);
                const Vec2 f = a - arc.c;
                const double bq = dot(f, d);
                const double cq = squaredNorm(f) - arc.rho * arc.rho;
                const double disc = bq * bq - len2 * cq;
                if (len2 == 0.0 || disc < 0.0)
                    return;
                const double sq = std::sqrt(disc);
                for (double t : {(-bq - sq) / len2, (-bq + sq) / len2})
                    if (t >= -1e-12 && t <= 1.0 + 1e-12)
                    {
                        const Vec2 x = a + d * t - arc.c;
                        const double u = ccwDelta(arc.th0, std::atan2(x.y, x.x));
                        if (arc.sweep > 0.0 && u < arc.sweep)
                            ts.push_back(u / arc.sweep);
                    }
            }

            /** Sorts the split parameters \e ts and probes each piece between two of them at three points:
                true when \e deep(at(t)) holds for one. */
            template <typename At, typename Deep> bool anyPieceDeep(std::vector<double> &ts, At at, Deep deep)
            {
                std::sort(ts.begin(), ts.end());
                for (std::size_t i = 0; i + 1 < ts.size(); ++i)
                {
                    const double t0 = ts[i];
                    const double t1 = ts[i + 1];
                    if (t1 <= t0)
                        continue;
                    for (double q : {0.25, 0.5, 0.75})
                        if (deep(at(t0 + q * (t1 - t0))))
                            return true;
                }
                return false;
            }
        } // namespace

        /** True when some part of the segment lies inside the polygon deeper than tol (crossing parameters
            split the segment into pieces that are either inside or outside; each piece is probed at three
            points). */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const Vec2 d = b - a;
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
                segmentCrossing(a, d, poly[i], poly[(i + 1) % n], ts);
            return anyPieceDeep(
                ts, [&](double t) { return a + d * t; },
                [&](const Vec2 &p) { return pointPolygonSignedDistance(p, poly) < -tol; });
        }

        /** The same with the polygon's edge index: a crossing point lies on the segment and (up to 1e-12 of
            the edge) on the edge, so only the edges listed along the segment can add one. */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const PolygonEdgeIndex &index, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const Vec2 d = b - a;
            const std::vector<Vec2> &poly = index.polygon();
            const std::size_t n = poly.size();
            index.anyEdgeOnSegment(a, b,
                                   [&](int e)
                                   {
                                       const auto i = static_cast<std::size_t>(e);
                                       segmentCrossing(a, d, poly[i], poly[(i + 1) % n], ts);
                                       return false;
                                   });
            return anyPieceDeep(
                ts, [&](double t) { return a + d * t; },
                [&](const Vec2 &p) { return index.signedDistanceBelow(p, -tol); });
        }

        /** True when some part of the arc lies inside the polygon deeper than tol (the arc is split at its
            intersections with the polygon's edges; each piece is probed at three points). */
        bool arcDeepInside(const Arc &arc, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
                arcCrossing(arc, poly[i], poly[(i + 1) % n], ts);
            return anyPieceDeep(
                ts, [&](double t) { return arc.at(t); },
                [&](const Vec2 &p) { return pointPolygonSignedDistance(p, poly) < -tol; });
        }

        /** The same with the polygon's edge index: an intersection point lies on the arc, so only the edges
            listed in the arc's bounding box can add one. */
        bool arcDeepInside(const Arc &arc, const PolygonEdgeIndex &index, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const std::vector<Vec2> &poly = index.polygon();
            const std::size_t n = poly.size();
            index.anyEdgeInBox(arcBoundingBox(arc).inflated(tol),
                               [&](int e)
                               {
                                   const auto i = static_cast<std::size_t>(e);
                                   arcCrossing(arc, poly[i], poly[(i + 1) % n], ts);
                                   return false;
                               });
            return anyPieceDeep(
                ts, [&](double t) { return arc.at(t); },
                [&](const Vec2 &p) { return index.signedDistanceBelow(p, -tol); });
        }

        Box arcBoundingBox(const Arc &arc)
        {
            // End points and the axis-extreme points of the arc.
            Box bb = boundingBox({arc.at(0.0), arc.at(1.0)});
            for (int k = 0; k < 4; ++k)
                if (arc.contains(k * 0.5 * kPi))
                {
                    const Vec2 p = polar(arc.c, arc.rho, k * 0.5 * kPi);
                    bb = boundingBox({{bb.xmin, bb.ymin}, {bb.xmax, bb.ymax}, p});
                }
            return bb;
        }
    } // namespace optimum_detail
} // namespace mhplan
