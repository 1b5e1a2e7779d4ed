// SPDX-License-Identifier: BSD-3-Clause
/* The memetic planners under the protocols of OMPL's own planner tests (docs/conventions.md, "OMPL's test
   protocols"), written anew here as a user's OMPL program would run them, with the user's own classes:
   - A grid map: a space derived from RealVectorStateSpace whose distance is the Manhattan distance of the
     integer cells (so the path length objective measures cells, not metres), bounds [0, w) x [0, h) (just
     under w and h), validity-checking resolution 0.016, a checker that reads the cell (int x, int y) of the
     map (vector::at: a query outside the map throws and fails the test, as it would read outside the user's
     array), a GoalState with threshold 1e-3 and a cost threshold of infinity (stop at the first solution).
     The returned path, its vertices reduced by OMPL's PathSimplifier and interpolated to twice its states,
     has every state in a free cell, and it passes an independent check every 1 mm.
   - Discs with OMPL's DiscreteMotionValidator at resolution 0.002: solve / clear / solve / solve / clear,
     then an always-terminating condition and budgets of 1 ms, 10 ms and 100 ms, every solve() of a fresh
     problem definition solved; per query, a cost threshold of infinity (the first solution, exact), then
     a threshold no path reaches and solve() in slices of 0.1 s with the solution paths cleared before each:
     every slice solved, exact, not "optimized", its cost never above the previous one; then the threshold
     set to the first cost: "optimized" (or unchanged); never below the straight line; the last path clear of
     every disc under a 1 mm check. */
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "src/registry/Registry.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include "RegistrySupport.h"
#include "SpaceProblems.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** \brief The user's space: R^2 whose distance is the Manhattan distance of the integer cells. */
    class CellSpace : public ob::RealVectorStateSpace
    {
      public:
        CellSpace() : ob::RealVectorStateSpace(2) {}
        double distance(const ob::State *a, const ob::State *b) const override
        {
            const double *u = a->as<StateType>()->values, *v = b->as<StateType>()->values;
            return std::abs(int(u[0]) - int(v[0])) + std::abs(int(u[1]) - int(v[1]));
        }
    };

    /** \brief The map, '#' blocked, indexed map[y][x]; 24 x 16 cells, walls with gaps of one cell. */
    const std::vector<std::string> &gridMap()
    {
        static const std::vector<std::string> map = {
            "........................", //
            "........#...............", //
            "........#.......#.......", //
            "........#.......#.......", //
            "........#.......#.......", //
            "........#.......#.......", //
            "..#######.......#.......", //
            "................#.......", //
            "........#########.......", //
            "........#...............", //
            "........#.......#######.", //
            "........#.....#.........", //
            "......###.....#.........", //
            "..............#.........", //
            "........#.....#.........", //
            "........#.....#.........", //
        };
        return map;
    }

    bool cellFree(double x, double y)
    {
        // As a user's checker reads its array: out of the map is out of the array (at() throws).
        const std::vector<std::string> &map = gridMap();
        return map.at(static_cast<std::size_t>(int(y))).at(static_cast<std::size_t>(int(x))) == '.';
    }

    /** \brief The user's set-up of the map: bounds [0, w) x [0, h) (just under), resolution 0.016, the
        array checker. */
    ob::SpaceInformationPtr gridMapSpace()
    {
        const std::vector<std::string> &map = gridMap();
        auto space = std::make_shared<CellSpace>();
        ob::RealVectorBounds bounds(2);
        bounds.setLow(0.0);
        bounds.high[0] = double(map.front().size()) - 1e-9;
        bounds.high[1] = double(map.size()) - 1e-9;
        space->setBounds(bounds);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityCheckingResolution(0.016);
        si->setStateValidityChecker(
            [](const ob::State *s)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                return cellFree(v[0], v[1]);
            });
        si->setup();
        return si;
    }

    struct Disc
    {
        double x, y, r;
    };

    const std::vector<Disc> &discs()
    {
        static const std::vector<Disc> d = {{5.0, 5.0, 1.5},  {9.0, 10.5, 2.0},  {14.0, 6.0, 1.8},
                                            {4.0, 14.0, 2.2}, {15.5, 14.5, 1.6}, {11.0, 3.0, 1.0},
                                            {8.0, 16.5, 1.2}, {12.5, 8.0, 0.8}};
        return d;
    }

    bool outsideDiscs(double x, double y)
    {
        for (const Disc &d : discs())
            if (std::hypot(x - d.x, y - d.y) <= d.r)
                return false;
        return true;
    }

    /** \brief Every point of the path every \e step passes \e free. */
    bool denseFree(const og::PathGeometric &path, double step, bool (*free)(double, double))
    {
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
        {
            const double *a = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = path.getState(i + 1)->as<ob::RealVectorStateSpace::StateType>()->values;
            const int n = std::max(1, int(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / step)));
            for (int k = 0; k <= n; ++k)
            {
                const double t = double(k) / double(n);
                if (!free(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t))
                    return false;
            }
        }
        return true;
    }

    ob::PlannerPtr allocate(const std::string &name, const ob::SpaceInformationPtr &si)
    {
        ob::PlannerPtr p = builtinPlanners().get(name).allocate(si);
        if (p->params().hasParam("seed"))
            applyPlannerParameters(*p, {{"seed", "5"}});
        return p;
    }

    ob::GoalPtr goalAt(const ob::SpaceInformationPtr &si, double x, double y)
    {
        ob::ScopedState<> g(si);
        g[0] = x;
        g[1] = y;
        if (si->getStateSpace()->getDimension() > 2)
            g[2] = 0.0; // SE(2): heading 0
        auto goal = std::make_shared<ob::GoalState>(si);
        goal->setState(g);
        goal->setThreshold(1e-3);
        return goal;
    }

    void setQuery(const ob::SpaceInformationPtr &si, ob::ProblemDefinition &pdef, double sx, double sy,
                  double gx, double gy)
    {
        ob::ScopedState<> s(si);
        s[0] = sx;
        s[1] = sy;
        if (si->getStateSpace()->getDimension() > 2)
            s[2] = 0.0;
        pdef.clearStartStates();
        pdef.addStartState(s);
        pdef.clearGoal();
        pdef.setGoal(goalAt(si, gx, gy));
    }

    og::PathGeometric &solutionOf(const ob::ProblemDefinition &pdef)
    {
        return *pdef.getSolutionPath()->as<og::PathGeometric>();
    }
} // namespace

class OmplProtocols : public ::testing::TestWithParam<std::string>
{
  protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
};

TEST_P(OmplProtocols, GridMapWithACellDistance)
{
    const ob::SpaceInformationPtr si = gridMapSpace();
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    auto opt = std::make_shared<ob::PathLengthOptimizationObjective>(si);
    opt->setCostThreshold(opt->infiniteCost()); // stop at the first solution
    pdef->setOptimizationObjective(opt);
    // Integer start and goal, as the map files give them (cell corners).
    const struct
    {
        double sx, sy, gx, gy;
    } queries[] = {{1.0, 1.0, 22.0, 14.0}, {22.0, 1.0, 1.0, 14.0}, {3.0, 8.0, 20.0, 4.0}};
    for (const auto &q : queries)
    {
        ob::PlannerPtr planner = allocate(GetParam(), si);
        planner->setProblemDefinition(pdef);
        planner->setup();
        setQuery(si, *pdef, q.sx, q.sy, q.gx, q.gy);
        pdef->clearSolutionPaths();
        ob::PlannerStatus status;
        ASSERT_NO_THROW(status = planner->solve(5.0)) << "a state outside the map was checked";
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION)
            << GetParam() << " from (" << q.sx << ", " << q.sy << ") to (" << q.gx << ", " << q.gy << ")";
        og::PathGeometric path = solutionOf(*pdef);
        EXPECT_TRUE(denseFree(path, 1e-3, cellFree))
            << GetParam() << ": the returned path crosses a blocked cell";
        og::PathSimplifier simplifier(si);
        simplifier.reduceVertices(path);
        path.interpolate(2 * path.getStateCount());
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            const double *v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            EXPECT_TRUE(cellFree(v[0], v[1])) << GetParam() << ": state " << i << " (" << v[0] << ", " << v[1]
                                              << ") of the simplified path is in a blocked cell";
        }
    }
}

namespace
{
    /** \brief The position (x, y) of a state of R^2 or of SE(2) (and its car spaces). */
    std::array<double, 2> position(const ob::State *s, bool planar)
    {
        if (planar)
        {
            const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
            return {v[0], v[1]};
        }
        const auto *se2 = s->as<ob::SE2StateSpace::StateType>();
        return {se2->getX(), se2->getY()};
    }

    /** \brief The path followed along the space's interpolation every \e step of the space's distance
        clear of the discs. */
    bool interpolatedFree(const og::PathGeometric &path, double step, bool planar)
    {
        og::PathGeometric fine(path);
        fine.interpolate(
            std::max<unsigned int>(fine.getStateCount(), unsigned(std::ceil(fine.length() / step))));
        for (std::size_t i = 0; i < fine.getStateCount(); ++i)
        {
            const auto p = position(fine.getState(i), planar);
            if (!outsideDiscs(p[0], p[1]))
                return false;
        }
        return true;
    }

    /** \brief OMPL's anytime protocol (the file's comment) for planner \e name on \e si (R^2 or SE(2)). */
    void anytimeProtocol(const std::string &name, const ob::SpaceInformationPtr &si, bool planar)
    {
        auto pdef = std::make_shared<ob::ProblemDefinition>(si);
        auto opt = std::make_shared<ob::PathLengthOptimizationObjective>(si);
        opt->setCostThreshold(opt->infiniteCost());
        pdef->setOptimizationObjective(opt);
        ob::PlannerPtr planner = allocate(name, si);
        planner->setProblemDefinition(pdef);
        planner->setup();

        // Solve and clear, as OMPL's basic planner test calls them.
        setQuery(si, *pdef, 1.0, 1.0, 19.0, 19.0);
        const auto timed = [](double s) { return ob::timedPlannerTerminationCondition(s); };
        planner->clear();
        EXPECT_TRUE(planner->solve(timed(1.0)));
        planner->clear();
        EXPECT_TRUE(planner->solve(timed(1.0)));
        EXPECT_TRUE(planner->solve(timed(1.0)));
        planner->clear();
        planner->solve(ob::plannerAlwaysTerminatingCondition());
        planner->solve(0.001);
        planner->solve(0.01);
        bool solved = planner->solve(0.1);
        if (!solved)
            solved = planner->solve(timed(1.0));
        EXPECT_TRUE(solved);
        planner->clear();
        planner->clear();

        const struct
        {
            double sx, sy, gx, gy;
        } queries[] = {{1.0, 1.0, 19.0, 19.0}, {19.0, 2.0, 1.5, 17.0}};
        for (const auto &q : queries)
        {
            setQuery(si, *pdef, q.sx, q.sy, q.gx, q.gy);
            const double straight = std::hypot(q.gx - q.sx, q.gy - q.sy);
            planner->clear();
            pdef->clearSolutionPaths();
            opt->setCostThreshold(opt->infiniteCost());
            ASSERT_EQ(planner->solve(1.0), ob::PlannerStatus::EXACT_SOLUTION) << name;
            const double first = solutionOf(*pdef).cost(opt).value();
            // A threshold no path reaches: every slice runs to its end.
            opt->setCostThreshold(ob::Cost(std::numeric_limits<double>::epsilon()));
            double previous = first;
            for (int slice = 0; slice < 6; ++slice)
            {
                pdef->clearSolutionPaths();
                const ob::PlannerStatus status = planner->solve(0.1);
                ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << name << ", slice " << slice;
                const double cost = solutionOf(*pdef).cost(opt).value();
                EXPECT_LE(cost, previous) << name << ", slice " << slice << ": the cost went up";
                EXPECT_FALSE(pdef->hasOptimizedSolution());
                EXPECT_FALSE(pdef->hasApproximateSolution());
                previous = cost;
            }
            EXPECT_LE(previous, first);
            // The threshold met by the first solution: the next solve() reports an optimized solution.
            pdef->clearSolutionPaths();
            opt->setCostThreshold(ob::Cost(first));
            ASSERT_TRUE(planner->solve(0.1));
            const double last = solutionOf(*pdef).cost(opt).value();
            EXPECT_TRUE(pdef->hasOptimizedSolution() || std::abs(last - first) <= 1e-9 * first) << name;
            EXPECT_GE(last, straight - 1e-9) << name << ": shorter than the straight line";
            if (planar)
                EXPECT_TRUE(denseFree(solutionOf(*pdef), 1e-3, outsideDiscs))
                    << name << ": the returned path enters a disc";
            else
                EXPECT_TRUE(interpolatedFree(solutionOf(*pdef), 1e-3, false))
                    << name << ": the returned path enters a disc";
        }
    }
} // namespace

TEST_P(OmplProtocols, DiscsAnytimeWithTheDiscreteValidator)
{
    // The user's set-up: R^2 [0, 20]^2, a point checker over the discs, OMPL's DiscreteMotionValidator at
    // resolution 0.002 (SpaceProblems.h); the problem definitions are the protocol's own.
    anytimeProtocol(
        GetParam(),
        test::planarAppProblem(outsideDiscs, 0.002, {1.0, 1.0}, {19.0, 19.0})->getSpaceInformation(), true);
}

TEST_P(OmplProtocols, DiscsAnytimeOnSE2AndDubins)
{
    // The same protocol off the plane (the state mode): SE(2) and a Dubins car (turning radius 1) over
    // [0, 20]^2, the point checker on the position, OMPL's DiscreteMotionValidator at resolution 0.002.
    for (const bool dubins : {false, true})
    {
        ob::StateSpacePtr space =
            dubins ? std::make_shared<ob::DubinsStateSpace>(1.0) : std::make_shared<ob::SE2StateSpace>();
        ob::RealVectorBounds bounds(2);
        bounds.setLow(0.0);
        bounds.setHigh(20.0);
        space->as<ob::SE2StateSpace>()->setBounds(bounds);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(
            [](const ob::State *s)
            {
                const auto p = position(s, false);
                return outsideDiscs(p[0], p[1]);
            });
        si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
        si->setStateValidityCheckingResolution(0.002);
        si->setup();
        SCOPED_TRACE(dubins ? "Dubins" : "SE(2)");
        anytimeProtocol(GetParam(), si, false);
    }
}

TEST(OmplProtocolsEveryPlanner, NoStateOutsideTheBoundsReachesTheUsersChecker)
{
    // Every registered mhplan planner on the grid map for 0.3 s: the user's checker reads its array with
    // at(), so a state outside the map would throw out of solve() (in a user's program: a read outside the
    // array). A planner that needs what this set-up lacks (a checker computing clearance) refuses it with
    // ompl::Exception, which is its documented answer; any other exception fails. Before this test the
    // spline-decoded population planners (SMA, LRSMA, LRSMA-OPS, PSO, GWO, WOA) asked the checker about
    // curve samples outside the bounds.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    for (const std::string &name :
         test::mhplanPlanners([](const PlannerEntry &) { return true; }, "registered"))
    {
        const ob::SpaceInformationPtr si = gridMapSpace();
        auto pdef = std::make_shared<ob::ProblemDefinition>(si);
        setQuery(si, *pdef, 1.0, 1.0, 22.0, 14.0);
        ob::PlannerPtr planner = allocate(name, si);
        planner->setProblemDefinition(pdef);
        try
        {
            planner->setup();
            planner->solve(0.3);
        }
        catch (const ompl::Exception &)
        {
            // refused: the planner's documented answer to a set-up it cannot use
        }
        catch (const std::exception &e)
        {
            ADD_FAILURE() << name << ": " << e.what();
        }
    }
}

TEST(OmplProtocolsEveryPlanner, AGoalThatCannotBeSampledIsAnInvalidGoal)
{
    // A user's goal region that only tests states (OMPL's GoalRegion, not sampleable): every planner needs a
    // goal state, and answers INVALID_GOAL (not INVALID_START), or refuses the problem with ompl::Exception.
    class NearCorner : public ob::GoalRegion
    {
      public:
        explicit NearCorner(const ob::SpaceInformationPtr &si) : ob::GoalRegion(si) { setThreshold(0.5); }
        double distanceGoal(const ob::State *s) const override
        {
            const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
            return std::hypot(v[0] - 19.0, v[1] - 19.0);
        }
    };
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    for (const std::string &name :
         test::mhplanPlanners([](const PlannerEntry &) { return true; }, "registered"))
    {
        const ob::SpaceInformationPtr si =
            test::planarAppProblem(outsideDiscs, 0.002, {1.0, 1.0}, {19.0, 19.0})->getSpaceInformation();
        auto pdef = std::make_shared<ob::ProblemDefinition>(si);
        setQuery(si, *pdef, 1.0, 1.0, 19.0, 19.0);
        pdef->clearGoal();
        pdef->setGoal(std::make_shared<NearCorner>(si));
        ob::PlannerPtr planner = allocate(name, si);
        planner->setProblemDefinition(pdef);
        try
        {
            planner->setup();
            EXPECT_EQ(planner->solve(0.1), ob::PlannerStatus::INVALID_GOAL) << name;
        }
        catch (const ompl::Exception &)
        {
            // refused: the planner's documented answer to a set-up it cannot use
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Memetic, OmplProtocols, ::testing::ValuesIn(test::ofFamily("memetic")));
