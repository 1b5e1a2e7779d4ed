// SPDX-License-Identifier: BSD-3-Clause
/* The spatial hash collision model gives exactly the analytic oracle's answers (isValid, clearance,
   segmentValid, segmentClearance compared with ==, not within a tolerance) on random worlds of circles,
   rotated rectangles, convex and non-convex polygons and mixtures, 10 to 3000 obstacles, point and disc
   robots, for random points (inside and outside the bounds), points on obstacle boundaries and vertices,
   short and long random segments and segments along polygon edges; it is chosen automatically above
   kAutoAnalyticMaxObstacles geometric obstacles. */
#include "src/collision/Collision.h"
#include "src/collision/SpatialHash.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace mhplan;

namespace
{

    double uniform(std::mt19937_64 &rng, double lo, double hi)
    {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    }

    /** A world of \e n obstacles of the given kind ("circles", "rectangles", "convex", "nonconvex",
        "mixed") in a square whose side grows with sqrt(n) (about a fifth covered, overlaps allowed). */
    World randomWorld(const std::string &kind, int n, double robotRadius, std::uint64_t seed)
    {
        std::mt19937_64 rng(seed);
        World w;
        w.name = kind + std::to_string(n);
        const double side = 4.0 * std::sqrt(static_cast<double>(std::max(n, 4)));
        w.bounds = {0.0, side, 0.0, side * 0.8};
        w.robotRadius = robotRadius;
        for (int i = 0; i < n; ++i)
        {
            // A few large obstacles among many small ones exercise buckets shared by many obstacles.
            const double scale = (i % 17 == 0) ? 3.0 : 1.0;
            const Vec2 c{uniform(rng, -1.0, side + 1.0), uniform(rng, -1.0, side * 0.8 + 1.0)};
            std::string k = kind;
            if (kind == "mixed")
                k = (i % 4 == 0)   ? "circles"
                    : (i % 4 == 1) ? "rectangles"
                    : (i % 4 == 2) ? "convex"
                                   : "nonconvex";
            if (k == "circles")
                w.circles.push_back({c, scale * uniform(rng, 0.2, 1.2)});
            else if (k == "rectangles")
                w.polygons.push_back(
                    makePolygon(rectangleCorners(c, scale * uniform(rng, 0.3, 2.0),
                                                 scale * uniform(rng, 0.3, 2.0), uniform(rng, 0.0, kPi)),
                                "rectangle"));
            else if (k == "convex")
            {
                std::vector<Vec2> v;
                const int m = 3 + static_cast<int>(rng() % 5);
                const double r = scale * uniform(rng, 0.3, 1.2);
                const double phase = uniform(rng, 0.0, 2.0 * kPi);
                for (int j = 0; j < m; ++j)
                {
                    const double a = phase + 2.0 * kPi * j / m;
                    v.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
                }
                w.polygons.push_back(makePolygon(v));
            }
            else
            {
                // A star (non-convex, simple): alternating outer and inner radii.
                std::vector<Vec2> v;
                const int m = 4 + static_cast<int>(rng() % 4);
                const double r = scale * uniform(rng, 0.5, 1.5);
                for (int j = 0; j < 2 * m; ++j)
                {
                    const double a = kPi * j / m;
                    const double rr = (j % 2 == 0) ? r : 0.4 * r;
                    v.push_back({c.x + rr * std::cos(a), c.y + rr * std::sin(a)});
                }
                w.polygons.push_back(makePolygon(v));
            }
        }
        w.queries.push_back({"default", {0.0, 0.0}, {side, side * 0.8}});
        return w;
    }

    /** Query points: uniform (with a margin outside the bounds), on circle boundaries, polygon vertices
        and edge midpoints. */
    std::vector<Vec2> queryPoints(const World &w, std::mt19937_64 &rng, int n)
    {
        std::vector<Vec2> pts;
        const Box &b = w.bounds;
        for (int i = 0; i < n; ++i)
            pts.push_back(
                {uniform(rng, b.xmin - 1.0, b.xmax + 1.0), uniform(rng, b.ymin - 1.0, b.ymax + 1.0)});
        for (std::size_t i = 0; i < w.circles.size(); i += 1 + w.circles.size() / 150)
        {
            const double a = uniform(rng, 0.0, 2.0 * kPi);
            const double r = w.circles[i].radius + w.robotRadius;
            pts.push_back({w.circles[i].center.x + r * std::cos(a), w.circles[i].center.y + r * std::sin(a)});
        }
        for (std::size_t i = 0; i < w.polygons.size(); i += 1 + w.polygons.size() / 150)
        {
            const auto &v = w.polygons[i].vertices;
            pts.push_back(v[0]);
            pts.push_back((v[0] + v[1]) * 0.5);
        }
        return pts;
    }

    /** Segments: short random ones, long ones across the world, and along polygon edges (touching). */
    std::vector<std::pair<Vec2, Vec2>> querySegments(const World &w, std::mt19937_64 &rng, int n)
    {
        std::vector<std::pair<Vec2, Vec2>> segs;
        const Box &b = w.bounds;
        for (int i = 0; i < n; ++i)
        {
            const Vec2 a{uniform(rng, b.xmin, b.xmax), uniform(rng, b.ymin, b.ymax)};
            if (i % 5 == 0)
                segs.emplace_back(a, Vec2{uniform(rng, b.xmin, b.xmax), uniform(rng, b.ymin, b.ymax)});
            else if (i % 5 == 1) // axis-parallel and vertical ones walk a single column or row
                segs.emplace_back(a, Vec2{a.x, uniform(rng, b.ymin, b.ymax)});
            else
            {
                const double l = uniform(rng, 0.0, 3.0), t = uniform(rng, 0.0, 2.0 * kPi);
                segs.emplace_back(a, a + Vec2{l * std::cos(t), l * std::sin(t)});
            }
        }
        for (std::size_t i = 0; i < w.polygons.size(); i += 1 + w.polygons.size() / 100)
        {
            const auto &v = w.polygons[i].vertices;
            segs.emplace_back(v[0], v[1]);
            segs.emplace_back(v[0] + (v[0] - v[1]) * 0.5, v[1] + (v[1] - v[0]) * 0.5);
        }
        return segs;
    }
} // namespace

class SpatialHashVsAnalytic : public ::testing::TestWithParam<std::tuple<std::string, int, double>>
{
};

TEST_P(SpatialHashVsAnalytic, EveryQueryEqualsTheOracle)
{
    const auto &[kind, n, radius] = GetParam();
    const World w = randomWorld(kind, n, radius, 1000u + static_cast<unsigned>(n));
    const AnalyticCollisionModel oracle(w);
    const SpatialHashCollisionModel hash(w);
    ASSERT_GE(hash.columns() * hash.rows(), n >= 100 ? 16 : 1) << "a useful number of buckets";
    std::mt19937_64 rng(17);
    // The oracle costs O(n) per query: fewer queries on the large worlds (still thousands of buckets).
    const int count = n >= 3000 ? 300 : n >= 300 ? 1000 : 4000;
    int mismatches = 0, valid = 0, points = 0;
    for (const Vec2 &p : queryPoints(w, rng, count))
    {
        ++points;
        const bool v = oracle.isValid(p);
        valid += v ? 1 : 0;
        if (v != hash.isValid(p) && ++mismatches < 5)
            ADD_FAILURE() << kind << n << ": isValid differs at (" << p.x << ", " << p.y << ")";
        if (oracle.clearance(p) != hash.clearance(p) && ++mismatches < 5)
            ADD_FAILURE() << kind << n << ": clearance at (" << p.x << ", " << p.y << ") "
                          << oracle.clearance(p) << " vs " << hash.clearance(p);
    }
    int validSegs = 0, segs = 0;
    for (const auto &[a, b] : querySegments(w, rng, count))
    {
        ++segs;
        const bool v = oracle.segmentValid(a, b);
        validSegs += v ? 1 : 0;
        if (v != hash.segmentValid(a, b) && ++mismatches < 5)
            ADD_FAILURE() << kind << n << ": segmentValid differs for (" << a.x << ", " << a.y << ") - ("
                          << b.x << ", " << b.y << ")";
        if (oracle.segmentClearance(a, b) != hash.segmentClearance(a, b) && ++mismatches < 5)
            ADD_FAILURE() << kind << n << ": segmentClearance differs " << oracle.segmentClearance(a, b)
                          << " vs " << hash.segmentClearance(a, b);
    }
    EXPECT_EQ(mismatches, 0);
    // Both answers occur: the comparison is not vacuous.
    EXPECT_GT(valid, points / 20);
    EXPECT_LT(valid, points - points / 20);
    EXPECT_GT(validSegs, segs / 50);
    EXPECT_LT(validSegs, segs - segs / 50);
}

INSTANTIATE_TEST_SUITE_P(Worlds, SpatialHashVsAnalytic,
                         ::testing::Combine(::testing::Values("circles", "rectangles", "convex", "nonconvex",
                                                              "mixed"),
                                            ::testing::Values(10, 300, 3000), ::testing::Values(0.0, 0.35)),
                         [](const auto &info)
                         {
                             return std::get<0>(info.param) + std::to_string(std::get<1>(info.param)) +
                                    (std::get<2>(info.param) > 0.0 ? "_disc" : "_point");
                         });

TEST(SpatialHash, EmptyWorldAndAutoSelection)
{
    World w = randomWorld("circles", 0, 0.2, 1);
    const SpatialHashCollisionModel empty(w);
    EXPECT_TRUE(std::isinf(empty.clearance({1.0, 1.0})));
    EXPECT_TRUE(empty.isValid({1.0, 0.5}));
    EXPECT_FALSE(empty.isValid({0.1, 0.5})) << "the disc must stay inside the bounds";
    w = randomWorld("circles", static_cast<int>(kAutoAnalyticMaxObstacles) + 1, 0.0, 2);
    EXPECT_EQ(makeCollisionModel(w)->name(), "hash");
    EXPECT_EQ(makeCollisionModel(w, parseCollisionBackend("hash"))->name(), "hash");
    w.circles.resize(kAutoAnalyticMaxObstacles);
    EXPECT_EQ(makeCollisionModel(w)->name(), "analytic");
    World g = w;
    g.grid = std::make_shared<OccupancyGrid>(4, 4, 1.0);
    EXPECT_THROW(SpatialHashCollisionModel{g}, InputError);
}
