// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Grey Wolf Optimizer as an OMPL planner ([LRSMA] Table 3's GWO). */
#ifndef MHPLAN_GREY_WOLF_H
#define MHPLAN_GREY_WOLF_H

#include "ompl_planners/population/SwarmPlanner.h"

namespace mhplan
{
    /** \brief Grey Wolf Optimizer (GWO): Mirjalili, Mirjalili & Lewis, "Grey Wolf Optimizer", Advances in
        Engineering Software 69:46-61, 2014, as [LRSMA] compares it (Table 3; `a` from 2 to 0;
        docs/algorithms.md 10.3).

        alpha, beta and delta are the three best solutions found so far (LeaderArchive). Each iteration t
        (1..T), a = 2 - 2 (t - 1) / T; every wolf X moves, per coordinate j with fresh r1, r2 ~ U(0, 1) for
        each leader k: A_k = 2 a r1 - a, C_k = 2 r2, D_k = |C_k L_kj - X_j|, X_k = L_kj - A_k D_k, and the new
        X_j = (X_1 + X_2 + X_3) / 3; the moved pack is clamped and evaluated, then the leaders updated.

        Choices where the paper leaves room (docs/algorithms.md 10.3): a falls as in the authors' code
        (2 at the first iteration, 2 / T at the last; the paper: "from 2 to 0"); the leaders are the best
        three ever with demotion (a new alpha pushes alpha to beta and beta to delta, as the paper's
        "three best solutions obtained so far"; the authors' code overwrites without demotion); the pack
        moves synchronously (all wolves from the same leaders). Framework: SwarmPlanner. */
    class GreyWolf : public SwarmPlanner
    {
      public:
        explicit GreyWolf(const ompl::base::SpaceInformationPtr &si);

        /** \brief The new coordinate of a wolf at \e x from the leaders' coordinates \e leader[3] with the
            random numbers \e r1[3], \e r2[3] and the coefficient \e a (eqs 3.1-3.7 of the paper). */
        static double hunt(double x, const double leader[3], double a, const double r1[3],
                           const double r2[3]);

      protected:
        bool iterate(unsigned int t) override;
        void startSwarm() override;
        void evaluated() override;

      private:
        LeaderArchive leaders_;
    };
} // namespace mhplan

#endif
