// SPDX-License-Identifier: BSD-3-Clause
/* The memetic improved variants (GA-MEM, SMA-MEM, LRSMA-MEM, MGO-MEM) and their toolkit: paths valid under
   an independent dense check, never shorter than the exact optimum, within a stated gap after a fixed
   generation budget on a generated 100-circle world and a maze, reproducible from the seed, clear() then
   solve(), the termination condition honoured; the anytime restarts of the [GMS] variants only without an
   iteration budget. Budgets are generations (never wall-clock), so the results are deterministic. */
#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "ompl_planners/memetic/MemeticGenetic.h"
#include "ompl_planners/memetic/MemeticToolkit.h"
#include "src/optimum/Optimum.h"
#include "ompl_planners/common/PopulationPlanner.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/collision/Validity.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/objectives/StateCostIntegralObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** \brief The memetic variants: every registered mhplan planner whose name ends in "-MEM". */
    std::vector<std::string> memeticPlanners()
    {
        std::vector<std::string> out;
        const PlannerRegistry &r = builtinPlanners();
        for (const std::string &name : r.names())
            if (r.get(name).origin == "mhplan" && name.size() > 4 &&
                name.compare(name.size() - 4, 4, "-MEM") == 0)
                out.push_back(name);
        return out;
    }

    World circles100()
    {
        GeneratorOptions o;
        o.seed = 2;
        o.count = 100;
        o.bounds = {0.0, 76.5, 0.0, 78.9};
        o.minSize = 1.0;
        o.maxSize = 6.0;
        return generateCircles(o);
    }

    World maze()
    {
        GeneratorOptions o;
        o.seed = 5;
        o.width = 12;
        o.height = 12;
        return generateMaze(o);
    }

    std::vector<Vec2> points(const og::PathGeometric &path)
    {
        std::vector<Vec2> out;
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
            out.push_back(statePosition(path.getState(i)));
        return out;
    }

    /** \brief Independent of the motion validator: every point at spacing 2 mm along every segment is inside
        the bounds and valid, up to 1e-9 m of penetration (a sample on a segment tangent to a circle may round
        into it by 1e-16). */
    bool denseValid(const CollisionModel &model, const Box &bounds, const std::vector<Vec2> &pts)
    {
        for (std::size_t i = 1; i < pts.size(); ++i)
        {
            const double len = distance(pts[i - 1], pts[i]);
            const auto n = static_cast<std::size_t>(std::ceil(len / 0.002)) + 1;
            for (std::size_t k = 0; k <= n; ++k)
            {
                const Vec2 q = pts[i - 1] + (pts[i] - pts[i - 1]) * (double(k) / double(n));
                if (!bounds.contains(q) || (!model.isValid(q) && !(model.clearance(q) > -1e-9)))
                {
                    std::cout << "invalid sample (" << q.x << ", " << q.y << ") on segment " << i << " of "
                              << pts.size() - 1 << ", clearance " << model.clearance(q) << ", segmentValid "
                              << model.segmentValid(pts[i - 1], pts[i]) << std::setprecision(17) << " ("
                              << pts[i - 1].x << ", " << pts[i - 1].y << ") -> (" << pts[i].x << ", "
                              << pts[i].y << ")\n"
                              << std::setprecision(6);
                    return false;
                }
            }
        }
        return true;
    }

    double length(const std::vector<Vec2> &pts)
    {
        double l = 0.0;
        for (std::size_t i = 1; i < pts.size(); ++i)
            l += distance(pts[i - 1], pts[i]);
        return l;
    }

    struct Outcome
    {
        ob::PlannerStatus status;
        std::vector<Vec2> path;
        unsigned long evaluations{0};
    };

    Outcome solve(const World &w, const CollisionModelPtr &model, const std::string &planner,
                  std::map<std::string, std::string> params)
    {
        og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
        ss->setPlanner(builtinPlanners().create(planner, ss->getSpaceInformation(), params));
        ss->setup();
        Outcome r;
        r.status = ss->solve(ob::PlannerTerminationCondition([] { return false; }));
        if (ss->haveSolutionPath())
            r.path = points(ss->getSolutionPath());
        r.evaluations =
            std::stoul(ss->getPlanner()->getPlannerProgressProperties().at("fitness evaluations INTEGER")());
        return r;
    }
} // namespace

class Memetic : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};

// Measured (seed 3, 15 generations, 280-810 evaluations): every variant reaches the optimum's class on both
// worlds, gaps 0.0037-0.0044 % on the circles and below 1e-6 % on the maze. The bounds (0.2 %, 1 %) leave
// room for other platforms' rounding and libraries.
TEST_P(Memetic, SolvesCirclesAndMazeNearTheOptimum)
{
    for (const bool isMaze : {false, true})
    {
        const World w = isMaze ? maze() : circles100();
        const CollisionModelPtr model = makeCollisionModel(w);
        const OptimumResult opt = computeOptimum(w, w.queries[0]);
        ASSERT_TRUE(opt.found);
        const Outcome r = solve(w, model, GetParam(), {{"seed", "3"}, {"max_iterations", "15"}});
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION) << w.name;
        ASSERT_GE(r.path.size(), 2u);
        EXPECT_EQ(r.path.front(), w.queries[0].start);
        EXPECT_EQ(r.path.back(), w.queries[0].goal);
        EXPECT_TRUE(denseValid(*model, w.bounds, r.path)) << w.name;
        const double len = length(r.path);
        EXPECT_GE(len, opt.length * (1.0 - 1e-9)) << w.name; // never shorter than the exact optimum
        const double gap = (len - opt.length) / opt.length;
        std::cout << GetParam() << " on " << w.name << ": gap " << 100.0 * gap << " % after " << r.evaluations
                  << " evaluations\n";
        EXPECT_LT(gap, isMaze ? 0.01 : 0.002) << w.name;
    }
}

TEST_P(Memetic, SameSeedSamePathAndClearRepeats)
{
    const World w = circles100();
    const CollisionModelPtr model = makeCollisionModel(w);
    const Outcome a = solve(w, model, GetParam(), {{"seed", "9"}, {"max_iterations", "4"}});
    const Outcome b = solve(w, model, GetParam(), {{"seed", "9"}, {"max_iterations", "4"}});
    ASSERT_EQ(a.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(a.path.size(), b.path.size());
    EXPECT_EQ(length(a.path), length(b.path));
    EXPECT_EQ(a.evaluations, b.evaluations);

    // clear() then solve() on the same planner repeats the run.
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ob::PlannerPtr p = builtinPlanners().create(GetParam(), ss->getSpaceInformation(),
                                                {{"seed", "9"}, {"max_iterations", "4"}});
    ss->setPlanner(p);
    ss->setup();
    auto never = ob::PlannerTerminationCondition([] { return false; });
    ASSERT_EQ(ss->solve(never), ob::PlannerStatus::EXACT_SOLUTION);
    const double first = ss->getSolutionPath().length();
    p->clear();
    ss->getProblemDefinition()->clearSolutionPaths();
    ASSERT_EQ(ss->solve(never), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(ss->getSolutionPath().length(), first);
    EXPECT_DOUBLE_EQ(first, length(a.path));
}

TEST_P(Memetic, HonoursTheTerminationCondition)
{
    // No iteration budget: the planner runs until the condition holds. Loose bound (shared machines).
    GeneratorOptions o;
    o.seed = 3;
    o.count = 300;
    o.bounds = {0.0, 132.0, 0.0, 136.0};
    o.minSize = 1.0;
    o.maxSize = 6.0;
    const World w = generateCircles(o);
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setPlanner(builtinPlanners().create(GetParam(), ss->getSpaceInformation(), {{"seed", "1"}}));
    ss->setup();
    const ompl::time::point t0 = ompl::time::now();
    const ob::PlannerStatus s = ss->solve(0.05);
    const double elapsed = ompl::time::seconds(ompl::time::now() - t0);
    EXPECT_EQ(s, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_LT(elapsed, 0.05 + 0.25) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Variants, Memetic, ::testing::ValuesIn(memeticPlanners()));

TEST(MemeticRegistry, FourVariants)
{
    EXPECT_EQ(memeticPlanners(), (std::vector<std::string>{"GA-MEM", "LRSMA-MEM", "MGO-MEM", "SMA-MEM"}));
}

TEST(MemeticToolkit, TightenNeverLengthensAndStaysValid)
{
    const World w = circles100();
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setup();
    ompl::RNG rng(4);
    MemeticToolkit tk(ss->getSpaceInformation(), rng);
    tk.setBounds(w.bounds);
    tk.randomiseField(std::hypot(w.bounds.width(), w.bounds.height()));
    const std::function<bool()> never = [] { return false; };
    MemeticPath path, closest;
    double closestDistance = std::numeric_limits<double>::infinity();
    ASSERT_EQ(tk.randomWalk(path, w.queries[0].start, w.queries[0].goal, 1.0, 1.0, 100000, never, closest,
                            closestDistance),
              MemeticToolkit::WalkResult::Found);
    EXPECT_TRUE(denseValid(*model, w.bounds, path));
    const double walked = MemeticToolkit::length(path);
    tk.shortcut(path, never);
    const double shortcut = MemeticToolkit::length(path);
    EXPECT_LE(shortcut, walked + 1e-12);
    EXPECT_TRUE(denseValid(*model, w.bounds, path));
    ASSERT_TRUE(tk.tighten(path, 0.05, 1e-10, 200, never, 20000, true));
    EXPECT_LE(MemeticToolkit::length(path), shortcut + 1e-12);
    EXPECT_TRUE(denseValid(*model, w.bounds, path));
    EXPECT_EQ(path.front(), w.queries[0].start);
    EXPECT_EQ(path.back(), w.queries[0].goal);
    // Fine subdivision around the arcs: no waypoint turns by much more than the limit.
    EXPECT_LT(MemeticToolkit::maxTurnAngle(path), 0.5);

    // A crossover of two walks joins them through the motion validator.
    MemeticPath other;
    tk.randomiseField(50.0);
    ASSERT_EQ(tk.randomWalk(other, w.queries[0].start, w.queries[0].goal, 1.0, 3.0, 100000, never, closest,
                            closestDistance),
              MemeticToolkit::WalkResult::Found);
    MemeticPath child;
    int spliced = 0;
    for (int k = 0; k < 20; ++k)
        if (tk.splice(path, other, 3.0, k % 2 == 0, child))
        {
            ++spliced;
            EXPECT_TRUE(denseValid(*model, w.bounds, child));
            EXPECT_EQ(child.front(), w.queries[0].start);
            EXPECT_EQ(child.back(), w.queries[0].goal);
        }
    EXPECT_GT(spliced, 0);
}

TEST(MemeticToolkit, SegmentCacheAnswersRepeatedChecksAndClears)
{
    const World w = circles100();
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setup();
    ompl::RNG rng(4);
    MemeticToolkit tk(ss->getSpaceInformation(), rng);
    tk.setBounds(w.bounds);
    const Vec2 a = w.queries[0].start, b = w.queries[0].goal, c(a.x + 0.5, a.y);
    const bool straight = tk.motionValid(a, b), shortOne = tk.motionValid(a, c);
    EXPECT_EQ(tk.motionChecks(), 2u);
    // The same segments again: the same verdicts (valid and invalid alike) from the cache, no new check.
    EXPECT_EQ(tk.motionValid(a, b), straight);
    EXPECT_EQ(tk.motionValid(a, c), shortOne);
    EXPECT_EQ(tk.motionChecks(), 2u);
    EXPECT_EQ(tk.cacheHits(), 2u);
    tk.clearCache();
    EXPECT_EQ(tk.motionValid(a, b), straight);
    EXPECT_EQ(tk.motionChecks(), 3u);
}

TEST(MemeticToolkit, LazyRoadmapGivesValidRoutesThatDiffer)
{
    const World w = circles100();
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setup();
    ompl::RNG rng(4);
    MemeticToolkit tk(ss->getSpaceInformation(), rng);
    tk.setBounds(w.bounds);
    const Vec2 start = w.queries[0].start, goal = w.queries[0].goal;
    const std::function<bool()> never = [] { return false; };
    tk.roadmapGrow(1000, start, goal, std::numeric_limits<double>::infinity());
    EXPECT_GT(tk.roadmapSize(), 2u);
    EXPECT_LE(tk.roadmapSize(), 1002u);
    MemeticPath first, second;
    ASSERT_TRUE(tk.roadmapPath(first, 4000, never));
    ASSERT_TRUE(tk.roadmapPath(second, 4000, never));
    for (const MemeticPath *p : {&first, &second})
    {
        EXPECT_TRUE(denseValid(*model, w.bounds, *p));
        EXPECT_EQ(p->front(), start);
        EXPECT_EQ(p->back(), goal);
    }
    // The penalties send the second route elsewhere: its interior points are not all those of the first.
    EXPECT_NE(first, second);
    // Informed pruning: with a bound, every kept sample lies inside the ellipse |start q| + |q goal| < bound.
    const double bound = 1.1 * distance(start, goal);
    tk.roadmapGrow(500, start, goal, bound);
    MemeticPath inside;
    if (tk.roadmapPath(inside, 4000, never))
    {
        for (const Vec2 &q : inside)
            EXPECT_LT(distance(start, q) + distance(q, goal), bound + 1e-9);
    }
    // A stop request ends the search.
    EXPECT_FALSE(tk.roadmapPath(inside, 4000, [] { return true; }));
}

TEST(MemeticToolkit, TubeRouteFindsTheShorterClassBesideAPath)
{
    // A 10 m square with a 1 x 1 m block at (5, 5): the path from (1, 5) to (9, 5) round the block's far side
    // of a second, long wall above it ((4.5, 6.5) to (5.5, 9.5)) is the wrong class; a tube of radius 3 m
    // round it holds the way between the block and the wall (the optimal class, 1 m wide), and the tube
    // reroute routes it (docs/variants.md, "The tube reroute"): a valid route from start to goal, shorter
    // than the path, not passing above the wall.
    World w;
    w.name = "tube";
    w.bounds = {0, 10, 0, 10};
    w.polygons.push_back(makePolygon(rectangleCorners({5, 5}, 1.0, 1.0, 0.0), "rectangle"));
    w.polygons.push_back(makePolygon(rectangleCorners({5, 8}, 1.0, 3.0, 0.0), "rectangle"));
    w.queries.push_back({"default", {1, 5}, {9, 5}});
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setup();
    ompl::RNG rng(4);
    MemeticToolkit tk(ss->getSpaceInformation(), rng);
    tk.setBounds(w.bounds);
    const std::function<bool()> never = [] { return false; };
    const MemeticPath above{{1, 5}, {4.4, 9.7}, {5.6, 9.7}, {9, 5}};
    ASSERT_TRUE(tk.pathValid(above));
    ASSERT_TRUE(denseValid(*model, w.bounds, above));
    MemeticPath route;
    ASSERT_TRUE(tk.tubeRoute(above, 3.0, 1000, 200, route, never));
    EXPECT_TRUE(tk.pathValid(route));
    EXPECT_TRUE(denseValid(*model, w.bounds, route));
    EXPECT_EQ(route.front(), Vec2(1, 5));
    EXPECT_EQ(route.back(), Vec2(9, 5));
    EXPECT_LT(length(route), length(above) - 1.0);
    for (const Vec2 &q : route)
        EXPECT_LT(q.y, 9.5) << "the route passes above the wall";
    // With no states there is no route (the straight line between the ends is blocked), and a stop ends it.
    MemeticPath narrow;
    EXPECT_FALSE(tk.tubeRoute(above, 3.0, 0, 200, narrow, never));
    EXPECT_FALSE(tk.tubeRoute(above, 3.0, 1000, 200, narrow, [] { return true; }));
}

TEST(MemeticToolkit, WalkIsExhaustedBehindAWall)
{
    World w;
    w.name = "walled";
    w.bounds = {0, 10, 0, 10};
    w.polygons.push_back(makePolygon(rectangleCorners({5, 5}, 1.0, 12.0, 0.0), "rectangle"));
    w.queries.push_back({"default", {1, 5}, {9, 5}});
    const CollisionModelPtr model = makeCollisionModel(w);
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
    ss->setup();
    ompl::RNG rng(4);
    MemeticToolkit tk(ss->getSpaceInformation(), rng);
    tk.setBounds(w.bounds);
    MemeticPath path, closest;
    double closestDistance = std::numeric_limits<double>::infinity();
    EXPECT_EQ(tk.randomWalk(
                  path, {1, 5}, {9, 5}, 0.5, 0.0, 100000, [] { return false; }, closest, closestDistance),
              MemeticToolkit::WalkResult::Exhausted);
    // The closest approach is the wall's face (x = 4.5 minus the lattice step at most).
    EXPECT_NEAR(closestDistance, 4.5, 0.5);
    EXPECT_EQ(closest.front(), Vec2(1, 5));
}

TEST(AnytimeRestarts, OnlyWithoutAnIterationBudgetAndOnlyForTheVariants)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const World w = circles100();
    const CollisionModelPtr model = makeCollisionModel(w);
    auto run = [&](const std::string &name, std::map<std::string, std::string> params, unsigned int ptcChecks,
                   unsigned long &restarts)
    {
        og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], model);
        ob::PlannerPtr p = builtinPlanners().create(name, ss->getSpaceInformation(), params);
        ss->setPlanner(p);
        ss->setup();
        ob::IterationTerminationCondition checks(ptcChecks);
        ss->solve(ptcChecks == 0 ? ob::PlannerTerminationCondition([] { return false; })
                                 : ob::PlannerTerminationCondition(checks));
        restarts = std::dynamic_pointer_cast<PopulationPlanner>(p)->restartCount();
        return std::stod(p->getPlannerProgressProperties().at("best cost REAL")());
    };
    unsigned long restarts = 0;
    // The registry switches the restarts on for the improved variants only.
    for (const char *name : {"SMA-OPS", "LRSMA-OPS", "MGO-OPS", "GA-WALK"})
        EXPECT_EQ(builtinPlanners()
                      .create(name, makeSimpleSetup(w, w.queries[0], model)->getSpaceInformation())
                      ->params()["stagnation_restart"]
                      .getValue(),
                  "30")
            << name;
    for (const char *name : {"SMA", "LRSMA", "MGO", "GA"})
        EXPECT_EQ(builtinPlanners()
                      .create(name, makeSimpleSetup(w, w.queries[0], model)->getSpaceInformation())
                      ->params()["stagnation_restart"]
                      .getValue(),
                  "0")
            << name;
    // Without an iteration budget (a condition that holds after a fixed number of checks: deterministic)
    // a variant with a short stagnation window restarts.
    run("SMA-OPS", {{"seed", "5"}, {"stagnation_restart", "3"}}, 40000, restarts);
    EXPECT_GT(restarts, 0u);
    // With an iteration budget the restarts stay off: the same run as with the switch off.
    const double with =
        run("SMA-OPS", {{"seed", "5"}, {"stagnation_restart", "3"}, {"max_iterations", "40"}}, 0, restarts);
    EXPECT_EQ(restarts, 0u);
    const double without =
        run("SMA-OPS", {{"seed", "5"}, {"stagnation_restart", "0"}, {"max_iterations", "40"}}, 0, restarts);
    EXPECT_EQ(with, without);
}

TEST(GridSegments, NearlyOnAGridLineBetweenTwoBlockedCellsIsInvalid)
{
    // Found by SMA-MEM pulling a path tight in this maze: a segment within 4e-15 of the grid line x = 18
    // between the blocked cells (17, 8) and (18, 8) passed segmentValid (it did not enter either open square
    // in floating point) and gave a path 14.6 % shorter than the optimum.
    const World w = maze();
    const CollisionModelPtr model = makeCollisionModel(w);
    const Vec2 a(18.0, 7.999999977176107), b(17.999999999999996, 9.0000000395060198);
    EXPECT_FALSE(model->isValid(Vec2(18.0, 8.5)));
    EXPECT_FALSE(model->segmentValid(a, b));
    EXPECT_FALSE(model->segmentValid(Vec2(18.0, 8.0), Vec2(18.0, 9.0))); // exactly on the line
}

namespace
{
    /** A user's plane whose distance is half the Euclidean one (a map in other units). */
    class HalvedPlane : public ob::RealVectorStateSpace
    {
      public:
        HalvedPlane() : ob::RealVectorStateSpace(2) {}
        double distance(const ob::State *a, const ob::State *b) const override
        {
            return 0.5 * ob::RealVectorStateSpace::distance(a, b);
        }
    };

    struct BoundProbe : MemeticGenetic
    {
        using MemeticGenetic::MemeticGenetic;
        using MemeticPlanner::informedBound;
    };
} // namespace

TEST(MemeticInformedSet, BoundsTheRoadmapOnlyWhereTheSpaceMeasuresThePlane)
{
    // The planar roadmap prunes samples q with |start q| + |q goal| (in the plane) not below the incumbent's
    // cost. That bound holds only when the cost is path length in the plane's metric: on a user's subclass of
    // RealVectorStateSpace with another distance (here half the plane's, so the incumbent's cost is half its
    // plane length) it would prune every sample; with another objective it bounds nothing.
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    struct Case
    {
        bool halved, length;
    };
    for (const Case c : {Case{false, true}, Case{true, true}, Case{false, false}})
    {
        std::shared_ptr<ob::RealVectorStateSpace> space =
            c.halved ? std::make_shared<HalvedPlane>() : std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 10.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(
            [](const ob::State *s)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                return std::hypot(v[0] - 5.0, v[1] - 5.0) > 1.5;
            });
        si->setup();
        auto pdef = std::make_shared<ob::ProblemDefinition>(si);
        ob::ScopedState<> start(space), goal(space);
        start[0] = start[1] = 1.0;
        goal[0] = goal[1] = 9.0;
        pdef->setStartAndGoalStates(start, goal);
        if (c.length)
            pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
        else
            pdef->setOptimizationObjective(std::make_shared<ob::StateCostIntegralObjective>(si, true));
        BoundProbe planner(si);
        planner.setProblemDefinition(pdef);
        planner.setup();
        ASSERT_EQ(planner.solve(ob::timedPlannerTerminationCondition(0.3)),
                  ob::PlannerStatus::EXACT_SOLUTION);
        const double bound = planner.informedBound();
        if (c.length && !c.halved)
        {
            const double cost = pdef->getSolutionPath()->cost(pdef->getOptimizationObjective()).value();
            EXPECT_NEAR(bound, cost, 1e-9 * cost);
            // The plane's bound: the shortest way round the disc is below it, the straight line too.
            EXPECT_GT(bound, std::hypot(8.0, 8.0));
        }
        else
            EXPECT_TRUE(std::isinf(bound))
                << "halved " << c.halved << ", length " << c.length << ": " << bound;
    }
}

namespace
{
    /** A user's own sampling motion validator (not OMPL's DiscreteMotionValidator): the end state and 7
       states at fixed fractions of every motion, however long. A piece of a motion it accepts is sampled
       elsewhere and may be refused. */
    class EighthsValidator : public ob::MotionValidator
    {
      public:
        explicit EighthsValidator(const ob::SpaceInformationPtr &si) : ob::MotionValidator(si) {}
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            if (!si_->isValid(s2))
                return false;
            ob::State *s = si_->allocState();
            bool ok = true;
            for (int k = 1; k < 8 && ok; ++k)
            {
                si_->getStateSpace()->interpolate(s1, s2, k / 8.0, s);
                ok = si_->isValid(s);
            }
            si_->freeState(s);
            ok ? ++valid_ : ++invalid_;
            return ok;
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2,
                         std::pair<ob::State *, double> &lastValid) const override
        {
            const bool ok = checkMotion(s1, s2);
            if (!ok)
            {
                lastValid.second = 0.0;
                if (lastValid.first != nullptr)
                    si_->copyState(lastValid.first, s1);
            }
            return ok;
        }
    };
} // namespace

TEST(MemeticPlanar, EveryReportedMotionPassesAUsersOwnSamplingValidator)
{
    // The plane with 40 small discs, a point checker and a user's own sampling validator: every memetic
    // planner's exact path must pass OMPL's PathGeometric::check(), i.e. that validator on every motion as
    // returned. The state mode reported pieces of accepted motions unchecked (tests/test_memetic_spaces.cpp,
    // OnOmplsOwnDubinsSpaceAsAUserBuildsIt); the planar mode passed this before and after that fix (seeds 1-8
    // at 15 generations as well), and this keeps it so.
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG placement(17);
    std::vector<std::array<double, 3>> discs;
    while (discs.size() < 40)
    {
        const std::array<double, 3> d{placement.uniformReal(3, 17), placement.uniformReal(3, 17),
                                      placement.uniformReal(0.2, 0.6)};
        discs.push_back(d);
    }
    for (const std::string name : {"GA-MEM", "SMA-MEM", "LRSMA-MEM", "MGO-MEM"})
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 20.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(
            [&discs](const ob::State *s)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                for (const auto &d : discs)
                    if (std::hypot(v[0] - d[0], v[1] - d[1]) <= d[2])
                        return false;
                return true;
            });
        si->setMotionValidator(std::make_shared<EighthsValidator>(si));
        si->setup();
        auto pdef = std::make_shared<ob::ProblemDefinition>(si);
        ob::ScopedState<> start(space), goal(space);
        start[0] = start[1] = 1.0;
        goal[0] = goal[1] = 19.0;
        pdef->setStartAndGoalStates(start, goal);
        pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
        ob::PlannerPtr p = builtinPlanners().create(name, si, {{"seed", "3"}, {"max_iterations", "4"}});
        p->setProblemDefinition(pdef);
        p->setup();
        ASSERT_EQ(p->solve(ob::PlannerTerminationCondition([] { return false; })),
                  ob::PlannerStatus::EXACT_SOLUTION)
            << name;
        const auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath());
        ASSERT_TRUE(path) << name;
        EXPECT_TRUE(path->check()) << name << ": a returned motion the validator refuses";
    }
}
