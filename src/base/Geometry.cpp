// SPDX-License-Identifier: BSD-3-Clause
#include "src/base/Geometry.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>

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

    namespace
    {
        /** \brief Lexicographic order of points (x, then y): the sweep's event order. */
        bool lexLess(const Vec2 &a, const Vec2 &b)
        {
            return a.x < b.x || (a.x == b.x && a.y < b.y);
        }

        /** \brief Edges i and j of an n-gon touch in a way a simple polygon forbids: non-adjacent edges must
            not meet at all, adjacent edges (sharing one vertex) must not fold back onto each other. */
        bool edgesConflict(const std::vector<Vec2> &poly, std::size_t i, std::size_t j)
        {
            const std::size_t n = poly.size();
            if (i > j)
                std::swap(i, j);
            const Vec2 &a = poly[i];
            const Vec2 &b = poly[(i + 1) % n];
            const Vec2 &c = poly[j];
            const Vec2 &d = poly[(j + 1) % n];
            const bool next = j == i + 1;
            const bool wrap = i == 0 && j == n - 1;
            if (next || wrap)
            {
                const Vec2 &shared = next ? b : a;
                const Vec2 &p = next ? a : b;
                const Vec2 &q = next ? d : c;
                return orientation(p, shared, q) == 0 && dot(p - shared, q - shared) > 0.0;
            }
            return segmentsIntersect(a, b, c, d);
        }

        /** \brief The all-pairs test: O(n^2), used for small polygons. */
        bool anyEdgesConflictBruteForce(const std::vector<Vec2> &poly)
        {
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i + 1; j < n; ++j)
                    if (edgesConflict(poly, i, j))
                        return true;
            return false;
        }

        /** \brief Shamos-Hoey sweep (docs/conventions.md, "Polygon simplicity"): O(n log n). The edges
            crossing a vertical sweep line are kept ordered by height; an intersection exists if and only if
            two edges that become neighbours in that order at some event intersect, so each edge is tested
            only against its neighbours when it is inserted and its two neighbours are tested against each
            other when it is removed. Vertices are unique (checked before), so two edges sharing an end point
            are adjacent edges of the polygon. The order compares two edges at the larger of their left end
            points' abscissae (the moment the later one enters), a vertical edge by its lower end; ties are
            broken by slope and then by index so that the order is strict. The intersection tests themselves
            are the exact orientation predicates of segmentsIntersect. */
        bool anyEdgesConflictSweep(const std::vector<Vec2> &poly)
        {
            const std::size_t n = poly.size();
            struct Edge
            {
                Vec2 l, r; // lexicographically smaller and larger end point
            };
            std::vector<Edge> edges(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &a = poly[i];
                const Vec2 &b = poly[(i + 1) % n];
                edges[i] = lexLess(a, b) ? Edge{a, b} : Edge{b, a};
            }
            const auto heightAt = [](const Edge &e, double x)
            {
                if (e.l.x == e.r.x)
                    return e.l.y;
                if (x <= e.l.x)
                    return e.l.y;
                if (x >= e.r.x)
                    return e.r.y;
                return e.l.y + (e.r.y - e.l.y) * ((x - e.l.x) / (e.r.x - e.l.x));
            };
            const auto below = [&](std::size_t i, std::size_t j)
            {
                if (i == j)
                    return false;
                const Edge &a = edges[i];
                const Edge &b = edges[j];
                const double x = std::max(a.l.x, b.l.x);
                const double ya = heightAt(a, x);
                const double yb = heightAt(b, x);
                if (ya != yb)
                    return ya < yb;
                // Same height at x: the one that rises less slowly is below; vertical edges rise fastest.
                const Vec2 da = a.r - a.l;
                const Vec2 db = b.r - b.l;
                const double c = cross(da, db); // > 0: b turns left of a, so a is below
                if (c != 0.0)
                    return c > 0.0;
                return i < j;
            };
            std::set<std::size_t, decltype(below)> active(below);
            std::vector<std::set<std::size_t, decltype(below)>::iterator> where(n, active.end());

            // Events: (point, kind, edge); at equal points insertions (kind 0) come before removals (kind 1),
            // so edges meeting at a point are compared while both are in the order.
            struct Event
            {
                Vec2 p;
                int kind;
                std::size_t edge;
            };
            std::vector<Event> events;
            events.reserve(2 * n);
            for (std::size_t i = 0; i < n; ++i)
            {
                events.push_back({edges[i].l, 0, i});
                events.push_back({edges[i].r, 1, i});
            }
            std::sort(events.begin(), events.end(),
                      [](const Event &a, const Event &b)
                      {
                          if (a.p.x != b.p.x)
                              return a.p.x < b.p.x;
                          if (a.kind != b.kind)
                              return a.kind < b.kind;
                          return a.p.y < b.p.y;
                      });
            for (const Event &ev : events)
            {
                if (ev.kind == 0)
                {
                    const auto [it, inserted] = active.insert(ev.edge);
                    if (!inserted)
                        return true; // unreachable with a strict order; conservative
                    where[ev.edge] = it;
                    if (std::next(it) != active.end() && edgesConflict(poly, ev.edge, *std::next(it)))
                        return true;
                    if (it != active.begin() && edgesConflict(poly, ev.edge, *std::prev(it)))
                        return true;
                }
                else
                {
                    const auto it = where[ev.edge];
                    if (it != active.begin() && std::next(it) != active.end() &&
                        edgesConflict(poly, *std::prev(it), *std::next(it)))
                        return true;
                    active.erase(it);
                }
            }
            return false;
        }
    } // namespace

    bool polygonIsSimple(const std::vector<Vec2> &poly)
    {
        const std::size_t n = poly.size();
        if (n < 3)
            return false;
        // Small polygons: the all-pairs test, which allocates nothing (it also runs inside collision
        // queries, through polygonIsConvex).
        if (n <= 16)
        {
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i + 1; j < n; ++j)
                    if (poly[i] == poly[j])
                        return false;
            return !anyEdgesConflictBruteForce(poly) && std::abs(signedArea2(poly)) > 0.0;
        }
        // A repeated vertex (consecutive or not) makes a polygon non-simple; after this check two edges
        // sharing an end point are adjacent edges.
        std::vector<Vec2> sorted(poly);
        std::sort(sorted.begin(), sorted.end(), lexLess);
        for (std::size_t i = 1; i < n; ++i)
            if (sorted[i] == sorted[i - 1])
                return false;
        return !anyEdgesConflictSweep(poly) && std::abs(signedArea2(poly)) > 0.0;
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

    bool segmentEntersPolygonInterior(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly,
                                      double depth)
    {
        thread_local std::vector<double> ts;
        boundaryCrossings(a, b, poly, ts);
        const Vec2 d = b - a;
        const double below = std::max(depth, 0.0);
        auto strictlyInside = [&](const Vec2 &p)
        { return pointInPolygon(p, poly) && pointPolygonBoundaryDistance(p, poly) > below; };
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
