// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: any single-objective pagmo2 algorithm as an OMPL planner on mhplan's path encodings and fitness
   (docs/algorithms.md 11). */
#ifndef MHPLAN_PAGMO_PLANNER_H
#define MHPLAN_PAGMO_PLANNER_H

#include "src/base/PlannerRegistry.h"
#include "ompl_planners/common/PopulationPlanner.h"
#include "ompl_planners/pagmo/PagmoCatalogue.h"

#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief A pagmo2 algorithm (PagmoCatalogue) as an OMPL planner, registered "pagmo:<name>"
        (docs/algorithms.md 11).

        The problem handed to pagmo is mhplan's: a candidate is the waypoint vector of PopulationPlanner
        (docs/algorithms.md 1.1; polyline decoding and the fitness \c auto by default, both parameters as for
        every population planner), bounded by the space's bounds, and its fitness is PopulationPlanner's
        (evaluate(): counted, the best path tracked and reported, every improvement sent to the
        intermediate-solution callback). The algorithm's own parameters are declared with pagmo's defaults,
        ranges and a description; values pagmo refuses in combination are refused by setup() with pagmo's
        reason.

        The initial population is N uniform random waypoint vectors evaluated by the planner (pagmo does not
        evaluate them again). Each iteration is one call of the algorithm's evolve() (PagmoCall: one
        generation with the algorithm's memory on, or its whole schedule, or its own stopping). The
        termination condition is tested before every fitness evaluation: when it holds the evaluation throws
        and the interrupted evolve() is discarded (the population stays as before it; an algorithm with
        memory may keep part of its adaptation). Randomness: pagmo's seeds (population and algorithm) are
        drawn from the planner's RNG when the population is drawn, so the run is a function of \c seed.
        When N is below the algorithm's smallest population (e.g. 7 for sade), that minimum is used and a
        warning says so. */
    class PagmoPlanner : public PopulationPlanner
    {
      public:
        PagmoPlanner(const ompl::base::SpaceInformationPtr &si, const PagmoAlgorithm &algorithm);
        ~PagmoPlanner() override;

        void setup() override;

        /** \brief The algorithm's parameter \e name as a number (a word: its index; a switch: 0 or 1). */
        double pagmoParameter(const std::string &name) const;
        const PagmoAlgorithm &algorithm() const { return algorithm_; }
        /** \brief Individuals pagmo evolves: max(N, the algorithm's minimum). */
        unsigned int pagmoPopulationSize() const;

        /** \brief The fitness pagmo calls (PathProblem): throws when the termination condition holds. */
        double pagmoFitness(const std::vector<double> &x);

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;

      private:
        void declarePagmoParameters();
        void setValue(std::size_t i, const std::string &text);
        std::string getValue(std::size_t i) const;

        const PagmoAlgorithm &algorithm_;
        std::vector<double> values_;
        std::vector<double> buffer_;
        struct State;
        std::unique_ptr<State> state_;
    };

    /** \brief Register "pagmo:<algorithm>" in \e registry (origin "pagmo", capabilities cap::AllSpaces |
       cap::Anytime); throws std::invalid_argument for an unknown algorithm (listing those that exist) or one
       that cannot plan (gradients, constraints, several objectives). */
    void registerPagmoPlanner(PlannerRegistry &registry, const std::string &algorithm);
    /** \brief Register every algorithm of pagmoAlgorithms(). */
    void registerPagmoPlanners(PlannerRegistry &registry);
} // namespace mhplan

#endif
