// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' lazy roadmap in the plane (docs/variants.md, "first paths from a lazy
   roadmap"): samples in the incumbent's informed set, k-nearest edges, A* routes under route penalties, only
   the edges of a found route checked. Part of MemeticToolkit; its path operators are in MemeticToolkit.cpp.
 */
#include "ompl_planners/memetic/MemeticToolkit.h"
#include "ompl_planners/memetic/RoadmapSearch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace mhplan
{
    void MemeticToolkit::roadmapClear()
    {
        rmPoints_.clear();
        rmEdges_.clear();
        rmAdjacent_.clear();
        rmPenalty_.clear();
    }

    void MemeticToolkit::roadmapGrow(unsigned int n, const Vec2 &start, const Vec2 &goal, double bound)
    {
        // Keep the samples inside the informed set, add n new ones (rejected outside it before any check).
        MemeticPath points{start, goal};
        auto inside = [&](const Vec2 &q)
        { return !std::isfinite(bound) || distance(start, q) + distance(q, goal) < bound; };
        for (std::size_t i = 2; i < rmPoints_.size(); ++i)
            if (inside(rmPoints_[i]))
                points.push_back(rmPoints_[i]);
        for (unsigned int k = 0, tries = 0; k < n && tries < 20 * n; ++tries)
        {
            const Vec2 q(rng_.uniformReal(bounds_.xmin, bounds_.xmax),
                         rng_.uniformReal(bounds_.ymin, bounds_.ymax));
            if (!inside(q))
                continue;
            ++k;
            if (pointValid(q))
                points.push_back(q);
        }
        rmPoints_.swap(points);
        rmPenalty_.assign(rmPoints_.size(), 0.0);
        nearestEdges(rmPoints_, bounds_, rmEdges_, rmAdjacent_);
    }

    void MemeticToolkit::nearestEdges(const MemeticPath &points, const Box &box,
                                      std::vector<RoadmapEdge> &edges,
                                      std::vector<std::vector<std::uint32_t>> &adjacent)
    {
        const std::size_t m = points.size();
        // k nearest neighbours (PRM*'s k = e (1 + 1/2) ln n), symmetric, found on a uniform grid of about
        // k / 4 points per cell (rings searched outwards until the k-th distance is inside the ring).
        const auto kn =
            static_cast<std::size_t>(std::ceil(4.08 * std::log(double(std::max<std::size_t>(m, 2)))));
        edges.clear();
        adjacent.assign(m, {});
        const double w = std::max(box.width(), 1e-12), hgt = std::max(box.height(), 1e-12);
        // At most 4 m + 16 cells along either side: points on a line (a box of no height) would otherwise
        // make cells of no size and rings without end.
        const double cell = std::max(
            std::sqrt(w * hgt * std::max(1.0, double(kn) / 4.0) / double(std::max<std::size_t>(m, 1))),
            std::max(w, hgt) / double(4 * m + 16));
        const long nx = std::max(1L, static_cast<long>(std::ceil(w / cell)));
        const long ny = std::max(1L, static_cast<long>(std::ceil(hgt / cell)));
        std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(nx * ny));
        auto cellOf = [&](const Vec2 &p, long &cx, long &cy)
        {
            cx = std::min(nx - 1, std::max(0L, static_cast<long>((p.x - box.xmin) / cell)));
            cy = std::min(ny - 1, std::max(0L, static_cast<long>((p.y - box.ymin) / cell)));
        };
        for (std::size_t i = 0; i < m; ++i)
        {
            long cx, cy;
            cellOf(points[i], cx, cy);
            grid[static_cast<std::size_t>(cy * nx + cx)].push_back(static_cast<std::uint32_t>(i));
        }
        std::vector<std::vector<std::uint32_t>> knn(m);
        std::vector<std::pair<double, std::uint32_t>> near;
        near.reserve(8 * kn);
        for (std::size_t i = 0; i < m; ++i)
        {
            long cx, cy;
            cellOf(points[i], cx, cy);
            near.clear();
            for (long ring = 0; ring <= std::max(nx, ny); ++ring)
            {
                for (long y = std::max(0L, cy - ring); y <= std::min(ny - 1, cy + ring); ++y)
                    for (long x = std::max(0L, cx - ring); x <= std::min(nx - 1, cx + ring); ++x)
                    {
                        if (std::labs(x - cx) != ring && std::labs(y - cy) != ring)
                            continue;
                        for (const std::uint32_t j : grid[static_cast<std::size_t>(y * nx + x)])
                            if (j != i)
                                near.emplace_back(squaredNorm(points[i] - points[j]), j);
                    }
                if (near.size() >= kn)
                {
                    std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(kn - 1),
                                     near.end());
                    const double reach = double(ring) * cell;
                    if (near[kn - 1].first <= reach * reach)
                        break;
                }
            }
            const std::size_t take = std::min(kn, near.size());
            std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(take), near.end());
            for (std::size_t t = 0; t < take; ++t)
                knn[i].push_back(near[t].second);
        }
        // Symmetric: an edge i-j when either is among the other's k nearest (once).
        for (std::size_t i = 0; i < m; ++i)
            for (const std::uint32_t j : knn[i])
            {
                if (j < i &&
                    std::find(knn[j].begin(), knn[j].end(), static_cast<std::uint32_t>(i)) != knn[j].end())
                    continue; // added from j's side
                const auto id = static_cast<std::uint32_t>(edges.size());
                adjacent[i].push_back(id);
                adjacent[j].push_back(id);
                edges.push_back({static_cast<std::uint32_t>(i), j, distance(points[i], points[j]), 0});
            }
    }

    bool MemeticToolkit::lazyRoute(const MemeticPath &points, std::vector<RoadmapEdge> &edges,
                                   const std::vector<std::vector<std::uint32_t>> &adjacent,
                                   const std::vector<double> &penalty, unsigned int maxInvalid,
                                   const std::function<bool()> &stop, std::vector<std::uint32_t> &nodes)
    {
        const std::size_t m = points.size();
        if (m < 2)
            return false;
        std::vector<double> g(m);
        std::vector<std::uint32_t> via(m);
        unsigned int refused = 0;
        const Vec2 goal = points[1];
        std::vector<double> h(m);
        for (std::size_t v = 0; v < m; ++v)
            h[v] = std::sqrt(squaredNorm(points[v] - goal));
        std::vector<std::uint32_t> route;
        while (true)
        {
            if (stop())
                return false;
            // A* from 0 to 1 under the penalties (weights >= lengths: the distance to the goal is
            // admissible).
            if (!penalisedRoadmapSearch(
                    adjacent, edges,
                    [](const RoadmapEdge &edge, std::uint32_t u) { return edge.a == u ? edge.b : edge.a; },
                    [](const RoadmapEdge &edge) { return edge.length; }, h, penalty, g, via))
                return false; // cut off in the roadmap
            nodes.clear();
            route.clear();
            for (std::uint32_t v = 1; v != 0;)
            {
                nodes.push_back(v);
                const RoadmapEdge &edge = edges[via[v]];
                route.push_back(via[v]);
                v = edge.a == v ? edge.b : edge.a;
            }
            nodes.push_back(0);
            std::reverse(nodes.begin(), nodes.end());
            std::reverse(route.begin(), route.end());
            // Every unknown edge of the route is checked (one A* per refused edge would cost more than the
            // checks).
            bool valid = true;
            for (std::size_t k = 0; k < route.size(); ++k)
            {
                RoadmapEdge &edge = edges[route[k]];
                if (edge.state == 0)
                    edge.state = motionValid(points[nodes[k]], points[nodes[k + 1]]) ? 1 : 2;
                valid = valid && edge.state == 1;
            }
            if (valid)
                return true;
            if (++refused >= maxInvalid)
                return false;
        }
    }

    bool MemeticToolkit::roadmapPath(MemeticPath &path, unsigned int maxInvalid,
                                     const std::function<bool()> &stop)
    {
        const std::size_t m = rmPoints_.size();
        std::vector<std::uint32_t> nodes;
        if (!lazyRoute(rmPoints_, rmEdges_, rmAdjacent_, rmPenalty_, maxInvalid, stop, nodes))
            return false;
        path.clear();
        for (const std::uint32_t v : nodes)
            path.push_back(rmPoints_[v]);
        // Penalise the route and its neighbourhood: the next call takes another way round.
        std::vector<char> hit(m, 0);
        for (const std::uint32_t v : nodes)
        {
            hit[v] = 1;
            for (const std::uint32_t id : rmAdjacent_[v])
                hit[rmEdges_[id].a == v ? rmEdges_[id].b : rmEdges_[id].a] = 1;
        }
        for (std::size_t v = 2; v < m; ++v)
            if (hit[v])
                rmPenalty_[v] += 1.0;
        return true;
    }

    bool MemeticToolkit::tubeRoute(const MemeticPath &path, double radius, unsigned int n,
                                   unsigned int maxInvalid, MemeticPath &out,
                                   const std::function<bool()> &stop)
    {
        const double total = length(path);
        if (path.size() < 2 || total <= 0.0 || radius <= 0.0)
            return false;
        MemeticPath points{path.front(), path.back()};
        points.reserve(n + 2);
        for (unsigned int k = 0; k < n; ++k)
        {
            std::size_t segment = 0;
            const Vec2 on = pointAt(path, rng_.uniformReal(0.0, total), segment);
            Vec2 offset;
            do
                offset = Vec2(rng_.uniformReal(-1.0, 1.0), rng_.uniformReal(-1.0, 1.0));
            while (squaredNorm(offset) > 1.0);
            const Vec2 q = on + offset * radius;
            if (inBounds(q) && pointValid(q))
                points.push_back(q);
        }
        // The tube's box: the path's, grown by the radius.
        Box box{path[0].x, path[0].x, path[0].y, path[0].y};
        for (const Vec2 &q : path)
        {
            box.xmin = std::min(box.xmin, q.x - radius);
            box.xmax = std::max(box.xmax, q.x + radius);
            box.ymin = std::min(box.ymin, q.y - radius);
            box.ymax = std::max(box.ymax, q.y + radius);
        }
        std::vector<RoadmapEdge> edges;
        std::vector<std::vector<std::uint32_t>> adjacent;
        nearestEdges(points, box, edges, adjacent);
        std::vector<std::uint32_t> nodes;
        if (!lazyRoute(points, edges, adjacent, std::vector<double>(points.size(), 0.0), maxInvalid, stop,
                       nodes))
            return false;
        out.clear();
        for (const std::uint32_t v : nodes)
            out.push_back(points[v]);
        return true;
    }
} // namespace mhplan
