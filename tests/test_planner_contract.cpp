// SPDX-License-Identifier: BSD-3-Clause
/* The contract every mhplan planner keeps (OMPL's Planner API as docs/conventions.md asks): solve / solve
   continues / clear / solve, a termination condition already true returns at once, tiny budgets, refused
   parameters named with their range, progress properties, the intermediate-solution callback, approximate
   solutions when no exact one exists, and foreign (non-mhplan) validity checkers. Lattice searches
   (isLatticeSearch) and potential-field walks (isWalk) keep it too, with the checks adapted where their
   nature differs. */
#include "mhplan/collision/Problem.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/collision/Validity.h"
#include "mhplan/io/WorldIO.h"

#include <ompl/util/Exception.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    std::vector<std::string> mhplanPlanners()
    {
        // The planners of ompl_planners/: population planners (with the [GMS] improved variants), lattice
        // searches and potential-field walks (other mhplan planners join when they register).
        std::vector<std::string> out;
        for (const char *name : {"SMA", "LRSMA", "MGO", "GA", "AStar", "ThetaStar", "SMA-GMS", "LRSMA-GMS",
                                 "MGO-GMS", "APF", "BFO", "ATBFO"})
            if (PlannerRegistry::builtin().has(name))
                out.push_back(name);
        return out;
    }

    og::SimpleSetupPtr seedProblem(const std::string &world = "bfo_case1")
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + world + ".yaml");
        return makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    }

    std::string progress(const ob::PlannerPtr &p, const std::string &name)
    {
        return p->getPlannerProgressProperties().at(name)();
    }

    ob::PlannerTerminationCondition never()
    {
        return ob::PlannerTerminationCondition([] { return false; });
    }

    /** \brief Deterministic lattice searches (AStar, ThetaStar): no seed, no population, no fitness; their
        iterations are node expansions, and a search needs many of them to reach the goal. */
    bool isLatticeSearch(const std::string &planner)
    {
        return planner == "AStar" || planner == "ThetaStar";
    }

    /** \brief Robot walks on the potential field (APF, BFO and ATBFO in their default online mode): not
        optimizing planners. Their iterations are robot steps (\c max_iterations bounds the steps per solve()
        call, 0 = walk on until the goal or the end of the walk), their fitness evaluations are evaluations of
        the field J, their best cost stays infinite until the walk reaches the goal (then it is exact, else
        approximate), they report no intermediate solutions, and they need a validity checker that computes
        clearance (the field's obstacle distance). */
    bool isWalk(const std::string &planner)
    {
        return planner == "APF" || planner == "BFO" || planner == "ATBFO";
    }

    /** \brief Fitness evaluations, or node expansions for a planner without a fitness. */
    unsigned long evaluations(const ob::PlannerPtr &p)
    {
        const auto &props = p->getPlannerProgressProperties();
        const auto it = props.find("fitness evaluations INTEGER");
        return std::stoul(it != props.end() ? it->second() : props.at("iterations INTEGER")());
    }

    /** \brief The iteration budget \e iterations of a population planner; lattice searches and walks run
        to the end. */
    std::string budget(const std::string &planner, const char *iterations)
    {
        return isLatticeSearch(planner) || isWalk(planner) ? "0" : iterations;
    }
} // namespace

class PlannerContract : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }

    ob::PlannerPtr make(const og::SimpleSetupPtr &ss, std::map<std::string, std::string> params = {})
    {
        ob::PlannerPtr p = PlannerRegistry::builtin().get(GetParam()).allocate(ss->getSpaceInformation());
        if (p->params().hasParam("seed"))
            params.emplace("seed", "11");
        applyPlannerParameters(*p, params);
        ss->setPlanner(p);
        ss->setup();
        return p;
    }
};

TEST_P(PlannerContract, SolveContinuesClearResets)
{
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p = make(ss, {{"max_iterations", "5"}});
    EXPECT_TRUE(p->getSpecs().approximateSolutions);
    // A walk does not optimize a path and has no intermediate solutions to report.
    EXPECT_EQ(p->getSpecs().optimizingPaths, !isWalk(GetParam()));
    EXPECT_EQ(p->getSpecs().canReportIntermediateSolutions, !isWalk(GetParam()));

    const ob::PlannerStatus s1 = p->solve(never());
    EXPECT_TRUE(s1 == ob::PlannerStatus::EXACT_SOLUTION || s1 == ob::PlannerStatus::APPROXIMATE_SOLUTION);
    EXPECT_EQ(progress(p, "iterations INTEGER"), "5");
    const unsigned long evals1 = evaluations(p);
    EXPECT_GT(evals1, 0u);
    const double cost1 = std::stod(progress(p, "best cost REAL"));
    if (isWalk(GetParam()))
    {
        // Five robot steps of 0.2 do not reach the goal: the walk so far is an approximate solution, and
        // the best cost stays infinite until the goal is reached.
        EXPECT_EQ(s1, ob::PlannerStatus::APPROXIMATE_SOLUTION);
        EXPECT_TRUE(ss->getProblemDefinition()->hasApproximateSolution());
        EXPECT_TRUE(std::isinf(cost1));
    }

    // A second call continues: five more iterations, never a worse best cost.
    p->solve(never());
    EXPECT_EQ(progress(p, "iterations INTEGER"), "10");
    EXPECT_GT(evaluations(p), evals1);
    EXPECT_LE(std::stod(progress(p, "best cost REAL")), cost1);

    // The reported cost is the objective's cost of the returned path.
    if (ss->haveExactSolutionPath())
    {
        const og::PathGeometric &path = ss->getSolutionPath();
        EXPECT_NEAR(path.length(), std::stod(progress(p, "best cost REAL")), 1e-4);
        EXPECT_TRUE(path.check());
    }

    p->clear();
    EXPECT_EQ(progress(p, "iterations INTEGER"), "0");
    EXPECT_EQ(evaluations(p), 0u);
    EXPECT_TRUE(std::isinf(std::stod(progress(p, "best cost REAL"))));
    ss->getProblemDefinition()->clearSolutionPaths();
    const ob::PlannerStatus s3 = p->solve(never());
    EXPECT_TRUE(s3 == ob::PlannerStatus::EXACT_SOLUTION || s3 == ob::PlannerStatus::APPROXIMATE_SOLUTION);
    EXPECT_EQ(progress(p, "iterations INTEGER"), "5");
    // With the seed parameter set, clear() + solve() repeats the first run exactly.
    EXPECT_EQ(evaluations(p), evals1);
    EXPECT_EQ(std::stod(progress(p, "best cost REAL")), cost1);
}

TEST_P(PlannerContract, TerminatedConditionReturnsAtOnce)
{
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p = make(ss);
    const ob::PlannerStatus s = p->solve(ob::PlannerTerminationCondition([] { return true; }));
    EXPECT_EQ(s, ob::PlannerStatus::TIMEOUT);
    EXPECT_EQ(evaluations(p), 0u);
    EXPECT_FALSE(ss->getProblemDefinition()->hasSolution());
}

TEST_P(PlannerContract, TinyBudgets)
{
    og::SimpleSetupPtr ss = seedProblem();
    // Walks: one robot step (BFO's online mode has bacteria but no waypoints: the smallest colony).
    std::map<std::string, std::string> tiny{{"max_iterations", "1"}};
    if (!isLatticeSearch(GetParam()) && !isWalk(GetParam()))
        tiny = {{"population_size", "2"}, {"waypoints", "1"}, {"max_iterations", "1"}};
    else if (GetParam() == "BFO" || GetParam() == "ATBFO")
        tiny.emplace("population_size", "2");
    ob::PlannerPtr p = make(ss, tiny);
    const ob::PlannerStatus s = p->solve(never());
    EXPECT_TRUE(s == ob::PlannerStatus::EXACT_SOLUTION || s == ob::PlannerStatus::APPROXIMATE_SOLUTION);
    EXPECT_EQ(progress(p, "iterations INTEGER"), "1");

    // A condition that turns true after three checks stops inside the first population (walks: inside the
    // first robot step, whose J evaluations each test it).
    p->clear();
    ob::IterationTerminationCondition three(3);
    p->setProblemDefinition(ss->getProblemDefinition());
    p->solve(ob::PlannerTerminationCondition(three));
    if (isLatticeSearch(GetParam()))
        EXPECT_LE(evaluations(p), 128u); // tested every 64 expansions on a sampled lattice
    else
    {
        EXPECT_LE(evaluations(p), 3u);
        EXPECT_EQ(progress(p, "iterations INTEGER"), "0");
    }
}

namespace
{
    /** \brief Collects OMPL's log messages (ParamSet reports a setter's std::invalid_argument as a warning).
     */
    class CapturingHandler : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel, const char *, int) override
        {
            text_ += text + "\n";
        }
        std::string take()
        {
            std::string t;
            t.swap(text_);
            return t;
        }

      private:
        std::string text_;
    };
} // namespace

TEST_P(PlannerContract, InvalidParametersAreRefusedByName)
{
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p = make(ss);
    std::vector<std::string> names;
    p->params().getParamNames(names);
    CapturingHandler capture;
    ompl::msg::useOutputHandler(&capture);
    unsigned int checked = 0;
    for (const std::string &name : names)
    {
        const std::string range = p->params()[name].getRangeSuggestion();
        const std::string before = p->params()[name].getValue();
        std::vector<std::string> bad;
        const auto first = range.find(':');
        if (first == std::string::npos)
        {
            if (range != "0,1")
                bad.push_back("no-such-choice"); // a list of words
        }
        else
        {
            const double lo = std::stod(range.substr(0, first));
            const double hi = std::stod(range.substr(range.rfind(':') + 1));
            for (const double v : {lo - 1.0, hi + 1.0})
                if (v >= 0.0 && v <= 4e9) // else not representable in an unsigned parameter
                {
                    std::ostringstream value;
                    value << std::setprecision(12) << v;
                    bad.push_back(value.str());
                }
        }
        for (const std::string &value : bad)
        {
            capture.take();
            EXPECT_FALSE(p->params().setParam(name, value))
                << GetParam() << " accepted " << name << " = " << value;
            const std::string msg = capture.take();
            // The setter's message names the parameter, the accepted values and the value given.
            EXPECT_NE(msg.find("parameter '" + name + "' must be"), std::string::npos) << msg;
            EXPECT_NE(msg.find(value), std::string::npos) << msg;
            EXPECT_EQ(p->params()[name].getValue(), before) << name;
            ++checked;
        }
    }
    ompl::msg::restorePreviousOutputHandler();
    EXPECT_GE(checked, isLatticeSearch(GetParam()) ? 3u : 15u) << GetParam();
    // Through the registry the same refusal becomes an InputError naming planner and parameter.
    try
    {
        PlannerRegistry::builtin().create(GetParam(), ss->getSpaceInformation(), {{"population_size", "1"}});
        ADD_FAILURE() << "population_size = 1 accepted";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("population_size"), std::string::npos) << e.what();
    }
}

TEST_P(PlannerContract, IntermediateSolutionsImprove)
{
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p = make(ss, {{"max_iterations", budget(GetParam(), "10")}});
    std::vector<double> costs;
    ss->getProblemDefinition()->setIntermediateSolutionCallback(
        [&](const ob::Planner *, const std::vector<const ob::State *> &states, const ob::Cost c)
        {
            EXPECT_GE(states.size(), 2u);
            costs.push_back(c.value());
        });
    ASSERT_EQ(p->solve(never()), ob::PlannerStatus::EXACT_SOLUTION);
    if (isWalk(GetParam()))
    {
        // A walk reports no intermediate solutions (specs say so): the callback stays silent, and the best
        // cost is the objective's cost of the exact walk.
        EXPECT_TRUE(costs.empty());
        EXPECT_NEAR(ss->getSolutionPath().length(), std::stod(progress(p, "best cost REAL")), 1e-4);
        return;
    }
    ASSERT_FALSE(costs.empty());
    for (std::size_t i = 1; i < costs.size(); ++i)
        EXPECT_LT(costs[i], costs[i - 1]);
    EXPECT_NEAR(costs.back(), std::stod(progress(p, "best cost REAL")), 1e-9);
}

TEST_P(PlannerContract, ApproximateWhenNoPathExists)
{
    // A wall across the whole box (and beyond it: touching the wall along the border would be valid).
    World w;
    w.name = "walled";
    w.bounds = {0, 10, 0, 10};
    w.polygons.push_back(makePolygon(rectangleCorners({5, 5}, 1.0, 12.0, 0.0), "rectangle"));
    w.queries.push_back({"default", {1, 5}, {9, 5}});
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    ob::PlannerPtr p = make(ss, {{"max_iterations", "3"}});
    EXPECT_EQ(p->solve(never()), ob::PlannerStatus::APPROXIMATE_SOLUTION);
    EXPECT_TRUE(ss->getProblemDefinition()->hasApproximateSolution());
    EXPECT_TRUE(std::isinf(std::stod(progress(p, "best cost REAL"))));
}

namespace
{
    /** \brief A foreign checker that computes clearance: free outside the disc of radius 2 at (5, 5). */
    class DiscChecker : public ob::StateValidityChecker
    {
      public:
        explicit DiscChecker(ob::SpaceInformation *si) : ob::StateValidityChecker(si)
        {
            specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
        }
        bool isValid(const ob::State *s) const override { return clearance(s) >= 0.0; }
        double clearance(const ob::State *s) const override
        {
            const auto *v = s->as<ob::RealVectorStateSpace::StateType>();
            return std::hypot(v->values[0] - 5.0, v->values[1] - 5.0) - 2.0;
        }
    };
} // namespace

TEST_P(PlannerContract, ForeignValidityCheckerAndMotionValidator)
{
    // OMPL's own discrete motion validator and a lambda checker: a disc of radius 2 at (5, 5).
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    space->setBounds(0.0, 10.0);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker(
        [](const ob::State *s)
        {
            const auto *v = s->as<ob::RealVectorStateSpace::StateType>();
            return std::hypot(v->values[0] - 5.0, v->values[1] - 5.0) >= 2.0;
        });
    si->setStateValidityCheckingResolution(0.001);
    si->setup();
    og::SimpleSetupPtr ss = std::make_shared<og::SimpleSetup>(si);
    ob::ScopedState<> start(space), goal(space);
    start[0] = 1.0;
    start[1] = 1.0;
    goal[0] = 9.0;
    goal[1] = 9.0;
    ss->setStartAndGoalStates(start, goal, 1e-9);
    if (isWalk(GetParam()))
    {
        // The field's obstacle distance is the checker's clearance(): a walk refuses in setup() a checker
        // that does not compute one, naming itself and the reason, instead of walking blind.
        try
        {
            make(ss);
            ADD_FAILURE() << GetParam() << " accepted a validity checker without clearance";
        }
        catch (const ompl::Exception &e)
        {
            EXPECT_NE(std::string(e.what()).find(GetParam() + ":"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("clearance"), std::string::npos) << e.what();
        }
        // A foreign checker that computes clearance (the same disc) is accepted and walked around.
        si->setStateValidityChecker(std::make_shared<DiscChecker>(si.get()));
        si->setup();
        ss = std::make_shared<og::SimpleSetup>(si);
        ss->setStartAndGoalStates(start, goal, 1e-9);
    }
    ob::PlannerPtr p = make(ss, {{"max_iterations", budget(GetParam(), "20")}});
    ASSERT_EQ(p->solve(never()), ob::PlannerStatus::EXACT_SOLUTION);
    const og::PathGeometric &path = ss->getSolutionPath();
    EXPECT_TRUE(path.check());
    EXPECT_GT(path.length(), std::hypot(8.0, 8.0));
}

INSTANTIATE_TEST_SUITE_P(Planners, PlannerContract, ::testing::ValuesIn(mhplanPlanners()));
