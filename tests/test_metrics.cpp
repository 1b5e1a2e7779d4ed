// SPDX-License-Identifier: BSD-3-Clause
/* Path metrics (src/metrics/Metrics.h) against hand computations, and the registration list of the metrics a
   campaign stores (src/metrics/MetricList.h).

   The clearance world:            y
                                  10 +----------------------+
                                     |                      |
                                     |        ( o )         |  circle at (5, 5), radius 1
                                     |                      |  robot radius 0.5
                                   2 |  A ------------- B   |  A = (1, 2), B = (9, 2)
                                   0 +----------------------+ x
                                     0                     10                                      */
#include "src/collision/Collision.h"
#include "src/metrics/MetricList.h"
#include "src/metrics/Metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace mhplan;

namespace
{
    World circleWorld()
    {
        World w;
        w.name = "metrics";
        w.bounds = {0.0, 10.0, 0.0, 10.0};
        w.robotRadius = 0.5;
        w.circles.push_back({{5.0, 5.0}, 1.0});
        return w;
    }
} // namespace

TEST(Metrics, StraightPathHasNoTurning)
{
    // Collinear vertices and a duplicate point change nothing.
    const std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 0}, {3, 0}};
    EXPECT_DOUBLE_EQ(maxCurvature(p), 0.0);
    EXPECT_DOUBLE_EQ(angleOverLength(p), 0.0);
    EXPECT_EQ(cuspCount(p), 0u);
    EXPECT_DOUBLE_EQ(smoothness(p), 0.0);
    EXPECT_EQ(withoutDuplicates(p).size(), 3u);
}

TEST(Metrics, RightAngle)
{
    // One turn of 90 degrees between two unit segments.
    const std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 1}};
    EXPECT_NEAR(turningAngle(p[0], p[1], p[2]), kPi / 2, 1e-15);
    // Menger curvature of (0,0)-(1,0)-(1,1): circumradius sqrt(2)/2.
    EXPECT_NEAR(maxCurvature(p), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(angleOverLength(p), (kPi / 2) / 2.0, 1e-15);
    EXPECT_EQ(cuspCount(p), 1u); // 90 > 60 degrees
    // (2 theta / (a + b))^2 = (pi / 2)^2
    EXPECT_NEAR(smoothness(p), kPi * kPi / 4, 1e-12);
}

TEST(Metrics, UnequalSegmentsUseTheMeanLength)
{
    // Turn of 90 degrees between segments of length 1 and 3: Bench-MR rescales both neighbours to the mean
    // length 2, so the curvature is that of the isosceles right triangle with legs 2: sqrt(2) / 2.
    const std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 3}};
    EXPECT_NEAR(maxCurvature(p), std::sqrt(2.0) / 2.0, 1e-12);
    EXPECT_NEAR(smoothness(p), std::pow(2 * (kPi / 2) / 4.0, 2), 1e-12);
}

TEST(Metrics, ShallowTurnIsNoCuspAndReversalIs)
{
    const double a = 30.0 * kPi / 180.0;
    const std::vector<Vec2> shallow{{0, 0}, {1, 0}, {1 + std::cos(a), std::sin(a)}};
    EXPECT_EQ(cuspCount(shallow), 0u);
    EXPECT_NEAR(angleOverLength(shallow), a / 2.0, 1e-12);
    EXPECT_NEAR(maxCurvature(shallow), 2 * std::sin(a / 2), 1e-12);
    const std::vector<Vec2> reversal{{0, 0}, {2, 0}, {0, 0}};
    EXPECT_EQ(cuspCount(reversal), 1u);
    EXPECT_NEAR(maxCurvature(reversal), 2.0 / 2.0, 1e-12); // limit 2 / L with L = 2
    EXPECT_NEAR(angleOverLength(reversal), kPi / 4.0, 1e-12);
    // A 120 degree zig-zag has two cusps at the default threshold and none at 130 degrees.
    const std::vector<Vec2> zigzag{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}, {1.5, std::sqrt(3.0) / 2}};
    EXPECT_EQ(cuspCount(zigzag), 2u);
    EXPECT_EQ(cuspCount(zigzag, 130.0 * kPi / 180.0), 0u);
}

TEST(Metrics, DegenerateInputs)
{
    EXPECT_DOUBLE_EQ(maxCurvature({}), 0.0);
    EXPECT_DOUBLE_EQ(maxCurvature({{1, 1}, {2, 2}}), 0.0);
    EXPECT_TRUE(std::isnan(angleOverLength({{1, 1}, {1, 1}})));
    EXPECT_EQ(cuspCount({{1, 1}}), 0u);
    EXPECT_NEAR(optimalityGapPercent(11.0, 10.0), 10.0, 1e-12);
    EXPECT_TRUE(std::isnan(optimalityGapPercent(11.0, 0.0)));
    EXPECT_TRUE(std::isnan(optimalityGapPercent(11.0, std::numeric_limits<double>::infinity())));
}

TEST(Metrics, ResampleKeepsVerticesAndSpacing)
{
    const std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 0.25}};
    const std::vector<Vec2> r = resamplePath(p, 0.3);
    // 1 / 0.3 -> 4 pieces, 0.25 / 0.3 -> 1 piece: 1 + 4 + 1 points.
    ASSERT_EQ(r.size(), 6u);
    EXPECT_EQ(r[4], p[1]);
    EXPECT_EQ(r.back(), p[2]);
    for (std::size_t i = 1; i < r.size(); ++i)
        EXPECT_LE(distance(r[i - 1], r[i]), 0.3 + 1e-12);
    EXPECT_THROW(resamplePath(p, 0.0), std::invalid_argument);
}

TEST(Metrics, ClearanceAlongAPath)
{
    const World w = circleWorld();
    const CollisionModelPtr model = makeCollisionModel(w, CollisionBackend::Analytic);
    const std::vector<Vec2> path{{1, 2}, {9, 2}};
    const ClearanceStats c = clearanceStats(path, *model, 0.001);
    // Closest approach below the centre: 3 - 1 - 0.5.
    EXPECT_NEAR(c.min, 1.5, 1e-9);
    // Mean of sqrt((x - 5)^2 + 9) - 1.5 over x in [1, 9]: (20 + 9 ln 3) / 8 - 1.5.
    EXPECT_NEAR(c.mean, (20.0 + 9.0 * std::log(3.0)) / 8.0 - 1.5, 1e-6);
    EXPECT_TRUE(denseCollisionFree(path, *model, 0.01));
    // Grazing the inflated circle (clearance exactly 0) is allowed; crossing it is not.
    EXPECT_TRUE(denseCollisionFree({{1, 3.5}, {9, 3.5}}, *model, 0.01));
    EXPECT_FALSE(denseCollisionFree({{1, 4}, {9, 4}}, *model, 0.01));
    // Leaving the bounds (the robot disc must stay inside) is a collision too.
    EXPECT_FALSE(denseCollisionFree({{1, 2}, {9.8, 2}}, *model, 0.01));

    const PathMetrics m = computePathMetrics({{1, 2}, {5, 2}, {9, 2}}, *model, defaultMetricStep(w));
    EXPECT_NEAR(m.length, 8.0, 1e-12);
    EXPECT_TRUE(m.collisionFree);
    EXPECT_NEAR(m.minClearance, 1.5, 1e-9);
    EXPECT_EQ(m.cusps, 0u);
    EXPECT_DOUBLE_EQ(defaultMetricStep(w), std::min(std::hypot(10.0, 10.0) / 2000.0, 0.125));
}

TEST(MetricList, BuiltInMetricsUnderTheirDatabaseNames)
{
    // The run properties existing databases and the report read (benchmarks/README.md), in this order.
    const std::vector<std::string> expected{
        "path length REAL",       "collision free BOOLEAN", "min clearance REAL",
        "mean clearance REAL",    "smoothness REAL",        "max curvature REAL",
        "angle over length REAL", "cusps INTEGER",          "optimality gap REAL"};
    std::vector<std::string> names;
    for (const PathMetric &m : pathMetrics())
        names.push_back(m.property);
    ASSERT_GE(names.size(), expected.size());
    EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + static_cast<long>(expected.size())),
              expected);

    // A right-angle path of length 8 in the circle world, reported exact, optimum 7.5.
    const World w = circleWorld();
    const CollisionModelPtr model = makeCollisionModel(w, CollisionBackend::Analytic);
    const MetricPath p = planarMetricPath(w, {{1, 2}, {9, 2}, {9, 2}, {9, 9}}, *model, 0.01, true, 7.5);
    std::map<std::string, std::optional<double>> v;
    for (const auto &kv : evaluatePathMetrics(p))
        v[kv.first] = kv.second;
    EXPECT_NEAR(*v["path length REAL"], 15.0, 1e-12);
    EXPECT_EQ(*v["cusps INTEGER"], 1.0); // 90 > 60 degrees
    EXPECT_NEAR(*v["optimality gap REAL"], 100.0, 1e-12);
    EXPECT_EQ(*v["collision free BOOLEAN"], 1.0);
    // Not exact: no gap stored.
    const MetricPath approximate = planarMetricPath(w, {{1, 2}, {9, 2}}, *model, 0.01, false, 7.5);
    for (const auto &kv : evaluatePathMetrics(approximate))
        EXPECT_EQ(kv.second.has_value(), kv.first != "optimality gap REAL") << kv.first;
}

TEST(MetricList, ANewMetricIsOneFunctionAndOneRegistration)
{
    // docs/conventions.md, "Adding a metric": the function, its registration, and it is evaluated.
    registerPathMetric({"straight share REAL", [](const MetricPath &p)
                        { return distance(p.points.front(), p.points.back()) / p.length; }});
    const World w = circleWorld();
    const CollisionModelPtr model = makeCollisionModel(w, CollisionBackend::Analytic);
    const auto values =
        evaluatePathMetrics(planarMetricPath(w, {{0, 0}, {3, 0}, {3, 4}}, *model, 0.01, true, 5.0));
    ASSERT_EQ(values.back().first, "straight share REAL");
    EXPECT_NEAR(*values.back().second, 5.0 / 7.0, 1e-12);
    // Refused: a duplicate name (whatever its type), a malformed property, no function.
    EXPECT_THROW(registerPathMetric({"straight share INTEGER", [](const MetricPath &) { return 0.0; }}),
                 std::invalid_argument);
    EXPECT_THROW(registerPathMetric({"cusps REAL", [](const MetricPath &) { return 0.0; }}),
                 std::invalid_argument);
    EXPECT_THROW(registerPathMetric({"Bad-Name REAL", [](const MetricPath &) { return 0.0; }}),
                 std::invalid_argument);
    EXPECT_THROW(registerPathMetric({"no type", [](const MetricPath &) { return 0.0; }}),
                 std::invalid_argument);
    EXPECT_THROW(registerPathMetric({"empty REAL", nullptr}), std::invalid_argument);
    EXPECT_FALSE(unregisterPathMetric("cusps INTEGER")); // built-in metrics stay
    EXPECT_TRUE(unregisterPathMetric("straight share REAL"));
    EXPECT_EQ(pathMetrics().back().property, "optimality gap REAL");
}
