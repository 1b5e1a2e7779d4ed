// SPDX-License-Identifier: BSD-3-Clause
/* Closed-form geometry against hand computations (the drawings are y-up). */
#include "mhplan/base/Geometry.h"

#include <gtest/gtest.h>

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
