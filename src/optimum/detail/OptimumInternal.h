// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: what the exact-optimum solvers share (the .cpp files of src/optimum), not part of the installed
   API: constants, the A* search, timing, and the solvers' entry points that computeOptimum dispatches to. */
#ifndef MHPLAN_OPTIMUM_DETAIL_OPTIMUM_INTERNAL_H
#define MHPLAN_OPTIMUM_DETAIL_OPTIMUM_INTERNAL_H

#include "src/optimum/Optimum.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace mhplan
{
    class GridCollisionModel;

    namespace optimum_detail
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        constexpr double kTwoPi = 2.0 * kPi;

        /** A* from \e s to \e goal over nodes 0..n-1: \e expand(u, relax) calls relax(v, w) for every edge
            u -> v of weight w; \e h is an admissible heuristic. Returns the node sequence from s to goal
           (empty when unreachable) and sets \e length (infinity then). */
        template <class Heuristic, class Expand>
        std::vector<int> aStar(std::size_t n, int s, int goal, Heuristic h, Expand expand, double &length)
        {
            std::vector<double> dist(n, kInf);
            std::vector<int> parent(n, -1);
            std::vector<char> closed(n, 0);
            using Item = std::pair<double, int>;
            std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
            dist[s] = 0.0;
            open.emplace(h(s), s);
            while (!open.empty())
            {
                const int u = open.top().second;
                open.pop();
                if (closed[u])
                    continue;
                closed[u] = 1;
                if (u == goal)
                    break;
                expand(u,
                       [&](int v, double w)
                       {
                           const double nd = dist[u] + w;
                           if (nd < dist[v])
                           {
                               dist[v] = nd;
                               parent[v] = u;
                               open.emplace(nd + h(v), v);
                           }
                       });
            }
            length = dist[goal];
            std::vector<int> out;
            if (!(length < kInf))
                return out;
            for (int v = goal; v != -1; v = parent[v])
                out.push_back(v);
            std::reverse(out.begin(), out.end());
            return out;
        }

        inline double secondsSince(std::chrono::steady_clock::time_point t0)
        {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }

        /** The tangent graph optimum of a geometric world (TangentGraph.cpp); \e keepVertex, when given,
            selects the polygon vertices that get a disc. Method "tangent-graph". */
        OptimumResult tangentGraphOptimum(const World &world, const Query &query,
                                          const OptimumOptions &options,
                                          std::function<bool(const Vec2 &)> keepVertex = {});

        /** The any-angle optimum of a point robot on a grid (GridAnyAngle.cpp). Method "grid-any-angle". */
        OptimumResult gridAnyAngleOptimum(const World &world, const Query &query,
                                          const GridCollisionModel &model, const OptimumOptions &options);

        /** The optimum of a disc robot on a grid (GridDiscRobot.cpp). Method "grid-tangent-graph". */
        OptimumResult gridDiscRobotOptimum(const World &world, const Query &query,
                                           const OptimumOptions &options);
    } // namespace optimum_detail
} // namespace mhplan

#endif
