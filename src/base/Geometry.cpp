// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/base/Geometry.h"

#include <algorithm>
#include <limits>

namespace mhplan
{
    Vec2 closestPointOnSegment(const Vec2 &p, const Vec2 &a, const Vec2 &b)
    {
        const Vec2 ab = b - a;
        const double len2 = squaredNorm(ab);
        if (len2 <= 0.0)
            return a;
        double t = dot(p - a, ab) / len2;
        t = std::clamp(t, 0.0, 1.0);
        return a + ab * t;
    }

    double pointSegmentDistance(const Vec2 &p, const Vec2 &a, const Vec2 &b)
    {
        return distance(p, closestPointOnSegment(p, a, b));
    }

    namespace
    {
        int orientation(const Vec2 &a, const Vec2 &b, const Vec2 &c)
        {
            const double v = cross(b - a, c - a);
            return (v > 0.0) - (v < 0.0);
        }

        bool onSegment(const Vec2 &p, const Vec2 &a, const Vec2 &b)
        {
            return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
                   p.y <= std::max(a.y, b.y);
        }
    } // namespace

    bool segmentsIntersect(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
    {
        const int o1 = orientation(a, b, c);
        const int o2 = orientation(a, b, d);
        const int o3 = orientation(c, d, a);
        const int o4 = orientation(c, d, b);
        if (o1 != o2 && o3 != o4)
            return true;
        if (o1 == 0 && onSegment(c, a, b))
            return true;
        if (o2 == 0 && onSegment(d, a, b))
            return true;
        if (o3 == 0 && onSegment(a, c, d))
            return true;
        if (o4 == 0 && onSegment(b, c, d))
            return true;
        return false;
    }

    bool segmentsCrossProperly(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
    {
        const int o1 = orientation(a, b, c);
        const int o2 = orientation(a, b, d);
        const int o3 = orientation(c, d, a);
        const int o4 = orientation(c, d, b);
        return o1 * o2 < 0 && o3 * o4 < 0;
    }

    double segmentSegmentDistance(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d)
    {
        if (segmentsIntersect(a, b, c, d))
            return 0.0;
        return std::min(std::min(pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d)),
                        std::min(pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)));
    }

    Box boundingBox(const std::vector<Vec2> &pts)
    {
        Box box{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
        for (const auto &p : pts)
        {
            box.xmin = std::min(box.xmin, p.x);
            box.xmax = std::max(box.xmax, p.x);
            box.ymin = std::min(box.ymin, p.y);
            box.ymax = std::max(box.ymax, p.y);
        }
        return box;
    }

    double signedArea2(const std::vector<Vec2> &poly)
    {
        double a = 0.0;
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i)
            a += cross(poly[i], poly[(i + 1) % n]);
        return a;
    }

    bool polygonIsConvex(const std::vector<Vec2> &poly)
    {
        const std::size_t n = poly.size();
        if (n < 3)
            return false;
        int sign = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const int o = orientation(poly[i], poly[(i + 1) % n], poly[(i + 2) % n]);
            if (o == 0)
                continue;
            if (sign == 0)
                sign = o;
            else if (o != sign)
                return false;
        }
        return sign != 0 && polygonIsSimple(poly);
    }

    bool polygonIsSimple(const std::vector<Vec2> &poly)
    {
        const std::size_t n = poly.size();
        if (n < 3)
            return false;
        for (std::size_t i = 0; i < n; ++i)
            if (poly[i] == poly[(i + 1) % n])
                return false;
        for (std::size_t i = 0; i < n; ++i)
        {
            const Vec2 &a = poly[i];
            const Vec2 &b = poly[(i + 1) % n];
            for (std::size_t j = i + 1; j < n; ++j)
            {
                const Vec2 &c = poly[j];
                const Vec2 &d = poly[(j + 1) % n];
                const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
                if (adjacent)
                {
                    // Adjacent edges share one vertex; they must not fold back onto each other.
                    const Vec2 &shared = (j == i + 1) ? b : a;
                    const Vec2 &p = (j == i + 1) ? a : b;
                    const Vec2 &q = (j == i + 1) ? d : c;
                    if (orientation(p, shared, q) == 0 && dot(p - shared, q - shared) > 0.0)
                        return false;
                    continue;
                }
                if (segmentsIntersect(a, b, c, d))
                    return false;
            }
        }
        return std::abs(signedArea2(poly)) > 0.0;
    }

    bool pointInPolygon(const Vec2 &p, const std::vector<Vec2> &poly)
    {
        const std::size_t n = poly.size();
        bool inside = false;
        for (std::size_t i = 0, j = n - 1; i < n; j = i++)
        {
            const Vec2 &a = poly[i];
            const Vec2 &b = poly[j];
            if (orientation(a, b, p) == 0 && onSegment(p, a, b))
                return true;
            if ((a.y > p.y) != (b.y > p.y))
            {
                const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (p.x < xCross)
                    inside = !inside;
            }
        }
        return inside;
    }

    double pointPolygonBoundaryDistance(const Vec2 &p, const std::vector<Vec2> &poly)
    {
        double best = std::numeric_limits<double>::infinity();
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i)
            best = std::min(best, pointSegmentDistance(p, poly[i], poly[(i + 1) % n]));
        return best;
    }

    double pointPolygonSignedDistance(const Vec2 &p, const std::vector<Vec2> &poly)
    {
        // A point exactly on an edge (exact orientation test) is at distance 0, whatever rounding the
        // closest-point computation would add.
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i)
        {
            const Vec2 &a = poly[i];
            const Vec2 &b = poly[(i + 1) % n];
            if (orientation(a, b, p) == 0 && onSegment(p, a, b))
                return 0.0;
        }
        const double d = pointPolygonBoundaryDistance(p, poly);
        return pointInPolygon(p, poly) ? -d : d;
    }

    double segmentPolygonDistance(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly)
    {
        if (pointInPolygon(a, poly) || pointInPolygon(b, poly))
            return 0.0;
        double best = std::numeric_limits<double>::infinity();
        const std::size_t n = poly.size();
        for (std::size_t i = 0; i < n; ++i)
        {
            best = std::min(best, segmentSegmentDistance(a, b, poly[i], poly[(i + 1) % n]));
            if (best == 0.0)
                return 0.0;
        }
        return best;
    }

    std::vector<Vec2> rectangleCorners(const Vec2 &center, double width, double height, double angle)
    {
        const double c = std::cos(angle);
        const double s = std::sin(angle);
        const double hx = 0.5 * width;
        const double hy = 0.5 * height;
        const Vec2 local[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
        std::vector<Vec2> out;
        out.reserve(4);
        for (const auto &l : local)
            out.emplace_back(center.x + c * l.x - s * l.y, center.y + s * l.x + c * l.y);
        return out;
    }
} // namespace mhplan

namespace mhplan
{
    namespace
    {
        /** Parameters t in [0, 1] where [a, b] meets the polygon's boundary (overlap ends included). */
        /** Fills \e ts (cleared first; callers pass thread-local buffers so hot paths do not allocate). */
        void boundaryCrossings(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly,
                               std::vector<double> &ts)
        {
            ts.clear();
            ts.push_back(0.0);
            ts.push_back(1.0);
            const Vec2 d = b - a;
            const double len2 = squaredNorm(d);
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &c = poly[i];
                const Vec2 &e = poly[(i + 1) % n];
                const Vec2 f = e - c;
                const double den = cross(d, f);
                if (den != 0.0)
                {
                    const double t = cross(c - a, f) / den;
                    const double u = cross(c - a, d) / den;
                    if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0)
                        ts.push_back(t);
                }
                else if (len2 > 0.0)
                {
                    // Parallel: project the edge's endpoints (collinear overlap ends and near misses alike).
                    for (const Vec2 &q : {c, e})
                    {
                        const double t = dot(q - a, d) / len2;
                        if (t > 0.0 && t < 1.0)
                            ts.push_back(t);
                    }
                }
            }
            std::sort(ts.begin(), ts.end());
        }
    } // namespace

    bool segmentEntersPolygonInterior(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly)
    {
        thread_local std::vector<double> ts;
        boundaryCrossings(a, b, poly, ts);
        const Vec2 d = b - a;
        auto strictlyInside = [&](const Vec2 &p)
        { return pointInPolygon(p, poly) && pointPolygonBoundaryDistance(p, poly) > 0.0; };
        if (strictlyInside(a) || strictlyInside(b))
            return true;
        for (std::size_t i = 0; i + 1 < ts.size(); ++i)
        {
            if (ts[i + 1] <= ts[i])
                continue;
            if (strictlyInside(a + d * (0.5 * (ts[i] + ts[i + 1]))))
                return true;
        }
        return false;
    }

    double deepestSegmentPenetration(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly)
    {
        const double outside = segmentPolygonDistance(a, b, poly);
        if (outside > 0.0)
            return outside;
        const Vec2 d = b - a;
        auto f = [&](double t) { return pointPolygonSignedDistance(a + d * t, poly); };
        thread_local std::vector<double> candidates;
        boundaryCrossings(a, b, poly, candidates);
        double best = std::numeric_limits<double>::infinity();
        if (polygonIsConvex(poly))
        {
            // Inside a convex polygon the signed distance is -min_i s_i(t) with s_i the (linear) distance to
            // edge i's supporting line: convex and piecewise linear in t, so its minimum over the inside
            // part is at a boundary crossing or where two s_i are equal.
            const std::size_t n = poly.size();
            const double orient = signedArea2(poly) >= 0.0 ? 1.0 : -1.0;
            thread_local std::vector<double> s0, s1;
            s0.resize(n);
            s1.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &c = poly[i];
                const Vec2 e = poly[(i + 1) % n] - c;
                const double len = norm(e);
                s0[i] = orient * cross(e, a - c) / len;
                s1[i] = orient * cross(e, d) / len;
            }
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i + 1; j < n; ++j)
                {
                    const double den = s1[i] - s1[j];
                    if (den == 0.0)
                        continue;
                    const double t = (s0[j] - s0[i]) / den;
                    if (t > 0.0 && t < 1.0)
                        candidates.push_back(t);
                }
            for (double t : candidates)
                best = std::min(best, f(t));
            return best;
        }
        // Non-convex: 64 samples, then a golden-section refinement around the best one (an upper bound
        // within |b - a| / 128 of the true minimum, and usually much closer).
        const int samples = 64;
        double bestT = 0.0;
        for (int k = 0; k <= samples; ++k)
            candidates.push_back(static_cast<double>(k) / samples);
        for (double t : candidates)
        {
            const double v = f(t);
            if (v < best)
            {
                best = v;
                bestT = t;
            }
        }
        double lo = std::max(0.0, bestT - 1.0 / samples);
        double hi = std::min(1.0, bestT + 1.0 / samples);
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        double f1 = f(x1), f2 = f(x2);
        for (int it = 0; it < 40; ++it)
        {
            if (f1 < f2)
            {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - g * (hi - lo);
                f1 = f(x1);
            }
            else
            {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + g * (hi - lo);
                f2 = f(x2);
            }
        }
        return std::min({best, f1, f2});
    }
} // namespace mhplan
