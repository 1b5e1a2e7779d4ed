// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: what PSO, WOA and GWO share on [LRSMA]'s framework (docs/algorithms.md 10): a population of
   waypoint vectors moved synchronously (every individual from the same previous population, then one
   evaluation round), the [LRSMA] defaults, the population view for the [GMS] switches. */
#ifndef MHPLAN_SWARM_PLANNER_H
#define MHPLAN_SWARM_PLANNER_H

#include "ompl_planners/common/PopulationPlanner.h"

#include <vector>

namespace mhplan
{
    /** \brief Base of the swarm comparators of [LRSMA] Table 3 (PSO, WOA, GWO; docs/algorithms.md 10).

        Defaults of [LRSMA] Table 2 and section 5.2 (the framework in which [LRSMA] compares every
        algorithm): N = 30, T = 30, m = 3 waypoints, spline decoding (n = 100), fitness S (eta1 = 1, eta2 =
        1000). The initial population is drawn uniformly in the bounds and evaluated (N evaluations). Each
        iteration a concrete algorithm writes the moved population into next() from the current one
        (member(), fitnessOf()), then moveRound() clamps and evaluates it (N evaluations); when the
        termination condition interrupts the round nothing is committed (the iteration is discarded, its
        evaluations still count). After every committed round, and after the initial one, evaluated() is
        called so that the algorithm updates its memory (personal bests, leaders). */
    class SwarmPlanner : public PopulationPlanner
    {
      public:
        SwarmPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);

        /** \brief The coefficient a of GWO and WOA at iteration t of T, falling linearly from 2 as the
            authors' code has it: 2 - 2 (t - 1) / T (2 at t = 1, 2 / T at t = T; docs/algorithms.md 10). */
        static double fallingCoefficient(unsigned int t, unsigned int T) { return 2.0 - 2.0 * (t - 1.0) / T; }

      protected:
        bool initialisePopulation() override;
        void clearPopulation() override;
        bool populationView(double *&x, double *&fitness) override;
        bool supportsGmsOperators() const override { return true; }
        void populationChanged() override { evaluated(); }

        /** \brief Called once the population and its fitness are current (after the initial round, every
            committed round and every change by the [GMS] operators): update the algorithm's memory. */
        virtual void evaluated() = 0;
        /** \brief Called by initialisePopulation() before the first evaluated() (reset the memory). */
        virtual void startSwarm() = 0;

        /** \brief Clamp and evaluate every row of next(); on success it becomes the population (evaluated()
            is called) and true is returned; false when interrupted (the population is unchanged). */
        bool moveRound();

        const double *member(unsigned int i) const { return x_.data() + std::size_t(i) * dimension(); }
        double fitnessOf(unsigned int i) const { return fit_[i]; }
        double *next(unsigned int i) { return next_.data() + std::size_t(i) * dimension(); }

      private:
        std::vector<double> x_, next_, fit_, nextFit_;
    };

    /** \brief The k best solutions seen so far (k = 1: the leader of WOA and PSO's global best; k = 3: GWO's
        alpha, beta and delta), kept sorted; a candidate enters only when strictly better than the k-th, and
        pushes the worse ones down (docs/algorithms.md 10). */
    class LeaderArchive
    {
      public:
        void reset(unsigned int k, unsigned int dimension);
        /** \brief Offer a solution; true when it entered the archive. */
        bool offer(const double *x, double fitness);
        unsigned int size() const { return static_cast<unsigned int>(fitness_.size()); }
        const double *position(unsigned int r) const { return x_.data() + std::size_t(r) * d_; }
        double fitness(unsigned int r) const { return fitness_[r]; }

      private:
        unsigned int d_{0};
        std::vector<double> x_, fitness_;
    };
} // namespace mhplan

#endif
