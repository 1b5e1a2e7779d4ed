// SPDX-License-Identifier: BSD-3-Clause
/* Tests of the exact optimum on occupancy grids (random grids against a brute-force visibility graph over
   the cell corners and against a plain octile Dijkstra, disc robots on grids against a dense roadmap from
   above and their own paths from below, the octile semantics) and at scale (a thousand circles, a 512^2
   maze). */
#include "OptimumSupport.h"

#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "src/collision/GridCollision.h"
#include "src/optimum/Optimum.h"
#include "src/io/WorldIO.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace mhplan;
using namespace mhplan::test;

namespace
{
    World randomGrid(int index)
    {
        GeneratorOptions o;
        o.seed = 500 + static_cast<std::uint64_t>(index);
        o.width = 8 + index % 13;
        o.height = 8 + (index * 7) % 11;
        o.density = 0.15 + 0.01 * (index % 16);
        o.cellSize = index % 3 == 0 ? 0.5 : 1.0;
        return generateGrid(o);
    }

    /** Plain Dijkstra over the MovingAI 8-connected cell graph (independent of computeGridOctileOptimum). */
    double plainOctile(const OccupancyGrid &g, const Vec2 &s, const Vec2 &t)
    {
        const int W = g.width();
        std::vector<std::vector<std::pair<int, double>>> adj(static_cast<std::size_t>(W) * g.height());
        for (int y = 0; y < g.height(); ++y)
            for (int x = 0; x < W; ++x)
            {
                if (g.blocked(x, y))
                    continue;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                    {
                        if ((dx == 0 && dy == 0) || g.blocked(x + dx, y + dy))
                            continue;
                        if (dx != 0 && dy != 0 && (g.blocked(x + dx, y) || g.blocked(x, y + dy)))
                            continue;
                        adj[static_cast<std::size_t>(y) * W + x].emplace_back(
                            (y + dy) * W + x + dx, dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
                    }
            }
        return dijkstra(adj, g.cellY(s.y) * W + g.cellX(s.x), g.cellY(t.y) * W + g.cellX(t.x));
    }
} // namespace

TEST(OptimumRandom, GridWorlds)
{
    double worstGap = 0.0;
    for (int i = 0; i < 100; ++i)
    {
        const World w = randomGrid(i);
        const Query &q = w.queries.front();
        const OptimumResult r = computeOptimum(w, q);
        ASSERT_TRUE(r.found) << "grid " << i;
        EXPECT_EQ(r.method, "grid-any-angle");
        ASSERT_TRUE(polylineValid(w, r.path)) << "grid " << i;
        EXPECT_TRUE(optimumWitnessed(w, q, r)) << "grid " << i;
        const double brute = bruteVisibility(w, q, gridCornerPoints(*w.grid));
        ASSERT_NEAR(brute, r.length, 1e-9 * r.length) << "grid " << i;
        EXPECT_NEAR(r.lengthCells, r.length / w.grid->cellSize(), 1e-12);
        const double road =
            roadmapLength(w, q, 4 * std::max(w.grid->width(), w.grid->height()), 200, 2.6, 3 + i);
        if (std::isfinite(road))
        {
            ASSERT_GE(road, r.length * (1.0 - 1e-9)) << "grid " << i;
            worstGap = std::max(worstGap, road / r.length - 1.0);
        }
        const OptimumResult oct = computeGridOctileOptimum(w, q);
        ASSERT_TRUE(oct.found);
        EXPECT_NEAR(oct.lengthCells, plainOctile(*w.grid, q.start, q.goal), 1e-9) << "grid " << i;
        EXPECT_NEAR(oct.length, oct.lengthCells * w.grid->cellSize(), 1e-12);
        EXPECT_LE(r.length, oct.length + 1e-9);
    }
    std::cout << "[optimum] grids: roadmap / optimum - 1 at most " << worstGap << "\n";
}

// A dense roadmap bounds the optimum from above; from below, the optimum's own path, checked point by point
// against the blocked cells (optimumWitnessed, OptimumSupport.h), is valid and exactly as long as reported,
// so a too-short optimum fails.
TEST(OptimumRandom, GridWorldsDiscRobot)
{
    double worstGap = 0.0;
    int witnessed = 0;
    for (int i = 0; i < 100; ++i)
    {
        GeneratorOptions o;
        o.seed = 900 + static_cast<std::uint64_t>(i);
        o.width = 6 + i % 9;
        o.height = 6 + (i * 5) % 8;
        o.density = 0.15 + 0.01 * (i % 12);
        o.cellSize = i % 2 == 0 ? 1.0 : 0.5;
        // Up to half a cell: a free cell's centre is always valid.
        o.robotRadius = o.cellSize * (0.05 + 0.45 * ((i * 37) % 100) / 100.0);
        const World w = generateGrid(o);
        const Query &q = w.queries.front();
        const OptimumResult r = computeOptimum(w, q);
        const double road =
            roadmapLength(w, q, 4 * std::max(w.grid->width(), w.grid->height()), 200, 2.6, 11 + i);
        if (std::isfinite(road))
        {
            ASSERT_TRUE(r.found) << "grid " << i;
            ASSERT_GE(road, r.length * (1.0 - 1e-9)) << "grid " << i;
            worstGap = std::max(worstGap, road / r.length - 1.0);
        }
        if (!r.found)
            continue;
        EXPECT_EQ(r.method, "grid-tangent-graph");
        ASSERT_TRUE(polylineValid(w, r.path)) << "grid " << i;
        EXPECT_TRUE(optimumWitnessed(w, q, r)) << "grid " << i;
        ++witnessed;
        EXPECT_NEAR(r.lengthCells, r.length / w.grid->cellSize(), 1e-12);
    }
    std::cout << "[optimum] disc-robot grids: roadmap / optimum - 1 at most " << worstGap
              << "; witnessed by its own path " << witnessed << " of 100\n";
}

TEST(OptimumGrid, OctileSemantics)
{
    // 3 x 3 grid, centre blocked: corner to corner needs 4 straight moves (diagonals would cut the corner).
    auto g = std::make_shared<OccupancyGrid>(3, 3, 2.0);
    g->setBlocked(1, 1, true);
    World w;
    w.name = "tiny";
    w.grid = g;
    w.bounds = g->bounds();
    const Query q{"q", g->cellCenter(0, 0), g->cellCenter(2, 2)};
    const OptimumResult oct = computeGridOctileOptimum(w, q);
    ASSERT_TRUE(oct.found);
    EXPECT_NEAR(oct.lengthCells, 4.0, 1e-12);
    EXPECT_NEAR(oct.length, 8.0, 1e-12);
    EXPECT_EQ(oct.path.size(), 5u);
    // Any-angle: around one corner of the blocked centre cell: 2 * |(1,1) -> (4,2)| = 2 sqrt(10).
    const OptimumResult any = computeOptimum(w, q);
    ASSERT_TRUE(any.found);
    EXPECT_NEAR(any.length, 2.0 * std::sqrt(10.0), 1e-12);
    EXPECT_NEAR(any.lengthCells, std::sqrt(10.0), 1e-12);

    // A pinch: two diagonal blocked cells let nothing through their common corner.
    auto p = std::make_shared<OccupancyGrid>(2, 2, 1.0);
    p->setBlocked(0, 1, true);
    p->setBlocked(1, 0, true);
    World pw;
    pw.name = "pinch";
    pw.grid = p;
    pw.bounds = p->bounds();
    const Query pq{"q", p->cellCenter(0, 0), p->cellCenter(1, 1)};
    EXPECT_FALSE(computeOptimum(pw, pq).found);
    EXPECT_FALSE(computeGridOctileOptimum(pw, pq).found);
}

// ------------------------------------------------------------------------------------------------------
// Scale: the times are printed (not asserted: tests never depend on the machine's speed).

TEST(OptimumScale, ThousandCircles)
{
    GeneratorOptions o;
    o.seed = 42;
    o.count = 1000;
    o.bounds = {0.0, 100.0, 0.0, 100.0};
    o.minSize = 0.2;
    o.maxSize = 1.5;
    const World w = generateCircles(o);
    const OptimumResult r = computeOptimum(w, w.queries.front());
    ASSERT_TRUE(r.found);
    EXPECT_TRUE(polylineValid(w, r.path));
    EXPECT_TRUE(optimumWitnessed(w, w.queries.front(), r));
    EXPECT_GE(r.length, distance(w.queries.front().start, w.queries.front().goal));
    std::cout << "[optimum] 1000 circles: " << r.length << " in " << r.seconds << " s (" << r.graphNodes
              << " nodes, " << r.graphEdges << " edges)\n";
}

TEST(OptimumScale, Maze512)
{
    // A perfect maze by randomised depth-first search (255 x 255 maze cells = 511 x 511 grid cells), in a
    // 512 x 512 grid (the extra row and column blocked).
    GeneratorOptions o;
    o.seed = 7;
    o.width = o.height = 255;
    const World m = generateMaze(o);
    auto g = std::make_shared<OccupancyGrid>(512, 512, 1.0);
    for (int y = 0; y < 512; ++y)
        for (int x = 0; x < 512; ++x)
            g->setBlocked(x, y, m.grid->blocked(x, y));
    World w = m;
    w.grid = g;
    w.bounds = g->bounds();
    const Query &q = w.queries.front();
    const OptimumResult any = computeOptimum(w, q);
    const OptimumResult oct = computeGridOctileOptimum(w, q);
    ASSERT_TRUE(any.found);
    ASSERT_TRUE(oct.found);
    EXPECT_LE(any.length, oct.length);
    EXPECT_TRUE(polylineValid(w, any.path));
    EXPECT_TRUE(optimumWitnessed(w, q, any));
    std::cout << "[optimum] 512 x 512 maze: any-angle " << any.length << " in " << any.seconds << " s ("
              << any.graphNodes << " nodes, " << any.graphEdges << " edges); octile " << oct.lengthCells
              << " cells in " << oct.seconds << " s\n";
}
