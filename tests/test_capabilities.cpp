// SPDX-License-Identifier: BSD-3-Clause
/* The registry's declared capabilities (PlannerEntry::capabilities, docs/spaces.md "Which planner runs
   where") against what every registered planner does: on a problem of each space kind (the shipped worlds of
   R^2, SE(2), Dubins and Reeds-Shepp, and the test's own R^3 and SE(3) problems) setup() accepts exactly the
   declared spaces with default parameters; a checker without clearance is refused exactly by the planners
   that declare cap::NeedsClearance; an anytime planner keeps improving until the termination condition, the
   others return with their first solution; a deterministic planner gives the same path whatever the seed.
   The termination conditions count their calls (no clock). */
#include "RegistrySupport.h"

#include "src/collision/Collision.h"
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace mhplan;

namespace
{
    /** \brief Free outside the ball of radius 0.2 around (0.5, 0.5, 0.5) in the unit cube (the position
        part of SE(3)); reports the exact clearance unless \e clearance is false. */
    class BallChecker : public ob::StateValidityChecker
    {
      public:
        BallChecker(const ob::SpaceInformationPtr &si, bool clearance, double radius)
            : ob::StateValidityChecker(si), radius_(radius)
        {
            specs_.clearanceComputationType =
                clearance ? ob::StateValidityCheckerSpecs::EXACT : ob::StateValidityCheckerSpecs::NONE;
        }
        bool isValid(const ob::State *s) const override
        {
            return si_->satisfiesBounds(s) && clearance(s) > 0.0;
        }
        double clearance(const ob::State *s) const override
        {
            const double *x = nullptr;
            if (const auto *se3 = dynamic_cast<const ob::SE3StateSpace *>(si_->getStateSpace().get()))
            {
                (void)se3;
                x = s->as<ob::SE3StateSpace::StateType>()->as<ob::RealVectorStateSpace::StateType>(0)->values;
            }
            else
                x = s->as<ob::RealVectorStateSpace::StateType>()->values;
            double d2 = 0.0;
            const unsigned int dim = std::min(3u, si_->getStateDimension());
            for (unsigned int i = 0; i < dim; ++i)
                d2 += (x[i] - 0.5) * (x[i] - 0.5);
            return std::sqrt(d2) - radius_;
        }

      private:
        double radius_;
    };

    /** \brief R^dim (dim 2 or 3) in the unit cube, or SE(3) when \e se3, around the ball of radius \e radius,
        from the low corner to the high one (goal threshold \e threshold). */
    og::SimpleSetupPtr ballProblem(unsigned int dim, bool se3, bool clearance, double radius = 0.2,
                                   double threshold = 1e-9)
    {
        ob::StateSpacePtr space;
        if (se3)
        {
            auto s = std::make_shared<ob::SE3StateSpace>();
            ob::RealVectorBounds b(3);
            b.setLow(0.0);
            b.setHigh(1.0);
            s->setBounds(b);
            space = s;
        }
        else
        {
            auto s = std::make_shared<ob::RealVectorStateSpace>(dim);
            s->setBounds(0.0, 1.0);
            space = s;
        }
        auto ss = std::make_shared<og::SimpleSetup>(space);
        ss->setStateValidityChecker(
            std::make_shared<BallChecker>(ss->getSpaceInformation(), clearance, radius));
        ob::ScopedState<> start(space), goal(space);
        if (se3)
        {
            auto *a = start->as<ob::SE3StateSpace::StateType>();
            auto *b = goal->as<ob::SE3StateSpace::StateType>();
            a->setXYZ(0.1, 0.1, 0.1);
            b->setXYZ(0.9, 0.9, 0.9);
            a->rotation().setIdentity();
            b->rotation().setIdentity();
        }
        else
            for (unsigned int i = 0; i < dim; ++i)
            {
                start[i] = 0.1;
                goal[i] = 0.9;
            }
        ss->setStartAndGoalStates(start, goal, threshold);
        ss->setOptimizationObjective(
            std::make_shared<ob::PathLengthOptimizationObjective>(ss->getSpaceInformation()));
        return ss;
    }

    og::SimpleSetupPtr worldProblem(const std::string &file)
    {
        const World world = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + file);
        return makeSimpleSetup(world, world.queries.front(), makeCollisionModel(world));
    }

    /** \brief An easy planar world: one disc on the straight line from start to goal (so that no first
        solution is provably optimal). */
    og::SimpleSetupPtr easyProblem()
    {
        const World world = parseWorldYaml("name: easy\nbounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\n"
                                           "robot: {radius: 0}\nobstacles:\n"
                                           "  - circle: {center: [4.5, 5.5], radius: 1}\n"
                                           "queries:\n  - {name: q, start: [1, 1], goal: [9, 9]}\n",
                                           "easy.yaml");
        return makeSimpleSetup(world, world.queries.front(), makeCollisionModel(world));
    }

    struct SpaceCase
    {
        const char *label;
        unsigned flag;
        std::function<og::SimpleSetupPtr()> make;
    };

    const std::vector<SpaceCase> &spaceCases()
    {
        static const std::vector<SpaceCase> cases{
            {"R2 world bfo_case1", cap::R2, [] { return worldProblem("bfo_case1.yaml"); }},
            {"R3 ball", cap::Rk, [] { return ballProblem(3, false, true); }},
            {"SE2 world se2_narrow_passage", cap::SE2,
             [] { return worldProblem("se2_narrow_passage.yaml"); }},
            {"Dubins world dubins_circles", cap::Dubins, [] { return worldProblem("dubins_circles.yaml"); }},
            {"Reeds-Shepp world reeds_shepp_parking", cap::ReedsShepp,
             [] { return worldProblem("reeds_shepp_parking.yaml"); }},
            {"SE3 ball", cap::SE3, [] { return ballProblem(3, true, true); }},
        };
        return cases;
    }

    /** \brief True when setup() of planner \e name on \e ss succeeds (false when it throws). */
    bool setsUp(const std::string &name, const og::SimpleSetupPtr &ss, ob::PlannerPtr *out = nullptr)
    {
        ob::PlannerPtr p = builtinPlanners().get(name).allocate(ss->getSpaceInformation());
        ss->setPlanner(p);
        try
        {
            ss->setup();
        }
        catch (const ompl::Exception &)
        {
            return false;
        }
        if (out != nullptr)
            *out = p;
        return true;
    }

    /** \brief A termination condition true after \e calls calls. */
    ob::PlannerTerminationCondition afterCalls(std::atomic<long> &count, long calls)
    {
        return ob::PlannerTerminationCondition([&count, calls] { return ++count > calls; });
    }

    class Capabilities : public ::testing::TestWithParam<std::string>
    {
      protected:
        void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
    };
} // namespace

TEST_P(Capabilities, TheDeclaredSpacesAreExactlyTheOnesSetupAccepts)
{
    const std::string &name = GetParam();
    const PlannerEntry &entry = builtinPlanners().get(name);
    for (const SpaceCase &c : spaceCases())
    {
        SCOPED_TRACE(c.label);
        // Seeded before the planner and its sampler exist: OMPL 1.5.2's LBTRRT aborts on an assertion of its
        // DynamicSSSP (an edge of zero weight) in about 1 of 8 unseeded runs of this test (docs/omplapp.md).
        ompl::RNG::setSeed(7);
        og::SimpleSetupPtr ss = c.make();
        EXPECT_EQ(spaceFlag(*ss->getStateSpace()), c.flag);
        const std::string why = builtinPlanners().whyNotApplicable(name, *ss->getSpaceInformation());
        ob::PlannerPtr p;
        const bool accepted = setsUp(name, ss, &p);
        EXPECT_EQ(accepted, entry.runsOn(c.flag)) << name << " declares " << spaceList(entry.capabilities);
        EXPECT_EQ(why.empty(), accepted) << why;
        if (accepted)
        {
            // It runs there: a short solve neither throws nor crashes.
            std::atomic<long> count{0};
            EXPECT_NO_THROW(p->solve(afterCalls(count, 30)));
            continue;
        }
        // The refusal is one sentence naming the planner and a registered planner that does run there.
        EXPECT_EQ(why.rfind(name + " cannot run on ", 0), 0u) << why;
        const auto at = why.find("; ");
        ASSERT_NE(at, std::string::npos) << why;
        const std::string other = why.substr(at + 2, why.find(" runs there") - at - 2);
        ASSERT_TRUE(builtinPlanners().has(other)) << why;
        EXPECT_TRUE(builtinPlanners().get(other).runsOn(c.flag));
        EXPECT_TRUE(setsUp(other, c.make())) << other << " named by: " << why;
    }
}

TEST_P(Capabilities, OnlyThePlannersThatDeclareItNeedClearance)
{
    const std::string &name = GetParam();
    const PlannerEntry &entry = builtinPlanners().get(name);
    og::SimpleSetupPtr ss = ballProblem(2, false, false);
    const bool accepted = setsUp(name, ss);
    EXPECT_EQ(accepted, !entry.has(cap::NeedsClearance)) << name;
    EXPECT_EQ(builtinPlanners().whyNotApplicable(name, *ss->getSpaceInformation()).empty(), accepted);
    EXPECT_TRUE(setsUp(name, ballProblem(2, false, true))) << name;
}

TEST_P(Capabilities, AnAnytimePlannerImprovesUntilTheTerminationConditionTheOthersStopAtTheirSolution)
{
    // With default parameters on an easy problem: the termination condition holds 20 calls after the first
    // solution is known (an intermediate solution reported, a finite "best cost" progress property, or a
    // solution in the problem definition; at most 10^6 calls before). An anytime planner is still running
    // then; any other returns (a walk may end short of the goal: an approximate solution) before the
    // condition ever held.
    const std::string &name = GetParam();
    og::SimpleSetupPtr ss = easyProblem();
    ompl::RNG::setSeed(3);
    ob::PlannerPtr p;
    ASSERT_TRUE(setsUp(name, ss, &p));
    const ob::ProblemDefinitionPtr pdef = ss->getProblemDefinition();
    std::atomic<long> calls{0}, afterSolution{0};
    std::atomic<bool> held{false}, reported{false};
    pdef->setIntermediateSolutionCallback([&](const ob::Planner *, const std::vector<const ob::State *> &,
                                              const ob::Cost) { reported = true; });
    const auto &props = p->getPlannerProgressProperties();
    const auto bestCost = props.find("best cost REAL");
    const auto solved = [&]
    {
        return reported || pdef->hasExactSolution() ||
               (bestCost != props.end() && std::isfinite(std::stod(bestCost->second())));
    };
    const ob::PlannerTerminationCondition ptc(
        [&]
        {
            const bool done = ++calls > 1000000 || (solved() && ++afterSolution > 20);
            if (done)
                held = true;
            return done;
        });
    const ob::PlannerStatus status = p->solve(ptc);
    ASSERT_TRUE(status == ob::PlannerStatus::EXACT_SOLUTION ||
                status == ob::PlannerStatus::APPROXIMATE_SOLUTION)
        << name << ": " << status.asString();
    EXPECT_LE(calls.load(), 1000000) << name << " found no solution";
    EXPECT_EQ(held.load(), builtinPlanners().get(name).has(cap::Anytime))
        << name << ": " << calls << " calls, " << afterSolution << " after the first solution";
}

TEST_P(Capabilities, ADeterministicPlannerGivesTheSamePathWhateverTheSeed)
{
    const std::string &name = GetParam();
    if (!builtinPlanners().get(name).has(cap::Deterministic))
        GTEST_SKIP() << name << " draws random numbers";
    std::vector<std::vector<double>> paths;
    for (const std::uint_fast32_t seed : {1u, 99u})
    {
        og::SimpleSetupPtr ss = easyProblem();
        ompl::RNG::setSeed(seed);
        ob::PlannerPtr p;
        ASSERT_TRUE(setsUp(name, ss, &p));
        if (p->params().hasParam("seed"))
            p->params().setParam("seed", std::to_string(seed));
        std::atomic<long> count{0};
        ASSERT_EQ(p->solve(afterCalls(count, 20000)), ob::PlannerStatus::EXACT_SOLUTION);
        std::vector<double> xy;
        for (const ob::State *s : ss->getSolutionPath().getStates())
            for (unsigned int i = 0; i < 2; ++i)
                xy.push_back(s->as<ob::RealVectorStateSpace::StateType>()->values[i]);
        paths.push_back(xy);
    }
    EXPECT_EQ(paths[0], paths[1]) << name;
}

INSTANTIATE_TEST_SUITE_P(Planners, Capabilities, ::testing::ValuesIn(builtinPlanners().names()),
                         [](const auto &info)
                         {
                             std::string n = info.param;
                             for (char &c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c)))
                                     c = '_';
                             return n;
                         });

TEST(CapabilityNames, SpacesAndWorldsMapToTheirFlags)
{
    EXPECT_EQ(spaceFlag(SpaceType::R2), cap::R2);
    EXPECT_EQ(spaceFlag(SpaceType::SE2), cap::SE2);
    EXPECT_EQ(spaceFlag(SpaceType::Dubins), cap::Dubins);
    EXPECT_EQ(spaceFlag(SpaceType::ReedsShepp), cap::ReedsShepp);
    EXPECT_EQ(spaceFlag(ob::RealVectorStateSpace(1)), cap::Rk);
    EXPECT_EQ(spaceFlag(ob::SO2StateSpace()), cap::OtherSpace);
    EXPECT_EQ(spaceList(cap::R2 | cap::Dubins), "R^2, Dubins");
    EXPECT_EQ(spaceList(cap::Planar), "R^2");
    EXPECT_THROW(builtinPlanners().whyNotApplicable("NoSuchPlanner", cap::R2, "R^2"), InputError);
    // The sentence the programs print: the planner, the space, what it declares, one that runs there.
    // The alternative is a faithful mhplan planner (same origin, faithful first) that runs on SE(2).
    const std::string why = builtinPlanners().whyNotApplicable("GA", cap::SE2, "the SE(2) world 'w'");
    const std::string head = "GA cannot run on the SE(2) world 'w': it plans on R^2 only; ";
    ASSERT_EQ(why.substr(0, head.size()), head);
    const std::string tail = " runs there";
    ASSERT_GT(why.size(), head.size() + tail.size());
    ASSERT_EQ(why.substr(why.size() - tail.size()), tail);
    const PlannerEntry &alternative =
        builtinPlanners().get(why.substr(head.size(), why.size() - head.size() - tail.size()));
    EXPECT_TRUE(alternative.runsOn(cap::SE2)) << why;
    EXPECT_FALSE(alternative.improved()) << why;
    EXPECT_EQ(alternative.origin, "mhplan") << why;
}
