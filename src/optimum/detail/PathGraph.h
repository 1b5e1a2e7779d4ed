// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the graph the tangent-graph and grid any-angle solvers search (nodes with positions, segment and
   arc edges), and how its shortest path becomes an OptimumResult. Not part of the installed API. */
#ifndef MHPLAN_OPTIMUM_DETAIL_PATH_GRAPH_H
#define MHPLAN_OPTIMUM_DETAIL_PATH_GRAPH_H

#include "src/optimum/detail/ArcGeometry.h"
#include "src/optimum/detail/OptimumInternal.h"

#include <utility>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        /** An undirected weighted graph with positions; arc edges remember their arc. */
        struct Graph
        {
            struct Edge
            {
                int to;
                double w;
                int arc; ///< index into arcs (oriented from the lower node id), or -1 for a segment
            };
            std::vector<Vec2> pos;
            /** Per node: the disc it lies on (centre, radius; radius 0 for points). */
            std::vector<std::pair<Vec2, double>> support;
            std::vector<std::vector<Edge>> adj;
            std::vector<Arc> arcs;
            std::vector<std::pair<int, int>> arcEnds;
            std::size_t edgeCount{0};

            int addNode(const Vec2 &p, const Vec2 &c = {}, double rho = 0.0)
            {
                pos.push_back(p);
                support.emplace_back(c, rho);
                adj.emplace_back();
                return static_cast<int>(pos.size()) - 1;
            }
            void addEdge(int a, int b, double w, int arc = -1)
            {
                adj[a].push_back({b, w, arc});
                adj[b].push_back({a, w, arc});
                ++edgeCount;
            }
            int addArc(int a, int b, const Arc &arc)
            {
                arcs.push_back(arc);
                arcEnds.emplace_back(a, b);
                const int id = static_cast<int>(arcs.size()) - 1;
                addEdge(a, b, arc.rho * arc.sweep, id);
                return id;
            }

            /** A* with the Euclidean heuristic to \e goal (admissible for every edge). Returns the node
                sequence (empty when unreachable) and sets length. */
            std::vector<int> shortestPath(int s, int g, double &length) const
            {
                return aStar(
                    pos.size(), s, g, [&](int v) { return distance(pos[v], pos[g]); },
                    [&](int u, auto &&relax)
                    {
                        for (const Edge &e : adj[u])
                            relax(e.to, e.w);
                    },
                    length);
            }

            /** The pieces along a node sequence: segments, arcs, and zero-sweep arcs at nodes on discs
                where the path only touches (so that the polyline is pushed off them too). */
            std::vector<OptimumPiece> pieces(const std::vector<int> &nodes) const
            {
                std::vector<OptimumPiece> out;
                for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
                {
                    const int u = nodes[i];
                    const int v = nodes[i + 1];
                    const Edge *best = nullptr;
                    for (const Edge &e : adj[u])
                        if (e.to == v && (best == nullptr || e.w < best->w))
                            best = &e;
                    OptimumPiece p;
                    p.from = pos[u];
                    p.to = pos[v];
                    p.length = best->w;
                    if (best->arc >= 0)
                    {
                        const Arc &a = arcs[best->arc];
                        p.arc = true;
                        p.center = a.c;
                        p.radius = a.rho;
                        p.sweep = arcEnds[best->arc].first == u ? a.sweep : -a.sweep;
                        out.push_back(p);
                        continue;
                    }
                    if (i > 0 && support[u].second > 0.0 && (out.empty() || !out.back().arc))
                    {
                        OptimumPiece touch;
                        touch.arc = true;
                        touch.from = touch.to = pos[u];
                        touch.center = support[u].first;
                        touch.radius = support[u].second;
                        out.push_back(touch);
                    }
                    if (p.length > 0.0)
                        out.push_back(p);
                }
                return out;
            }
        };

        /** Searches \e g from \e s to \e t and fills \e res: the graph's size, the pieces, the exact length
           and the polyline (OptimumResult::path) clamped into \e inner, start and goal exactly at its ends.
         */
        void finish(OptimumResult &res, const Graph &g, int s, int t, const Query &query, double scale,
                    const Box &inner, const OptimumOptions &opt);
    } // namespace optimum_detail
} // namespace mhplan

#endif
