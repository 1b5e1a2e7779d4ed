// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the [GMS] path operators (docs/algorithms.md 1.5) on explicit point lists, for any planner. */
#ifndef MHPLAN_OPERATORS_H
#define MHPLAN_OPERATORS_H

#include "ompl_planners/common/Fitness.h"

#include <ompl/util/RandomNumbers.h>

#include <vector>

namespace mhplan
{
    /** \brief Node repair, line-segment repair, node improvement, simplification and revision of [GMS] on a
        path given as a list of points (first = start, last = goal; both are never moved or removed).
        Validity goes through a PathFitness, i.e. the problem's own validity checker and motion validator,
        so the operators work on geometric and grid worlds alike (continuous versions of the grid operators:
        rings of samples instead of BFS over cells, docs/algorithms.md 1.5). Replacement is a population-level
        operator and lives in the planners. Randomness from the RNG passed in.

        \e step is the base length of the operators' moves (default 1% of the bounds' larger side).

        Planar only (rings of 16 angles, 8 compass moves, the perpendicular of a segment): the constructor
        throws std::invalid_argument when the fitness is configured for a space of dimension other than 2. */
    class PathOperators
    {
      public:
        PathOperators(PathFitness &fitness, ompl::RNG &rng, const Box &bounds, double step);

        /** \brief A uniformly random valid point (up to \e tries samples; the last sample if none is valid).
         */
        Vec2 randomFreePoint(unsigned int tries = 100);
        /** \brief Move an invalid point to the first valid sample on growing rings (radius k step, 16 angles
            with a random offset, k = 1..200); false when none was found. */
        bool repairNode(Vec2 &p);
        /** \brief Node repair on every interior node. */
        void repairNodes(std::vector<Vec2> &path);
        /** \brief Line-segment repair: for each invalid segment between valid nodes, try points on the
            perpendicular bisector at offsets k * max(2% of the segment, step), both sides alternately,
            k = 1..maxTries, and insert the first one from which both halves are valid. */
        void repairSegments(std::vector<Vec2> &path, unsigned int maxTries = 60);
        /** \brief Simplification: remove node i when node i-1 sees node i+1, to a fixed point. */
        void simplify(std::vector<Vec2> &path);
        /** \brief Revision: remove repeated nodes and cut the loop between two visits of the same node. */
        void revise(std::vector<Vec2> &path);
        /** \brief Node improvement: for each interior node try the 8 compass moves of size step * 4, 2, 1;
            keep the first move that lowers the [GMS] f1 while both adjacent segments stay valid. Only for
            feasible paths (returns false and does nothing otherwise). */
        bool improveNodes(std::vector<Vec2> &path);
        /** \brief A random collision-free node sequence from \e start to \e goal (the initialisation of the
            GA-WALK variant): a depth-first walk on the lattice start + step * (i, j) over the 8 compass
           moves, each move ranked by its progress toward the goal plus uniform noise in [0, \e noise) and
           taken when its segment is valid and its node unvisited (dead ends are backed out of), until the
           goal is in sight. At most \e maxExpansions walk steps; false (and \e path unspecified) when the
           goal was not reached. The path has no loops; simplify() it to a few nodes. */
        bool randomLatticePath(std::vector<Vec2> &path, const Vec2 &start, const Vec2 &goal,
                               unsigned int maxExpansions, double noise = 1.5);

      private:
        bool inBounds(const Vec2 &p) const;

        PathFitness &fitness_;
        ompl::RNG &rng_;
        Box bounds_;
        double step_;
        std::vector<Vec2> scratch_;
    };
} // namespace mhplan

#endif
