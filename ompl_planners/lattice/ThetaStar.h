// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: Theta* (any-angle A*) on an 8-connected lattice as an OMPL planner (a deterministic baseline). */
#ifndef MHPLAN_THETA_STAR_H
#define MHPLAN_THETA_STAR_H

#include "ompl_planners/lattice/LatticePlanner.h"

namespace mhplan
{
    /** \brief Theta* (Nash, Daniel, Koenig, Felner, "Theta*: Any-angle path planning on grids", AAAI 2007,
        the basic variant) on the lattice of LatticePlanner (the same nodes and neighbours as AStar).

        When node s is expanded, each neighbour n is reached either from s's parent p in a straight line
        (path 2, when the segment p-n passes the shared motion validator: the line-of-sight test) or, failing
        that, from s over the lattice edge (path 1). The virtual start and goal take part like any node, so
        a goal in sight of the start gives the straight segment.

        Choices: the Euclidean distance to the goal as heuristic (as in the paper); ties in f towards larger
        g; closed nodes are never reopened; the line-of-sight test is skipped when path 2 could not improve
        the neighbour (path 1 is never shorter than path 2, by the triangle inequality); on sampled lattices
        a neighbour's lattice edge is checked only when path 2 fails. Paths are any-angle, never longer than
        the AStar path on the same lattice in practice (not guaranteed by the paper), and not necessarily
        optimal any-angle paths. */
    class ThetaStar : public LatticePlanner
    {
      public:
        explicit ThetaStar(const ompl::base::SpaceInformationPtr &si);

      protected:
        SearchResult search(const ompl::base::PlannerTerminationCondition &ptc,
                            unsigned long maxExpansions) override;
        double heuristic(LatticeNode n) const override;

      private:
        /** \brief Relax neighbour \e n (at \e pn) of the expanded node \e s through s's parent or through the
            edge s-n of length \e edgeCost; \e edgeKnownValid says whether that edge needs no check. */
        void relax(LatticeNode s, const Vec2 &ps, LatticeNode n, const Vec2 &pn, double edgeCost,
                   bool edgeKnownValid, double hn);
    };
} // namespace mhplan

#endif
