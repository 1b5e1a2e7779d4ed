// SPDX-License-Identifier: BSD-3-Clause
/* The contract every mhplan planner keeps (OMPL's Planner API as docs/conventions.md asks): solve / solve
   continues / clear / solve, a termination condition already true returns at once, tiny budgets, refused
   parameters named with their range, progress properties, the intermediate-solution callback, approximate
   solutions when no exact one exists, and foreign (non-mhplan) validity checkers; on SE(2) and Dubins
   problems (docs/spaces.md) by every planner that supports them, the others refusing them at setup(). Lattice
   searches (isLatticeSearch) and potential-field walks (isWalk) keep it too, with the checks adapted where
   their nature differs. The registry, the seed problem and the planner kinds: ContractSupport.h; determinism
   per seed: test_determinism.cpp. */
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/collision/Validity.h"
#include "src/io/WorldIO.h"
#include "ompl_planners/common/PopulationPlanner.h"

#include <ompl/util/Exception.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "RegistrySupport.h"
#include "SpaceProblems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

#include "ContractSupport.h"

using namespace mhplan::contract;

class PlannerContract : public ::testing::TestWithParam<std::string>
{
  protected:
    static ob::PlannerPtr makePlanner(const std::string &name)
    {
        return contractRegistry().get(name).allocate(seedProblem()->getSpaceInformation());
    }

    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }

    ob::PlannerPtr make(const og::SimpleSetupPtr &ss, std::map<std::string, std::string> params = {})
    {
        ob::PlannerPtr p = contractRegistry().get(GetParam()).allocate(ss->getSpaceInformation());
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
    // A walk does not optimize a path; every mhplan planner reports its improvements (a walk: one).
    EXPECT_EQ(p->getSpecs().optimizingPaths, !isWalk(GetParam()));
    EXPECT_TRUE(p->getSpecs().canReportIntermediateSolutions);

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
    {
        tiny = {{"population_size", "2"}, {"max_iterations", "1"}};
        // The memetic variants have no fixed waypoint count (their paths grow with the problem).
        if (makePlanner(GetParam())->params().hasParam("waypoints"))
            tiny.emplace("waypoints", "1");
    }
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
        contractRegistry().create(GetParam(), ss->getSpaceInformation(), {{"population_size", "1"}});
        ADD_FAILURE() << "population_size = 1 accepted";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("population_size"), std::string::npos) << e.what();
    }
}

namespace
{
    /** \brief The numeric bounds of a range suggestion "lo:step:hi"; false for a list of words or a switch.
     */
    bool numericRange(const std::string &range, double &lo, double &hi)
    {
        const auto first = range.find(':');
        if (first == std::string::npos)
            return false;
        lo = std::stod(range.substr(0, first));
        hi = std::stod(range.substr(range.rfind(':') + 1));
        return true;
    }

    /** \brief \e v as OMPL prints a double parameter (digits10 significant digits). */
    std::string formatNumber(double v)
    {
        std::ostringstream out;
        out << std::setprecision(std::numeric_limits<double>::digits10) << v;
        return out.str();
    }

    std::vector<std::string> splitWords(const std::string &list)
    {
        std::vector<std::string> out;
        std::stringstream in(list);
        std::string word;
        while (std::getline(in, word, ','))
            out.push_back(word);
        return out;
    }
} // namespace

TEST_P(PlannerContract, ParametersRoundTrip)
{
    // Every parameter the planner declares: its current value, both ends of its range (and an inner value),
    // every word of its list, both values of a switch: setParam then getParam gives the same string, and
    // the planner's own value string is accepted again unchanged.
    ob::PlannerPtr p = makePlanner(GetParam());
    std::vector<std::string> names;
    p->params().getParamNames(names);
    ASSERT_FALSE(names.empty()) << GetParam();
    for (const std::string &name : names)
    {
        ob::GenericParam &param = p->params()[name];
        const std::string range = param.getRangeSuggestion();
        EXPECT_FALSE(range.empty()) << GetParam() << " " << name << " declares no range";
        const std::string before = param.getValue();
        std::vector<std::string> values{before};
        double lo = 0.0, hi = 0.0;
        if (range == "0,1")
            values.insert(values.end(), {"1", "0"});
        else if (numericRange(range, lo, hi))
        {
            const bool integral = before.find_first_of(".e") == std::string::npos;
            const double mid = integral ? std::floor((lo + hi) / 2.0) : (lo + hi) / 2.0;
            values.insert(values.end(), {formatNumber(lo), formatNumber(mid), formatNumber(hi)});
        }
        else
            for (const std::string &word : splitWords(range))
                values.push_back(word);
        for (const std::string &value : values)
        {
            ASSERT_NO_THROW(applyPlannerParameters(*p, {{name, value}}))
                << GetParam() << " " << name << "=" << value;
            EXPECT_EQ(param.getValue(), value) << GetParam() << " " << name;
        }
        applyPlannerParameters(*p, {{name, before}});
        EXPECT_EQ(param.getValue(), before) << GetParam() << " " << name;
    }
}

TEST_P(PlannerContract, SwitchesAcceptBoolSpellingsAndBadValuesAreRefusedWithTheRange)
{
    ob::PlannerPtr p = makePlanner(GetParam());
    std::vector<std::string> names;
    p->params().getParamNames(names);
    const auto refused = [&](const std::string &name, const std::string &value, const std::string &accepted)
    {
        try
        {
            applyPlannerParameters(*p, {{name, value}});
            ADD_FAILURE() << GetParam() << " accepted " << name << " = " << value;
        }
        catch (const InputError &e)
        {
            const std::string what = e.what();
            EXPECT_NE(what.find("parameter '" + name + "'"), std::string::npos) << what;
            EXPECT_NE(what.find(accepted), std::string::npos) << what;
        }
    };
    for (const std::string &name : names)
    {
        const std::string range = p->params()[name].getRangeSuggestion();
        const std::string before = p->params()[name].getValue();
        double lo = 0.0, hi = 0.0;
        if (range == "0,1")
        {
            // Switches are bool: true/false and 1/0.
            for (const auto &[given, stored] : std::vector<std::pair<std::string, std::string>>{
                     {"true", "1"}, {"false", "0"}, {"1", "1"}, {"0", "0"}})
            {
                applyPlannerParameters(*p, {{name, given}});
                EXPECT_EQ(p->params()[name].getValue(), stored) << GetParam() << " " << name << "=" << given;
            }
            applyPlannerParameters(*p, {{name, before}});
            refused(name, "2", "one of {0,1}");
            refused(name, "yes", "one of {0,1}");
        }
        else if (numericRange(range, lo, hi))
        {
            const std::string accepted =
                "[" + range.substr(0, range.find(':')) + ", " + range.substr(range.rfind(':') + 1) + "]";
            refused(name, formatNumber(lo - 1.0), accepted);
            refused(name, formatNumber(hi + 1.0), accepted);
            refused(name, "abc", accepted);
            refused(name, "", accepted);
        }
        else
            refused(name, "no-such-choice", "one of {" + range + "}");
        EXPECT_EQ(p->params()[name].getValue(), before) << GetParam() << " " << name;
        applyPlannerParameters(*p, {{name, before}});
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
    // Strictly decreasing costs, the last one the returned path's cost (a walk reports once: the exact walk).
    ASSERT_FALSE(costs.empty());
    if (isWalk(GetParam()))
    {
        EXPECT_EQ(costs.size(), 1u);
    }
    for (std::size_t i = 1; i < costs.size(); ++i)
        EXPECT_LT(costs[i], costs[i - 1]);
    EXPECT_NEAR(costs.back(), std::stod(progress(p, "best cost REAL")), 1e-9);
    EXPECT_NEAR(costs.back(), ss->getSolutionPath().length(), 1e-6);
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

// Every registered mhplan planner, and the test's own planner.
INSTANTIATE_TEST_SUITE_P(Planners, PlannerContract, ::testing::ValuesIn(contractPlanners()));

class PlannerContractSE2 : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
};

TEST_P(PlannerContractSE2, SupportedPlannersKeepTheContractTheOthersRefuseAtSetup)
{
    // The registry's capabilities say which planners support state spaces beyond the plane
    // (docs/spaces.md): they keep the contract on an SE(2) stick problem and a Dubins car problem (no
    // world file; the test's own geometry) with their default parameters (SMA's and LRSMA's default
    // decoding "auto" among them), every other planner refuses both at setup(), naming itself.
    const PlannerEntry &entry = contractRegistry().get(GetParam());
    for (const bool dubins : {false, true})
    {
        SCOPED_TRACE(dubins ? "Dubins" : "SE(2)");
        og::SimpleSetupPtr ss = dubins ? test::carProblem(false) : test::blockProblem();
        ob::PlannerPtr p = entry.allocate(ss->getSpaceInformation());
        if (!entry.runsOn(dubins ? cap::Dubins : cap::SE2))
        {
            try
            {
                ss->setPlanner(p);
                ss->setup();
                ADD_FAILURE() << GetParam() << " accepted a non-planar state space";
            }
            catch (const ompl::Exception &e)
            {
                EXPECT_NE(std::string(e.what()).find(GetParam() + ": "), std::string::npos) << e.what();
                // (APF, online BFO and the lattice searches still report isSetup() after refusing.)
                if (test::familyOf(GetParam()) == "population" || test::familyOf(GetParam()) == "memetic")
                {
                    EXPECT_FALSE(p->isSetup());
                }
            }
            continue;
        }
        std::map<std::string, std::string> params{{"seed", "11"}, {"max_iterations", "10"}};
        // A memetic iteration re-connects and tightens every path of the population with tree searches of
        // up to 2000 states under the Dubins validator (and re-connects the elite the same way): a small
        // population without elite re-connects keeps ten iterations to seconds.
        if (test::familyOf(GetParam()) == "memetic")
        {
            params["population_size"] = "4";
            params["elite_rewalks"] = "0";
        }
        applyPlannerParameters(*p, params);
        ss->setPlanner(p);
        ss->setup();
        std::vector<double> costs;
        ss->getProblemDefinition()->setIntermediateSolutionCallback(
            [&](const ob::Planner *, const std::vector<const ob::State *> &states, const ob::Cost c)
            {
                EXPECT_GE(states.size(), 2u);
                costs.push_back(c.value());
            });
        const ob::PlannerStatus s1 = p->solve(never());
        EXPECT_TRUE(s1 == ob::PlannerStatus::EXACT_SOLUTION || s1 == ob::PlannerStatus::APPROXIMATE_SOLUTION);
        EXPECT_EQ(progress(p, "iterations INTEGER"), "10");
        const unsigned long evals1 = evaluations(p);
        const double cost1 = std::stod(progress(p, "best cost REAL"));
        EXPECT_GT(evals1, 0u);
        // A second call continues.
        EXPECT_EQ(p->solve(never()), ob::PlannerStatus::EXACT_SOLUTION) << GetParam();
        EXPECT_EQ(progress(p, "iterations INTEGER"), "20");
        EXPECT_GT(evaluations(p), evals1);
        const double cost2 = std::stod(progress(p, "best cost REAL"));
        EXPECT_LE(cost2, cost1);
        if (ss->haveExactSolutionPath())
        {
            // The reported cost is the objective's: the space's distances along the returned states.
            const og::PathGeometric &path = ss->getSolutionPath();
            EXPECT_TRUE(path.check());
            EXPECT_NEAR(path.length(), cost2, 1e-9 * cost2);
            ASSERT_FALSE(costs.empty());
            for (std::size_t i = 1; i < costs.size(); ++i)
                EXPECT_LT(costs[i], costs[i - 1]);
            EXPECT_NEAR(costs.back(), cost2, 1e-9 * cost2);
            ob::PlannerData data(ss->getSpaceInformation());
            p->getPlannerData(data);
            EXPECT_EQ(data.numVertices(), path.getStateCount());
            EXPECT_EQ(data.numStartVertices(), 1u);
            EXPECT_EQ(data.numGoalVertices(), 1u);
        }
        // clear() forgets everything; the seeded run repeats exactly.
        p->clear();
        EXPECT_EQ(evaluations(p), 0u);
        EXPECT_TRUE(std::isinf(std::stod(progress(p, "best cost REAL"))));
        ss->getProblemDefinition()->clearSolutionPaths();
        p->solve(never());
        EXPECT_EQ(evaluations(p), evals1);
        EXPECT_EQ(std::stod(progress(p, "best cost REAL")), cost1);
        // A termination condition already true returns at once.
        p->clear();
        EXPECT_EQ(p->solve(ob::PlannerTerminationCondition([] { return true; })), ob::PlannerStatus::TIMEOUT);
        EXPECT_EQ(evaluations(p), 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Planners, PlannerContractSE2, ::testing::ValuesIn(contractPlanners()));

TEST(PlannerContractRegistry, HoldsEveryBuiltinMhplanPlannerAndTheTestsOwn)
{
    std::vector<std::string> expected = mhplanPlanners();
    expected.push_back("StraightLineRestarts");
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(contractPlanners(), expected);
    EXPECT_FALSE(builtinPlanners().has("StraightLineRestarts"));
}

TEST(PlannerRegistryTags, EveryMhplanPlannerHasAKnownFamily)
{
    // The tests classify a planner by its class's family (population, memetic, lattice, walk;
    // test::familyOf): a planner of none of them would silently miss the checks of its kind.
    const std::set<std::string> families{"population", "memetic", "lattice", "walk"};
    std::set<std::string> seen;
    for (const std::string &name : mhplanPlanners())
    {
        const PlannerEntry &e = builtinPlanners().get(name);
        const std::string family = test::familyOf(name);
        EXPECT_EQ(families.count(family), 1u) << name << " has family '" << family << "'";
        seen.insert(family);
        // An improved variant says so in its description; a faithful planner does not.
        EXPECT_EQ(e.description.find("improved") != std::string::npos, e.has(cap::Improved)) << name;
    }
    EXPECT_EQ(seen, families);
}
