// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the 8-connected grid optimum with MovingAI semantics (computeGridOctileOptimum). */
#include "src/optimum/Optimum.h"

#include "src/optimum/detail/OptimumInternal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <vector>

namespace mhplan
{
    using optimum_detail::aStar;
    using optimum_detail::kInf;
    using optimum_detail::secondsSince;

    namespace
    {
        void requireGrid(const World &world, const char *what)
        {
            if (!world.isGrid())
                throw InputError(std::string(what) + ": world '" + world.name + "' is not a grid world");
        }
    } // namespace

    OptimumResult computeGridOctileOptimum(const World &world, const Query &query)
    {
        requirePlanarSpace(world);
        requireGrid(world, "grid octile optimum");
        const auto t0 = std::chrono::steady_clock::now();
        const OccupancyGrid &g = *world.grid;
        const int W = g.width();
        const int H = g.height();
        auto cellFor = [&](const Vec2 &p, const char *field)
        {
            const int ix = g.cellX(p.x);
            const int iy = g.cellY(p.y);
            int best = -1;
            double bestD = kInf;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                {
                    const int cx = ix + dx;
                    const int cy = iy + dy;
                    if (g.blocked(cx, cy))
                        continue;
                    const Box b = g.cellBox(cx, cy);
                    if (!b.contains(p))
                        continue;
                    const double d = distance(p, g.cellCenter(cx, cy));
                    if (d < bestD)
                    {
                        bestD = d;
                        best = cy * W + cx;
                    }
                }
            if (best < 0)
            {
                std::ostringstream m;
                m << (world.file.empty() ? world.name : world.file) << ": query '" << query.name
                  << "' field '" << field << "' (" << p.x << ", " << p.y
                  << ") is not in a free cell of the grid";
                throw InputError(m.str());
            }
            return best;
        };
        const int s = cellFor(query.start, "start");
        const int t = cellFor(query.goal, "goal");
        const double sqrt2 = std::sqrt(2.0);
        const int tx = t % W;
        const int ty = t / W;
        auto h = [&](int c)
        {
            const int dx = std::abs(c % W - tx);
            const int dy = std::abs(c / W - ty);
            return (sqrt2 - 1.0) * std::min(dx, dy) + std::max(dx, dy);
        };
        double lengthCells = kInf;
        const std::vector<int> cells = aStar(
            static_cast<std::size_t>(W) * H, s, t, h,
            [&](int c, auto &&relax)
            {
                const int cx = c % W;
                const int cy = c / W;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                    {
                        if ((dx == 0 && dy == 0) || g.blocked(cx + dx, cy + dy))
                            continue;
                        if (dx != 0 && dy != 0 && (g.blocked(cx + dx, cy) || g.blocked(cx, cy + dy)))
                            continue;
                        relax((cy + dy) * W + cx + dx, (dx != 0 && dy != 0) ? sqrt2 : 1.0);
                    }
            },
            lengthCells);
        std::size_t edges = 0;
        // Graph size: free cells and their MovingAI moves (each undirected move counted once).
        std::size_t nodes = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
            {
                if (g.blocked(x, y))
                    continue;
                ++nodes;
                const int fwd[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
                for (const auto &d : fwd)
                {
                    if (g.blocked(x + d[0], y + d[1]))
                        continue;
                    if (d[0] != 0 && d[1] != 0 && (g.blocked(x + d[0], y) || g.blocked(x, y + d[1])))
                        continue;
                    ++edges;
                }
            }
        OptimumResult res;
        res.method = "grid-octile";
        res.graphNodes = nodes;
        res.graphEdges = edges;
        if (!cells.empty())
        {
            res.found = true;
            res.lengthCells = lengthCells;
            res.length = lengthCells * g.cellSize();
            for (int c : cells)
                res.path.push_back(g.cellCenter(c % W, c / W));
            for (std::size_t i = 0; i + 1 < res.path.size(); ++i)
            {
                OptimumPiece p;
                p.from = res.path[i];
                p.to = res.path[i + 1];
                p.length = distance(p.from, p.to);
                res.pieces.push_back(p);
            }
        }
        res.seconds = secondsSince(t0);
        return res;
    }
} // namespace mhplan
