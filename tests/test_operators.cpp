// SPDX-License-Identifier: BSD-3-Clause
/* The switchable [GMS] operators of PopulationPlanner (gms_repair, gms_revise, gms_simplify, gms_improve,
   gms_scope, gms_replace_fraction): validation, defaults, refusal where they cannot apply, and what the
   improved variants SMA-OPS, LRSMA-OPS and MGO-OPS achieve on bfo_case2 with the papers' budgets. */
#include "src/optimum/Optimum.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/io/WorldIO.h"

#include "ompl_planners/population/LRSMA.h"
#include "ompl_planners/population/MountainGazelle.h"
#include "ompl_planners/common/Operators.h"
#include "ompl_planners/population/SlimeMould.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/MotionValidator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include "AllocationCounter.h"

#include "RegistrySupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    World seedWorld(const std::string &name)
    {
        return loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
    }

    const char *const kSwitches[] = {"gms_initial", "gms_repair", "gms_revise", "gms_simplify",
                                     "gms_improve"};

    struct Outcome
    {
        unsigned int exact{0};
        double medianGapPercent{std::numeric_limits<double>::infinity()};
        double bestGapPercent{std::numeric_limits<double>::infinity()};
        unsigned long evaluations{0};
    };

    /** \brief 20 seeds of \e planner on \e world at the papers' budgets (N = 30, T = 30 iterations); a path
        is exact when the planner says so and every segment passes a fresh collision model's segmentValid. */
    Outcome run20(const World &world, double optimum, const std::string &planner,
                  std::map<std::string, std::string> params = {})
    {
        const CollisionModelPtr check = makeCollisionModel(world);
        std::vector<double> lengths;
        Outcome out;
        for (unsigned long seed = 1; seed <= 20; ++seed)
        {
            og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
            params["seed"] = std::to_string(seed);
            params.emplace("population_size", "30");
            params.emplace("max_iterations", "30");
            const ob::PlannerPtr p = builtinPlanners().create(planner, ss->getSpaceInformation(), params);
            ss->setPlanner(p);
            const ob::PlannerStatus status = ss->solve(ob::PlannerTerminationCondition([] { return false; }));
            out.evaluations +=
                std::stoul(p->getPlannerProgressProperties().at("fitness evaluations INTEGER")());
            if (status != ob::PlannerStatus::EXACT_SOLUTION)
                continue;
            const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
            bool valid = true;
            for (std::size_t i = 1; i < pts.size() && valid; ++i)
                valid = check->segmentValid(pts[i - 1], pts[i]);
            // An exact status is a claim that the path is collision-free: a path that fails the fresh model
            // is a planner defect, not a run to leave out of the counts.
            EXPECT_TRUE(valid) << planner << " seed " << seed << " on " << world.name
                               << ": exact solution whose path collides";
            if (!valid)
                continue;
            ++out.exact;
            lengths.push_back(polylineLength(pts));
        }
        if (!lengths.empty())
        {
            std::sort(lengths.begin(), lengths.end());
            out.medianGapPercent = 100.0 * (lengths[lengths.size() / 2] / optimum - 1.0);
            out.bestGapPercent = 100.0 * (lengths.front() / optimum - 1.0);
        }
        return out;
    }

    ob::SpaceInformationPtr planarSpace()
    {
        return std::make_shared<ob::SpaceInformation>(makeStateSpace(seedWorld("bfo_case2")));
    }
} // namespace

TEST(GmsOperators, SwitchesDefaultOffAndAreValidated)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const std::string &name : test::faithful("population"))
    {
        if (name.find("-GMS") != std::string::npos)
            continue; // [GMS]'s SMA and MGO switch operators on (VariantsAreRegistered... checks them)
        const ob::PlannerPtr p = builtinPlanners().create(name, planarSpace());
        auto *pp = dynamic_cast<PopulationPlanner *>(p.get());
        ASSERT_NE(pp, nullptr) << name;
        for (const char *s : kSwitches)
        {
            EXPECT_EQ(p->params()[s].getValue(), "0") << name << " " << s;
            EXPECT_EQ(p->params()[s].getRangeSuggestion(), "0,1") << name << " " << s;
            // A switch is a bool: "2" is refused by name, true/false and 1/0 are accepted.
            EXPECT_THROW(applyPlannerParameters(*p, {{s, "2"}}), InputError) << name << " " << s;
            EXPECT_EQ(p->params()[s].getValue(), "0") << name << " " << s;
            applyPlannerParameters(*p, {{s, "true"}});
            EXPECT_EQ(p->params()[s].getValue(), "1") << name << " " << s;
            applyPlannerParameters(*p, {{s, "false"}});
            EXPECT_EQ(p->params()[s].getValue(), "0") << name << " " << s;
        }
        EXPECT_EQ(p->params()["gms_scope"].getValue(), "best");
        EXPECT_EQ(std::stod(p->params()["gms_replace_fraction"].getValue()), 0.0);
        EXPECT_FALSE(pp->gmsOperatorsEnabled()) << name;
        EXPECT_FALSE(p->params().setParam("gms_replace_fraction", "1.5"));
        EXPECT_FALSE(p->params().setParam("gms_scope", "worst"));
        EXPECT_EQ(p->params()["gms_scope"].getValue(), "best");
    }
    // The setters name the parameter, the allowed range and the value given.
    SlimeMould sma(planarSpace());
    auto expectMessage = [](const std::function<void()> &f, const std::string &what)
    {
        try
        {
            f();
            ADD_FAILURE() << "no exception for " << what;
        }
        catch (const std::invalid_argument &e)
        {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    GmsSettings gms;
    for (const double f : {-0.1, 1.01})
    {
        gms.replaceFraction = f;
        expectMessage([&] { sma.setGmsSettings(gms); }, "'gms_replace_fraction' must be in [0, 1]");
    }
    expectMessage([&] { gms.setScope("worst"); }, "'gms_scope' must be 'best' or 'all'; got 'worst'");
    EXPECT_FALSE(sma.gmsOperatorsEnabled());
}

TEST(GmsOperators, VariantsAreRegisteredWithDistinctNamesAndSwitchesOn)
{
    unsigned int faithfulGms = 0, improved = 0;
    for (const std::string &name : test::ofFamily("population"))
    {
        const ob::PlannerPtr p = builtinPlanners().create(name, planarSpace());
        EXPECT_EQ(p->getName(), name);
        const bool gms = name.find("-GMS") != std::string::npos;
        const bool ops = name.find("-OPS") != std::string::npos;
        const PlannerEntry &entry = builtinPlanners().get(name);
        EXPECT_EQ(dynamic_cast<PopulationPlanner &>(*p).gmsOperatorsEnabled(), gms || ops) << name;
        if (gms)
        {
            // [GMS]'s SMA / MGO (docs/algorithms.md 1.5): repair, segment repair and node improvement on the
            // initial and new individuals; simplification, revision and replacement every iteration; the
            // [GMS] fitness; faithful, not an improved variant.
            ++faithfulGms;
            EXPECT_FALSE(entry.has(cap::Improved)) << name;
            EXPECT_EQ(p->params()["gms_initial"].getValue(), "1") << name;
            EXPECT_EQ(p->params()["gms_revise"].getValue(), "1") << name;
            EXPECT_EQ(p->params()["gms_simplify"].getValue(), "1") << name;
            EXPECT_EQ(p->params()["gms_repair"].getValue(), "0") << name;
            EXPECT_EQ(p->params()["gms_improve"].getValue(), "0") << name;
            EXPECT_EQ(p->params()["gms_scope"].getValue(), "all") << name;
            EXPECT_DOUBLE_EQ(std::stod(p->params()["gms_replace_fraction"].getValue()), 0.1) << name;
            EXPECT_EQ(p->params()["fitness"].getValue(), "gms") << name;
            EXPECT_EQ(p->params()["decoding"].getValue(), "polyline") << name;
            EXPECT_NE(entry.description.find("[GMS]"), std::string::npos) << name;
        }
        if (ops)
        {
            ++improved;
            EXPECT_TRUE(entry.has(cap::Improved)) << name;
            EXPECT_EQ(p->params()["gms_repair"].getValue(), "1");
            EXPECT_EQ(p->params()["gms_simplify"].getValue(), "1");
            EXPECT_EQ(p->params()["gms_improve"].getValue(), "1");
            EXPECT_NE(entry.description.find("improved variant (not in the paper)"), std::string::npos);
        }
    }
    EXPECT_EQ(faithfulGms, 2u);
    EXPECT_EQ(improved, 3u);
    // The original SMA is [LRSMA]'s: spline decoding (the default "auto" is the spline on R^k,
    // docs/spaces.md), fitness S, no operator.
    const ob::PlannerPtr sma = builtinPlanners().create("SMA", planarSpace());
    EXPECT_EQ(sma->params()["decoding"].getValue(), "auto");
    EXPECT_EQ(sma->params()["fitness"].getValue(), "lrsma");
}

TEST(GmsOperators, RefusedInKDAndByAlgorithmsWithoutAPopulationView)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto space = std::make_shared<ob::RealVectorStateSpace>(3);
    space->setBounds(0.0, 1.0);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker([](const ob::State *) { return true; });
    si->setup();
    for (const char *s : {"gms_repair", "gms_revise", "gms_simplify", "gms_improve", "gms_replace_fraction"})
    {
        SlimeMould sma(si);
        if (std::string(s) == "gms_replace_fraction")
            ASSERT_TRUE(sma.params().setParam(s, "0.1"));
        else
            ASSERT_TRUE(sma.params().setParam(s, "1"));
        try
        {
            sma.setup();
            ADD_FAILURE() << s << " accepted in R^3";
        }
        catch (const ompl::Exception &e)
        {
            EXPECT_NE(std::string(e.what()).find(s), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("dimension 3"), std::string::npos) << e.what();
        }
        EXPECT_FALSE(sma.isSetup());
    }
    // Off again: accepted.
    SlimeMould sma(si);
    ASSERT_TRUE(sma.params().setParam("gms_repair", "1"));
    ASSERT_TRUE(sma.params().setParam("gms_repair", "0"));
    EXPECT_NO_THROW(sma.setup());
    // The GA (its own operators) exposes no waypoint population.
    const ob::PlannerPtr ga = builtinPlanners().create("GA", planarSpace());
    ga->params().setParam("gms_simplify", "1");
    try
    {
        ga->setup();
        ADD_FAILURE() << "GA accepted gms_simplify";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("gms_simplify"), std::string::npos) << e.what();
    }
}

TEST(GmsOperators, OffMeansBitIdentical)
{
    // Scope alone switches nothing on: the same seed gives the same path, cost and evaluation count.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = seedWorld("bfo_case2");
    for (const std::string name : {"SMA", "LRSMA", "MGO"})
    {
        std::vector<double> costs;
        std::vector<std::string> evaluations;
        for (const std::string scope : {"best", "all"})
        {
            og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
            const ob::PlannerPtr p = builtinPlanners().create(name, ss->getSpaceInformation(),
                                                              {{"seed", "7"},
                                                               {"max_iterations", "10"},
                                                               {"gms_scope", scope},
                                                               {"gms_replace_fraction", "0"}});
            ss->setPlanner(p);
            ss->solve(ob::PlannerTerminationCondition([] { return false; }));
            costs.push_back(polylineLength(pathPoints(ss->getSolutionPath())));
            evaluations.push_back(p->getPlannerProgressProperties().at("fitness evaluations INTEGER")());
        }
        EXPECT_EQ(costs[0], costs[1]) << name;
        EXPECT_EQ(evaluations[0], evaluations[1]) << name;
    }
}

TEST(GmsOperators, EveryOperatorAndReplacementRunsAndKeepsTheReportConsistent)
{
    // Each switch alone, and all of them with scope "all" and replacement, on bfo_case2: every exact path
    // the planner reports is truly collision-free, at least the optimum long and its reported best cost.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = seedWorld("bfo_case2");
    const double optimum = computeOptimum(world, world.queries[0]).length;
    const CollisionModelPtr check = makeCollisionModel(world);
    const std::vector<std::map<std::string, std::string>> settings{{{"gms_repair", "1"}},
                                                                   {{"gms_revise", "1"}},
                                                                   {{"gms_simplify", "1"}},
                                                                   {{"gms_improve", "1"}},
                                                                   {{"gms_replace_fraction", "0.2"}},
                                                                   {{"gms_repair", "1"},
                                                                    {"gms_revise", "1"},
                                                                    {"gms_simplify", "1"},
                                                                    {"gms_improve", "1"},
                                                                    {"gms_scope", "all"},
                                                                    {"gms_replace_fraction", "0.1"}}};
    // Seeded and bounded by 10 iterations, so each run's outcome repeats. Measured: every MGO run, and SMA
    // and LRSMA with every switch on (the last setting; LRSMA also with repair alone) end with an exact
    // path; SMA's and LRSMA's other single switches do not within 10 iterations. Those must stay exact
    // (checked below); any other run must at least end with an approximate solution.
    const std::set<std::string> mustBeExact{"MGO/0", "MGO/1", "MGO/2",   "MGO/3",  "MGO/4",
                                            "MGO/5", "SMA/5", "LRSMA/0", "LRSMA/5"};
    std::set<std::string> exact;
    for (const std::string name : {"SMA", "LRSMA", "MGO"})
        for (std::size_t k = 0; k < settings.size(); ++k)
        {
            auto params = settings[k];
            og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
            params["seed"] = "3";
            params["max_iterations"] = "10";
            const ob::PlannerPtr p = builtinPlanners().create(name, ss->getSpaceInformation(), params);
            ss->setPlanner(p);
            const ob::PlannerStatus status = ss->solve(ob::PlannerTerminationCondition([] { return false; }));
            if (status != ob::PlannerStatus::EXACT_SOLUTION)
            {
                EXPECT_EQ(status, ob::PlannerStatus::APPROXIMATE_SOLUTION) << name << " setting " << k;
                continue;
            }
            exact.insert(name + "/" + std::to_string(k));
            const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
            for (std::size_t i = 1; i < pts.size(); ++i)
                EXPECT_TRUE(check->segmentValid(pts[i - 1], pts[i])) << name;
            EXPECT_GE(polylineLength(pts), optimum - 1e-6) << name;
            EXPECT_NEAR(polylineLength(pts),
                        std::stod(p->getPlannerProgressProperties().at("best cost REAL")()), 1e-9);
        }
    for (const std::string &run : mustBeExact)
        EXPECT_EQ(exact.count(run), 1u) << run << " ended without an exact path";
}

namespace
{
    /** \brief Exact, allocation-free motion check against one disc obstacle (centre (5, 5), radius 2). */
    class DiscMotionValidator : public ob::MotionValidator
    {
      public:
        using ob::MotionValidator::MotionValidator;
        static bool free(double x, double y) { return (x - 5) * (x - 5) + (y - 5) * (y - 5) > 4.0; }
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            const double *a = s1->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = s2->as<ob::RealVectorStateSpace::StateType>()->values;
            const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
            const double u = l2 > 0 ? std::clamp(((5 - a[0]) * dx + (5 - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
            return free(a[0] + u * dx, a[1] + u * dy);
        }
        bool checkMotion(const ob::State *, const ob::State *,
                         std::pair<ob::State *, double> &) const override
        {
            return false;
        }
    };
} // namespace

TEST(GmsOperators, OperatorStepAllocatesNothingOnceWarm)
{
    // A continued solve() of 10 iterations allocates the same with every operator on (all individuals,
    // replacement) as without: only the solution report allocates, not the operator step. (A problem with an
    // allocation-free validator: the analytic collision model's segmentValid allocates by itself.)
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    std::vector<unsigned long> counts;
    for (const bool on : {false, true})
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 10.0);
        og::SimpleSetup ss(space);
        ss.setStateValidityChecker(
            [](const ob::State *s)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                return DiscMotionValidator::free(v[0], v[1]);
            });
        ss.getSpaceInformation()->setMotionValidator(
            std::make_shared<DiscMotionValidator>(ss.getSpaceInformation()));
        ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
        start[0] = 1.0;
        start[1] = 5.2;
        goal[0] = 9.0;
        goal[1] = 4.9;
        ss.setStartAndGoalStates(start, goal);
        ss.setOptimizationObjective(
            std::make_shared<ob::PathLengthOptimizationObjective>(ss.getSpaceInformation()));
        auto sma = std::make_shared<SlimeMould>(ss.getSpaceInformation());
        sma->setSeed(5);
        sma->setMaxIterations(10);
        if (on)
        {
            for (const char *s : kSwitches)
                ASSERT_TRUE(sma->params().setParam(s, "1"));
            ASSERT_TRUE(sma->params().setParam("gms_scope", "all"));
            ASSERT_TRUE(sma->params().setParam("gms_replace_fraction", "0.2"));
        }
        ss.setPlanner(sma);
        for (int warm = 0; warm < 3; ++warm)
            ss.solve(ob::PlannerTerminationCondition([] { return false; }));
        ASSERT_TRUE(ss.haveExactSolutionPath());
        ss.getProblemDefinition()->clearSolutionPaths();
        const unsigned long evaluations = sma->evaluationCount();
        const unsigned long before = test::heapAllocations();
        sma->solve(ob::PlannerTerminationCondition([] { return false; }));
        counts.push_back(test::heapAllocations() - before);
        EXPECT_GE(sma->evaluationCount() - evaluations, on ? 600u : 300u);
    }
    EXPECT_EQ(counts[0], counts[1]) << "faithful " << counts[0] << ", with the operators " << counts[1];
}

TEST(GmsOperators, VariantsOnBfoCase2AtThePapersBudgets)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = seedWorld("bfo_case2");
    const double optimum = computeOptimum(world, world.queries[0]).length;
    EXPECT_NEAR(optimum, 14.4198, 1e-3);
    // Measured (20 seeds, N = 30, 30 iterations); asserted with a small margin.
    // Measured: SMA-OPS 20/20, 1.18%; LRSMA-OPS 20/20, 0.53%; MGO-OPS 20/20, 4.58% (faithful SMA, LRSMA,
    // MGO: about +22%, see test_metaheuristics).
    const std::map<std::string, std::pair<unsigned int, double>> expected{
        {"SMA-OPS", {19, 2.5}}, {"LRSMA-OPS", {19, 1.5}}, {"MGO-OPS", {19, 6.0}}};
    for (const auto &e : expected)
    {
        const Outcome o = run20(world, optimum, e.first);
        std::cout << std::setw(10) << e.first << " bfo_case2: exact " << o.exact << "/20, median gap "
                  << std::setprecision(4) << o.medianGapPercent << "%, best gap " << o.bestGapPercent
                  << "%, evaluations " << o.evaluations << "\n";
        EXPECT_GE(o.exact, e.second.first) << e.first;
        EXPECT_LE(o.medianGapPercent, e.second.second) << e.first;
        EXPECT_GE(o.bestGapPercent, -1e-6) << e.first << " beats the optimum";
    }
}

// Faithful vs variant on every shipped seed world (for the report; run with --gtest_also_run_disabled_tests).
TEST(GmsOperators, DISABLED_AllSeedWorldsFaithfulVersusVariant)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const std::string w :
         {"bfo_case1", "bfo_case1_moved", "bfo_case2", "lrsma_scenario1", "lrsma_scenario2",
          "lrsma_scenario3", "gms_grid10", "gms_grid20", "gms_grid30"})
    {
        const World world = seedWorld(w);
        const double optimum = computeOptimum(world, world.queries[0]).length;
        for (const std::string name : {"SMA", "SMA-OPS", "LRSMA", "LRSMA-OPS", "MGO", "MGO-OPS"})
        {
            const Outcome o = run20(world, optimum, name);
            std::cout << std::setw(16) << w << " " << std::setw(10) << name << ": exact " << std::setw(2)
                      << o.exact << "/20, median gap " << std::setprecision(4) << o.medianGapPercent << "%\n";
        }
    }
}

// The faithful algorithms with about the variants' evaluation budget on bfo_case2 (more iterations, schedule
// stretched to match), to separate the operators' effect from the extra evaluations (for the report).
TEST(GmsOperators, DISABLED_FaithfulWithTheVariantsBudget)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = seedWorld("bfo_case2");
    const double optimum = computeOptimum(world, world.queries[0]).length;
    for (const auto &c :
         std::vector<std::pair<std::string, std::string>>{{"SMA", "60"}, {"LRSMA", "52"}, {"MGO", "38"}})
    {
        const Outcome o =
            run20(world, optimum, c.first, {{"iterations", c.second}, {"max_iterations", c.second}});
        std::cout << c.first << " T = " << c.second << ": exact " << o.exact << "/20, median gap "
                  << std::setprecision(4) << o.medianGapPercent << "%, evaluations per run "
                  << o.evaluations / 20 << "\n";
    }
}

TEST(GaWalk, RandomLatticePathIsCollisionFreeSeededAndFailsWhenEnclosed)
{
    const World world = seedWorld("gms_grid30");
    og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
    ss->getSpaceInformation()->setup();
    PathFitness fit(ss->getSpaceInformation());
    fit.configure(FitnessKind::FeasibleInfeasible, FitnessWeights());
    const Box box = world.bounds;
    const double step = 0.01 * std::max(box.width(), box.height());
    const CollisionModelPtr check = makeCollisionModel(world); // independent of the fitness' checker
    auto walk = [&](std::uint32_t seed, std::vector<Vec2> &path)
    {
        ompl::RNG rng(seed);
        PathOperators ops(fit, rng, box, step);
        return ops.randomLatticePath(path, world.queries[0].start, world.queries[0].goal, 20000);
    };
    std::vector<Vec2> a, b, c;
    ASSERT_TRUE(walk(1, a));
    ASSERT_TRUE(walk(1, b));
    ASSERT_TRUE(walk(2, c));
    EXPECT_EQ(a, b); // same seed, same walk
    EXPECT_NE(a, c); // another seed, another walk
    EXPECT_EQ(a.front(), world.queries[0].start);
    EXPECT_EQ(a.back(), world.queries[0].goal);
    for (std::size_t i = 1; i < a.size(); ++i)
        ASSERT_TRUE(check->segmentValid(a[i - 1], a[i])) << i;
    for (std::size_t i = 0; i < a.size(); ++i) // no loops: every node once
        for (std::size_t j = i + 1; j < a.size(); ++j)
            ASSERT_NE(a[i], a[j]);

    // A goal inside a closed box: the walk gives up (false) after its budget, it does not hang.
    World closed;
    closed.name = "closed";
    closed.bounds = {0, 10, 0, 10};
    closed.polygons.push_back(
        makePolygon({{5.9, 5.9}, {9.1, 5.9}, {9.1, 6.2}, {5.9, 6.2}})); // overlapping walls:
    closed.polygons.push_back(
        makePolygon({{5.9, 8.8}, {9.1, 8.8}, {9.1, 9.1}, {5.9, 9.1}})); // no gap along a
    closed.polygons.push_back(makePolygon({{5.9, 5.9}, {6.2, 5.9}, {6.2, 9.1}, {5.9, 9.1}})); // shared edge
    closed.polygons.push_back(makePolygon({{8.8, 5.9}, {9.1, 5.9}, {9.1, 9.1}, {8.8, 9.1}}));
    closed.queries.push_back({"default", {1, 1}, {7.5, 7.5}});
    og::SimpleSetupPtr cs = makeSimpleSetup(closed, closed.queries[0], makeCollisionModel(closed));
    cs->getSpaceInformation()->setup();
    PathFitness cfit(cs->getSpaceInformation());
    cfit.configure(FitnessKind::FeasibleInfeasible, FitnessWeights());
    ompl::RNG rng(3);
    PathOperators ops(cfit, rng, closed.bounds, 0.1);
    std::vector<Vec2> none;
    EXPECT_FALSE(ops.randomLatticePath(none, {1, 1}, {7.5, 7.5}, 5000));
}

TEST(GaWalk, VariantSolvesTheGridThatTheFaithfulGaMisses)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = seedWorld("gms_grid20");
    const double optimum = computeOptimum(world, world.queries[0]).length;
    // 20 seeds, N = 50, 20 generations (the paper's G = 100 takes ~5x longer and only helps GA-WALK).
    // Measured: GA 11/20 exact (median gap unbounded), GA-WALK 20/20 (median gap ~3 %).
    const std::map<std::string, std::string> params{{"population_size", "50"}, {"max_iterations", "20"}};
    const Outcome walk = run20(world, optimum, "GA-WALK", params);
    const Outcome nodes = run20(world, optimum, "GA", params);
    std::cout << "gms_grid20: GA-WALK exact " << walk.exact << "/20, median gap " << walk.medianGapPercent
              << "%; GA exact " << nodes.exact << "/20, median gap " << nodes.medianGapPercent << "%\n";
    EXPECT_EQ(walk.exact, 20u);
    EXPECT_LE(walk.medianGapPercent, 5.0);
    EXPECT_GE(walk.bestGapPercent, -1e-6);
    EXPECT_LT(nodes.exact, walk.exact);
}
