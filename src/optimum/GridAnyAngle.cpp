// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the exact any-angle optimum of a point robot on a grid, the visibility graph of the blocked
   region's convex corners found by octant sweeps (computeOptimum in Optimum.h describes the method). */
#include "src/collision/GridCollision.h"
#include "src/optimum/detail/OptimumInternal.h"
#include "src/optimum/detail/PathGraph.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        namespace
        {
            /** Any-angle optimum on a grid for a point robot: visibility graph of the convex corners. */
            class GridAnyAngle
            {
              public:
                GridAnyAngle(const World &w, const Query &q, const GridCollisionModel &model)
                    : world_(w), query_(q), model_(model), grid_(*w.grid), W_(grid_.width()),
                      H_(grid_.height()), s_(grid_.cellSize()), o_(grid_.origin())
                {
                }

                OptimumResult run(const OptimumOptions &opt)
                {
                    OptimumResult res;
                    res.method = "grid-any-angle";
                    // Corner nodes: lattice points with exactly one blocked cell among their four.
                    nodeAt_.assign(static_cast<std::size_t>(W_ + 1) * (H_ + 1), -1);
                    for (int vy = 0; vy <= H_; ++vy)
                        for (int vx = 0; vx <= W_; ++vx)
                        {
                            int count = 0;
                            int qx = 0, qy = 0;
                            for (int dy = -1; dy <= 0; ++dy)
                                for (int dx = -1; dx <= 0; ++dx)
                                    if (grid_.blocked(vx + dx, vy + dy))
                                    {
                                        ++count;
                                        qx = dx == 0 ? 1 : -1;
                                        qy = dy == 0 ? 1 : -1;
                                    }
                            if (count != 1)
                                continue;
                            nodeAt_[vertexIndex(vx, vy)] = g_.addNode(worldPoint(vx, vy));
                            quadrant_.emplace_back(qx, qy);
                            lattice_.emplace_back(vx, vy);
                        }
                    const int corners = static_cast<int>(g_.pos.size());
                    seen_.assign(corners, -1);
                    const int s = g_.addNode(query_.start);
                    const int t = g_.addNode(query_.goal);
                    // First try a tight ellipse (2% above the straight line), then the octile bound, which is
                    // always enough; a path no longer than the bound in use is the optimum.
                    const double ceiling = upperBound();
                    std::vector<double> bounds;
                    const double tight = 1.02 * distance(query_.start, query_.goal) + 1e-9 * s_;
                    if (tight < ceiling)
                        bounds.push_back(tight);
                    bounds.push_back(ceiling);
                    for (double bound : bounds)
                    {
                        bound_ = bound;
                        for (auto &adj : g_.adj)
                            adj.clear();
                        g_.edgeCount = 0;
                        seen_.assign(corners, -1);
                        for (int u = 0; u < corners; ++u)
                            if (distance(g_.pos[u], query_.start) + distance(g_.pos[u], query_.goal) <=
                                bound_)
                                scanFrom(u, Vec2{static_cast<double>(lattice_[u].first),
                                                 static_cast<double>(lattice_[u].second)});
                        scanFrom(s, cellUnits(query_.start));
                        scanFrom(t, cellUnits(query_.goal));
                        if (model_.segmentValid(query_.start, query_.goal))
                            g_.addEdge(s, t, distance(query_.start, query_.goal));
                        res = OptimumResult();
                        res.method = "grid-any-angle";
                        finish(res, g_, s, t, query_, std::max(world_.bounds.width(), world_.bounds.height()),
                               world_.bounds, opt);
                        if (res.found && res.length <= bound_)
                            break;
                    }
                    res.lengthCells = res.length / s_;
                    return res;
                }

              private:
                const World &world_;
                const Query &query_;
                const GridCollisionModel &model_;
                const OccupancyGrid &grid_;
                int W_, H_;
                double s_;
                Vec2 o_;
                Graph g_;
                std::vector<int> nodeAt_;
                std::vector<std::pair<int, int>> quadrant_, lattice_;
                std::vector<int> seen_;
                /** Upper bound on the optimum (see upperBound()); longer paths are not looked for. */
                double bound_{kInf};

                /** The 8-connected optimum's path, joined to the exact start and goal, is a valid any-angle
                   path: its length bounds the optimum, and a shorter path never leaves the ellipse {x : |x -
                   start| + |x - goal| <= bound}. Infinity when the octile search finds no path. */
                double upperBound() const
                {
                    const OptimumResult oct = computeGridOctileOptimum(world_, query_);
                    if (!oct.found)
                        return kInf;
                    return oct.length + distance(query_.start, oct.path.front()) +
                           distance(oct.path.back(), query_.goal) + 1e-9 * std::max(1.0, oct.length);
                }

                std::size_t vertexIndex(int vx, int vy) const
                {
                    return static_cast<std::size_t>(vy) * (W_ + 1) + vx;
                }
                Vec2 worldPoint(int vx, int vy) const { return {o_.x + vx * s_, o_.y + vy * s_}; }
                Vec2 cellUnits(const Vec2 &p) const { return {(p.x - o_.x) / s_, (p.y - o_.y) / s_}; }

                bool tautAt(int node, double dx, double dy) const
                {
                    const auto &q = quadrant_[node];
                    return dx * dy * q.first * q.second <= 0.0;
                }

                /** Called for every corner vertex the sweep from node u (at p, cell units) finds possibly
                    visible: checks the pruning rules, then the segment exactly, then adds the edge. */
                void candidate(int u, const Vec2 &p, int vx, int vy)
                {
                    if (vx < 0 || vy < 0 || vx > W_ || vy > H_)
                        return;
                    const int v = nodeAt_[vertexIndex(vx, vy)];
                    if (v < 0 || v == u || seen_[v] == u)
                        return;
                    seen_[v] = u;
                    const bool uIsCorner = u < static_cast<int>(seen_.size());
                    if (uIsCorner && v < u)
                        return; // the pair is handled from v's sweep
                    const double dx = vx - p.x;
                    const double dy = vy - p.y;
                    if (!tautAt(v, dx, dy) || (uIsCorner && !tautAt(u, dx, dy)))
                        return;
                    const Vec2 &a = g_.pos[u];
                    const Vec2 &b = g_.pos[v];
                    const double via = std::min(distance(query_.start, a) + distance(b, query_.goal),
                                                distance(query_.start, b) + distance(a, query_.goal));
                    if (via + distance(a, b) > bound_)
                        return; // on no path shorter than the octile one
                    if (!model_.segmentValid(a, b))
                        return;
                    g_.addEdge(u, v, distance(g_.pos[u], g_.pos[v]));
                }

                /** Octant sweep (shadow casting) from p in cell units: the set of visible directions in each
                    octant is kept as closed slope intervals; every blocked cell of the columns swept removes
                   the open interval of slopes of rays through its interior (shrunk by 1e-10, so the candidate
                   set is a superset of the visible corners; candidate() confirms each exactly). */
                void scanFrom(int u, const Vec2 &p)
                {
                    // A lattice origin gives exact slopes (quotients of small integers, correctly rounded, so
                    // equal rationals give equal doubles); any other origin gets blocked intervals shrunk by
                    // eps.
                    const bool lattice = p.x == std::floor(p.x) && p.y == std::floor(p.y);
                    const double eps = lattice ? 0.0 : 1e-10;
                    for (int oct = 0; oct < 8; ++oct)
                    {
                        const int sx = (oct & 1) ? -1 : 1;
                        const int sy = (oct & 2) ? -1 : 1;
                        const bool swap = (oct & 4) != 0;
                        const double P = swap ? p.y : p.x;
                        const double Q = swap ? p.x : p.y;
                        const int sp = swap ? sy : sx;
                        const int sq = swap ? sx : sy;
                        const double fu = sp > 0 ? std::floor(P) + 1.0 - P : P - (std::ceil(P) - 1.0);
                        const double fv = sq > 0 ? std::floor(Q) + 1.0 - Q : Q - (std::ceil(Q) - 1.0);
                        const bool onLine = fv == 1.0; // the octant's lower ray runs along a grid line
                        auto cellBlocked = [&](double uMid, double vMid)
                        {
                            const int a = static_cast<int>(std::floor(P + sp * uMid));
                            const int b = static_cast<int>(std::floor(Q + sq * vMid));
                            return swap ? grid_.blocked(b, a) : grid_.blocked(a, b);
                        };
                        std::vector<std::pair<double, double>> vis{{0.0, 1.0}}, nextVis, scratch;
                        const int maxK = W_ + H_ + 4;
                        for (int k = 0; k <= maxK && !vis.empty(); ++k)
                        {
                            const double uL = fu + k - 1.0;
                            const double uR = fu + k;
                            if (uL > 0.0)
                            {
                                const int line = static_cast<int>(std::lround(P + sp * uL));
                                for (const auto &iv : vis)
                                {
                                    const int j0 =
                                        static_cast<int>(std::ceil(iv.first * uL - (fv - 1.0) - 1e-9));
                                    const int j1 =
                                        static_cast<int>(std::floor(iv.second * uL - (fv - 1.0) + 1e-9));
                                    for (int j = j0; j <= j1; ++j)
                                    {
                                        const int other =
                                            static_cast<int>(std::lround(Q + sq * (fv - 1.0 + j)));
                                        if (swap)
                                            candidate(u, p, other, line);
                                        else
                                            candidate(u, p, line, other);
                                    }
                                }
                            }
                            nextVis = vis;
                            auto subtract = [&](double a, double b)
                            {
                                std::vector<std::pair<double, double>> &out = scratch;
                                out.clear();
                                for (const auto &iv : nextVis)
                                {
                                    if (b <= iv.first || a >= iv.second)
                                    {
                                        out.push_back(iv);
                                        continue;
                                    }
                                    if (a >= iv.first)
                                        out.emplace_back(iv.first, a);
                                    if (b <= iv.second)
                                        out.emplace_back(b, iv.second);
                                }
                                nextVis.swap(out);
                            };
                            const double uMid = 0.5 * (uL + uR);
                            for (const auto &iv : vis)
                            {
                                const double vmin = iv.first * std::max(uL, 0.0);
                                const double vmax = iv.second * uR;
                                const int j0 = static_cast<int>(std::floor(vmin - fv + 1.0)) - 1;
                                const int j1 = static_cast<int>(std::floor(vmax - fv + 1.0)) + 1;
                                for (int j = j0; j <= j1; ++j)
                                {
                                    const double va = fv - 1.0 + j;
                                    const double vb = va + 1.0;
                                    if (vb <= 0.0 || !cellBlocked(uMid, va + 0.5))
                                        continue;
                                    const double lo = va >= 0.0 ? va / uR + eps : -kInf;
                                    const double hi = uL > 0.0 ? vb / uL - eps : kInf;
                                    if (lo < hi)
                                        subtract(lo, hi);
                                }
                            }
                            // The lower ray along a grid line is blocked where the cells on both sides are.
                            if (onLine && cellBlocked(uMid, 0.5) && cellBlocked(uMid, -0.5))
                                subtract(-kInf, 2.0 * eps + 1e-12);
                            vis.swap(nextVis);
                        }
                    }
                }
            };
        } // namespace

        OptimumResult gridAnyAngleOptimum(const World &world, const Query &query,
                                          const GridCollisionModel &model, const OptimumOptions &options)
        {
            GridAnyAngle solver(world, query, model);
            return solver.run(options);
        }
    } // namespace optimum_detail
} // namespace mhplan
