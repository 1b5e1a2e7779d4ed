// SPDX-License-Identifier: BSD-3-Clause
/* Issue 17, faithful to the seed papers (docs/algorithms.md, the corrections of 2026-12-01): for each
   correction a trace on a constructed problem where the paper's rule and the old rule differ.
   - LRSMA's stagnation monitor (eq 8): rotation on the third consecutive stagnant iteration, not the second;
   - ATBFO's imp_count (Pseudo code 1): the tumble move is not counted;
   - [GMS]'s SMA reads maximised reciprocal fitness values (its p and weights differ from the sum form);
   - [GMS]'s SMA and MGO apply node repair, line-segment repair and node improvement to the initial
   population;
   - the GA's crossover finds a common node within a tolerance (or by cell on grids), not by exact equality.
 */
#include "benchmarks/Campaign.h"
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "ompl_planners/common/Fitness.h"
#include "ompl_planners/field/BacterialColony.h"
#include "ompl_planners/population/Genetic.h"
#include "ompl_planners/population/LRSMA.h"
#include "ompl_planners/population/SlimeMould.h"
#include "src/registry/Registry.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <map>
#include <string>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    World seedWorld(const std::string &name)
    {
        return loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
    }

    /** \brief A registry planner set up on a seed world with \e params; the problem stays alive with it. */
    struct PlannerRun
    {
        og::SimpleSetupPtr ss;
        ob::PlannerPtr planner;
    };

    PlannerRun makeRun(const std::string &world, const std::string &planner,
                       const std::map<std::string, std::string> &params)
    {
        const World w = seedWorld(world);
        PlannerRun r;
        r.ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
        r.planner = builtinPlanners().create(planner, r.ss->getSpaceInformation());
        applyPlannerParameters(*r.planner, params);
        r.ss->setPlanner(r.planner);
        r.ss->setup();
        return r;
    }

    ob::PlannerStatus solveUnbounded(const PlannerRun &r)
    {
        return r.planner->solve(ob::PlannerTerminationCondition([] { return false; }));
    }
} // namespace

// ------------------------------------------------------------------------------------------------------------
// 4. LRSMA's stagnation monitor, eq 8: tau(t) is read before its update.

TEST(Fidelity, StagnationMonitorRotatesOnTheThirdStagnantIteration)
{
    // A constructed best-fitness sequence F(0..12): changes of 0.1 (stagnant, Fmin = 1) except one jump.
    const std::vector<double> F{100, 99.9, 99.8, 99.7, 99.6, 99.5, 99.4, 90.0, 89.9, 89.8, 89.7, 89.6, 89.5};
    StagnationMonitor paper(1.0, 2);
    std::vector<int> fired;
    // The old rule (increment, then test tau == Tmax), for contrast.
    unsigned int oldTau = 0;
    std::vector<int> oldFired;
    for (std::size_t t = 1; t < F.size(); ++t)
    {
        const double dF = std::abs(F[t] - F[t - 1]);
        if (paper.update(dF))
            fired.push_back(static_cast<int>(t));
        if (dF < 1.0 && oldTau < 2)
            ++oldTau;
        if (oldTau == 2 && dF < 1.0)
        {
            oldTau = 0;
            oldFired.push_back(static_cast<int>(t));
        }
        if (dF >= 1.0)
            oldTau = 0;
    }
    // Stagnant at t = 1..6 (rotations on the 3rd and 6th), reset at t = 7 (dF = 9.4), stagnant at 8..12
    // (rotation on the 3rd: t = 10).
    EXPECT_EQ(fired, (std::vector<int>{3, 6, 10}));
    EXPECT_EQ(oldFired, (std::vector<int>{2, 4, 6, 9, 11}));
    EXPECT_EQ(paper.tau(), 2u); // t = 11, 12 stagnant after the rotation at 10
}

TEST(Fidelity, LrsmaCountsOneRotationPerThreeStagnantIterations)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    // Fmin huge: every iteration is stagnant, so 9 iterations give rotations at 3, 6, 9 (the old rule: 4).
    const PlannerRun r = makeRun("lrsma_scenario1", "LRSMA",
                                 {{"seed", "3"}, {"stagnation_tolerance", "1e9"}, {"max_iterations", "9"}});
    solveUnbounded(r);
    const auto &lrsma = dynamic_cast<const LRSMA &>(*r.planner);
    EXPECT_EQ(lrsma.iterationCount(), 9u);
    EXPECT_EQ(lrsma.rotationCount(), 3u);
    // Fmin = 0: never stagnant, never a rotation.
    const PlannerRun never = makeRun("lrsma_scenario1", "LRSMA",
                                     {{"seed", "3"}, {"stagnation_tolerance", "0"}, {"max_iterations", "9"}});
    solveUnbounded(never);
    EXPECT_EQ(dynamic_cast<const LRSMA &>(*never.planner).rotationCount(), 0u);
}

// ------------------------------------------------------------------------------------------------------------
// 5. ATBFO's imp_count counts the improving swims only.

namespace
{
    /** \brief One bacterium on a line, always tumbling toward +x: J = |x - target|. */
    class LineProblem : public ColonyProblem
    {
      public:
        explicit LineProblem(double target) : target_(target) {}
        double cost(const double *x) override { return std::abs(x[0] - target_); }
        void randomPosition(double *x) override { x[0] = 0.0; }
        void constrain(double * /*x*/) override {}
        void randomDirection(double *phi, unsigned int /*dim*/, ompl::RNG & /*rng*/) override
        {
            phi[0] = 1.0;
        }

      private:
        double target_;
    };

    /** \brief Whether the single bacterium keeps its direction after one chemotactic step toward \e target
        (step C = 1, Ns = 6, F_improv = 3). */
    bool keepsAfterOneStep(double target)
    {
        ColonySettings s;
        s.stepSize = 1.0;
        s.swimLength = 6;
        s.improvementThreshold = 3;
        s.adaptiveTumble = true;
        s.chemotacticSteps = 8;
        BacterialColony colony(s);
        LineProblem problem(target);
        ompl::RNG rng(1);
        colony.start(1, 1, problem);
        EXPECT_EQ(colony.step(problem, rng), BacterialColony::Step::StepDone);
        return colony.keepsDirection(0);
    }
} // namespace

TEST(Fidelity, AtbfoDoesNotCountTheTumbleAsAnImprovement)
{
    // From x = 0 toward target 4: the tumble to 1 improves, the swims to 2, 3, 4 improve (3), the swim to 5
    // does not. Pseudo code 1: imp_count = 3, not > F_improv = 3: a fresh direction. (The old count, 4 with
    // the tumble, kept it.)
    EXPECT_FALSE(keepsAfterOneStep(4.0));
    // Target 5: four improving swims: kept.
    EXPECT_TRUE(keepsAfterOneStep(5.0));
    // Target 10: the swim stops after Ns = 6 improving swims: imp_count = 6 = Ns at most, kept.
    EXPECT_TRUE(keepsAfterOneStep(10.0));
}

// ------------------------------------------------------------------------------------------------------------
// 2. [GMS]'s SMA reads maximised reciprocals: p and the weights differ from the sum form.

TEST(Fidelity, SmaCoefficientsOfTheReciprocalFitnessDifferFromTheSumForm)
{
    // Three feasible paths with f1 denominators 15, 16, 20 (best, middle, worst) and best-ever 15.
    const double d[3] = {15.0, 16.0, 20.0};
    // Sum form (minimised denominators): p = tanh|S - DF| = tanh(1) for the middle one; the weight term.
    const double pSum = SlimeMould::oscillationProbability(d[1], d[0]);
    const double wSum = SlimeMould::weightTerm(d[0], d[2], d[1], false);
    // Paper's form (maximised f1 = 1 / denominator).
    const double f[3] = {1.0 / d[0], 1.0 / d[1], 1.0 / d[2]};
    const double pMax = SlimeMould::oscillationProbability(f[1], f[0]);
    const double wMax = SlimeMould::weightTerm(f[0], f[2], f[1], true);
    EXPECT_NEAR(pSum, std::tanh(1.0), 1e-12);
    EXPECT_NEAR(pMax, std::tanh(1.0 / 15.0 - 1.0 / 16.0), 1e-12);
    EXPECT_LT(pMax, 0.01); // the vc branch dominates in [GMS]'s SMA
    EXPECT_NEAR(wSum, std::log10(1.0 / 5.0 + 1.0), 1e-9);
    // (1/15 - 1/16) / (1/15 - 1/20) = (1/240) / (1/60) = 0.25
    EXPECT_NEAR(wMax, std::log10(0.25 + 1.0), 1e-9);
    EXPECT_GT(std::abs(wMax - wSum), 0.01);
    // Best and worst give the ends of the range in both forms.
    EXPECT_NEAR(SlimeMould::weightTerm(f[0], f[2], f[0], true), 0.0, 1e-12);
    EXPECT_NEAR(SlimeMould::weightTerm(f[0], f[2], f[2], true), std::log10(2.0), 1e-9);
    EXPECT_NEAR(SlimeMould::weightTerm(d[0], d[2], d[2], false), std::log10(2.0), 1e-9);
    // A value above bF (an infeasible path of higher f2 ranked below a feasible one) is clamped to [0, 1].
    EXPECT_NEAR(SlimeMould::weightTerm(f[1], f[2], f[0], true), 0.0, 1e-12);
    EXPECT_NEAR(SlimeMould::weightTerm(f[0], f[1], f[2], true), std::log10(2.0), 1e-12);
}

TEST(Fidelity, GmsSmaRunsOnTheMaximisedValues)
{
    // Same seed, same problem: SMA with the [GMS] fitness (maximised values in its update) and the same
    // planner with the [LRSMA] fitness follow different traces; SMA-GMS's fitness is gms.
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const std::map<std::string, std::string> common{
        {"seed", "4"}, {"max_iterations", "30"}, {"decoding", "polyline"}};
    auto withFitness = [&](const std::string &fit)
    {
        auto params = common;
        params["fitness"] = fit;
        const PlannerRun r = makeRun("gms_grid10", "SMA", params);
        solveUnbounded(r);
        return dynamic_cast<const SlimeMould &>(*r.planner).bestCost();
    };
    const double gms = withFitness("gms"), lrsma = withFitness("lrsma");
    EXPECT_NE(gms, lrsma);
    const PlannerRun faithful = makeRun("gms_grid10", "SMA-GMS", {{"seed", "4"}, {"max_iterations", "5"}});
    solveUnbounded(faithful);
    EXPECT_EQ(dynamic_cast<const SlimeMould &>(*faithful.planner).fitnessKind(),
              FitnessKind::FeasibleInfeasible);
}

// ------------------------------------------------------------------------------------------------------------
// 1. [GMS]'s SMA and MGO: the operators on the initial population.

TEST(Fidelity, GmsInitialOperatesOnEveryIndividualOfTheInitialPopulation)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const std::string planner : {"SMA", "MGO"})
    {
        // Only gms_initial on: N initial evaluations + N operated candidates, then one iteration (SMA: N,
        // MGO: 4N). Without it: no operated candidate.
        const unsigned int n = 10, perIteration = planner == "SMA" ? n : 4 * n;
        std::map<std::string, std::string> p{{"seed", "2"},
                                             {"population_size", std::to_string(n)},
                                             {"max_iterations", "1"},
                                             {"decoding", "polyline"}};
        const PlannerRun off = makeRun("bfo_case2", planner, p);
        solveUnbounded(off);
        p["gms_initial"] = "1";
        const PlannerRun on = makeRun("bfo_case2", planner, p);
        solveUnbounded(on);
        const auto &a = dynamic_cast<const PopulationPlanner &>(*off.planner);
        const auto &b = dynamic_cast<const PopulationPlanner &>(*on.planner);
        EXPECT_EQ(a.evaluationCount(), n + perIteration) << planner;
        EXPECT_EQ(b.evaluationCount(), 2 * n + perIteration) << planner;
    }
    // The faithful [GMS] versions have it on, with the per-iteration operators and replacement.
    for (const std::string planner : {"SMA-GMS", "MGO-GMS"})
    {
        const PlannerRun r = makeRun("bfo_case2", planner, {{"seed", "2"}, {"max_iterations", "2"}});
        solveUnbounded(r);
        const auto &pp = dynamic_cast<const PopulationPlanner &>(*r.planner);
        EXPECT_TRUE(pp.gmsSettings().initial);
        // 30 initial + 30 operated + per iteration: the update, 30 revised/simplified, 3 replaced + 3
        // operated.
        const unsigned long update = planner == "SMA-GMS" ? 30 : 120;
        EXPECT_EQ(pp.evaluationCount(), 60 + 2 * (update + 30 + 6)) << planner;
    }
}

// ------------------------------------------------------------------------------------------------------------
// GA: the crossover's common node by tolerance or by cell.

TEST(Fidelity, GaCommonNodeWithinATolerance)
{
    const Genetic::Individual a{{0, 0}, {2, 3}, {5, 5}, {10, 10}};
    const Genetic::Individual b{{0, 0}, {3, 1}, {5.0 + 1e-9, 5.0 - 1e-9}, {10, 10}};
    std::size_t ia = 0, ib = 0;
    // Exact equality (tolerance 0, the old rule) misses the node that is not a bit-identical copy.
    EXPECT_FALSE(Genetic::findCommonNode(a, b, 0, 0.0, nullptr, ia, ib));
    ASSERT_TRUE(Genetic::findCommonNode(a, b, 0, 0.1, nullptr, ia, ib));
    EXPECT_EQ(ia, 2u);
    EXPECT_EQ(ib, 2u);
    // Nodes 1 m apart are not common under a 0.1 m tolerance.
    const Genetic::Individual c{{0, 0}, {6, 5}, {10, 10}};
    EXPECT_FALSE(Genetic::findCommonNode(a, c, 0, 0.1, nullptr, ia, ib));
    // On a grid of 1 m cells: (5.2, 5.7) and (5.9, 5.1) share cell (5, 5); (6, 5) does not.
    OccupancyGrid grid(10, 10, 1.0);
    EXPECT_TRUE(Genetic::sameNode({5.2, 5.7}, {5.9, 5.1}, 0.0, &grid));
    EXPECT_FALSE(Genetic::sameNode({5.9, 5.1}, {6.0, 5.1}, 0.0, &grid));
    ASSERT_TRUE(Genetic::findCommonNode(a, c, 0, 0.0, &grid, ia, ib) == false);
    const Genetic::Individual d{{0, 0}, {5.7, 5.2}, {10, 10}};
    ASSERT_TRUE(Genetic::findCommonNode(a, d, 0, 0.0, &grid, ia, ib));
    EXPECT_EQ(ia, 2u);
    EXPECT_EQ(ib, 1u);
}

// ------------------------------------------------------------------------------------------------------------
// 7. The default campaign compares like with like: ATBFO runs, [LRSMA]'s 100 runs per planner, [GMS]'s SMA /
// MGO.

TEST(Fidelity, DefaultCampaignRunsThePapersPlannersAndRunCounts)
{
    const std::string file = std::string(MHPLAN_ENVIRONMENTS_DIR) + "/../benchmarks/seeds.yaml";
    std::ifstream in(file);
    ASSERT_TRUE(in) << file;
    std::stringstream text;
    text << in.rdbuf();
    const bench::Campaign c = bench::parseCampaign(text.str(), file);
    std::map<std::string, unsigned int> runs;
    for (const auto &p : c.planners)
        runs[p.planner] = bench::runsOf(c, p);
    for (const char *name :
         {"ATBFO", "BFO", "SMA-GMS", "MGO-GMS", "GA", "SMA", "LRSMA", "MGO", "GWO", "WOA", "PSO"})
        EXPECT_EQ(runs.count(name), 1u) << name;
    // All five rows of [LRSMA] Table 3 (GWO, WOA, PSO, SMA, LRSMA) and MGO.
    for (const char *name : {"SMA", "LRSMA", "MGO", "GWO", "WOA", "PSO"})
        EXPECT_EQ(runs[name], 100u) << name << ": [LRSMA] Table 3 has 100 runs per algorithm";
    // The memetic planners beside OMPL's anytime baselines (issue 31), each with enough runs for a median and
    // its 95 % interval (benchmarks/seeds.yaml: 8 runs of each memetic planner paid for by 12 of each
    // baseline).
    for (const char *name : {"GA-MEM", "SMA-MEM", "LRSMA-MEM", "MGO-MEM"})
        EXPECT_GE(runs[name], 8u) << name;
    for (const char *name : {"RRTstar", "InformedRRTstar", "BITstar"})
        EXPECT_GE(runs[name], 12u) << name;
    // A planner's runs must be a positive integer; the message names the field.
    try
    {
        bench::parseCampaign("campaign: c\nworlds: [bfo_case1]\nplanners:\n  - {planner: SMA, runs: 0}\n",
                             "x.yaml");
        ADD_FAILURE() << "runs: 0 accepted";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("planners[0].runs"), std::string::npos) << e.what();
    }
}

TEST(Fidelity, GmsInfeasibleBaseIsAParameter)
{
    // D of f2: the path's own f1 denominator (default) or a constant (20 x the sum of the bounds' sides).
    World world;
    world.name = "one_circle";
    world.bounds = {0, 10, 0, 10};
    world.circles.push_back({{5, 5}, 1.0});
    world.queries.push_back({"default", {0, 5}, {10, 5}});
    og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
    ss->getSpaceInformation()->setup();
    PathFitness fit(ss->getSpaceInformation());
    FitnessWeights w;
    fit.configure(FitnessKind::FeasibleInfeasible, w);
    const std::vector<Vec2> straight{{0, 5}, {10, 5}};
    const FitnessResult a = fit.evaluate(straight, straight);
    EXPECT_NEAR(a.fitness, fit.gmsFeasibleFitness(straight) + a.violation, 1e-9);
    w.infeasibleBaseIsPath = false;
    fit.configure(FitnessKind::FeasibleInfeasible, w);
    const FitnessResult b = fit.evaluate(straight, straight);
    EXPECT_NEAR(b.fitness, 20.0 * (10.0 + 10.0) + b.violation, 1e-9);
    EXPECT_NEAR(b.gmsValue, 1.0 / b.fitness, 1e-15);
    // The planner parameter.
    const PlannerRun r = makeRun("bfo_case1", "GA", {{"infeasible_base", "constant"}});
    EXPECT_EQ(r.planner->params()["infeasible_base"].getValue(), "constant");
    EXPECT_THROW(applyPlannerParameters(*r.planner, {{"infeasible_base", "zero"}}), InputError);
}
