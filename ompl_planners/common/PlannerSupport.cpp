// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/PlannerSupport.h"

#include "ompl_planners/common/DubinsGuard.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace ob = ompl::base;

namespace mhplan
{
    void addPathToPlannerData(const ob::SpaceInformation &si, std::size_t count,
                              const std::function<void(ob::State *, std::size_t)> &fill, bool lastIsGoal,
                              ob::PlannerData &data, std::vector<ob::State *> &owned)
    {
        unsigned int previous = ob::PlannerData::INVALID_INDEX;
        for (std::size_t i = 0; i < count; ++i)
        {
            ob::State *s = si.allocState();
            owned.push_back(s);
            fill(s, i);
            const ob::PlannerDataVertex v(s);
            const unsigned int index = i == 0                           ? data.addStartVertex(v)
                                       : (i + 1 == count && lastIsGoal) ? data.addGoalVertex(v)
                                                                        : data.addVertex(v);
            if (i > 0)
                data.addEdge(previous, index);
            previous = index;
        }
    }

    void freeStates(const ob::SpaceInformation &si, std::vector<ob::State *> &owned)
    {
        for (ob::State *s : owned)
            si.freeState(s);
        owned.clear();
    }

    void addSolution(const ob::Planner &planner, const ob::ProblemDefinitionPtr &pdef,
                     const ob::SpaceInformationPtr &si, std::size_t count,
                     const std::function<void(ob::State *, std::size_t)> &fill, bool exact,
                     const ob::Cost &cost, double approximateDistance)
    {
        auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
        ob::State *s = si->allocState();
        for (std::size_t i = 0; i < count; ++i)
        {
            fill(s, i);
            path->append(s);
        }
        si->freeState(s);
        if (!exact && path->getStateCount() > 0)
        {
            // An approximate solution is collision-free, as OMPL's planners' are: the best valid prefix
            // (docs/conventions.md, "Approximate solutions"): the states from the start while every state
            // and motion is valid, cut at the one nearest the goal; its distance to the goal is the
            // solution's difference.
            std::vector<ob::State *> &states = path->getStates();
            const ob::GoalPtr &goal = pdef->getGoal();
            // The bounds before the checker: a user's checker is never asked about a state outside them.
            const auto valid1 = [&](const ob::State *s) { return si->satisfiesBounds(s) && si->isValid(s); };
            // Pairs OMPL 1.5.2's Dubins code would abort on are refused, and measured without it
            // (docs/spaces.md, "OMPL's Dubins assertions").
            const DubinsGuard dubins(si->getStateSpace().get());
            const auto *goalState = dynamic_cast<const ob::GoalState *>(goal.get());
            std::size_t valid = valid1(states[0]) ? 1 : 0;
            while (valid > 0 && valid < states.size() && valid1(states[valid]) &&
                   dubins.checkMotion(*si, states[valid - 1], states[valid]))
                ++valid;
            std::size_t best = 0;
            double bestDistance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < valid; ++i)
            {
                double d = std::numeric_limits<double>::infinity();
                if (goalState != nullptr && dubins.active())
                    d = dubins.distance(*si, states[i], goalState->getState());
                else if (goal)
                    goal->isSatisfied(states[i], &d);
                if (d < bestDistance)
                {
                    bestDistance = d;
                    best = i;
                }
            }
            if (valid == 0)
            {
                approximateDistance = std::numeric_limits<double>::infinity();
                best = 0; // only the start, which is itself invalid: OMPL refuses such a problem anyway
            }
            else if (std::isfinite(bestDistance))
                approximateDistance = bestDistance;
            for (std::size_t i = best + 1; i < states.size(); ++i)
                si->freeState(states[i]);
            states.resize(best + 1);
        }
        ob::PlannerSolution solution(path);
        solution.setPlannerName(planner.getName());
        if (exact)
        {
            const ob::OptimizationObjectivePtr &opt = pdef->getOptimizationObjective();
            if (opt)
                solution.setOptimized(opt, cost, opt->isSatisfied(cost));
        }
        else
            solution.setApproximate(std::max(approximateDistance, 1e-12));
        pdef->addSolutionPath(solution);
    }

    void reportImprovement(const ob::Planner *planner, const ob::ProblemDefinitionPtr &pdef,
                           const ob::SpaceInformation &si, std::size_t count,
                           const std::function<void(ob::State *, std::size_t)> &fill, const ob::Cost &cost)
    {
        if (!pdef)
            return;
        const auto &callback = pdef->getIntermediateSolutionCallback();
        if (!callback)
            return;
        std::vector<ob::State *> states;
        states.reserve(count);
        for (std::size_t i = 0; i < count; ++i)
        {
            states.push_back(si.allocState());
            fill(states.back(), i);
        }
        const std::vector<const ob::State *> view(states.begin(), states.end());
        callback(planner, view, cost);
        for (ob::State *s : states)
            si.freeState(s);
    }

    std::string formatCost(double cost)
    {
        std::ostringstream out;
        out << std::setprecision(17) << cost;
        return out.str();
    }
} // namespace mhplan
