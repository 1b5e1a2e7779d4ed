// SPDX-License-Identifier: BSD-3-Clause
/* Tests of the exact optimum on geometric worlds: closed forms, the shipped seed worlds, random worlds
   against a dense roadmap (for point robots among polygons against a brute-force visibility graph too),
   witnessed from below by their own paths, and circle worlds between their inscribed and circumscribed
   polygons. Grids and scale: test_optimum_grid.cpp. */
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

// ------------------------------------------------------------------------------------------------------
// Closed forms.

TEST(Optimum, StraightLineWhenFree)
{
    World w = box10();
    const OptimumResult r = computeOptimum(w, query({1, 2}, {8, 6}));
    ASSERT_TRUE(r.found);
    EXPECT_NEAR(r.length, std::hypot(7.0, 4.0), 1e-12);
    EXPECT_EQ(r.method, "tangent-graph");
    ASSERT_EQ(r.path.size(), 2u);
}

/*   One disc between start and goal:   S ----\__(  c  )__/---- G
     L = 2 sqrt(d^2 - R^2) + R (pi - 2 acos(R / d)), d = |S - c| = |G - c|. */
TEST(Optimum, OneDiscClosedForm)
{
    for (double robot : {0.0, 0.3})
    {
        World w = box10(robot);
        w.circles.push_back({{5.0, 5.0}, 1.7});
        const OptimumResult r = computeOptimum(w, query({1, 5}, {9, 5}));
        ASSERT_TRUE(r.found);
        const double R = 1.7 + robot;
        const double d = 4.0;
        const double expected = 2.0 * std::sqrt(d * d - R * R) + R * (kPi - 2.0 * std::acos(R / d));
        EXPECT_NEAR(r.length, expected, 1e-9) << "robot radius " << robot;
        double sum = 0.0;
        int arcs = 0;
        for (const auto &p : r.pieces)
        {
            sum += p.length;
            arcs += p.arc && p.sweep != 0.0 ? 1 : 0;
        }
        EXPECT_NEAR(sum, r.length, 1e-12);
        EXPECT_EQ(arcs, 1);
        EXPECT_TRUE(polylineValid(w, r.path));
        // The polyline is a close, slightly longer approximation.
        EXPECT_GE(polyline(r.path), r.length - 1e-9);
        EXPECT_LE(polyline(r.path), r.length + 1e-4);
    }
}

/* Two overlapping discs (centres 2 apart, radii 1.5): the path may not pass through the lens; it runs over
   both: tangent, arc, the common outer tangent (length 2), arc, tangent. */
TEST(Optimum, TwoOverlappingDiscs)
{
    World w = box10();
    w.circles.push_back({{4.0, 5.0}, 1.5});
    w.circles.push_back({{6.0, 5.0}, 1.5});
    const OptimumResult r = computeOptimum(w, query({0.5, 5}, {9.5, 5}));
    ASSERT_TRUE(r.found);
    const double R = 1.5;
    const double d = 3.5;
    const double expected = 2.0 * std::sqrt(d * d - R * R) + 2.0 * R * (kPi / 2 - std::acos(R / d)) + 2.0;
    EXPECT_NEAR(r.length, expected, 1e-9);
    EXPECT_TRUE(polylineValid(w, r.path));
}

/* A triangle with its only reachable convex corner at (6, 5); start (2, 2), goal (2, 8).
   r = 0: S -> (6,5) -> G, 5 + 5. r = 0.5: the corner is a disc of radius 0.5: two tangents and an arc. */
TEST(Optimum, PolygonCorner)
{
    for (double robot : {0.0, 0.5})
    {
        World w = box10(robot);
        w.polygons.push_back(makePolygon({{-1, 4}, {6, 5}, {-1, 6}}));
        const OptimumResult r = computeOptimum(w, query({2, 2}, {2, 8}));
        ASSERT_TRUE(r.found);
        double expected = 10.0;
        if (robot > 0.0)
        {
            const double d = 5.0;
            const double beta = std::acos(robot / d);
            const double as = std::atan2(-3.0, -4.0);
            const double ag = std::atan2(3.0, -4.0);
            const double sweep = (ag - beta) - (as + beta);
            expected = 2.0 * std::sqrt(d * d - robot * robot) + robot * sweep;
        }
        EXPECT_NEAR(r.length, expected, 1e-9) << "robot radius " << robot;
        EXPECT_TRUE(polylineValid(w, r.path));
    }
}

/* A point robot around a non-convex polygon (a U open to the left) whose reflex corners must be ignored
   and whose edges still block: S inside the U, G outside on the right. */
TEST(Optimum, NonConvexPolygon)
{
    World w = box10();
    w.polygons.push_back(makePolygon({{2, 2}, {8, 2}, {8, 8}, {2, 8}, {2, 7}, {7, 7}, {7, 3}, {2, 3}}));
    const OptimumResult r = computeOptimum(w, query({5, 5}, {9, 5}));
    ASSERT_TRUE(r.found);
    // Out through the opening at x = 2 (corner (2, 7) or (2, 3)), around (8, 8) or (8, 2).
    const double expected = std::sqrt(13.0) + 1.0 + 6.0 + std::sqrt(10.0);
    EXPECT_NEAR(r.length, expected, 1e-9);
    EXPECT_TRUE(polylineValid(w, r.path));
}

/* The box: start on the boundary, and a disc that crosses the lower wall: the path must go over it. */
TEST(Optimum, BoxBoundary)
{
    World w = box10();
    w.circles.push_back({{5.0, 0.0}, 2.0});
    const OptimumResult r = computeOptimum(w, query({0, 0}, {10, 0}));
    ASSERT_TRUE(r.found);
    const double expected = 2.0 * std::sqrt(21.0) + 2.0 * (kPi - 2.0 * std::acos(0.4));
    EXPECT_NEAR(r.length, expected, 1e-9);
    EXPECT_TRUE(polylineValid(w, r.path));

    // Start and goal on the wall with a free straight line along it.
    World free = box10();
    free.circles.push_back({{5.0, 5.0}, 1.0});
    const OptimumResult along = computeOptimum(free, query({0, 0}, {10, 0}));
    EXPECT_NEAR(along.length, 10.0, 1e-12);
    EXPECT_TRUE(polylineValid(free, along.path));

    // A disc touching all four walls: passage only by touching the walls; the arc runs through the contact
    // points (0, 5) and (5, 10).
    World big = box10();
    big.circles.push_back({{5.0, 5.0}, 5.0});
    const OptimumResult r2 = computeOptimum(big, query({0.5, 0.5}, {9.5, 9.5}));
    ASSERT_TRUE(r2.found);
    const double d = 4.5 * std::sqrt(2.0);
    const double beta = std::acos(5.0 / d);
    EXPECT_NEAR(r2.length, 2.0 * std::sqrt(d * d - 25.0) + 5.0 * (kPi - 2.0 * beta), 1e-9);
    EXPECT_TRUE(polylineValid(big, r2.path));

    // With a robot disc, a wall-crossing disc closes the passage entirely.
    World closed = box10(0.5);
    closed.circles.push_back({{5.0, 5.0}, 4.6});
    const OptimumResult none = computeOptimum(closed, query({1, 1}, {9, 9}));
    EXPECT_FALSE(none.found);
    EXPECT_TRUE(std::isinf(none.length));
}

/* Touching is allowed: two discs that touch at (4, 5) let a point robot pass straight through the contact
   point; a start on a circle and a start on a polygon corner need no special casing. */
TEST(Optimum, TouchingContacts)
{
    World w = box10();
    w.circles.push_back({{3.0, 5.0}, 1.0});
    w.circles.push_back({{5.0, 5.0}, 1.0});
    const OptimumResult r = computeOptimum(w, query({4, 2}, {4, 8}));
    ASSERT_TRUE(r.found);
    EXPECT_NEAR(r.length, 6.0, 1e-12);
    EXPECT_TRUE(polylineValid(w, r.path));

    // Start on the first circle (at its leftmost point), goal behind it: the path hugs the circle.
    const OptimumResult onCircle = computeOptimum(w, query({2, 5}, {3, 3}));
    ASSERT_TRUE(onCircle.found);
    // From (2,5) along the circle (centre (3,5), radius 1) to the tangent point of the goal (3,3)
    // (d = 2, beta = acos(1/2) = pi/3): the tangent point at angle -pi/2 - pi/3 = 7 pi/6, so an arc of pi/6
    // from angle pi, then the tangent of length sqrt(3).
    EXPECT_NEAR(onCircle.length, kPi / 6.0 + std::sqrt(3.0), 1e-9);
    EXPECT_TRUE(polylineValid(w, onCircle.path));

    World p = box10();
    p.polygons.push_back(makePolygon({{4, 4}, {6, 4}, {6, 6}, {4, 6}}));
    const OptimumResult fromCorner = computeOptimum(p, query({4, 4}, {6, 6.5}));
    ASSERT_TRUE(fromCorner.found);
    EXPECT_NEAR(fromCorner.length, 2.0 + std::hypot(2.0, 0.5), 1e-12);
    EXPECT_TRUE(polylineValid(p, fromCorner.path));
}

/* The lower-side oracle rejects a too-short optimum: a disc robot (r = 0.3) around a square, the correct
   optimum witnessed by its own path, then three corruptions of it: the length alone shortened by 1e-6
   relative, the length and every piece's length shortened alike, and the straight line through the square
   reported with its own length. */
TEST(Optimum, WitnessRejectsATooShortOptimum)
{
    World w = box10(0.3);
    w.polygons.push_back(makePolygon({{4, 4}, {6, 4}, {6, 6}, {4, 6}}));
    const Query q = query({1, 5}, {9, 5.5});
    const OptimumResult r = computeOptimum(w, q);
    ASSERT_TRUE(r.found);
    EXPECT_TRUE(optimumWitnessed(w, q, r));

    OptimumResult shorter = r;
    shorter.length *= 1.0 - 1e-6;
    EXPECT_FALSE(optimumWitnessed(w, q, shorter));

    OptimumResult consistent = r;
    consistent.length = 0.0;
    for (auto &p : consistent.pieces)
    {
        p.length *= 1.0 - 1e-6;
        consistent.length += p.length;
    }
    EXPECT_FALSE(optimumWitnessed(w, q, consistent));

    OptimumResult through = r;
    through.pieces.assign(1, OptimumPiece());
    through.pieces.front().from = q.start;
    through.pieces.front().to = q.goal;
    through.pieces.front().length = distance(q.start, q.goal);
    through.length = through.pieces.front().length;
    through.path = {q.start, q.goal};
    EXPECT_FALSE(optimumWitnessed(w, q, through));
}

TEST(Optimum, InvalidInputs)
{
    World w = box10();
    w.circles.push_back({{5.0, 5.0}, 1.0});
    EXPECT_THROW(computeOptimum(w, query({5, 5}, {9, 9})), InputError);
    EXPECT_THROW(computeOptimum(w, query({1, 1}, {11, 9})), InputError);
    OptimumOptions bad;
    bad.arcDeviation = 0.0;
    EXPECT_THROW(computeOptimum(w, query({1, 1}, {9, 9}), bad), std::invalid_argument);
    EXPECT_THROW(computeGridOctileOptimum(w, query({1, 1}, {9, 9})), InputError);
    // A disc robot on a grid with too many convex corners for the all-pairs tangent graph.
    GeneratorOptions o;
    o.seed = 3;
    o.width = o.height = 200;
    o.density = 0.2;
    o.robotRadius = 0.2;
    const World g = generateGrid(o);
    EXPECT_THROW(computeOptimum(g, g.queries.front()), InputError);
}

// ------------------------------------------------------------------------------------------------------
// Shipped worlds.

TEST(Optimum, SeedWorldsReproduceTheSpec)
{
    const World c1 = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case1.yaml");
    const World c2 = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case2.yaml");
    const OptimumResult r1 = computeOptimum(c1, c1.queries.front());
    const OptimumResult r2 = computeOptimum(c2, c2.queries.front());
    ASSERT_TRUE(r1.found);
    ASSERT_TRUE(r2.found);
    EXPECT_NEAR(r1.length, 14.2734, 5e-5);
    EXPECT_NEAR(r2.length, 14.4198, 5e-5);
    EXPECT_TRUE(polylineValid(c1, r1.path));
    EXPECT_TRUE(polylineValid(c2, r2.path));
    std::cout << "[optimum] bfo_case1 " << r1.length << " in " << r1.seconds * 1e3 << " ms; bfo_case2 "
              << r2.length << " in " << r2.seconds * 1e3 << " ms (" << r2.graphNodes << " nodes, "
              << r2.graphEdges << " edges)\n";
}

TEST(Optimum, EveryShippedWorld)
{
    for (const char *name : {"bfo_case1", "bfo_case1_moved", "bfo_case2", "lrsma_scenario1",
                             "lrsma_scenario2", "lrsma_scenario3", "gms_grid10", "gms_grid20", "gms_grid30"})
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
        for (const Query &q : w.queries)
        {
            const OptimumResult r = computeOptimum(w, q);
            ASSERT_TRUE(r.found) << name;
            EXPECT_TRUE(polylineValid(w, r.path)) << name;
            EXPECT_TRUE(optimumWitnessed(w, q, r)) << name;
            EXPECT_GE(r.length, distance(q.start, q.goal) - 1e-12) << name;
            if (w.isGrid())
            {
                const OptimumResult oct = computeGridOctileOptimum(w, q);
                ASSERT_TRUE(oct.found);
                EXPECT_LE(r.length, oct.length + 1e-9) << name;
                EXPECT_NEAR(r.lengthCells * w.grid->cellSize(), r.length, 1e-12);
            }
            std::cout << "[optimum] " << name << " '" << q.name << "': " << r.length << " (" << r.method
                      << ", " << r.seconds * 1e3 << " ms)\n";
        }
    }
}

// ------------------------------------------------------------------------------------------------------
// Random worlds: the optimum is valid, never longer than a dense roadmap (which never beats it by more
// than 1e-9 relative) and, for point robots among polygons and on grids, equal to a brute-force
// visibility graph. From below, on every world: its own path, re-checked point by point against the shapes
// (optimumWitnessed, OptimumSupport.h), is valid and exactly as long as reported, so it is never shorter
// than the true optimum.

namespace
{
    std::vector<Vec2> starPolygon(Rng &rng, const Vec2 &c)
    {
        const int k = static_cast<int>(rng.uniform(5.0, 9.999));
        // Jittered even angles: consecutive gaps stay below pi, so the star polygon is simple.
        std::vector<double> angles;
        const double offset = rng.uniform(0.0, 2.0 * kPi);
        for (int i = 0; i < k; ++i)
            angles.push_back(offset + 2.0 * kPi * (i + rng.uniform(0.0, 0.8)) / k);
        std::vector<Vec2> v;
        for (double a : angles)
        {
            const double r = rng.uniform(0.3, 1.3);
            v.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
        }
        return v;
    }

    enum class Kind
    {
        Circles,
        Polygons,
        Mixed
    };

    World randomWorld(Kind kind, int index)
    {
        Rng rng(1000 + 7919 * static_cast<std::uint64_t>(index) + 31 * static_cast<int>(kind));
        World w = box10(index % 2 == 0 ? 0.0 : rng.uniform(0.05, 0.3));
        w.name = "random";
        const int n = static_cast<int>(rng.uniform(4.0, 12.0));
        for (int i = 0; i < n; ++i)
        {
            const Vec2 c{rng.uniform(-0.5, 10.5), rng.uniform(-0.5, 10.5)};
            const bool circle = kind == Kind::Circles || (kind == Kind::Mixed && rng.uniform(0.0, 1.0) < 0.5);
            if (circle)
                w.circles.push_back({c, rng.uniform(0.2, 1.5)});
            else if (rng.uniform(0.0, 1.0) < 0.5)
                w.polygons.push_back(makePolygon(
                    rectangleCorners(c, rng.uniform(0.3, 2.5), rng.uniform(0.3, 2.5), rng.uniform(0.0, kPi)),
                    "rectangle"));
            else
            {
                const std::vector<Vec2> star = starPolygon(rng, c);
                if (polygonIsSimple(star))
                    w.polygons.push_back(makePolygon(star));
            }
        }
        const CollisionModelPtr model = makeCollisionModel(w);
        const Box in = w.bounds.inflated(-w.robotRadius);
        auto sample = [&] { return sampleValid(rng, w, *model); };
        Vec2 s = sample();
        Vec2 g = sample();
        // Half of the queries run corner to corner (start and goal on the admissible box).
        if (index % 4 < 2 && model->isValid({in.xmin, in.ymin}) && model->isValid({in.xmax, in.ymax}))
        {
            s = {in.xmin, in.ymin};
            g = {in.xmax, in.ymax};
        }
        w.queries.push_back({"default", s, g});
        return w;
    }

    void checkAgainstRoadmap(Kind kind, const char *label)
    {
        double worstGap = 0.0, sumGap = 0.0;
        int compared = 0, bruteCompared = 0, witnessed = 0;
        for (int i = 0; i < 100; ++i)
        {
            const World w = randomWorld(kind, i);
            const Query &q = w.queries.front();
            const OptimumResult r = computeOptimum(w, q);
            const double road = roadmapLength(w, q, 48, 300, 2.6, 77 + i);
            if (std::isfinite(road))
            {
                ASSERT_TRUE(r.found) << label << " world " << i;
                if (road < r.length * (1.0 - 1e-9) && std::getenv("MHPLAN_OPTIMUM_DUMP"))
                    std::cout << worldToYaml(w) << "\n";
                ASSERT_GE(road, r.length * (1.0 - 1e-9)) << label << " world " << i;
                worstGap = std::max(worstGap, road / r.length - 1.0);
                sumGap += road / r.length - 1.0;
                ++compared;
            }
            if (!r.found)
                continue;
            ASSERT_TRUE(polylineValid(w, r.path)) << label << " world " << i;
            EXPECT_TRUE(optimumWitnessed(w, q, r)) << label << " world " << i;
            ++witnessed;
            if (w.robotRadius == 0.0 && w.circles.empty())
            {
                const double brute = bruteVisibility(w, q, polygonVertices(w));
                EXPECT_NEAR(brute, r.length, 1e-9 * r.length) << label << " world " << i;
                ++bruteCompared;
            }
        }
        EXPECT_GE(compared, 60) << label;
        std::cout << "[optimum] " << label << ": roadmap / optimum - 1 over " << compared << " worlds: mean "
                  << sumGap / std::max(compared, 1) << ", max " << worstGap
                  << "; brute-force visibility graph " << bruteCompared
                  << " worlds; witnessed by its own path " << witnessed << " worlds\n";
    }
} // namespace

TEST(OptimumRandom, CircleWorlds)
{
    checkAgainstRoadmap(Kind::Circles, "circles");
}

TEST(OptimumRandom, PolygonWorlds)
{
    checkAgainstRoadmap(Kind::Polygons, "polygons");
}

namespace
{
    /** \brief \e w's admissible space for its disc robot as a point-robot world of polygons: each circle,
        grown by the robot radius, replaced by the regular k-gon inscribed in it (\e scale 1) or
        circumscribed about it (\e scale 1 / cos(pi / k)); the box shrunk by the robot radius. */
    World circlesAsPolygons(const World &w, int k, bool circumscribed)
    {
        World out = box10(0.0);
        out.name = w.name;
        out.bounds = w.bounds.inflated(-w.robotRadius);
        const double scale = circumscribed ? 1.0 / std::cos(kPi / k) : 1.0;
        for (const Circle &c : w.circles)
        {
            std::vector<Vec2> v;
            const double r = (c.radius + w.robotRadius) * scale;
            for (int i = 0; i < k; ++i)
                v.push_back({c.center.x + r * std::cos(2.0 * kPi * i / k),
                             c.center.y + r * std::sin(2.0 * kPi * i / k)});
            out.polygons.push_back(makePolygon(v));
        }
        return out;
    }

    /** \brief The graph nodes for \e w's regular polygons: their vertices moved out from the centre by a
        relative 1e-9, so that a path running along an edge keeps a clearance above the rounding of the exact
        segment test (which may judge a segment lying on an obstacle's edge to enter it by 1e-16). The lengths
        change by less than 1e-8 relative. */
    std::vector<Vec2> nodesAround(const World &w)
    {
        std::vector<Vec2> out;
        for (const auto &p : w.polygons)
        {
            Vec2 c{0.0, 0.0};
            for (const Vec2 &v : p.vertices)
                c = c + v;
            c = c * (1.0 / static_cast<double>(p.vertices.size()));
            for (const Vec2 &v : p.vertices)
                out.push_back(c + (v - c) * (1.0 + 1e-9));
        }
        return out;
    }
} // namespace

// Issue 19, the lower-side oracle: on random circle worlds (point and disc robots) the optimum lies between
// the shortest paths among inscribed polygons (a larger free space: a lower bound) and among circumscribed
// ones (a smaller free space: an upper bound where it has a path), both found by a brute-force visibility
// graph that knows nothing of arcs or tangents. A too-short optimum fails the lower bound.
TEST(OptimumRandom, CircleWorldsBetweenInscribedAndCircumscribedPolygons)
{
    const int k = 32;
    int bracketed = 0;
    double worst = 0.0;
    for (int i = 0; i < 30; ++i)
    {
        const World w = randomWorld(Kind::Circles, i);
        const Query &q = w.queries.front();
        const OptimumResult r = computeOptimum(w, q);
        const World inner = circlesAsPolygons(w, k, false);
        const World outer = circlesAsPolygons(w, k, true);
        const double lower = bruteVisibility(inner, q, nodesAround(inner));
        const double upper = bruteVisibility(outer, q, nodesAround(outer));
        if (!r.found)
        {
            EXPECT_FALSE(std::isfinite(upper))
                << "world " << i << ": no optimum, yet a path around the polygons";
            continue;
        }
        ASSERT_TRUE(std::isfinite(lower)) << "world " << i;
        EXPECT_GE(r.length, lower * (1.0 - 1e-8))
            << "world " << i << ": optimum shorter than the lower bound";
        if (std::isfinite(upper))
        {
            EXPECT_LE(r.length, upper * (1.0 + 1e-8)) << "world " << i;
            // The bounds close in as k grows: the k-gons are within (1 / cos(pi / k) - 1) of the circles.
            EXPECT_LT(upper / lower - 1.0, 0.01) << "world " << i;
            worst = std::max(worst, upper / lower - 1.0);
            ++bracketed;
        }
    }
    EXPECT_GE(bracketed, 20);
    std::cout << "[optimum] circles between " << k << "-gons: " << bracketed
              << " of 30 worlds bracketed, widest " << worst << "\n";
}

TEST(OptimumRandom, MixedWorlds)
{
    checkAgainstRoadmap(Kind::Mixed, "mixed");
}

// ------------------------------------------------------------------------------------------------------
// Large polygons: the edge index (OptimumOptions::polygonEdgeIndex) changes no result.

namespace
{
    /** \brief A simple star polygon of \e n vertices about \e c (angles strictly increasing):
        even vertices at radius in [0.8, 1] times \e outer, odd ones in [0.45, 0.75] times it (every other
        vertex convex), and \e slits narrow notches down to 0.1 times \e outer. */
    std::vector<Vec2> largeStar(Rng &rng, int n, const Vec2 &c, double outer, int slits = 0)
    {
        std::vector<double> radius;
        for (int i = 0; i < n; ++i)
            radius.push_back(outer * (i % 2 == 0 ? rng.uniform(0.8, 1.0) : rng.uniform(0.45, 0.75)));
        for (int k = 0; k < slits; ++k)
        {
            const int at = static_cast<int>(rng.uniform(0.0, n - 3.0));
            radius[at + 1] = radius[at + 2] = outer * rng.uniform(0.1, 0.3);
        }
        std::vector<Vec2> v;
        for (int i = 0; i < n; ++i)
        {
            const double a = 2.0 * kPi * (i + rng.uniform(0.0, 0.5)) / n;
            v.push_back({c.x + radius[i] * std::cos(a), c.y + radius[i] * std::sin(a)});
        }
        return v;
    }

    /** \brief One or two large star polygons (some with slits), a few circles, a random valid query. */
    World largePolygonWorld(int index)
    {
        Rng rng(5000 + 104729 * static_cast<std::uint64_t>(index));
        World w = box10(index % 2 == 0 ? 0.0 : rng.uniform(0.02, 0.2));
        w.name = "large-polygons";
        const int sizes[] = {200, 300, 400, 500, 250, 600};
        const int n = sizes[index % 6];
        if (index % 3 == 2)
        {
            w.polygons.push_back(makePolygon(largeStar(rng, n, {3.0, 5.0}, 2.3, 3)));
            w.polygons.push_back(makePolygon(largeStar(rng, n / 2, {7.3, 5.0}, 2.0, 2)));
        }
        else
            w.polygons.push_back(makePolygon(largeStar(rng, n, {5.0, 5.0}, 3.8, index % 2 == 0 ? 4 : 0)));
        const int circles = static_cast<int>(rng.uniform(1.0, 4.999));
        for (int i = 0; i < circles; ++i)
            w.circles.push_back({{rng.uniform(0.5, 9.5), rng.uniform(0.5, 9.5)}, rng.uniform(0.1, 0.6)});
        for (const auto &p : w.polygons)
            EXPECT_TRUE(polygonIsSimple(p.vertices));
        const CollisionModelPtr model = makeCollisionModel(w);
        auto sample = [&] { return sampleValid(rng, w, *model); };
        const Vec2 s = sample();
        const Vec2 g = sample();
        w.queries.push_back({"default", s, g});
        return w;
    }
} // namespace

// Random worlds of polygons with 100 to 600 vertices (point and disc robots): the optimum with the edge
// index has the same graph and length (1e-12 relative) as with the plain per-edge checks, and is witnessed
// by its own path.
TEST(OptimumLargePolygon, EdgeIndexChangesNothing)
{
    OptimumOptions plain;
    plain.polygonEdgeIndex = false;
    int found = 0;
    for (int i = 0; i < 12; ++i)
    {
        const World w = largePolygonWorld(i);
        const Query &q = w.queries.front();
        const OptimumResult indexed = computeOptimum(w, q);
        const OptimumResult reference = computeOptimum(w, q, plain);
        ASSERT_EQ(indexed.found, reference.found) << "world " << i;
        EXPECT_EQ(indexed.graphNodes, reference.graphNodes) << "world " << i;
        EXPECT_EQ(indexed.graphEdges, reference.graphEdges) << "world " << i;
        if (!indexed.found)
            continue;
        ++found;
        EXPECT_NEAR(indexed.length, reference.length, 1e-12 * reference.length) << "world " << i;
        EXPECT_TRUE(optimumWitnessed(w, q, indexed)) << "world " << i;
        EXPECT_TRUE(polylineValid(w, indexed.path)) << "world " << i;
    }
    EXPECT_GE(found, 8);
}

// Timing of one large polygon (disabled: run with --gtest_also_run_disabled_tests; MHPLAN_PLAIN=1 times the
// plain per-edge checks).
TEST(OptimumLargePolygon, DISABLED_Timing)
{
    OptimumOptions options;
    options.polygonEdgeIndex = std::getenv("MHPLAN_PLAIN") == nullptr;
    for (int n : {500, 1000, 2000})
        for (double robot : {0.0, 0.1})
        {
            Rng rng(4242 + n);
            World w = box10(robot);
            w.polygons.push_back(makePolygon(largeStar(rng, n, {5.0, 5.0}, 4.2)));
            const Query q = query({0.3, 5.0}, {9.7, 5.2});
            const OptimumResult r = computeOptimum(w, q, options);
            std::cout << "[optimum] " << n << " vertices, robot " << robot << ": " << r.seconds
                      << " s, length " << r.length << ", nodes " << r.graphNodes << ", edges " << r.graphEdges
                      << std::endl;
        }
}
