// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the exact optimum of a disc robot on a grid, the tangent graph over the blocked cells on the
   region's boundary (computeOptimum in Optimum.h describes the method). */
#include "src/base/World.h"
#include "src/optimum/detail/OptimumInternal.h"

#include <cmath>
#include <string>

namespace mhplan
{
    namespace optimum_detail
    {
        namespace
        {
            /** Largest number of convex corners for the disc-robot grid optimum (the tangent graph checks all
                pairs of corner discs). */
            constexpr std::size_t kMaxGridDiscCorners = 4000;

            /** Convex corners of the blocked region: lattice points with exactly one blocked cell of four. */
            bool convexCorner(const OccupancyGrid &g, int vx, int vy)
            {
                int count = 0;
                for (int dy = -1; dy <= 0; ++dy)
                    for (int dx = -1; dx <= 0; ++dx)
                        count += g.blocked(vx + dx, vy + dy) ? 1 : 0;
                return count == 1;
            }

            /** A disc robot on a grid: the tangent graph over the blocked cells on the region's boundary as
                squares, with discs at the region's convex corners only. */
        } // namespace

        OptimumResult gridDiscRobotOptimum(const World &world, const Query &query,
                                           const OptimumOptions &options)
        {
            const OccupancyGrid &g = *world.grid;
            std::size_t corners = 0;
            for (int vy = 0; vy <= g.height(); ++vy)
                for (int vx = 0; vx <= g.width(); ++vx)
                    corners += convexCorner(g, vx, vy) ? 1 : 0;
            if (corners > kMaxGridDiscCorners)
                throw InputError("optimum: grid world '" + world.name + "' with robot radius " +
                                 std::to_string(world.robotRadius) + " has " + std::to_string(corners) +
                                 " convex corners; the disc-robot grid optimum supports at most " +
                                 std::to_string(kMaxGridDiscCorners) + " (a point robot has no such limit)");
            World squares;
            squares.name = world.name;
            squares.bounds = world.bounds;
            squares.robotRadius = world.robotRadius;
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                {
                    if (!g.blocked(ix, iy))
                        continue;
                    bool boundary = false;
                    for (int dy = -1; dy <= 1 && !boundary; ++dy)
                        for (int dx = -1; dx <= 1 && !boundary; ++dx)
                            boundary = g.inside(ix + dx, iy + dy) && !g.blocked(ix + dx, iy + dy);
                    if (!boundary)
                        continue;
                    const Box b = g.cellBox(ix, iy);
                    squares.polygons.push_back(makePolygon(
                        {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}}, "cell"));
                }
            auto keep = [&g](const Vec2 &v)
            {
                const int vx = static_cast<int>(std::lround((v.x - g.origin().x) / g.cellSize()));
                const int vy = static_cast<int>(std::lround((v.y - g.origin().y) / g.cellSize()));
                return convexCorner(g, vx, vy);
            };
            OptimumResult res = tangentGraphOptimum(squares, query, options, keep);
            res.method = "grid-tangent-graph";
            res.lengthCells = res.found ? res.length / g.cellSize() : 0.0;
            return res;
        }
    } // namespace optimum_detail
} // namespace mhplan
