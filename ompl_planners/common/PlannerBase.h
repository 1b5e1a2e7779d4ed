// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the one base of mhplan's OMPL planners (docs/conventions.md, "Planner base"): the bookkeeping every
   family shares, written once. */
#ifndef MHPLAN_PLANNER_BASE_H
#define MHPLAN_PLANNER_BASE_H

#include "src/base/Parameters.h"

#include <ompl/base/Cost.h>
#include <ompl/base/Planner.h>
#include <ompl/util/RandomNumbers.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The shared parameters' one set of limits (every planner declaring one of them uses these):
        \c seed 0..4294967295 (0 = the seed drawn from OMPL's global seed), \c max_iterations 0..1e9 (0 = no
        limit; the lattice searches count expansions in the millions), \c population_size 2..10000. */
    struct SharedParameterRanges
    {
        static const ParamRange seed;
        static const ParamRange maxIterations;
        static const ParamRange populationSize;
    };

    /** \brief Base of mhplan's planners (OMPL's Planner underneath). It owns, once:
        - the shared parameters \c seed, \c max_iterations and \c population_size with one set of limits
          (SharedParameterRanges); a family declares those it has (declareSeed(), declareMaxIterations(),
          declarePopulationSize()) and may override the setters to react (call the base setter first: it
          checks the range and stores the value);
        - the member RNG (only in seeded planners: constructing an ompl::RNG draws from OMPL's global seed
          generator, so a planner without randomness does not construct one) and its seeding (seedRng());
        - the progress properties the database and the report read by name: \c best \c cost (REAL,
          infinity before a solution), \c iterations and, where a family counts them, \c fitness
          \c evaluations (INTEGER), all atomics safe to read from the benchmark's sampling thread;
        - improvement reporting, the solution epilogue (the path added to the problem definition, exact or
          approximate), the states handed to PlannerData (owned until clear()), two scratch states and
          refuseSetup(). */
    class PlannerBase : public ompl::base::Planner
    {
      public:
        /** \brief \e seeded: the planner has a \c seed parameter and an RNG. */
        PlannerBase(const ompl::base::SpaceInformationPtr &si, const std::string &name, bool seeded);
        ~PlannerBase() override;

        /** \brief ompl::base::Planner::clear(), then forgets the PlannerData states and resets the progress
            counters (best cost, iterations, evaluations). */
        void clear() override;

        /** \brief Seed of this planner's RNG; 0 keeps the seed drawn from OMPL's global generator. */
        virtual void setSeed(unsigned long seed);
        unsigned long getSeed() const { return seed_; }
        /** \brief Iterations per solve() call, 0 = until the termination condition. */
        virtual void setMaxIterations(unsigned int n);
        unsigned int getMaxIterations() const { return maxIterations_; }
        /** \brief Population size N. */
        virtual void setPopulationSize(unsigned int n);
        unsigned int getPopulationSize() const { return populationSize_; }

        /** \brief Objective cost of the best solution (infinity before one exists). */
        double bestCost() const { return bestCostValue_.load(); }
        /** \brief Completed iterations since the last clear(). */
        unsigned long iterationCount() const { return iterationCount_.load(); }
        /** \brief Fitness evaluations since the last clear(). */
        unsigned long evaluationCount() const { return evaluationCount_.load(); }

      protected:
        /** \brief Declare \c seed (SharedParameterRanges::seed). */
        void declareSeed();
        /** \brief Declare \c max_iterations with what one iteration is (\e description). */
        void declareMaxIterations(const char *description);
        /** \brief Declare \c population_size with the default \e n and what an individual is. */
        void declarePopulationSize(unsigned int n, const char *description);
        /** \brief Add the progress properties \c best \c cost and \c iterations, and \c fitness
            \c evaluations when \e evaluations. */
        void declareProgress(bool evaluations);

        /** \brief Seed the RNG with \c seed when it is not 0 (else it keeps the seed drawn at construction).
         */
        void seedRng();

        /** \brief Leave the planner not set up, log \e message with OMPL_ERROR (prefixed with the planner's
            name) and throw ompl::Exception with the same text: how setup() refuses a problem. */
        [[noreturn]] void refuseSetup(const std::string &message);

        /** \brief The first start state and one goal sample of the problem; false, with OMPL_ERROR naming the
            planner, when there is none (inputFailure() then says which). */
        bool startAndGoal(const ompl::base::State *&start, const ompl::base::State *&goal);
        /** \brief Why the last startAndGoal() failed: INVALID_START, or INVALID_GOAL (no goal state to be
           had, e.g. a GoalRegion that only tests states). */
        ompl::base::PlannerStatus::StatusType inputFailure() const { return inputFailure_; }

        /** \brief Writes point i of a path into a state. */
        using PathFill = std::function<void(ompl::base::State *, std::size_t)>;
        /** \brief The intermediate-solution callback on an improvement (reportImprovement()). */
        void reportImprovementOf(std::size_t count, const PathFill &fill, const ompl::base::Cost &cost);
        /** \brief The solution epilogue: the path added to the problem definition (addSolution()). */
        void addSolutionPath(std::size_t count, const PathFill &fill, bool exact,
                             const ompl::base::Cost &cost, double approximateDistance);
        /** \brief ompl::base::Planner::getPlannerData(), then the path as a chain of vertices
            (addPathToPlannerData(); the states are the planner's until clear()). */
        void pathToPlannerData(ompl::base::PlannerData &data, std::size_t count, const PathFill &fill,
                               bool lastIsGoal) const;

        /** \brief Scratch state \e i (0 or 1), allocated on first use, freed with the planner. */
        ompl::base::State *scratchState(unsigned int i);

        ompl::RNG rng_;
        std::atomic<double> bestCostValue_;
        std::atomic<unsigned long> iterationCount_{0};
        std::atomic<unsigned long> evaluationCount_{0};
        /** \brief The shared parameters (set through the setters, which check them). */
        unsigned long seed_{0};
        unsigned int maxIterations_{0};
        unsigned int populationSize_{0};

      private:
        ompl::base::State *scratch_[2]{nullptr, nullptr};
        /** \brief States handed to PlannerData (it keeps the pointers): owned here until clear(). */
        mutable std::vector<ompl::base::State *> plannerDataStates_;
        ompl::base::PlannerStatus::StatusType inputFailure_{ompl::base::PlannerStatus::INVALID_START};
    };
} // namespace mhplan

#endif
