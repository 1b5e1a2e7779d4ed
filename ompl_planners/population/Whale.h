// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Whale Optimization Algorithm as an OMPL planner ([LRSMA] Table 3's WOA). */
#ifndef MHPLAN_WHALE_H
#define MHPLAN_WHALE_H

#include "ompl_planners/population/SwarmPlanner.h"

#include <cmath>

namespace mhplan
{
    /** \brief Whale Optimization Algorithm (WOA): Mirjalili & Lewis, "The Whale Optimization Algorithm",
        Advances in Engineering Software 95:51-67, 2016, as [LRSMA] compares it (Table 3; `a` from 2 to 0;
        docs/algorithms.md 10.2).

        The leader X* is the best solution found so far. Each iteration t (1..T), a = 2 - 2 (t - 1) / T;
        every whale X draws r1, r2, p ~ U(0, 1) and l ~ U(-1, 1), A = 2 a r1 - a, C = 2 r2, and moves every
        coordinate j by one rule (choose()):
        - p < 0.5 and |A| < 1, encircling (eqs 2.1-2.2): X_j = X*_j - A |C X*_j - X_j|;
        - p < 0.5 and |A| >= 1, search for prey (eqs 2.7-2.8): X_j = R_j - A |C R_j - X_j| with R a random
          whale of the current pod;
        - p >= 0.5, bubble-net spiral (eq 2.5): X_j = |X*_j - X_j| e^(b l) cos(2 pi l) + X*_j.
        The moved pod is clamped and evaluated, then the leader updated.

        Choices where the paper leaves room (docs/algorithms.md 10.2): A and C are scalars per whale (the
        paper's |A| < 1 test needs one number; the authors' code does the same); R is one whale per move
        (the code draws one per coordinate); l ~ U(-1, 1) as the paper (the code narrows it to
        [a2, 1], a2 from -1 to -2); b = 1 (\c spiral); a as in the code (2 at the first iteration, 2 / T at
        the last); synchronous moves. Framework: SwarmPlanner.

        Planar only (R^2; setup() refuses other spaces naming them): on a Dubins car space OMPL 1.5.2's
        Dubins distance aborted the process (an assertion in its RSR word) on waypoints WOA proposed, and in
        R^3 and R^6 its paths stayed over 30 % above the shortest (docs/algorithms.md 10.2). */
    class Whale : public SwarmPlanner
    {
      public:
        explicit Whale(const ompl::base::SpaceInformationPtr &si);

        /** \brief Spiral shape constant b (0.01..10). */
        void setSpiral(double b);
        double getSpiral() const { return b_; }

        enum class Move
        {
            Encircle,
            Search,
            Spiral
        };
        /** \brief The rule a whale follows for the draws \e p and \e A. */
        static Move choose(double p, double A)
        {
            return p >= 0.5 ? Move::Spiral : std::abs(A) < 1.0 ? Move::Encircle : Move::Search;
        }
        /** \brief The new coordinate of a whale at \e x under \e move (\e target: the leader's coordinate,
            or the random whale's for Search; \e l and \e b only for Spiral). */
        static double moveCoordinate(Move move, double x, double target, double A, double C, double l,
                                     double b);

        /** \brief PopulationPlanner::setup(), then refuses every space but R^2 (docs/algorithms.md 10.2). */
        void setup() override;

      protected:
        bool iterate(unsigned int t) override;
        void startSwarm() override;
        void evaluated() override;

      private:
        double b_{1.0};
        LeaderArchive leader_;
    };
} // namespace mhplan

#endif
