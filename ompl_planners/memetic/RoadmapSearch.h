// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the route search of the memetic planners' lazy roadmaps, shared by the planar and the state mode
   (docs/variants.md, "First paths: a lazy roadmap"). */
#ifndef MHPLAN_OMPL_PLANNERS_MEMETIC_ROADMAP_SEARCH_H
#define MHPLAN_OMPL_PLANNERS_MEMETIC_ROADMAP_SEARCH_H

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace mhplan
{
    /** \brief A* from roadmap vertex 0 (the start) to vertex 1 (the goal). An edge's weight is its length
        times 1 + (penalty of its ends) / 2, so a route already refused or taken costs more the next time;
        edges whose \c state is 2 (found invalid) are skipped. \c outgoing lists the edge ids leaving each
        vertex; \c far(edge, u) is the edge's other end seen from \c u, \c length(edge) its length; \c h is an
        admissible estimate of the remaining length per vertex (zeros give Dijkstra). On return \c g holds the
        weighted cost-to-come and \c via the edge id each reached vertex was entered by. False when the goal
        cannot be reached. */
    template <class Edge, class Far, class Length>
    bool penalisedRoadmapSearch(const std::vector<std::vector<std::uint32_t>> &outgoing,
                                const std::vector<Edge> &edges, Far far, Length length,
                                const std::vector<double> &h, const std::vector<double> &penalty,
                                std::vector<double> &g, std::vector<std::uint32_t> &via)
    {
        const std::size_t m = outgoing.size();
        g.assign(m, std::numeric_limits<double>::infinity());
        via.assign(m, std::numeric_limits<std::uint32_t>::max());
        using Entry = std::pair<double, std::uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
        g[0] = 0.0;
        open.push({h[0], 0u});
        while (!open.empty())
        {
            const Entry e = open.top();
            open.pop();
            const std::uint32_t u = e.second;
            if (u == 1)
                break;
            if (e.first > g[u] + h[u] * (1.0 + 1e-12))
                continue;
            for (const std::uint32_t id : outgoing[u])
            {
                const Edge &edge = edges[id];
                if (edge.state == 2)
                    continue;
                const std::uint32_t v = far(edge, u);
                const double w = length(edge) * (1.0 + 0.5 * (penalty[u] + penalty[v]));
                if (g[u] + w < g[v])
                {
                    g[v] = g[u] + w;
                    via[v] = id;
                    open.push({g[v] + h[v], v});
                }
            }
        }
        return g[1] < std::numeric_limits<double>::infinity();
    }
} // namespace mhplan

#endif
