// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the [GMS] genetic algorithm as an OMPL planner. */
#ifndef MHPLAN_GENETIC_H
#define MHPLAN_GENETIC_H

#include "src/base/World.h"
#include "ompl_planners/common/Operators.h"
#include "ompl_planners/common/PopulationPlanner.h"

#include <memory>
#include <string>

namespace mhplan
{
    /** \brief Genetic algorithm of [GMS] ("Using Mountain Gazelle and Slime Mould Algorithms to Solve the
       Path Planning Problem", Adv. Defence Sci. & Technol., 2024; docs/algorithms.md 1.4, 1.5 and 2).

        An individual is a variable-length list of points from start to goal (the continuous form of the
        grid-node encoding, 1.4). Initial population (and replacement individuals): 1..\c waypoints random
        free points per individual, then node repair, line-segment repair, revision, simplification and node
        improvement (the paper's abstract puts node improvement on the initial population). Each generation:
       elitism (the best survives), tournament selection (size 2), with probability \c crossover_rate
       one-point crossover at an interior node common to both parents, else at random cut points; with
       probability \c mutation_rate a mutation: insert a random free node (probability \c insert_delete_rate),
        delete one (same probability), otherwise move a random interior node to a random free location;
        then node repair, line-segment repair, revision, simplification, node improvement, evaluation with
        the [GMS] f1/f2 (1.3), and replacement of the worst \c replace_fraction by fresh repaired random
        individuals.

        Choices where the spec leaves room:
        - Defaults N = 50, G = 100 (parameter \c iterations, the generations per run with max_iterations),
          crossover 0.8, mutation 0.1, insert/delete 0.05 each, tournament 2, replacement 10%,
          \c waypoints = 5 initial random nodes at most; fitness [GMS] (parameter \c fitness may select S).
        - Operators are the continuous versions of PathOperators (step 1% of the bounds' larger side);
          node improvement is applied to every offspring that is feasible after repair (parameter
          \c node_improvement). The validity checks inside the operators are not counted as fitness
          evaluations; every evaluated individual is.
        - The crossover's common node: two interior nodes are the same node when they lie in the same cell
          of the grid (grid worlds: mhplan's grid model behind the validity checker) or, elsewhere, within
          \c common_node_tolerance times the bounds' larger side (default 0.01) of each other, so that the
          crossover also fires on nodes that are not copies inherited from a common ancestor (exact equality
          of doubles would only match such copies). The children join at the matched nodes.
        - The fitness is [GMS]'s maximised reciprocal form (PathFitness; the GA only ranks).
        - \c decoding and \c spline_samples do not apply (paths are polylines through the nodes).
        - Planar only: the [GMS] node encoding comes from grid maps and its operators (ring search for node
          repair, the 8 compass moves of node improvement, the perpendicular bisector of segment repair) are
          written for the plane; setup() refuses a RealVectorStateSpace of dimension other than 2, and every
          other state space (SE(2), Dubins, Reeds-Shepp, ...), with ompl::Exception (use SMA, LRSMA or MGO in
          R^k and on those spaces, docs/spaces.md). */
    class Genetic : public PopulationPlanner
    {
      public:
        /** \brief \e name: "GA" (registry variants pass their own, e.g. "GA-WALK"). */
        explicit Genetic(const ompl::base::SpaceInformationPtr &si, const std::string &name = "GA");
        ~Genetic() override;

        /** \brief Refuse a space that is not a 2-dimensional RealVectorStateSpace (SE(2), Dubins and every
            other state space too), else PopulationPlanner::setup(). */
        void setup() override;

        /** \brief Crossover probability (0..1). */
        void setCrossoverRate(double r);
        double getCrossoverRate() const { return crossoverRate_; }
        /** \brief Mutation probability per offspring (0..1). */
        void setMutationRate(double r);
        double getMutationRate() const { return mutationRate_; }
        /** \brief Probability of an insert (and of a delete) mutation (0..0.5). */
        void setInsertDeleteRate(double r);
        double getInsertDeleteRate() const { return insertDeleteRate_; }
        /** \brief Tournament size (1..100). */
        void setTournamentSize(unsigned int k);
        unsigned int getTournamentSize() const { return tournamentSize_; }
        /** \brief Share of the population replaced by fresh individuals each generation (0..1). */
        void setReplaceFraction(double f);
        double getReplaceFraction() const { return replaceFraction_; }
        /** \brief How new individuals are drawn: "nodes" (the spec's random node sequences: 1..waypoints
           random free points, then repaired; the default) or "walk" (a random collision-free lattice walk
           from start to goal, PathOperators::randomLatticePath, simplified; falls back to "nodes" when the
           walk does not reach the goal within 20000 steps). "walk" is the improved variant GA-WALK: not in
           [GMS]. */
        void setInitialisation(const std::string &mode);
        std::string getInitialisation() const { return walk_ ? "walk" : "nodes"; }
        /** \brief Distance under which two nodes count as common in the crossover, as a fraction of the
            bounds' larger side (0..1; 0 = exact equality; not used on grid worlds, where cells decide). */
        void setCommonNodeTolerance(double f);
        double getCommonNodeTolerance() const { return commonTolerance_; }

        using Individual = std::vector<Vec2>;
        /** \brief The crossover's test: \e p and \e q are the same node (same cell of \e grid when it is
            not null, else |p - q| <= \e tolerance). */
        static bool sameNode(const Vec2 &p, const Vec2 &q, double tolerance, const OccupancyGrid *grid);
        /** \brief The first interior node of \e a, searched from interior index \e offset on (cyclically),
            that is the same node (sameNode()) as an interior node of \e b; false when there is none. */
        static bool findCommonNode(const Individual &a, const Individual &b, std::size_t offset,
                                   double tolerance, const OccupancyGrid *grid, std::size_t &ia,
                                   std::size_t &ib);

        /** \brief Apply node improvement to the offspring. */
        void setNodeImprovement(bool on) { nodeImprovement_ = on; }
        bool getNodeImprovement() const { return nodeImprovement_; }

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;

      private:
        void randomIndividual(Individual &ind);
        void repair(Individual &ind, bool improve);
        unsigned int tournament();
        void crossover(const Individual &a, const Individual &b, Individual &c1, Individual &c2);
        void mutate(Individual &ind);

        double crossoverRate_{0.8};
        double mutationRate_{0.1};
        double insertDeleteRate_{0.05};
        unsigned int tournamentSize_{2};
        double replaceFraction_{0.1};
        bool nodeImprovement_{true};
        bool walk_{false};
        double commonTolerance_{0.01};
        /** \brief The grid behind the validity checker (grid worlds), else null; set per problem. */
        const OccupancyGrid *grid_{nullptr};
        double tolerance_{0.0};

        std::unique_ptr<PathOperators> ops_;
        std::vector<Individual> pop_, next_;
        std::vector<double> fit_, nextFit_;
        std::vector<unsigned int> order_;
    };
} // namespace mhplan

#endif
