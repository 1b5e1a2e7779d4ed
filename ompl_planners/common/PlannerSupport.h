// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: small pieces every mhplan planner shares (planner data of a path, progress formatting). The cusps
   of a path are a metric (src/metrics/Metrics.h, docs/metrics.md). */
#ifndef MHPLAN_PLANNER_SUPPORT_H
#define MHPLAN_PLANNER_SUPPORT_H

#include <ompl/base/Cost.h>
#include <ompl/base/Planner.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Add a path of \e count points to \e data as a chain of vertices joined by edges: the first a
        start vertex, the last a goal vertex when \e lastIsGoal. \e fill(state, i) writes point i into a
       state. PlannerData keeps the state pointers it is given (and merges vertices by pointer), so one state
       is allocated per point and appended to \e owned, which the planner frees with freeStates() when it
        clears or is destroyed (as OMPL's planners own their trees' states). */
    void addPathToPlannerData(const ompl::base::SpaceInformation &si, std::size_t count,
                              const std::function<void(ompl::base::State *, std::size_t)> &fill,
                              bool lastIsGoal, ompl::base::PlannerData &data,
                              std::vector<ompl::base::State *> &owned);

    /** \brief Free the states of \e owned with \e si and empty it. */
    void freeStates(const ompl::base::SpaceInformation &si, std::vector<ompl::base::State *> &owned);

    /** \brief Report an improvement of a planner's best solution: when \e pdef has an intermediate-solution
        callback, call it with \e planner, the \e count states of the path (\e fill(state, i) writes point i;
        the states are allocated with \e si and freed after the call) and \e cost. Every mhplan planner calls
        this at each improvement of its best solution. */
    void reportImprovement(const ompl::base::Planner *planner, const ompl::base::ProblemDefinitionPtr &pdef,
                           const ompl::base::SpaceInformation &si, std::size_t count,
                           const std::function<void(ompl::base::State *, std::size_t)> &fill,
                           const ompl::base::Cost &cost);

    /** \brief Add a planner's result to \e pdef: the \e count states of the path (\e fill(state, i) writes
        point i), named after \e planner; optimized with \e cost when \e exact, else approximate: only the
        best valid prefix of the path (docs/conventions.md, "Approximate solutions": collision-free, cut at
        its state nearest the goal) at that state's distance to the goal (\e approximateDistance when the
        goal gives none; at least 1e-12, so OMPL counts it as approximate). */
    void addSolution(const ompl::base::Planner &planner, const ompl::base::ProblemDefinitionPtr &pdef,
                     const ompl::base::SpaceInformationPtr &si, std::size_t count,
                     const std::function<void(ompl::base::State *, std::size_t)> &fill, bool exact,
                     const ompl::base::Cost &cost, double approximateDistance);

    /** \brief A cost as a progress property value (17 significant digits, "inf" when none). */
    std::string formatCost(double cost);
} // namespace mhplan

#endif
