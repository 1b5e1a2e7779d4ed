// SPDX-License-Identifier: BSD-3-Clause
/* Shared by the optimum tests (test_optimum.cpp, test_optimum_grid.cpp): portable random numbers, a test
   world, independent path checks and the brute-force references (a dense roadmap, a visibility graph, plain
   Dijkstra) the exact optimum is compared with. */
#ifndef MHPLAN_TESTS_OPTIMUM_SUPPORT_H
#define MHPLAN_TESTS_OPTIMUM_SUPPORT_H

#include "mhplan/collision/Collision.h"
#include "mhplan/collision/GridCollision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <random>
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
