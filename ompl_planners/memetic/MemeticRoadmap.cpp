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
        const std::size_t m = rmPoints_.size();
        // k nearest neighbours (PRM*'s k = e (1 + 1/2) ln n), symmetric, found on a uniform grid of about
        // k / 4 points per cell (rings searched outwards until the k-th distance is inside the ring).
        const auto kn =
            static_cast<std::size_t>(std::ceil(4.08 * std::log(double(std::max<std::size_t>(m, 2)))));
        rmEdges_.clear();
        rmAdjacent_.assign(m, {});
        rmPenalty_.assign(m, 0.0);
        const double w = std::max(bounds_.width(), 1e-12), hgt = std::max(bounds_.height(), 1e-12);
        const double cell =
            std::sqrt(w * hgt * std::max(1.0, double(kn) / 4.0) / double(std::max<std::size_t>(m, 1)));
        const long nx = std::max(1L, static_cast<long>(std::ceil(w / cell)));
        const long ny = std::max(1L, static_cast<long>(std::ceil(hgt / cell)));
        std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(nx * ny));
        auto cellOf = [&](const Vec2 &p, long &cx, long &cy)
        {
            cx = std::min(nx - 1, std::max(0L, static_cast<long>((p.x - bounds_.xmin) / cell)));
            cy = std::min(ny - 1, std::max(0L, static_cast<long>((p.y - bounds_.ymin) / cell)));
        };
        for (std::size_t i = 0; i < m; ++i)
        {
            long cx, cy;
            cellOf(rmPoints_[i], cx, cy);
            grid[static_cast<std::size_t>(cy * nx + cx)].push_back(static_cast<std::uint32_t>(i));
        }
        std::vector<std::vector<std::uint32_t>> knn(m);
        std::vector<std::pair<double, std::uint32_t>> near;
        near.reserve(8 * kn);
        for (std::size_t i = 0; i < m; ++i)
        {
            long cx, cy;
            cellOf(rmPoints_[i], cx, cy);
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
                                near.emplace_back(squaredNorm(rmPoints_[i] - rmPoints_[j]), j);
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
                const auto id = static_cast<std::uint32_t>(rmEdges_.size());
                rmAdjacent_[i].push_back(id);
                rmAdjacent_[j].push_back(id);
                rmEdges_.push_back(
                    {static_cast<std::uint32_t>(i), j, distance(rmPoints_[i], rmPoints_[j]), 0});
            }
    }

    bool MemeticToolkit::roadmapPath(MemeticPath &path, unsigned int maxInvalid,
                                     const std::function<bool()> &stop)
    {
        const std::size_t m = rmPoints_.size();
        if (m < 2)
            return false;
        std::vector<double> g(m);
        std::vector<std::uint32_t> via(m);
        std::vector<std::uint32_t> nodes;
        unsigned int refused = 0;
        const Vec2 goal = rmPoints_[1];
        std::vector<double> h(m);
        for (std::size_t v = 0; v < m; ++v)
            h[v] = std::sqrt(squaredNorm(rmPoints_[v] - goal));
        while (true)
        {
            if (stop())
                return false;
            // A* from 0 to 1 under the penalties (weights >= lengths: the distance to the goal is
            // admissible).
            if (!penalisedRoadmapSearch(
                    rmAdjacent_, rmEdges_,
                    [](const RoadmapEdge &edge, std::uint32_t u) { return edge.a == u ? edge.b : edge.a; },
                    [](const RoadmapEdge &edge) { return edge.length; }, h, rmPenalty_, g, via))
                return false; // cut off in the roadmap
            nodes.clear();
            std::vector<std::uint32_t> edges;
            for (std::uint32_t v = 1; v != 0;)
            {
                nodes.push_back(v);
                const RoadmapEdge &edge = rmEdges_[via[v]];
                edges.push_back(via[v]);
                v = edge.a == v ? edge.b : edge.a;
            }
            nodes.push_back(0);
            std::reverse(nodes.begin(), nodes.end());
            std::reverse(edges.begin(), edges.end());
            // Every unknown edge of the route is checked (one A* per refused edge would cost more than the
            // checks).
            bool valid = true;
            for (std::size_t k = 0; k < edges.size(); ++k)
            {
                RoadmapEdge &edge = rmEdges_[edges[k]];
                if (edge.state == 0)
                    edge.state = motionValid(rmPoints_[nodes[k]], rmPoints_[nodes[k + 1]]) ? 1 : 2;
                valid = valid && edge.state == 1;
            }
            if (valid)
                break;
            if (++refused >= maxInvalid)
                return false;
        }
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
} // namespace mhplan
