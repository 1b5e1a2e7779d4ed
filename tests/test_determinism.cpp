// SPDX-License-Identifier: BSD-3-Clause
/* Determinism per seed (docs/conventions.md, "Randomness and seeds"): every planner of the contract registry
   (ContractSupport.h: every built-in mhplan planner and the test's own), run twice from fresh planner objects
   on fresh problems with the same seed, repeats its run; another seed gives another run. */
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "ContractSupport.h"
#include "RegistrySupport.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace mhplan;
using namespace mhplan::contract;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** \brief What a run shows of its randomness: the best-cost trace (the intermediate-solution callback),
        the returned path (exact or approximate), the fitness evaluations (or node expansions). */
    struct SeededRun
    {
        std::vector<double> trace;
        std::vector<Vec2> path;
        unsigned long evaluations{0};
        std::string bestCost;
    };

    /** \brief True when \e planner declares a "seed" parameter. */
    bool takesSeed(const std::string &planner)
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        return contractRegistry()
            .get(planner)
            .allocate(std::make_shared<ob::SpaceInformation>(space))
            ->params()
            .hasParam("seed");
    }

    /** \brief One run of \e planner on a fresh problem (bfo_case1) by a fresh planner object, with \e seed
        (none when empty), iteration-bounded: 5 iterations of a population, 40 steps of a walk, a whole
        lattice search. OMPL's global generator is advanced first, so that a planner drawing from it (not from
        its seed) would not repeat. */
    SeededRun freshRun(const std::string &planner, const std::string &seed)
    {
        ompl::RNG().uniform01();
        og::SimpleSetupPtr ss = seedProblem();
        ob::PlannerPtr p = contractRegistry().get(planner).allocate(ss->getSpaceInformation());
        std::map<std::string, std::string> params{{"max_iterations", isLatticeSearch(planner) ? "0"
                                                                     : isWalk(planner)        ? "40"
                                                                                              : "5"}};
        if (!seed.empty())
            params["seed"] = seed;
        applyPlannerParameters(*p, params);
        ss->setPlanner(p);
        ss->setup();
        SeededRun r;
        ss->getProblemDefinition()->setIntermediateSolutionCallback(
            [&r](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost cost)
            { r.trace.push_back(cost.value()); });
        p->solve(never());
        if (ss->haveSolutionPath())
            r.path = pathPoints(ss->getSolutionPath());
        r.evaluations = evaluations(p);
        r.bestCost = progress(p, "best cost REAL");
        return r;
    }
} // namespace

class PlannerDeterminism : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};

// Same seed, same run, from two fresh planner objects on two fresh problems (not clear() + solve() on one
// object, as SolveContinuesClearResets); another seed, another run. A planner without a seed (the lattice
// searches, APF) repeats from fresh objects too: it draws no random number.
TEST_P(PlannerDeterminism, FreshPlannersSameSeedSameRunAnotherSeedAnotherRun)
{
    const bool seeded = takesSeed(GetParam());
    const SeededRun a = freshRun(GetParam(), seeded ? "7" : "");
    const SeededRun b = freshRun(GetParam(), seeded ? "7" : "");
    ASSERT_GE(a.path.size(), 2u) << "no path returned";
    EXPECT_GT(a.evaluations, 0u);
    EXPECT_EQ(a.trace, b.trace);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(a.bestCost, b.bestCost);
    if (!seeded)
        return;
    // Another seed, another run: a planner whose paths live on a lattice (GA-WALK's walks) can end two
    // seeds on the same best path, so the first of seeds 8, 9, 10 whose run differs from seed 7's in its
    // path or its improvements is taken; none differing means the seed is not used.
    SeededRun c = freshRun(GetParam(), "8");
    for (const char *other : {"9", "10"})
    {
        if (c.path != a.path || c.trace != a.trace)
            break;
        c = freshRun(GetParam(), other);
    }
    ASSERT_GE(c.path.size(), 2u) << "no path returned";
    EXPECT_TRUE(c.path != a.path || c.trace != a.trace) << "seeds 7, 8, 9 and 10 return the same run";
    // Populations report improvements from the first evaluation on; walks only on reaching the goal.
    if (!isWalk(GetParam()))
    {
        ASSERT_FALSE(a.trace.empty());
        EXPECT_NE(a.trace, c.trace) << "seed 7 and another give the same best-cost trace";
    }
}

INSTANTIATE_TEST_SUITE_P(Planners, PlannerDeterminism, ::testing::ValuesIn(contractPlanners()));

TEST(PlannerDeterminismCoverage, EveryPopulationAndMemeticPlannerTakesASeed)
{
    // They are checked with two seeds above only when they take one.
    for (const char *family : {"population", "memetic"})
        for (const std::string &name : test::ofFamily(family))
            EXPECT_TRUE(takesSeed(name)) << name;
    EXPECT_TRUE(takesSeed("StraightLineRestarts"));
}
