// SPDX-License-Identifier: BSD-3-Clause
/* The hot paths (validity, motion and clearance queries of every collision model) never touch the heap once
   warm: fitness and planner loops call them millions of times. Counted with a replaced global operator new.
 */
#include "mhplan/collision/Collision.h"
#include "mhplan/io/Generators.h"
#include "mhplan/io/WorldIO.h"

#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <random>

using namespace mhplan;

namespace
{
    /** Allocations during 2000 calls of each query: isValid, segmentValid, clearance, segmentClearance. */
    std::array<long, 4> allocationsDuring(const CollisionModel &model, const Box &b)
    {
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax);
        std::vector<Vec2> pts(2000);
        for (auto &p : pts)
            p = {ux(rng), uy(rng)};
        std::array<long, 4> out{};
        double sink = 0.0;
        // Pass 0 warms up (thread-local scratch buffers grow to their working size once); pass 1 counts.
        for (int q = 0; q < 8; ++q)
        {
            const long before = static_cast<long>(test::heapAllocations());
            for (std::size_t i = 0; i + 1 < pts.size(); ++i)
            {
                const Vec2 &a = pts[i];
                // Short segments, as planners check them (a tenth of the world's size at most).
                const Vec2 bb = a + (pts[i + 1] - a) * 0.1;
                switch (q % 4)
                {
                case 0:
                    sink += model.isValid(a) ? 1.0 : 0.0;
                    break;
                case 1:
                    sink += model.segmentValid(a, bb) ? 1.0 : 0.0;
                    break;
                case 2:
                    sink += model.clearance(a);
                    break;
                default:
                    sink += model.segmentClearance(a, bb);
                }
            }
            if (q >= 4)
                out[q - 4] = static_cast<long>(test::heapAllocations()) - before;
        }
        EXPECT_FALSE(std::isnan(sink));
        return out;
    }
} // namespace

TEST(Allocation, CollisionQueriesDoNotAllocate)
{
    const World circles = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case2.yaml");
    GeneratorOptions o;
    o.count = 40;
    o.seed = 5;
    const World rects = generateRectangles(o); // convex polygons
    const World grid = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid20.yaml");
    o.count = 500;
    const World many = generateCircles(o);
    const std::array<long, 4> none{0, 0, 0, 0};
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(circles, CollisionBackend::Analytic), circles.bounds),
              none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::Analytic), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::FCL), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(many, CollisionBackend::FCL), many.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(many, CollisionBackend::Hash), many.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(rects, CollisionBackend::Hash), rects.bounds), none);
    EXPECT_EQ(allocationsDuring(*makeCollisionModel(grid, CollisionBackend::Grid), grid.bounds), none);
}
