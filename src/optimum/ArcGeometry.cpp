// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/optimum/detail/ArcGeometry.h"

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

        /** True when some part of the segment lies inside the polygon deeper than tol (crossing parameters
            split the segment into pieces that are either inside or outside; each piece is probed at three
            points). */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const Vec2 d = b - a;
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &p = poly[i];
                const Vec2 e = poly[(i + 1) % n] - p;
                const double den = cross(d, e);
                if (den == 0.0)
                    continue;
                const Vec2 w = p - a;
                const double t = cross(w, e) / den;
                const double s = cross(w, d) / den;
                if (t > 0.0 && t < 1.0 && s >= -1e-12 && s <= 1.0 + 1e-12)
                    ts.push_back(t);
            }
            std::sort(ts.begin(), ts.end());
            for (std::size_t i = 0; i + 1 < ts.size(); ++i)
            {
                const double t0 = ts[i];
                const double t1 = ts[i + 1];
                if (t1 <= t0)
                    continue;
                for (double q : {0.25, 0.5, 0.75})
                    if (pointPolygonSignedDistance(a + d * (t0 + q * (t1 - t0)), poly) < -tol)
                        return true;
            }
            return false;
        }

        /** True when some part of the arc lies inside the polygon deeper than tol (the arc is split at its
            intersections with the polygon's edges; each piece is probed at three points). */
        bool arcDeepInside(const Arc &arc, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &a = poly[i];
                const Vec2 d = poly[(i + 1) % n] - a;
                const double len2 = squaredNorm(d);
                const Vec2 f = a - arc.c;
                const double bq = dot(f, d);
                const double cq = squaredNorm(f) - arc.rho * arc.rho;
                const double disc = bq * bq - len2 * cq;
                if (len2 == 0.0 || disc < 0.0)
                    continue;
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
            std::sort(ts.begin(), ts.end());
            for (std::size_t i = 0; i + 1 < ts.size(); ++i)
            {
                const double t0 = ts[i];
                const double t1 = ts[i + 1];
                if (t1 <= t0)
                    continue;
                for (double q : {0.25, 0.5, 0.75})
                    if (pointPolygonSignedDistance(arc.at(t0 + q * (t1 - t0)), poly) < -tol)
                        return true;
            }
            return false;
        }
    } // namespace optimum_detail
} // namespace mhplan
