// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: A* on an 8-connected lattice as an OMPL planner (a deterministic baseline). */
#ifndef MHPLAN_ASTAR_H
#define MHPLAN_ASTAR_H

#include "ompl_planners/lattice/LatticePlanner.h"

namespace mhplan
{
    /** \brief A* (Hart, Nilsson, Raphael, "A formal basis for the heuristic determination of minimum cost
        paths", IEEE Trans. SSC 4(2):100-107, 1968) on the 8-connected lattice of LatticePlanner: straight
       moves cost one spacing, diagonal moves sqrt 2 spacings.

        On grid worlds (point robot) the lattice is the map's cells with the MovingAI rules (a diagonal move
        needs both side cells free), so its lengths are those of the MovingAI benchmark scenarios; no motion
        validator call is made during the search (the moves are valid for the exact grid model by
        construction, and the final path is checked once). On other worlds the lattice is sampled at spacing
        \c resolution; node validity by the validity checker, every edge by the motion validator (checked
        lazily, only when it would improve a node).

        Choices: the octile heuristic spacing * (max(dx, dy) + (sqrt 2 - 1) min(dx, dy)) towards the goal,
        lowered by the largest difference between octile and Euclidean length of the goal's links (0 when
        the goal is a node), which keeps it consistent with the straight goal links; ties in f are broken
        towards larger g (deeper nodes first); closed nodes are never reopened (the heuristic is
        consistent); the open list is LatticeOpenList (binary heap with decrease-key, flat arrays). The
        search minimises length; the reported cost is the problem's objective. */
    class AStar : public LatticePlanner
    {
      public:
        explicit AStar(const ompl::base::SpaceInformationPtr &si);

      protected:
        SearchResult search(const ompl::base::PlannerTerminationCondition &ptc,
                            unsigned long maxExpansions) override;
        double heuristic(LatticeNode n) const override;

      private:
        template <bool GridCells>
        SearchResult run(const ompl::base::PlannerTerminationCondition &ptc, unsigned long maxExpansions);
    };
} // namespace mhplan

#endif
