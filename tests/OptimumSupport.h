// SPDX-License-Identifier: BSD-3-Clause
/* Shared by the optimum tests (test_optimum.cpp, test_optimum_grid.cpp): portable random numbers, a test
   world, independent path checks (the exact motion validator; a dense check from the shapes themselves that
   makes the optimum's own path a witness of its length) and the brute-force references (a dense roadmap, a
   visibility graph, plain Dijkstra) the exact optimum is compared with. */
#ifndef MHPLAN_TESTS_OPTIMUM_SUPPORT_H
#define MHPLAN_TESTS_OPTIMUM_SUPPORT_H

#include "src/collision/Collision.h"
#include "src/collision/GridCollision.h"
#include "src/optimum/Optimum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

namespace mhplan::test
{
    /** Portable uniform numbers (fixed seeds give the same worlds everywhere). */
    class Rng
    {
      public:
        explicit Rng(std::uint64_t seed) : engine_(seed) {}
        double uniform(double lo, double hi)
        {
            return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1.0p-53);
        }

      private:
        std::mt19937_64 engine_;
    };

    inline World box10(double robotRadius = 0.0)
    {
        World w;
        w.name = "test";
        w.bounds = {0.0, 10.0, 0.0, 10.0};
        w.robotRadius = robotRadius;
        return w;
    }

    /** Every consecutive pair of the polyline passes the exact motion validator of the world's model. */
    inline ::testing::AssertionResult polylineValid(const World &world, const std::vector<Vec2> &path)
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        if (path.empty())
            return ::testing::AssertionFailure() << "empty path";
        for (std::size_t i = 0; i + 1 < path.size(); ++i)
            if (!model->segmentValid(path[i], path[i + 1]))
                return ::testing::AssertionFailure()
                       << "segment " << i << " (" << path[i].x << ", " << path[i].y << ") -> ("
                       << path[i + 1].x << ", " << path[i + 1].y << ") invalid, clearance "
                       << model->segmentClearance(path[i], path[i + 1]);
        return ::testing::AssertionSuccess();
    }

    inline double polyline(const std::vector<Vec2> &p)
    {
        double s = 0.0;
        for (std::size_t i = 0; i + 1 < p.size(); ++i)
            s += distance(p[i], p[i + 1]);
        return s;
    }

    /** Signed distance from \e p to the closed box \e b (negative inside). */
    inline double pointBoxSignedDistance(const Vec2 &p, const Box &b)
    {
        const double dx = std::max(b.xmin - p.x, p.x - b.xmax);
        const double dy = std::max(b.ymin - p.y, p.y - b.ymax);
        if (dx <= 0.0 && dy <= 0.0)
            return std::max(dx, dy);
        return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
    }

    /** Clearance of the robot's disc centred at \e p, from the world's shapes and Geometry.h's primitives
        alone (no collision model, nothing of the optimum solver): the distance from \e p to the walls of the
        bounds, to every circle, to every polygon (edges by pointSegmentDistance, inside by pointInPolygon)
        and to every blocked cell as a closed square (cells outside the grid blocked), minus the robot
        radius; negative inside an obstacle. Grid cells more than one cell beyond the robot's disc are
        skipped: they cannot make it negative, so above the cell size the value is only a lower bound. */
    inline double independentClearance(const World &w, const Vec2 &p)
    {
        const double r = w.robotRadius;
        const Box &b = w.bounds;
        double c = std::min({p.x - b.xmin, b.xmax - p.x, p.y - b.ymin, b.ymax - p.y}) - r;
        for (const Circle &circle : w.circles)
            c = std::min(c, distance(p, circle.center) - circle.radius - r);
        for (const Polygon &poly : w.polygons)
        {
            const auto &v = poly.vertices;
            double d = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < v.size(); ++i)
                d = std::min(d, pointSegmentDistance(p, v[i], v[(i + 1) % v.size()]));
            c = std::min(c, (pointInPolygon(p, v) ? -d : d) - r);
        }
        if (w.isGrid())
        {
            const OccupancyGrid &g = *w.grid;
            const Box gb = g.bounds();
            c = std::min(c, std::min({p.x - gb.xmin, gb.xmax - p.x, p.y - gb.ymin, gb.ymax - p.y}) - r);
            const int x0 = std::max(0, g.cellX(p.x - r) - 1),
                      x1 = std::min(g.width() - 1, g.cellX(p.x + r) + 1);
            const int y0 = std::max(0, g.cellY(p.y - r) - 1),
                      y1 = std::min(g.height() - 1, g.cellY(p.y + r) + 1);
            for (int iy = y0; iy <= y1; ++iy)
                for (int ix = x0; ix <= x1; ++ix)
                    if (g.blocked(ix, iy))
                        c = std::min(c, pointBoxSignedDistance(p, g.cellBox(ix, iy)) - r);
        }
        return c;
    }

    /** Points at most \e spacing apart along a straight segment or an arc of the optimum, end points
        included. */
    inline std::vector<Vec2> pieceSamples(const OptimumPiece &p, double spacing)
    {
        const double len = p.arc ? p.radius * std::fabs(p.sweep) : distance(p.from, p.to);
        const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / spacing)));
        std::vector<Vec2> out;
        const double th0 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x);
        for (std::size_t k = 0; k <= n; ++k)
        {
            const double t = static_cast<double>(k) / static_cast<double>(n);
            if (p.arc)
                out.push_back({p.center.x + p.radius * std::cos(th0 + t * p.sweep),
                               p.center.y + p.radius * std::sin(th0 + t * p.sweep)});
            else
                out.push_back(p.from + (p.to - p.from) * t);
        }
        return out;
    }

    /** The independent dense check: every point at most \e spacing apart along the polyline has an
        independentClearance of at least -\e tol. */
    inline ::testing::AssertionResult denselyClear(const World &w, const std::vector<Vec2> &path,
                                                   double spacing, double tol)
    {
        for (std::size_t i = 0; i + 1 < path.size(); ++i)
        {
            OptimumPiece seg;
            seg.from = path[i];
            seg.to = path[i + 1];
            for (const Vec2 &x : pieceSamples(seg, spacing))
                if (independentClearance(w, x) < -tol)
                    return ::testing::AssertionFailure()
                           << "segment " << i << " enters an obstacle at (" << x.x << ", " << x.y
                           << "), clearance " << independentClearance(w, x);
        }
        return ::testing::AssertionSuccess();
    }

    /** The lower-side oracle every world admits: the optimum must be witnessed by a real path no longer than
        the length it reports. A too-short optimum fails it, for it would have to cut through an obstacle or
        misreport its length. Checks, with sizes relative to the world's size S (max of width and height):
        - the exact path (OptimumResult::pieces) runs from the query's start to its goal without gaps
          (1e-9 S), every arc starts and ends on its circle where its sweep says;
        - every piece's length is its geometric length (|to - from|, radius * |sweep|) and their sum is the
          reported length (1e-9 relative);
        - points at most 1e-4 S apart along the pieces have an independentClearance >= -1e-7 S (touching
          obstacles is allowed, so arcs and corners lie at clearance 0);
        - the drawing polyline (OptimumResult::path) passes the same dense check; without arcs of positive
          radius its length is the reported one (1e-9 relative), with them it may exceed it by what the
          circumscribed polylines add (the arc deviation times each sweep, and the 1e-10 S push per arc).
        The pinch rule of point robots on grids (no passage between two blocked cells that meet at a corner)
        is no clearance and is not checked here: test_optimum_grid.cpp compares those optima with a
        brute-force visibility graph over the exact motion validator. */
    inline ::testing::AssertionResult optimumWitnessed(const World &w, const Query &q, const OptimumResult &r,
                                                       double arcDeviation = OptimumOptions().arcDeviation)
    {
        if (!r.found)
            return ::testing::AssertionFailure() << "no optimum to witness";
        const double scale = std::max(w.bounds.width(), w.bounds.height());
        const double gapTol = 1e-9 * scale;
        const double spacing = 1e-4 * scale;
        const double tol = 1e-7 * scale;
        const double push = 1e-10 * scale;
        const double lengthTol = 1e-9 * std::max(r.length, gapTol);
        auto at = [](const Vec2 &p)
        {
            std::ostringstream s;
            s << "(" << p.x << ", " << p.y << ")";
            return s.str();
        };
        Vec2 end = q.start;
        double geometric = 0.0;
        double allowance = 0.0;
        for (std::size_t k = 0; k < r.pieces.size(); ++k)
        {
            const OptimumPiece &p = r.pieces[k];
            if (distance(p.from, end) > gapTol)
                return ::testing::AssertionFailure()
                       << "piece " << k << " starts at " << at(p.from) << ", the path is at " << at(end);
            double len = distance(p.from, p.to);
            if (p.arc)
            {
                const double th1 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x) + p.sweep;
                const Vec2 swept{p.center.x + p.radius * std::cos(th1),
                                 p.center.y + p.radius * std::sin(th1)};
                if (std::fabs(distance(p.from, p.center) - p.radius) > gapTol ||
                    distance(swept, p.to) > gapTol)
                    return ::testing::AssertionFailure()
                           << "arc " << k << " from " << at(p.from) << " to " << at(p.to)
                           << " is not on its circle " << at(p.center) << ", radius " << p.radius
                           << ", sweep " << p.sweep;
                len = p.radius * std::fabs(p.sweep);
                if (p.radius > 0.0)
                    allowance += std::max(arcDeviation * scale, 2.0 * push) * std::fabs(p.sweep) + 4.0 * push;
            }
            if (std::fabs(len - p.length) > lengthTol)
                return ::testing::AssertionFailure()
                       << "piece " << k << " reports length " << p.length << ", its geometry has " << len;
            for (const Vec2 &x : pieceSamples(p, spacing))
                if (independentClearance(w, x) < -tol)
                    return ::testing::AssertionFailure()
                           << "piece " << k << " enters an obstacle at " << at(x) << ", clearance "
                           << independentClearance(w, x);
            geometric += len;
            end = p.to;
        }
        if (r.pieces.empty())
            geometric = distance(q.start, q.goal);
        else if (distance(end, q.goal) > gapTol)
            return ::testing::AssertionFailure()
                   << "the path ends at " << at(end) << ", the goal is " << at(q.goal);
        if (std::fabs(geometric - r.length) > lengthTol)
            return ::testing::AssertionFailure()
                   << "reported length " << r.length << ", the path's pieces measure " << geometric;
        const ::testing::AssertionResult drawn = denselyClear(w, r.path, spacing, tol);
        if (!drawn)
            return ::testing::AssertionFailure() << "the polyline: " << drawn.message();
        const double drawnLength = polyline(r.path);
        if (drawnLength > r.length + lengthTol + allowance ||
            (allowance == 0.0 && drawnLength < r.length - lengthTol))
            return ::testing::AssertionFailure()
                   << "the polyline measures " << drawnLength << ", the reported length is " << r.length
                   << " (allowance for arcs " << allowance << ")";
        return ::testing::AssertionSuccess();
    }

    /** Shortest path over a graph given as adjacency lists (plain Dijkstra). */
    inline double dijkstra(const std::vector<std::vector<std::pair<int, double>>> &adj, int s, int t)
    {
        std::vector<double> dist(adj.size(), std::numeric_limits<double>::infinity());
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
        dist[s] = 0.0;
        open.emplace(0.0, s);
        while (!open.empty())
        {
            const auto [d, u] = open.top();
            open.pop();
            if (d > dist[u])
                continue;
            for (const auto &[v, w] : adj[u])
                if (d + w < dist[v])
                {
                    dist[v] = d + w;
                    open.emplace(dist[v], v);
                }
        }
        return dist[t];
    }

    /** A uniformly random point of the world's robot-centre box that \e model accepts (rejection sampling).
     */
    inline Vec2 sampleValid(Rng &rng, const World &w, const CollisionModel &model)
    {
        const Box in = w.bounds.inflated(-w.robotRadius);
        for (;;)
        {
            const Vec2 p{rng.uniform(in.xmin, in.xmax), rng.uniform(in.ymin, in.ymax)};
            if (model.isValid(p))
                return p;
        }
    }

    /** A dense PRM*-style roadmap: a lattice of \e n x \e n points plus \e extra random samples, start and
        goal; every pair closer than \e radius joined when the exact motion validator accepts it. */
    inline double roadmapLength(const World &world, const Query &q, int n, int extra, double radiusCells,
                                std::uint64_t seed)
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        const Box in = world.bounds.inflated(-world.robotRadius);
        std::vector<Vec2> pts{q.start, q.goal};
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
            {
                const Vec2 p{in.xmin + in.width() * (i + 0.5) / n, in.ymin + in.height() * (j + 0.5) / n};
                if (model->isValid(p))
                    pts.push_back(p);
            }
        Rng rng(seed);
        for (int k = 0; k < extra; ++k)
        {
            const Vec2 p{rng.uniform(in.xmin, in.xmax), rng.uniform(in.ymin, in.ymax)};
            if (model->isValid(p))
                pts.push_back(p);
        }
        const double radius = radiusCells * std::max(in.width(), in.height()) / n;
        // Bucket the points for the neighbour search.
        const int nb = std::max(1, static_cast<int>(std::max(in.width(), in.height()) / radius));
        const double cs = std::max(in.width(), in.height()) / nb;
        std::vector<std::vector<int>> buckets(static_cast<std::size_t>(nb + 1) * (nb + 1));
        auto bucketOf = [&](const Vec2 &p)
        {
            const int bx = std::clamp(static_cast<int>((p.x - in.xmin) / cs), 0, nb);
            const int by = std::clamp(static_cast<int>((p.y - in.ymin) / cs), 0, nb);
            return std::make_pair(bx, by);
        };
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            const auto [bx, by] = bucketOf(pts[i]);
            buckets[static_cast<std::size_t>(by) * (nb + 1) + bx].push_back(static_cast<int>(i));
        }
        std::vector<std::vector<std::pair<int, double>>> adj(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            const auto [bx, by] = bucketOf(pts[i]);
            for (int y = std::max(0, by - 1); y <= std::min(nb, by + 1); ++y)
                for (int x = std::max(0, bx - 1); x <= std::min(nb, bx + 1); ++x)
                    for (int j : buckets[static_cast<std::size_t>(y) * (nb + 1) + x])
                    {
                        if (j <= static_cast<int>(i))
                            continue;
                        const double d = distance(pts[i], pts[j]);
                        if (d > radius || !model->segmentValid(pts[i], pts[j]))
                            continue;
                        adj[i].emplace_back(j, d);
                        adj[j].emplace_back(static_cast<int>(i), d);
                    }
        }
        return dijkstra(adj, 0, 1);
    }

    /** Brute-force visibility graph for a point robot: every pair of candidate points checked with the
        world's exact motion validator (no pruning, no spatial index). */
    inline double bruteVisibility(const World &world, const Query &q, const std::vector<Vec2> &corners)
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        std::vector<Vec2> pts{q.start, q.goal};
        pts.insert(pts.end(), corners.begin(), corners.end());
        std::vector<std::vector<std::pair<int, double>>> adj(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i)
            for (std::size_t j = i + 1; j < pts.size(); ++j)
                if (model->segmentValid(pts[i], pts[j]))
                {
                    const double d = distance(pts[i], pts[j]);
                    adj[i].emplace_back(static_cast<int>(j), d);
                    adj[j].emplace_back(static_cast<int>(i), d);
                }
        return dijkstra(adj, 0, 1);
    }

    inline std::vector<Vec2> polygonVertices(const World &w)
    {
        std::vector<Vec2> out;
        for (const auto &p : w.polygons)
            out.insert(out.end(), p.vertices.begin(), p.vertices.end());
        return out;
    }

    inline std::vector<Vec2> gridCornerPoints(const OccupancyGrid &g)
    {
        std::vector<Vec2> out;
        for (int vy = 0; vy <= g.height(); ++vy)
            for (int vx = 0; vx <= g.width(); ++vx)
            {
                int blocked = 0;
                for (int dy = -1; dy <= 0; ++dy)
                    for (int dx = -1; dx <= 0; ++dx)
                        blocked += g.blocked(vx + dx, vy + dy) ? 1 : 0;
                if (blocked > 0 && blocked < 4)
                    out.push_back({g.origin().x + vx * g.cellSize(), g.origin().y + vy * g.cellSize()});
            }
        return out;
    }

    inline Query query(const Vec2 &s, const Vec2 &g)
    {
        return {"q", s, g};
    }
} // namespace mhplan::test

#endif
