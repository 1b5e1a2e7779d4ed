// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: GA-MEM, the memetic genetic algorithm (an improved variant, not in [GMS]). */
#ifndef MHPLAN_MEMETIC_GENETIC_H
#define MHPLAN_MEMETIC_GENETIC_H

#include "ompl_planners/memetic/MemeticPlanner.h"

namespace mhplan
{
    /** \brief GA-MEM: the genetic algorithm's selection / crossover / mutation on variable-length feasible
        paths, with memetic local search (MemeticPlanner: walks, tightening, elite polish, restarts). In the
        state mode (any space but R^2, docs/spaces.md) the crossover joins paths of states at close states
        and the mutations are the detour (0.35) and the re-connect of a piece (0.65).

        Each generation produces N offspring: a parent by tournament (size \c tournament_size, on cost);
        with probability \c crossover_rate a second parent and a path crossover where the parents pass
        close to each other (MemeticToolkit::splice: one or two joints with equal probability, joint radius
        2.5 resampling steps of the first parent, the joints checked by the motion validator); with
        probability \c mutation_rate (and always when the crossover found no joint) one of three mutations
        (probabilities 0.25, 0.1, 0.65: the re-walk was measured to find most class changes), each of which
       moves a piece of the path to the other side of nearby obstacles (another homotopy class): a detour
       through a random point (MemeticToolkit::detour, span scale 0.3), a flip of a waypoint across the chord
       of its neighbours (MemeticToolkit::flip) or a re-walk of a piece (MemeticToolkit::rewalk, span scale
       0.3, at most 4000 lattice nodes). The offspring is tightened and evaluated and enters by deterministic
       crowding (it replaces the most similar individual, by the signature distance, when it is cheaper), so
       paths in different homotopy classes survive side by side and the best is never lost. With probability
       \c immigrant_rate per generation one fresh walk enters the same way. Offspring identical to their
       parent (no operator applied) are not evaluated. */
    class MemeticGenetic : public MemeticPlanner
    {
      public:
        explicit MemeticGenetic(const ompl::base::SpaceInformationPtr &si,
                                const std::string &name = "GA-MEM");

        void setCrossoverRate(double r);
        double getCrossoverRate() const { return crossoverRate_; }
        void setMutationRate(double r);
        double getMutationRate() const { return mutationRate_; }
        void setImmigrantRate(double r);
        double getImmigrantRate() const { return immigrantRate_; }
        void setTournamentSize(unsigned int k);
        unsigned int getTournamentSize() const { return tournamentSize_; }

      protected:
        bool generation(unsigned long t) override;

      private:
        std::size_t tournament();
        /** \brief State mode: an offspring of parent \e a into \e child.states; false when no operator
            changed it. */
        bool stateOffspring(std::size_t a, Individual &child);

        double crossoverRate_{0.7};
        double mutationRate_{0.5};
        double immigrantRate_{0.3};
        unsigned int tournamentSize_{2};
    };
} // namespace mhplan

#endif
