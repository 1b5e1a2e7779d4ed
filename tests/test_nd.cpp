// SPDX-License-Identifier: BSD-3-Clause
/* mhplan's population planners on RealVectorStateSpaces of any dimension, through OMPL's C++ API with the
   user's own validity checker and OMPL's DiscreteMotionValidator (no mhplan world, checker or validator):

       [0,1]^k, k = 3 and 6, one hypersphere obstacle of radius 0.25 at the centre
       start (0.05, ..., 0.05)  ->  goal (0.95, ..., 0.95): the straight line runs through the sphere.

   Every returned path is checked independently (densely sampled against the sphere, not through the
   planner's motion validator), and setup() refuses unsupported spaces with a clear ompl::Exception. */
#include "ompl_planners/common/Fitness.h"
#include "ompl_planners/common/PopulationPlanner.h"
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "src/registry/Registry.h"
#include "ompl_planners/population/SlimeMould.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include "AllocationCounter.h"
#include "EvaluationProbe.h"

#include "RegistrySupport.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    constexpr double kRadius = 0.25;

    /** \brief Distance from the centre of [0,1]^k minus the sphere's radius (negative inside). */
    double sphereClearance(const double *v, unsigned int k)
    {
        double s = 0.0;
        for (unsigned int j = 0; j < k; ++j)
            s += (v[j] - 0.5) * (v[j] - 0.5);
        return std::sqrt(s) - kRadius;
    }

    /** \brief A user-written checker that also reports an exact clearance (specs say so). */
    class SphereChecker : public ob::StateValidityChecker
    {
      public:
        explicit SphereChecker(const ob::SpaceInformationPtr &si) : ob::StateValidityChecker(si)
        {
            specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
        }
        bool isValid(const ob::State *s) const override { return clearance(s) >= 0.0; }
        double clearance(const ob::State *s) const override
        {
            return sphereClearance(s->as<ob::RealVectorStateSpace::StateType>()->values,
                                   si_->getStateDimension());
        }
    };

    /** \brief The problem above; \e clearanceChecker selects SphereChecker, else a plain lambda (whose
        clearance OMPL reports as not computed). */
    og::SimpleSetupPtr sphereProblem(unsigned int k, bool clearanceChecker)
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(k);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        if (clearanceChecker)
            si->setStateValidityChecker(std::make_shared<SphereChecker>(si));
        else
            si->setStateValidityChecker(
                [k](const ob::State *s)
                { return sphereClearance(s->as<ob::RealVectorStateSpace::StateType>()->values, k) >= 0.0; });
        si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
        si->setStateValidityCheckingResolution(0.0005); // of the extent sqrt(k): about 1 mm
        si->setup();
        auto ss = std::make_shared<og::SimpleSetup>(si);
        ob::ScopedState<> start(space), goal(space);
        for (unsigned int j = 0; j < k; ++j)
        {
            start[j] = 0.05;
            goal[j] = 0.95;
        }
        ss->setStartAndGoalStates(start, goal, 1e-9);
        return ss;
    }

    /** \brief Independent check: every state in [0,1]^k, and every segment outside the sphere at 1e-4
        spacing. */
    ::testing::AssertionResult denselyValid(const og::PathGeometric &path, unsigned int k)
    {
        std::vector<double> a(k), b(k), q(k);
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            const double *v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            for (unsigned int j = 0; j < k; ++j)
                if (v[j] < 0.0 || v[j] > 1.0)
                    return ::testing::AssertionFailure() << "state " << i << " leaves the bounds";
        }
        for (std::size_t i = 1; i < path.getStateCount(); ++i)
        {
            const double *p0 = path.getState(i - 1)->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *p1 = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            double len = 0.0;
            for (unsigned int j = 0; j < k; ++j)
                len += (p1[j] - p0[j]) * (p1[j] - p0[j]);
            const auto steps =
                std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::sqrt(len) / 1e-4)));
            for (std::size_t s = 0; s <= steps; ++s)
            {
                const double u = double(s) / steps;
                for (unsigned int j = 0; j < k; ++j)
                    q[j] = p0[j] + (p1[j] - p0[j]) * u;
                if (sphereClearance(q.data(), k) < 0.0)
                    return ::testing::AssertionFailure()
                           << "segment " << i << " enters the sphere at u = " << u;
            }
        }
        return ::testing::AssertionSuccess();
    }

    /** \brief Length of the shortest path from start to goal: the two tangents from start and goal (at
        distance d from the centre) and the great-circle arc between the tangent points. */
    double shortestAroundSphere(unsigned int k)
    {
        const double d = 0.45 * std::sqrt(double(k));
        const double pi = std::acos(-1.0);
        return 2.0 * std::sqrt(d * d - kRadius * kRadius) + kRadius * (pi - 2.0 * std::acos(kRadius / d));
    }

    ob::PlannerTerminationCondition never()
    {
        return ob::PlannerTerminationCondition([] { return false; });
    }

    ob::PlannerPtr makePlanner(const og::SimpleSetupPtr &ss, const std::string &name, unsigned long seed,
                               unsigned int iterations)
    {
        ob::PlannerPtr p = builtinPlanners().create(
            name, ss->getSpaceInformation(),
            {{"seed", std::to_string(seed)}, {"max_iterations", std::to_string(iterations)}});
        ss->setPlanner(p);
        return p;
    }
} // namespace

// ---------------------------------------------------------------------------------------------------------
// SMA, LRSMA (spline decoding) and MGO find exact, independently valid paths in R^3 and R^6.

class NdPlanner : public ::testing::TestWithParam<std::tuple<std::string, unsigned int, bool>>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};

TEST_P(NdPlanner, FindsAValidPathAroundTheHypersphere)
{
    const auto &[name, k, clearanceChecker] = GetParam();
    og::SimpleSetupPtr ss = sphereProblem(k, clearanceChecker);
    ob::PlannerPtr p = makePlanner(ss, name, 5, 30);
    ASSERT_EQ(ss->solve(never()), ob::PlannerStatus::EXACT_SOLUTION);
    double bestCost = 0.0;
    if (const auto &mp = std::dynamic_pointer_cast<MemeticPlanner>(p))
    {
        // The memetic planners run in their state mode off the plane (docs/spaces.md).
        EXPECT_TRUE(mp->stateMode());
        EXPECT_EQ(mp->iterationCount(), 30u);
        EXPECT_GT(mp->motionCheckCount(), 0u);
        bestCost = mp->bestCost();
    }
    else
    {
        const auto &pp = std::dynamic_pointer_cast<PopulationPlanner>(p);
        ASSERT_TRUE(pp);
        EXPECT_EQ(pp->iterationCount(), 30u);
        EXPECT_EQ(pp->penaltyMode(), clearanceChecker ? PenaltyMode::Clearance : PenaltyMode::ValidityOnly);
        bestCost = pp->bestCost();
    }

    const og::PathGeometric &path = ss->getSolutionPath();
    ASSERT_GE(path.getStateCount(), 3u);
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    EXPECT_EQ(si->distance(path.getState(0), ss->getProblemDefinition()->getStartState(0)), 0.0);
    EXPECT_TRUE(ss->getProblemDefinition()->getGoal()->isSatisfied(path.getState(path.getStateCount() - 1)));
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
        EXPECT_TRUE(si->isValid(path.getState(i))) << "state " << i;
    EXPECT_TRUE(path.check());
    EXPECT_TRUE(denselyValid(path, k));
    // Around the sphere: never shorter than the shortest path (tangent, great-circle arc, tangent; it stays
    // inside the cube), and close to it (measured over seeds 1..20: at most 25% above, median 2-10% above).
    EXPECT_GE(path.length(), shortestAroundSphere(k) - 1e-9);
    EXPECT_LT(path.length(), 1.3 * shortestAroundSphere(k));
    EXPECT_NEAR(path.length(), bestCost, 1e-9);
    // The planner data is the same path, k-dimensional states included.
    ob::PlannerData data(si);
    p->getPlannerData(data);
    ASSERT_EQ(data.numVertices(), path.getStateCount());
    EXPECT_EQ(si->distance(data.getGoalVertex(0).getState(), path.getState(path.getStateCount() - 1)), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Planners, NdPlanner,
                         ::testing::Combine(::testing::ValuesIn(test::mhplanPlanners(
                                                [](const PlannerEntry &e) { return e.runsOn(cap::Rk); },
                                                "N-D")),
                                            ::testing::Values(3u, 6u), ::testing::Bool()),
                         [](const auto &info)
                         {
                             std::string name = std::get<0>(info.param); // GoogleTest names: [A-Za-z0-9_]
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name + "_" + std::to_string(std::get<1>(info.param)) + "D_" +
                                    (std::get<2>(info.param) ? "clearance" : "validityOnly");
                         });

TEST(NdPlanner, GmsFitnessKeepsSplinePathsInsideTheBounds)
{
    // OMPL's checkers and DiscreteMotionValidator ignore the bounds; LRSMA's spline overshoots them, and the
    // [GMS] fitness has no out-of-bounds term: the fitness itself must refuse points outside (measured before
    // that rule: 9 of 10 seeds returned a path leaving [0,1]^6).
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (unsigned long seed = 1; seed <= 3; ++seed)
    {
        og::SimpleSetupPtr ss = sphereProblem(6, true);
        ob::PlannerPtr p = makePlanner(ss, "LRSMA", seed, 30);
        ASSERT_TRUE(p->params().setParam("fitness", "gms"));
        ASSERT_EQ(ss->solve(never()), ob::PlannerStatus::EXACT_SOLUTION) << "seed " << seed;
        EXPECT_TRUE(denselyValid(ss->getSolutionPath(), 6)) << "seed " << seed;
    }
}

TEST(NdPlanner, SameSeedSameTraceIn3D)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto run = [](unsigned long seed)
    {
        og::SimpleSetupPtr ss = sphereProblem(3, false);
        std::vector<double> trace;
        ss->getProblemDefinition()->setIntermediateSolutionCallback(
            [&trace](const ob::Planner *, const std::vector<const ob::State *> &states, const ob::Cost c)
            {
                EXPECT_GE(states.size(), 2u);
                trace.push_back(c.value());
            });
        makePlanner(ss, "LRSMA", seed, 10);
        ss->solve(never());
        return trace;
    };
    const std::vector<double> a = run(3), b = run(3), c = run(4);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

// ---------------------------------------------------------------------------------------------------------
// The encoding and the penalty in R^k.

TEST(NdEncoding, SplineOfEachCoordinateReproducesCubicsIn3D)
{
    // Not-a-knot splines reproduce cubics exactly, coordinate by coordinate.
    auto f = [](unsigned int c, double t) { return (c + 1) * t * t * t - 2.0 * t * t + c * t + 1.0; };
    const unsigned int k = 3, m = 4;
    const double T = m + 1;
    double start[k], goal[k];
    std::vector<double> x;
    for (unsigned int c = 0; c < k; ++c)
    {
        start[c] = f(c, 0.0);
        goal[c] = f(c, T);
    }
    for (unsigned int i = 1; i <= m; ++i)
        for (unsigned int c = 0; c < k; ++c)
            x.push_back(f(c, i));
    WaypointDecoder dec;
    dec.configure(start, goal, k, m, PathDecoding::Spline, 21);
    EXPECT_EQ(dec.dimension(), m * k);
    dec.decode(x.data());
    const PointsView path = dec.pathView();
    ASSERT_EQ(path.size(), 21u);
    ASSERT_EQ(path.dim, k);
    for (std::size_t s = 0; s < path.size(); ++s)
        for (unsigned int c = 0; c < k; ++c)
            EXPECT_NEAR(path[s][c], f(c, T * s / 20.0), 1e-9) << "sample " << s << " coordinate " << c;
    EXPECT_THROW(dec.path(), std::logic_error); // no planar view of a 3D path
}

TEST(NdEncoding, ValidityOnlyPenaltyIsTheFractionOfInvalidSamples)
{
    og::SimpleSetupPtr ss = sphereProblem(3, false);
    PathFitness fit(ss->getSpaceInformation());
    fit.configure(FitnessKind::LengthPenalty, FitnessWeights());
    ASSERT_EQ(fit.penaltyMode(), PenaltyMode::ValidityOnly);
    // Four samples, two inside the sphere (one at its centre, one just inside), one outside the bounds by
    // 0.5.
    const double path[] = {0.0, 0.0, 0.0, 1.0, 1.0, 1.0};
    const double samples[] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.7, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5};
    const FitnessResult r = fit.evaluate(PointsView{path, 2, 3}, PointsView{samples, 4, 3});
    EXPECT_FALSE(r.feasible);
    EXPECT_NEAR(r.violation, (1.0 + 1.0 + 0.0 + 0.5) / 4.0, 1e-12);
    EXPECT_NEAR(r.length, std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(r.fitness, std::sqrt(3.0) + 1000.0 * r.violation, 1e-9);
    // Outside the bounds is invalid even though the user's checker accepts it.
    EXPECT_TRUE(fit.pointValid(samples + 6));
    EXPECT_FALSE(fit.pointValid(samples + 9));
    EXPECT_FALSE(fit.segmentValid(samples + 6, samples + 9));

    // With a clearance-reporting checker the same samples score their penetration depth.
    og::SimpleSetupPtr ss2 = sphereProblem(3, true);
    PathFitness fit2(ss2->getSpaceInformation());
    fit2.configure(FitnessKind::LengthPenalty, FitnessWeights());
    ASSERT_EQ(fit2.penaltyMode(), PenaltyMode::Clearance);
    const FitnessResult r2 = fit2.evaluate(PointsView{path, 2, 3}, PointsView{samples, 4, 3});
    EXPECT_NEAR(r2.violation, (0.25 + 0.05 + 0.0 + 0.5) / 4.0, 1e-12);

    // [GMS] in R^3: a feasible path scores length + danger + 0.1 x the turning angle (90 degrees here).
    fit2.configure(FitnessKind::FeasibleInfeasible, FitnessWeights());
    const double corner[] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.0, 0.1, 0.1};
    const PointsView cp{corner, 3, 3};
    ASSERT_TRUE(fit2.pathValid(cp));
    const double dangerFree = 0.2 + 0.1 * std::acos(0.0);
    EXPECT_GE(fit2.gmsFeasibleFitness(cp), dangerFree);
    FitnessWeights noDanger;
    noDanger.safetyWeight = 0.0;
    fit2.configure(FitnessKind::FeasibleInfeasible, noDanger);
    EXPECT_NEAR(fit2.gmsFeasibleFitness(cp), dangerFree, 1e-12);
}

// ---------------------------------------------------------------------------------------------------------
// What setup() refuses, with a message naming the planner and what it needs.

namespace
{
    /** \brief The message of the ompl::Exception \e f throws ("" when it throws none). */
    template <typename F> std::string thrownMessage(F &&f)
    {
        try
        {
            f();
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
        return "";
    }
} // namespace

class NdRefusal : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
    void TearDown() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};

TEST_P(NdRefusal, SE2StateSpaceIsRefusedAtSetup)
{
    auto space = std::make_shared<ob::SE2StateSpace>();
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0.0);
    bounds.setHigh(1.0);
    space->setBounds(bounds);
    auto ss = std::make_shared<og::SimpleSetup>(space);
    ss->setStateValidityChecker([](const ob::State *) { return true; });
    ob::ScopedState<ob::SE2StateSpace> start(space), goal(space);
    start->setXY(0.1, 0.1);
    goal->setXY(0.9, 0.9);
    ss->setStartAndGoalStates(start, goal);
    // The planners that declare SE(2) (the registry's capabilities, docs/spaces.md)
    // accept SE(2) with the polyline decoding (tests/test_spaces_planners.cpp runs them there); the
    // planar ones refuse it, naming themselves and the space.
    if (builtinPlanners().get(GetParam()).runsOn(cap::SE2))
    {
        ob::PlannerPtr p = builtinPlanners().create(GetParam(), ss->getSpaceInformation(),
                                                    {{"decoding", "polyline"}, {"max_iterations", "2"}});
        ss->setPlanner(p);
        EXPECT_NO_THROW(ss->setup());
        EXPECT_TRUE(p->isSetup());
        EXPECT_NE(p->solve(never()), ob::PlannerStatus::TIMEOUT);
        return;
    }
    ob::PlannerPtr p = builtinPlanners().create(GetParam(), ss->getSpaceInformation(), {});
    ss->setPlanner(p);

    const std::string msg = thrownMessage([&] { ss->setup(); });
    EXPECT_EQ(msg.rfind(GetParam() + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(space->getName()), std::string::npos) << msg;
    EXPECT_FALSE(p->isSetup());
    // solve() sets the planner up first, so it refuses the same way (and never crashes).
    const std::string again = thrownMessage([&] { p->solve(never()); });
    EXPECT_EQ(again, msg);
    EXPECT_FALSE(ss->getProblemDefinition()->hasSolution());
}

// Every population planner: the planar ones refuse SE(2), the others accept it.
INSTANTIATE_TEST_SUITE_P(Planners, NdRefusal, ::testing::ValuesIn(test::ofFamily("population")));

TEST(NdRefusal, GeneticAlgorithmIsPlanarOnly)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    og::SimpleSetupPtr ss = sphereProblem(3, true);
    ob::PlannerPtr p = makePlanner(ss, "GA", 1, 1);
    const std::string msg = thrownMessage([&] { ss->setup(); });
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    EXPECT_EQ(msg.rfind("GA: needs a 2-dimensional RealVectorStateSpace", 0), 0u) << msg;
    EXPECT_NE(msg.find("got dimension 3"), std::string::npos) << msg;
    EXPECT_FALSE(p->isSetup());
}

TEST(NdRefusal, EveryPlanarPopulationOrMemeticPlannerRefusesR3ByName)
{
    // What a registry entry without cap::Rk promises: R^3 is refused at setup, naming the planner and
    // the dimension.
    const std::vector<std::string> planar = test::mhplanPlanners(
        [](const PlannerEntry &e)
        {
            return !e.runsOn(cap::Rk) &&
                   (test::familyOf(e.name) == "population" || test::familyOf(e.name) == "memetic");
        },
        "planar");
    for (const std::string &name : planar)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        og::SimpleSetupPtr ss = sphereProblem(3, true);
        ob::PlannerPtr p = makePlanner(ss, name, 1, 1);
        const std::string msg = thrownMessage([&] { ss->setup(); });
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        EXPECT_EQ(msg.rfind(name + ": ", 0), 0u) << msg;
        EXPECT_NE(msg.find("dimension 3"), std::string::npos) << msg;
        EXPECT_FALSE(p->isSetup()) << name;
    }
}

// ---------------------------------------------------------------------------------------------------------
// No heap allocation per fitness evaluation, in R^6 (with a motion validator that allocates nothing itself:
// OMPL's DiscreteMotionValidator allocates a state per call).

namespace
{
    /** \brief Exact straight-segment test against the sphere (closest point of the segment to the centre).
     */
    class SphereMotionValidator : public ob::MotionValidator
    {
      public:
        explicit SphereMotionValidator(const ob::SpaceInformationPtr &si) : ob::MotionValidator(si) {}
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            const unsigned int k = si_->getStateDimension();
            const double *a = s1->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = s2->as<ob::RealVectorStateSpace::StateType>()->values;
            double ab = 0.0, ac = 0.0;
            for (unsigned int j = 0; j < k; ++j)
            {
                ab += (b[j] - a[j]) * (b[j] - a[j]);
                ac += (0.5 - a[j]) * (b[j] - a[j]);
            }
            const double t = ab > 0.0 ? std::min(1.0, std::max(0.0, ac / ab)) : 0.0;
            double d2 = 0.0;
            for (unsigned int j = 0; j < k; ++j)
            {
                const double q = a[j] + t * (b[j] - a[j]) - 0.5;
                d2 += q * q;
            }
            return d2 >= kRadius * kRadius;
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2,
                         std::pair<ob::State *, double> &) const override
        {
            return checkMotion(s1, s2);
        }
    };

    using EvaluationProbe = test::EvaluationProbe<SlimeMould>;
} // namespace

TEST(NdEvaluation, NoHeapAllocationPerFitnessEvaluation)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const bool clearanceChecker : {false, true})
        for (const char *decoding : {"polyline", "spline"})
            for (const char *fitness : {"lrsma", "gms"})
            {
                og::SimpleSetupPtr ss = sphereProblem(6, clearanceChecker);
                const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
                si->setMotionValidator(std::make_shared<SphereMotionValidator>(si));
                auto probe = std::make_shared<EvaluationProbe>(si);
                probe->setDecoding(decoding);
                probe->setFitness(fitness);
                probe->setSeed(9);
                probe->setMaxIterations(1);
                ss->setPlanner(probe);
                ss->solve(never()); // prepares the problem and the buffers
                std::vector<double> xs(200 * std::size_t(probe->candidateDimension()));
                for (std::size_t i = 0; i < 200; ++i)
                    probe->randomCandidate(xs.data() + i * probe->candidateDimension());
                const unsigned long before = probe->evaluationCount();
                const unsigned long allocations = test::heapAllocations();
                for (std::size_t i = 0; i < 200; ++i)
                    probe->evaluateCandidate(xs.data() + i * probe->candidateDimension());
                EXPECT_EQ(test::heapAllocations() - allocations, 0u)
                    << decoding << " " << fitness << (clearanceChecker ? " clearance" : " validity-only");
                EXPECT_EQ(probe->evaluationCount() - before, 200u);
            }
    // The counter sees allocations: OMPL's DiscreteMotionValidator allocates a state per checkMotion().
    og::SimpleSetupPtr ss = sphereProblem(6, true);
    auto probe = std::make_shared<EvaluationProbe>(ss->getSpaceInformation());
    probe->setFitness("gms");
    probe->setSeed(9);
    probe->setMaxIterations(1);
    ss->setPlanner(probe);
    ss->solve(never());
    // One random candidate may end its first segment inside the obstacle, and the validator then returns
    // before it allocates; fifty candidates (from a fixed seed) always reach a full segment check.
    std::vector<double> xs(50 * std::size_t(probe->candidateDimension()));
    for (std::size_t i = 0; i < 50; ++i)
        probe->randomCandidate(xs.data() + i * probe->candidateDimension());
    const unsigned long allocations = test::heapAllocations();
    for (std::size_t i = 0; i < 50; ++i)
        probe->evaluateCandidate(xs.data() + i * probe->candidateDimension());
    EXPECT_GT(test::heapAllocations() - allocations, 0u);
}
