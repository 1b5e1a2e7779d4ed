// SPDX-License-Identifier: BSD-3-Clause
/* OMPL's geometric planners in the registry (docs/cli.md, "OMPL's planners"): every one solves a small
   problem on R^2 and on SE(2) (iteration-bounded), OMPL.app's names resolve to one entry whatever their
   case, and OMPL's parameter range suggestions are hints (large values accepted, garbage refused). */
#include "src/base/World.h"
#include "src/registry/Registry.h"

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** The obstacle of the small problem: the box [0.4, 0.6] x [0, 0.7] of the unit square (a wall from the
        bottom that the path from (0.1, 0.1) to (0.9, 0.1) must go over), grown by \e margin. The planners
        see it grown by 0.01, more than OMPL's discrete motion checks step (0.002 of the space's extent) can
        cut into a corner; the independent check tests the wall itself. */
    bool inWall(double x, double y, double margin = 0.0)
    {
        return x >= 0.4 - margin && x <= 0.6 + margin && y <= 0.7 + margin;
    }

    double xOf(const ob::State *s, bool se2)
    {
        return se2 ? s->as<ob::SE2StateSpace::StateType>()->getX()
                   : s->as<ob::RealVectorStateSpace::StateType>()->values[0];
    }
    double yOf(const ob::State *s, bool se2)
    {
        return se2 ? s->as<ob::SE2StateSpace::StateType>()->getY()
                   : s->as<ob::RealVectorStateSpace::StateType>()->values[1];
    }

    og::SimpleSetupPtr wallProblem(bool se2)
    {
        ob::StateSpacePtr space;
        if (se2)
        {
            auto s = std::make_shared<ob::SE2StateSpace>();
            ob::RealVectorBounds b(2);
            b.setLow(0.0);
            b.setHigh(1.0);
            s->setBounds(b);
            space = s;
        }
        else
        {
            auto s = std::make_shared<ob::RealVectorStateSpace>(2);
            s->setBounds(0.0, 1.0);
            space = s;
        }
        auto ss = std::make_shared<og::SimpleSetup>(space);
        ss->setStateValidityChecker([se2](const ob::State *s)
                                    { return !inWall(xOf(s, se2), yOf(s, se2), 0.01); });
        ss->getSpaceInformation()->setStateValidityCheckingResolution(0.002);
        ob::ScopedState<> start(space), goal(space);
        start[0] = 0.1;
        start[1] = 0.1;
        goal[0] = 0.9;
        goal[1] = 0.1;
        if (se2)
        {
            start[2] = 0.0;
            goal[2] = 1.0;
        }
        ss->setStartAndGoalStates(start, goal, 0.02);
        return ss;
    }

    std::vector<std::string> omplPlanners()
    {
        std::vector<std::string> out;
        for (const auto &n : builtinPlanners().names())
            if (builtinPlanners().get(n).origin == "ompl")
                out.push_back(n);
        return out;
    }
} // namespace

namespace
{
    /** Iterations (evaluations of the termination condition) each planner gets. LBTRRT keeps improving
        until the condition ends it and adds its path to the problem only then, at about 1.5 ms an iteration
        here. */
    unsigned iterationsFor(const std::string &planner)
    {
        if (planner == "LBTRRT")
            return 2000;
        // The parallel planners' threads share the condition's count, and how far a thread got when it ran
        // out depends on the scheduling (pSBL missed the goal under load once): a larger bound, still ended
        // by the first exact solution.
        if (planner == "pSBL" || planner == "pRRT")
            return 200000;
        return 20000;
    }
} // namespace

class OmplPlannerSolves : public ::testing::TestWithParam<std::string>
{
};

TEST_P(OmplPlannerSolves, WallProblemOnR2AndSE2)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const bool se2 : {false, true})
    {
        ompl::RNG::setSeed(7);
        og::SimpleSetupPtr ss = wallProblem(se2);
        // SST's default radii (selection 5, pruning 3) suit spaces far larger than the unit square: there
        // every node but one would be pruned. Scaled to the problem, as a user would.
        std::map<std::string, std::string> params;
        if (GetParam() == "SST")
            params = {{"selection_radius", "0.05"}, {"pruning_radius", "0.02"}};
        ss->setPlanner(builtinPlanners().create(GetParam(), ss->getSpaceInformation(), params));
        // Any path satisfies the objective: the optimizing planners stop at their first solution. The
        // iteration bound ends the run; the condition is evaluated by every thread of the parallel planners.
        auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(ss->getSpaceInformation());
        objective->setCostThreshold(ob::Cost(std::numeric_limits<double>::infinity()));
        ss->setOptimizationObjective(objective);
        ss->setup();
        // The run also stops at the first exact solution (LBTRRT, for one, does not stop by itself).
        const ob::PlannerTerminationCondition ptc = ob::plannerOrTerminationCondition(
            ob::plannerOrTerminationCondition(
                ob::IterationTerminationCondition(iterationsFor(GetParam())),
                ob::exactSolnPlannerTerminationCondition(ss->getProblemDefinition())),
            ob::timedPlannerTerminationCondition(60.0));
        const ob::PlannerStatus status = ss->solve(ptc);
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << GetParam() << (se2 ? " on SE(2)" : " on R^2");
        og::PathGeometric path = ss->getSolutionPath();
        ASSERT_GE(path.getStateCount(), 2u);
        // Independent check: the straight segments sampled every 1e-3, none in the wall.
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
        {
            const double x0 = xOf(path.getState(i), se2), y0 = yOf(path.getState(i), se2);
            const double x1 = xOf(path.getState(i + 1), se2), y1 = yOf(path.getState(i + 1), se2);
            const int n = 1 + static_cast<int>(std::hypot(x1 - x0, y1 - y0) / 1e-3);
            for (int k = 0; k <= n; ++k)
            {
                const double t = static_cast<double>(k) / n;
                ASSERT_FALSE(inWall(x0 + t * (x1 - x0), y0 + t * (y1 - y0)))
                    << GetParam() << (se2 ? " SE(2)" : " R^2") << " segment " << i << " enters the wall";
            }
        }
        EXPECT_NEAR(xOf(path.getStates().back(), se2), 0.9, 0.021) << GetParam();
    }
}

INSTANTIATE_TEST_SUITE_P(Registry, OmplPlannerSolves, ::testing::ValuesIn(omplPlanners()),
                         [](const ::testing::TestParamInfo<std::string> &i) { return i.param; });

TEST(OmplPlanners, EveryOmplAppNameResolvesToOneEntry)
{
    const PlannerRegistry &reg = builtinPlanners();
    const std::map<std::string, std::string> expected = {{"est", "EST"},
                                                         {"biest", "BiEST"},
                                                         {"projest", "ProjEST"},
                                                         {"sbl", "SBL"},
                                                         {"kpiece", "KPIECE1"},
                                                         {"bkpiece", "BKPIECE1"},
                                                         {"lbkpiece", "LBKPIECE1"},
                                                         {"pdst", "PDST"},
                                                         {"stride", "STRIDE"},
                                                         {"rrt", "RRT"},
                                                         {"rrtconnect", "RRTConnect"},
                                                         {"lazyrrt", "LazyRRT"},
                                                         {"trrt", "TRRT"},
                                                         {"bitrrt", "BiTRRT"},
                                                         {"lbtrrt", "LBTRRT"},
                                                         {"rrtstar", "RRTstar"},
                                                         {"informedrrtstar", "InformedRRTstar"},
                                                         {"sorrtstar", "SORRTstar"},
                                                         {"rrtsharp", "RRTsharp"},
                                                         {"rrtxstatic", "RRTXstatic"},
                                                         {"prm", "PRM"},
                                                         {"prmstar", "PRMstar"},
                                                         {"lazyprm", "LazyPRM"},
                                                         {"lazyprmstar", "LazyPRMstar"},
                                                         {"spars", "SPARS"},
                                                         {"spars2", "SPARStwo"},
                                                         {"fmt", "FMTstar"},
                                                         {"bfmt", "BFMTstar"},
                                                         {"cforest", "CForest"},
                                                         {"bitstar", "BITstar"},
                                                         {"abitstar", "ABITstar"},
                                                         {"aitstar", "AITstar"},
                                                         {"sst", "SST"}};
    for (const auto &[alias, name] : expected)
    {
        ASSERT_TRUE(reg.has(alias)) << alias;
        EXPECT_EQ(reg.get(alias).name, name) << alias;
        std::string upper = alias;
        for (char &c : upper)
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        EXPECT_EQ(reg.get(upper).name, name) << upper;
    }
    // OMPL's own spellings of the same planners.
    EXPECT_EQ(reg.get("FMT").name, "FMTstar");
    EXPECT_EQ(reg.get("kBITstar").name, "BITstar");
    // Aliases are not entries: the list of names holds each planner once.
    for (const auto &n : reg.names())
        EXPECT_EQ(reg.aliases().count(n), 0u) << n;
    // Unknown names are refused with the list of names and aliases.
    try
    {
        reg.get("kpiece2");
        ADD_FAILURE() << "kpiece2 accepted";
    }
    catch (const InputError &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("unknown planner 'kpiece2'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("KPIECE1"), std::string::npos) << msg;
        EXPECT_NE(msg.find("spars2"), std::string::npos) << msg;
    }
    // A name taken ignoring case, or an alias of nothing, cannot be added.
    PlannerRegistry r;
    r.add({"Alpha", "test", "", [](const ob::SpaceInformationPtr &) { return ob::PlannerPtr(); }});
    EXPECT_THROW(
        r.add({"ALPHA", "test", "", [](const ob::SpaceInformationPtr &) { return ob::PlannerPtr(); }}),
        std::invalid_argument);
    EXPECT_THROW(r.addAlias("alpha", "Alpha"), std::invalid_argument);
    EXPECT_THROW(r.addAlias("beta", "Gamma"), std::invalid_argument);
    r.addAlias("a", "Alpha");
    EXPECT_EQ(r.get("A").name, "Alpha");
}

TEST(OmplPlanners, RangeSuggestionsAreHintsAndGarbageIsRefused)
{
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    space->setBounds(0.0, 1.0);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker([](const ob::State *) { return true; });
    si->setup();
    const PlannerRegistry &reg = builtinPlanners();
    // Beyond OMPL's suggestions (rewire_factor 1:2, range 0:10000) but accepted by OMPL's setters.
    ob::PlannerPtr p = reg.create("rrtstar", si, {{"rewire_factor", "2.5"}, {"range", "20000"}});
    EXPECT_EQ(p->params()["rewire_factor"].getValue(), "2.5");
    EXPECT_EQ(p->params()["range"].getValue(), "20000");
    p = reg.create("kpiece", si, {{"range", "1e6"}, {"goal_bias", "1"}});
    EXPECT_EQ(std::stod(p->params()["range"].getValue()), 1e6);
    for (const auto &[param, value] :
         std::vector<std::pair<std::string, std::string>>{{"range", "lots"},
                                                          {"range", "nan"},
                                                          {"range", "-1"},
                                                          {"range", "1e999"},
                                                          {"goal_bias", ""},
                                                          {"rewire_factor", "2.5x"}})
        EXPECT_THROW(reg.create("RRTstar", si, {{param, value}}), InputError) << param << "=" << value;
    // An integer parameter takes integers only: OMPL would store 2 for 2.5 and 4294967295 for -1.
    EXPECT_THROW(reg.create("PRM", si, {{"max_nearest_neighbors", "2.5"}}), InputError);
    EXPECT_THROW(reg.create("PRM", si, {{"max_nearest_neighbors", "-1"}}), InputError);
    EXPECT_NO_THROW(reg.create("PRM", si, {{"max_nearest_neighbors", "500"}}));
}

TEST(OmplPlanners, ProjectionPlannersHaveDefaultProjectionsOnSE2SE3AndRk)
{
    // KPIECE1, ProjEST, SBL, PDST and STRIDE need a projection: OMPL registers one for these spaces.
    std::vector<ob::StateSpacePtr> spaces;
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    ob::RealVectorBounds b2(2);
    b2.setLow(-1);
    b2.setHigh(1);
    se2->setBounds(b2);
    spaces.push_back(se2);
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    ob::RealVectorBounds b3(3);
    b3.setLow(-1);
    b3.setHigh(1);
    se3->setBounds(b3);
    spaces.push_back(se3);
    auto r5 = std::make_shared<ob::RealVectorStateSpace>(5);
    r5->setBounds(-1, 1);
    spaces.push_back(r5);
    for (const auto &space : spaces)
    {
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker([](const ob::State *) { return true; });
        si->setup();
        EXPECT_TRUE(space->hasDefaultProjection()) << space->getName();
        for (const char *name : {"kpiece", "bkpiece", "lbkpiece", "projest", "sbl", "pdst", "stride"})
        {
            auto pdef = std::make_shared<ob::ProblemDefinition>(si);
            ob::ScopedState<> s(space), g(space);
            s.random();
            g.random();
            pdef->setStartAndGoalStates(s, g, 0.5);
            ob::PlannerPtr p = builtinPlanners().create(name, si);
            p->setProblemDefinition(pdef);
            EXPECT_NO_THROW(p->setup()) << name << " on " << space->getName();
            EXPECT_TRUE(p->isSetup()) << name;
        }
    }
}
