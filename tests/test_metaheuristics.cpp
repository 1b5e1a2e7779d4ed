// SPDX-License-Identifier: BSD-3-Clause
/* mhplan's metaheuristic planners (ompl_planners/): the shared encoding and fitness, determinism per seed,
   and solution quality on every shipped seed world with the papers' settings (20 fixed seeds each), measured
   against the exact optimum. */
#include "ompl_planners/common/Fitness.h"
#include "ompl_planners/common/PathEncoding.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/collision/Validity.h"
#include "src/io/WorldIO.h"
#include "src/optimum/Optimum.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>

#include "RegistrySupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    World seedWorld(const std::string &name)
    {
        return loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
    }

    /** \brief Independent dense check: every point at 1 mm spacing is valid in a fresh analytic or grid model
        (not the motion validator the planners used). */
    bool denselyValid(const World &world, const std::vector<Vec2> &pts)
    {
        const CollisionModelPtr model =
            makeCollisionModel(world, world.isGrid() ? CollisionBackend::Grid : CollisionBackend::Analytic);
        for (std::size_t i = 1; i < pts.size(); ++i)
        {
            const double len = distance(pts[i - 1], pts[i]);
            const auto steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / 1e-3)));
            for (std::size_t k = 0; k <= steps; ++k)
                if (!model->isValid(pts[i - 1] + (pts[i] - pts[i - 1]) * (double(k) / steps)))
                    return false;
        }
        return true;
    }

    struct RunResult
    {
        ob::PlannerStatus status;
        bool exactValid{false};
        double length{std::numeric_limits<double>::infinity()};
        std::vector<double> trace;
        unsigned long evaluations{0};
    };

    RunResult runPlanner(const World &world, const std::string &planner, unsigned long seed,
                         std::map<std::string, std::string> params = {})
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], model);
        params["seed"] = std::to_string(seed);
        ob::PlannerPtr p = builtinPlanners().create(planner, ss->getSpaceInformation(), params);
        ss->setPlanner(p);
        RunResult r;
        ss->getProblemDefinition()->setIntermediateSolutionCallback(
            [&r](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost cost)
            { r.trace.push_back(cost.value()); });
        r.status = ss->solve(ob::PlannerTerminationCondition([] { return false; }));
        r.evaluations = std::stoul(p->getPlannerProgressProperties().at("fitness evaluations INTEGER")());
        if (r.status == ob::PlannerStatus::EXACT_SOLUTION)
        {
            const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
            r.exactValid = denselyValid(world, pts);
            r.length = polylineLength(pts);
        }
        return r;
    }

    double median(std::vector<double> v)
    {
        std::sort(v.begin(), v.end());
        return v.empty() ? std::numeric_limits<double>::infinity() : v[v.size() / 2];
    }
} // namespace

// ---------------------------------------------------------------------------------------------------------
// Encoding and fitness.

TEST(WaypointDecoder, NotAKnotSplineReproducesCubics)
{
    // Not-a-knot splines reproduce any cubic exactly: x(t) = t^3 - 3t^2 + 2t, y(t) = 0.5 t^3 + t.
    auto fx = [](double t) { return t * t * t - 3 * t * t + 2 * t; };
    auto fy = [](double t) { return 0.5 * t * t * t + t; };
    for (unsigned int m : {2u, 3u, 4u, 7u})
    {
        WaypointDecoder dec;
        const double T = m + 1;
        dec.configure({fx(0), fy(0)}, {fx(T), fy(T)}, m, PathDecoding::Spline, 41);
        std::vector<double> x;
        for (unsigned int i = 1; i <= m; ++i)
        {
            x.push_back(fx(i));
            x.push_back(fy(i));
        }
        dec.decode(x.data());
        ASSERT_EQ(dec.path().size(), 41u);
        for (unsigned int k = 0; k < 41; ++k)
        {
            const double t = T * k / 40.0;
            EXPECT_NEAR(dec.path()[k].x, fx(t), 1e-9) << "m=" << m << " k=" << k;
            EXPECT_NEAR(dec.path()[k].y, fy(t), 1e-9) << "m=" << m << " k=" << k;
        }
    }
    // Three points: the parabola through them.
    WaypointDecoder dec;
    dec.configure({0, 0}, {2, 0}, 1, PathDecoding::Spline, 5);
    const double x[] = {1.0, 1.0};
    dec.decode(x);
    EXPECT_NEAR(dec.path()[1].y, 0.75, 1e-12); // y = t (2 - t) at t = 0.5
}

TEST(WaypointDecoder, PolylineSamplesFollowTheSegments)
{
    WaypointDecoder dec;
    dec.configure({0, 0}, {4, 0}, 1, PathDecoding::Polyline, 5);
    const double x[] = {2.0, 2.0};
    dec.decode(x);
    ASSERT_EQ(dec.path().size(), 3u);
    EXPECT_EQ(dec.path()[1], Vec2(2, 2));
    ASSERT_EQ(dec.samples().size(), 5u);
    EXPECT_NEAR(dec.samples()[1].x, 1.0, 1e-12);
    EXPECT_NEAR(dec.samples()[1].y, 1.0, 1e-12);
    EXPECT_NEAR(dec.samples()[3].x, 3.0, 1e-12);
    EXPECT_NEAR(dec.samples()[3].y, 1.0, 1e-12);
}

TEST(PathFitness, LrsmaCircleFormulaAndFeasibility)
{
    // One circle of radius 1 at (5, 5) in [0, 10]^2.
    World world;
    world.name = "one_circle";
    world.bounds = {0, 10, 0, 10};
    world.circles.push_back({{5, 5}, 1.0});
    world.queries.push_back({"default", {0, 5}, {10, 5}});
    og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
    ss->getSpaceInformation()->setup();
    PathFitness fit(ss->getSpaceInformation());
    fit.configure(FitnessKind::LengthPenalty, FitnessWeights());
    EXPECT_TRUE(fit.exactCircles());
    // Samples: (5, 5) (centre, v = 1) and (5.5, 5) (v = 0.5), (0, 5) free: f2 = (1 + 0.5 + 0) / 3.
    const std::vector<Vec2> path{{0, 5}, {10, 5}};
    const FitnessResult r = fit.evaluate(path, {{5, 5}, {5.5, 5}, {0, 5}});
    EXPECT_NEAR(r.length, 10.0, 1e-12);
    EXPECT_NEAR(r.violation, 0.5, 1e-12);
    EXPECT_NEAR(r.fitness, 10.0 + 1000.0 * 0.5, 1e-9);
    EXPECT_FALSE(r.feasible);
    // Free samples but a colliding segment: infeasible, with the small hidden-collision violation.
    const FitnessResult hidden = fit.evaluate(path, {{0, 5}, {10, 5}});
    EXPECT_FALSE(hidden.feasible);
    EXPECT_GT(hidden.fitness, 10.0);
    // A detour above the circle is feasible and scores its length.
    const std::vector<Vec2> detour{{0, 5}, {5, 7}, {10, 5}};
    const FitnessResult ok = fit.evaluate(detour, detour);
    EXPECT_TRUE(ok.feasible);
    EXPECT_NEAR(ok.fitness, 2 * std::hypot(5, 2), 1e-12);
    // [GMS] (docs/algorithms.md 1.3, maximised reciprocals): the feasible path has f1 = 1 / (dis + saf +
    // 0.1 smo), the infeasible one f2 = 1 / (D + lin + cro) with D its own f1 denominator; the key that
    // planners minimise is -f1 (feasible) or 1 / f2 (infeasible).
    fit.configure(FitnessKind::FeasibleInfeasible, FitnessWeights());
    const FitnessResult g1 = fit.evaluate(detour, detour);
    EXPECT_TRUE(g1.feasible);
    const double den1 = fit.gmsFeasibleFitness(detour);
    EXPECT_GT(den1, 2 * std::hypot(5, 2)); // plus danger and turning terms
    EXPECT_NEAR(g1.gmsValue, 1.0 / den1, 1e-15);
    EXPECT_NEAR(g1.fitness, -1.0 / den1, 1e-15);
    EXPECT_NEAR(gmsValueOfKey(g1.fitness), g1.gmsValue, 1e-15);
    const FitnessResult g2 = fit.evaluate(path, path);
    EXPECT_FALSE(g2.feasible);
    EXPECT_NEAR(g2.violation, 2.0 / 10.0 + 1.0 / 10.0, 0.01); // 2 m of 10 inside, one crossing
    // D = 10 m + danger 1 (the segment touches the obstacle: alpha = 1) + no turn.
    EXPECT_NEAR(fit.gmsFeasibleFitness(path), 11.0, 1e-9);
    EXPECT_NEAR(g2.fitness, 11.0 + g2.violation, 1e-9);
    EXPECT_NEAR(g2.gmsValue, 1.0 / (11.0 + g2.violation), 1e-12);
    EXPECT_NEAR(gmsValueOfKey(g2.fitness), g2.gmsValue, 1e-15);
    // Feasibility first: the feasible key is below the infeasible one, whatever the values.
    EXPECT_LT(g1.fitness, g2.fitness);
    // The old minimised-sum form would have scored the feasible path den1 > 0: the key is now negative.
    EXPECT_LT(g1.fitness, 0.0);
}

// ---------------------------------------------------------------------------------------------------------
// Determinism: the same seed gives the same best-cost trace.

class MetaheuristicPlanner : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MetaheuristicPlanner, SameSeedSameTrace)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const World world = seedWorld("bfo_case1");
    const RunResult a = runPlanner(world, GetParam(), 7, {{"max_iterations", "20"}});
    const RunResult b = runPlanner(world, GetParam(), 7, {{"max_iterations", "20"}});
    const RunResult c = runPlanner(world, GetParam(), 8, {{"max_iterations", "20"}});
    ASSERT_FALSE(a.trace.empty());
    EXPECT_EQ(a.trace, b.trace);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_NE(a.trace, c.trace);
}

// Every faithful population planner the registry knows.
INSTANTIATE_TEST_SUITE_P(Planners, MetaheuristicPlanner, ::testing::ValuesIn(test::faithful("population")));

// ---------------------------------------------------------------------------------------------------------
// Quality on every shipped seed world with the papers' settings, 20 fixed seeds.

namespace
{
    /** \brief Exact optimum of a seed world's default query, by the exact solver (computeOptimum,
        src/optimum/Optimum.h), computed once per world and cached across the planners. On bfo_case1 and
        bfo_case2 it reproduces docs/algorithms.md 9.1 (test_optimum.cpp checks that). */
    const OptimumResult &optimumOf(const std::string &world)
    {
        static std::map<std::string, OptimumResult> cache;
        auto it = cache.find(world);
        if (it == cache.end())
        {
            const World w = seedWorld(world);
            it = cache.emplace(world, computeOptimum(w, w.queries[0])).first;
        }
        return it->second;
    }

    /** \brief What a planner achieves on a world with the papers' settings over 20 seeds (the goal is
        minExact >= 19 and maxGap <= 5%), the median gap measured against the exact optimum (optimumOf). The
        runs are iteration-bounded with fixed seeds, so the figures are deterministic and each bound is the
        measured figure with a margin: minExact is the measured count less one or two runs (19 wherever 19 or
        20 were measured, the goal; 1 where a single run was), maxGap the measured median gap rounded
        up plus 2 percentage points (at least the 5%). Whenever a run is exact, the median gap is
        checked against maxGap and the best length against the optimum. */
    struct Expectation
    {
        std::string world;
        unsigned int minExact;
        double maxGapPercent;
        /** \brief Why the row asserts nothing (set by noExactRun). */
        std::string why{};
    };

    /** \brief A row that measured no exact run in 20: it can assert neither a count nor a gap, and \e why
        says why there is none. maxGap is NaN, so an exact run appearing later fails the gap check until the
        row is measured again. */
    Expectation noExactRun(const std::string &world, const std::string &why)
    {
        return {world, 0, std::numeric_limits<double>::quiet_NaN(), why};
    }

    const std::vector<std::string> &seedWorlds()
    {
        static const std::vector<std::string> worlds{"bfo_case1",       "bfo_case1_moved", "bfo_case2",
                                                     "lrsma_scenario1", "lrsma_scenario2", "lrsma_scenario3",
                                                     "gms_grid10",      "gms_grid20",      "gms_grid30"};
        return worlds;
    }

    std::map<std::string, std::vector<Expectation>> expectations()
    {
        // Faithful algorithms, papers' budgets (SMA/LRSMA/MGO: N = 30, T = 30, m = 3; GA: N = 50, G = 100).
        // The comments give what was measured: exact runs of 20, median gap to the optimum. The continuous
        // planners cannot reach the goal on bfo_case2 (12 circles: three waypoints and 30 x 30
        // evaluations leave the median 18-26% above the optimum) nor on the larger grids (the optima of
        // gms_grid20 and gms_grid30 have 9 segments; three waypoints give a path of 4 segments or a cubic
        // spline through them); the numbers are asserted as measured so that a regression shows, and
        // reported.
        const std::string maze3 =
            "measured 0/20: three waypoints within the papers' budget find no collision-free path through "
            "this "
            "maze (its optimum has 9 segments); with no exact run there is no count and no gap to assert";
        return {
            // SMA as [LRSMA] compares it: spline decoding, fitness S (docs/algorithms.md 4, 5).
            {"SMA",
             {{"bfo_case1", 19, 5.0},        // 20/20, 2.02%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.29%
              {"bfo_case2", 12, 24.0},       // 13/20, 21.62%
              {"lrsma_scenario1", 19, 6.0},  // 20/20, 3.30%
              {"lrsma_scenario2", 15, 20.0}, // 16/20, 17.20%
              {"lrsma_scenario3", 17, 14.0}, // 18/20, 11.96%
              {"gms_grid10", 19, 6.0},       // 19/20, 3.54%
              {"gms_grid20", 1, 15.0},       // 1/20, 12.16%
              noExactRun("gms_grid30", maze3)}},
            {"LRSMA",
             {{"bfo_case1", 19, 5.0},        // 20/20, 0.61%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.21%
              {"bfo_case2", 14, 23.0},       // 16/20, 20.39%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 1.25%
              {"lrsma_scenario2", 13, 8.0},  // 15/20, 5.20%
              {"lrsma_scenario3", 19, 14.0}, // 19/20, 11.66%
              {"gms_grid10", 6, 28.0},       // 8/20, 26.00%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            {"MGO",
             {{"bfo_case1", 19, 5.0},        // 20/20, 0.22%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.16%
              {"bfo_case2", 19, 25.0},       // 20/20, 22.12%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 0.05%
              {"lrsma_scenario2", 19, 5.0},  // 20/20, 2.93%
              {"lrsma_scenario3", 19, 12.0}, // 20/20, 9.61%
              {"gms_grid10", 19, 6.0},       // 20/20, 3.14%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            // [LRSMA] Table 3's comparators (docs/algorithms.md 10): spline decoding, fitness S, the papers'
            // settings (PSO c1 = c2 = 0.4, w = 1; WOA and GWO a from 2 to 0).
            {"PSO",
             {{"bfo_case1", 19, 5.0},        // 20/20, 1.79%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 1.04%
              {"bfo_case2", 2, 39.0},        // 3/20, 36.64%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 2.24%
              {"lrsma_scenario2", 6, 23.0},  // 8/20, 20.88%
              {"lrsma_scenario3", 11, 19.0}, // 13/20, 16.29%
              {"gms_grid10", 19, 9.0},       // 20/20, 6.07%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            {"WOA",
             {{"bfo_case1", 19, 13.0},       // 20/20, 10.41%
              {"bfo_case1_moved", 19, 11.0}, // 20/20, 8.29%
              {"bfo_case2", 2, 38.0},        // 4/20, 35.42%
              {"lrsma_scenario1", 11, 16.0}, // 13/20, 13.58%
              {"lrsma_scenario2", 2, 21.0},  // 4/20, 18.31%
              {"lrsma_scenario3", 9, 19.0},  // 11/20, 16.92%
              {"gms_grid10", 6, 20.0},       // 8/20, 17.75%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            {"GWO",
             {{"bfo_case1", 19, 5.0},        // 20/20, 0.62%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.12%
              {"bfo_case2", 7, 24.0},        // 9/20, 21.78%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 2.14%
              {"lrsma_scenario2", 11, 16.0}, // 13/20, 13.28%
              {"lrsma_scenario3", 16, 15.0}, // 18/20, 12.30%
              {"gms_grid10", 19, 5.0},       // 19/20, 1.96%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            // [GMS]'s SMA and MGO: the six operators, the maximised [GMS] fitness
            // (docs/algorithms.md 1.3, 1.5).
            // Measured: SMA-GMS 14/20 on gms_grid10 where SMA (S, no operators) has 19/20: with the maximised
            // f1 near 1 / length, p = tanh|f - DF| is small and most coordinates take the vc branch.
            {"SMA-GMS",
             {{"bfo_case1", 19, 5.0},        // 20/20, 1.07%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.59%
              {"bfo_case2", 19, 28.0},       // 20/20, 25.81%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 0.49%
              {"lrsma_scenario2", 19, 10.0}, // 20/20, 7.37%
              {"lrsma_scenario3", 19, 16.0}, // 20/20, 13.97%
              {"gms_grid10", 12, 11.0},      // 14/20, 8.48%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            {"MGO-GMS",
             {{"bfo_case1", 19, 5.0},        // 20/20, 0.64%
              {"bfo_case1_moved", 19, 5.0},  // 20/20, 0.34%
              {"bfo_case2", 19, 20.0},       // 20/20, 17.69%
              {"lrsma_scenario1", 19, 5.0},  // 20/20, 0.17%
              {"lrsma_scenario2", 19, 6.0},  // 20/20, 3.41%
              {"lrsma_scenario3", 19, 13.0}, // 20/20, 10.84%
              {"gms_grid10", 19, 5.0},       // 20/20, 1.90%
              noExactRun("gms_grid20", maze3),
              noExactRun("gms_grid30", maze3)}},
            {"GA",
             {{"bfo_case1", 19, 5.0},       // 20/20, 0.78%
              {"bfo_case1_moved", 19, 5.0}, // 20/20, 0.32%
              {"bfo_case2", 19, 5.0},       // 20/20, 1.31%
              {"lrsma_scenario1", 19, 5.0}, // 20/20, 0.28%
              {"lrsma_scenario2", 19, 5.0}, // 20/20, 0.88%
              {"lrsma_scenario3", 19, 5.0}, // 20/20, 0.84%
              {"gms_grid10", 19, 5.0},      // 20/20, 2.17%
              {"gms_grid20", 3, 12.0},      // 4/20, 9.05%
              noExactRun(
                  "gms_grid30",
                  "measured 0/20: 1 to 5 random points per new individual, the [GMS] repairs and 100 "
                  "generations find no collision-free path through this maze (30% blocked, its optimum "
                  "has 9 segments); with no exact run there is no count and no gap to assert")}},
        };
    }
} // namespace

class MetaheuristicQuality : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MetaheuristicQuality, PapersSettingsOnEverySeedWorld)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const std::string planner = GetParam();
    const auto table = expectations().at(planner);
    ASSERT_EQ(table.size(), seedWorlds().size());
    for (const Expectation &e : table)
    {
        const World world = seedWorld(e.world);
        std::vector<double> lengths;
        unsigned int exact = 0, claimedExact = 0;
        for (unsigned long seed = 1; seed <= 20; ++seed)
        {
            // max_iterations = the schedule length T: the papers' fixed budgets.
            const ob::PlannerPtr probe = builtinPlanners().create(
                planner, std::make_shared<ob::SpaceInformation>(makeStateSpace(world)));
            const RunResult r = runPlanner(world, planner, seed,
                                           {{"max_iterations", probe->params()["iterations"].getValue()}});
            claimedExact += r.status == ob::PlannerStatus::EXACT_SOLUTION ? 1 : 0;
            if (r.exactValid)
            {
                ++exact;
                lengths.push_back(r.length);
            }
        }
        const OptimumResult &optimum = optimumOf(e.world);
        ASSERT_TRUE(optimum.found) << e.world;
        const double opt = optimum.length;
        const double med = median(lengths);
        const double best = lengths.empty() ? std::numeric_limits<double>::infinity()
                                            : *std::min_element(lengths.begin(), lengths.end());
        const double gap = 100.0 * optimalityGap(med, optimum);
        std::cout << std::setw(7) << planner << " " << std::setw(16) << e.world << ": exact " << exact
                  << "/20, median length " << med << ", best " << best << ", optimum " << opt << " ("
                  << optimum.method << ", " << optimum.pieces.size() << " pieces), median gap " << gap
                  << "%\n";
        // Every exact solution passes the independent dense check.
        EXPECT_EQ(claimedExact, exact) << planner << " " << e.world;
        EXPECT_GE(exact, e.minExact) << planner << " " << e.world;
        if (e.minExact == 0)
        {
            EXPECT_FALSE(e.why.empty())
                << planner << " " << e.world << ": a row expecting no exact run says why";
        }
        if (exact > 0)
        {
            EXPECT_FALSE(std::isnan(e.maxGapPercent))
                << planner << " " << e.world
                << ": exact runs where none were measured; measure the row again";
            EXPECT_LE(gap, e.maxGapPercent) << planner << " " << e.world;
            EXPECT_GE(best, opt - 1e-6) << planner << " " << e.world << " beats the optimum";
        }
    }
}

// Every faithful population planner the registry knows; one without an expectation table fails (at()).
INSTANTIATE_TEST_SUITE_P(Planners, MetaheuristicQuality, ::testing::ValuesIn(test::faithful("population")));

TEST(MetaheuristicQuality, EveryExpectationNamesARegisteredFaithfulPopulationPlanner)
{
    // A misspelt or removed name in the table fails here instead of being skipped.
    for (const auto &kv : expectations())
    {
        ASSERT_TRUE(builtinPlanners().has(kv.first)) << kv.first;
        EXPECT_EQ(test::familyOf(kv.first), "population") << kv.first;
        EXPECT_FALSE(builtinPlanners().get(kv.first).has(cap::Improved)) << kv.first;
    }
}
