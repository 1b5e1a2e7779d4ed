// SPDX-License-Identifier: BSD-3-Clause
/* Closed-form geometry against hand computations (the drawings are y-up). */
#include "src/base/Geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace mhplan;

namespace
{
    //  (0,2) +-----+ (2,2)
    //        |     |
    //  (0,0) +-----+ (2,0)
    const std::vector<Vec2> kSquare = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    //  U shape, opening upwards:
    //  (0,3) +--+     +--+ (3,3)
    //        |  |     |  |
    //        |  +-----+  |   inner floor at y = 1, walls 1 thick
    //  (0,0) +-----------+ (3,0)
    const std::vector<Vec2> kU = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
} // namespace

TEST(Geometry, PointSegmentDistance)
{
    EXPECT_DOUBLE_EQ(pointSegmentDistance({0, 1}, {-1, 0}, {1, 0}), 1.0);
    EXPECT_DOUBLE_EQ(pointSegmentDistance({3, 4}, {0, 0}, {0, 0}), 5.0);
    EXPECT_DOUBLE_EQ(pointSegmentDistance({2, 1}, {-1, 0}, {1, 0}), std::sqrt(2.0));
}

TEST(Geometry, SegmentIntersection)
{
    EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_TRUE(segmentsCrossProperly({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_TRUE(segmentsIntersect({0, 0}, {1, 1}, {1, 1}, {2, 0})); // touching at an end
    EXPECT_FALSE(segmentsCrossProperly({0, 0}, {1, 1}, {1, 1}, {2, 0}));
    EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));  // collinear overlap
    EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {2, 0}, {3, 0})); // collinear, apart
    EXPECT_DOUBLE_EQ(segmentSegmentDistance({0, 0}, {1, 0}, {2, 0}, {3, 0}), 1.0);
    EXPECT_DOUBLE_EQ(segmentSegmentDistance({0, 0}, {2, 0}, {1, 1}, {1, 3}), 1.0);
}

TEST(Geometry, PolygonPredicates)
{
    EXPECT_TRUE(polygonIsSimple(kSquare));
    EXPECT_TRUE(polygonIsConvex(kSquare));
    EXPECT_TRUE(polygonIsSimple(kU));
    EXPECT_FALSE(polygonIsConvex(kU));
    EXPECT_FALSE(polygonIsSimple({{0, 0}, {2, 2}, {2, 0}, {0, 2}})); // bow tie
    EXPECT_FALSE(polygonIsSimple({{0, 0}, {1, 0}, {1, 0}, {0, 1}})); // repeated vertex
    EXPECT_FALSE(polygonIsSimple({{0, 0}, {1, 0}, {2, 0}}));         // zero area
    EXPECT_FALSE(polygonIsSimple({{0, 0}, {2, 0}, {1, 0}, {1, 1}})); // edge folds back
    EXPECT_DOUBLE_EQ(signedArea2(kSquare), 8.0);
    EXPECT_TRUE(pointInPolygon({1, 1}, kSquare));
    EXPECT_TRUE(pointInPolygon({2, 1}, kSquare)); // boundary counts
    EXPECT_FALSE(pointInPolygon({1.5, 2}, kU));   // in the U's notch... on its top edge? no: notch is open
    EXPECT_FALSE(pointInPolygon({1.5, 2.5}, kU));
    EXPECT_TRUE(pointInPolygon({0.5, 2.5}, kU));
}

TEST(Geometry, SignedDistanceToPolygon)
{
    EXPECT_DOUBLE_EQ(pointPolygonSignedDistance({3, 1}, kSquare), 1.0);
    EXPECT_DOUBLE_EQ(pointPolygonSignedDistance({3, 3}, kSquare), std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(pointPolygonSignedDistance({1, 1}, kSquare), -1.0);
    EXPECT_DOUBLE_EQ(pointPolygonSignedDistance({0.5, 1}, kSquare), -0.5);
    EXPECT_DOUBLE_EQ(pointPolygonSignedDistance({1.5, 2}, kU), 0.5); // in the notch, 0.5 from both walls
}

TEST(Geometry, SegmentAgainstPolygon)
{
    EXPECT_DOUBLE_EQ(segmentPolygonDistance({-1, 3}, {3, 3}, kSquare), 1.0);
    EXPECT_DOUBLE_EQ(segmentPolygonDistance({-1, 1}, {3, 1}, kSquare), 0.0);
    EXPECT_DOUBLE_EQ(segmentPolygonDistance({0.5, 0.5}, {1, 1}, kSquare), 0.0); // fully inside
    // Running along an edge or touching a corner does not enter the interior; crossing does.
    EXPECT_FALSE(segmentEntersPolygonInterior({-1, 0}, {3, 0}, kSquare));
    EXPECT_FALSE(segmentEntersPolygonInterior({-1, 1}, {1, 3}, kSquare)); // touches corner (0,2)
    EXPECT_FALSE(segmentEntersPolygonInterior({0, 0}, {0, 2}, kSquare));
    EXPECT_TRUE(segmentEntersPolygonInterior({-1, 1}, {3, 1}, kSquare));
    EXPECT_TRUE(segmentEntersPolygonInterior({0, 0}, {2, 2}, kSquare));     // the diagonal, corner to corner
    EXPECT_TRUE(segmentEntersPolygonInterior({1, 1}, {1.2, 1.2}, kSquare)); // inside, no crossing
    // Through the U's notch from above: touches the notch floor only.
    EXPECT_FALSE(segmentEntersPolygonInterior({1.5, 4}, {1.5, 1}, kU));
    EXPECT_TRUE(segmentEntersPolygonInterior({1.5, 4}, {1.5, 0.5}, kU));
    // Across the notch along y = 3 (the top of both arms): touching only.
    EXPECT_FALSE(segmentEntersPolygonInterior({-1, 3}, {4, 3}, kU));
    EXPECT_TRUE(segmentEntersPolygonInterior({-1, 2.5}, {4, 2.5}, kU));
}

TEST(Geometry, DeepestPenetrationAlongASegment)
{
    // Through the square's centre: depth 1 at (1,1).
    EXPECT_NEAR(deepestSegmentPenetration({-1, 1}, {3, 1}, kSquare), -1.0, 1e-12);
    EXPECT_NEAR(deepestSegmentPenetration({-1, 0.5}, {3, 0.5}, kSquare), -0.5, 1e-12);
    EXPECT_NEAR(deepestSegmentPenetration({-1, 4}, {3, 4}, kSquare), 2.0, 1e-12);
    // Against dense sampling on random segments (convex: exact; U: an upper bound close to the truth).
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 4.0);
    for (int i = 0; i < 2000; ++i)
    {
        const Vec2 a{u(rng), u(rng)}, b{u(rng), u(rng)};
        for (const auto *poly : {&kSquare, &kU})
        {
            double sampled = std::numeric_limits<double>::infinity();
            for (int k = 0; k <= 2000; ++k)
                sampled = std::min(sampled, pointPolygonSignedDistance(a + (b - a) * (k / 2000.0), *poly));
            const double exact = deepestSegmentPenetration(a, b, *poly);
            const double len = distance(a, b);
            // sampled is within len/4000 above the true minimum (the signed distance is 1-Lipschitz).
            EXPECT_GE(exact, std::min(sampled, segmentPolygonDistance(a, b, *poly)) - len / 4000.0 - 1e-12);
            if (poly == &kSquare)
                EXPECT_LE(exact, sampled + 1e-12) << "segment " << i;
            else
                EXPECT_LE(exact, sampled + len / 128.0) << "segment " << i;
        }
    }
}

TEST(Geometry, RectangleCorners)
{
    const auto c = rectangleCorners({1, 1}, 2, 4, 0.0);
    EXPECT_EQ(c[0], Vec2(0, -1));
    EXPECT_EQ(c[2], Vec2(2, 3));
    const auto r = rectangleCorners({0, 0}, 2, 2, std::atan(1.0)); // 45 degrees: a diamond
    EXPECT_NEAR(r[0].x, 0.0, 1e-12);
    EXPECT_NEAR(r[0].y, -std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(std::abs(signedArea2(r)), 8.0, 1e-12);
}

namespace
{
    /** \brief The definition of a simple polygon, checked over all pairs of edges: no repeated vertex, no two
        non-adjacent edges meet, adjacent edges do not fold back, non-zero area. The oracle for the
        O(n log n) sweep behind polygonIsSimple (which uses it only below 17 vertices). */
    bool simpleByAllPairs(const std::vector<mhplan::Vec2> &p)
    {
        using mhplan::Vec2;
        const std::size_t n = p.size();
        if (n < 3)
            return false;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (p[i] == p[j])
                    return false;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
            {
                const Vec2 &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
                if (j == i + 1 || (i == 0 && j == n - 1))
                {
                    const Vec2 &s = j == i + 1 ? b : a;
                    const Vec2 &u = j == i + 1 ? a : b;
                    const Vec2 &v = j == i + 1 ? d : c;
                    if (mhplan::cross(u - s, v - s) == 0.0 && mhplan::dot(u - s, v - s) > 0.0)
                        return false;
                }
                else if (mhplan::segmentsIntersect(a, b, c, d))
                    return false;
            }
        return std::abs(mhplan::signedArea2(p)) > 0.0;
    }

    std::vector<mhplan::Vec2> starPolygon(std::mt19937 &rng, std::size_t n, double rmin, double rmax)
    {
        std::uniform_real_distribution<double> radius(rmin, rmax);
        std::vector<mhplan::Vec2> p;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = radius(rng);
            p.push_back({r * std::cos(t), r * std::sin(t)});
        }
        return p;
    }
} // namespace

// Issue 19: the simplicity check is an O(n log n) sweep; it gives the all-pairs answer on polygons that are
// simple, that cross, and that touch exactly (integer grids: collinear edges, vertices on edges, verticals).
TEST(Geometry, PolygonSimplicitySweepAgreesWithAllPairs)
{
    std::mt19937 rng(20261201);
    int simple = 0, notSimple = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const std::size_t n = 17 + static_cast<std::size_t>(trial % 40);
        std::vector<mhplan::Vec2> p;
        switch (trial % 4)
        {
        case 0: // star-shaped: simple
            p = starPolygon(rng, n, 0.5, 1.0);
            break;
        case 1: // star-shaped with one vertex thrown far: usually crosses
        {
            p = starPolygon(rng, n, 0.5, 1.0);
            std::uniform_real_distribution<double> u(-2.0, 2.0);
            p[static_cast<std::size_t>(trial) % n] = {u(rng), u(rng)};
            break;
        }
        case 2: // vertices on a small integer grid: exact touching, collinearity, vertical edges
        {
            std::uniform_int_distribution<int> c(0, 6);
            for (std::size_t i = 0; i < n; ++i)
                p.push_back({static_cast<double>(c(rng)), static_cast<double>(c(rng))});
            break;
        }
        default: // rectilinear star on a grid: simple or touching at exactly representable points
        {
            std::uniform_int_distribution<int> r(2, 4);
            for (std::size_t i = 0; i < n; ++i)
            {
                const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
                p.push_back({std::round(r(rng) * std::cos(t) * 2.0), std::round(r(rng) * std::sin(t) * 2.0)});
            }
            break;
        }
        }
        const bool expected = simpleByAllPairs(p);
        ASSERT_EQ(mhplan::polygonIsSimple(p), expected) << "trial " << trial;
        (expected ? simple : notSimple) += 1;
    }
    // Both answers occur often enough for the comparison to mean something.
    EXPECT_GT(simple, 700);
    EXPECT_GT(notSimple, 700);
}

// Issue 19: a 20,000-vertex polygon is checked (the sweep; the all-pairs test took 5 s); one vertex moved
// across the polygon makes it non-simple.
TEST(Geometry, LargePolygonSimplicity)
{
    std::mt19937 rng(7);
    std::vector<mhplan::Vec2> p = starPolygon(rng, 20000, 0.9, 1.0);
    EXPECT_TRUE(mhplan::polygonIsSimple(p));
    p[5000] = {0.0, -1.5}; // outside the bottom of the polygon: both new edges cross it
    EXPECT_FALSE(mhplan::polygonIsSimple(p));
}
