// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Mountain Gazelle Optimizer as an OMPL planner. */
#ifndef MHPLAN_MOUNTAIN_GAZELLE_H
#define MHPLAN_MOUNTAIN_GAZELLE_H

#include "ompl_planners/common/PopulationPlanner.h"

namespace mhplan
{
    /** \brief Mountain Gazelle Optimizer (MGO): Abdollahzadeh, Gharehchopogh, Khodadadi, Mirjalili, "Mountain
        Gazelle Optimizer: A new Nature-inspired Metaheuristic Algorithm for Global Optimization Problems",
        Advances in Engineering Software 174:103282, 2022 (docs/algorithms.md section 3).

        As constructed (registry name "MGO") this is the original MGO of that paper on the waypoint encoding
        (docs/algorithms.md 1.1), with no [GMS] operator. [GMS]'s own MGO is the registry name "MGO-GMS": the
        same update with the [GMS] operators where [GMS] puts them (PopulationPlanner's gms_* switches,
        gms_initial on) and the [GMS] fitness (1.3, 1.5; MGO only ranks, so the maximised reciprocals order
        its population exactly as their keys do).

        Each iteration, for every gazelle X: coefficient vectors Cof_1 = (a + 1) + r3, Cof_2 = a N2,
        Cof_3 = r4, Cof_4 = N3 N4^2 cos(2 r5 N3) with a = -1 - t/T (Cof_r = one of the four, drawn afresh at
        each use); BH = X_ra floor(r1) + M_pr ceil(r2) (X_ra of rank in [ceil(N/3), N], M_pr the mean of
        ceil(N/3) distinct random gazelles); F = N1 exp(2 - 2t/T); D_v = (|X| + |male|)(2 r6 - 1); four
        offspring TSM, MH, BMH, MSF (see the spec), clamped and evaluated; then population and offspring are
        merged, sorted, and the best N kept. 4N evaluations per iteration; male_gazelle = best so far.

        Choices where the spec leaves room:
        - Defaults: N = 30, T = 30 ([LRSMA]'s budget), m = 3 waypoints, polyline decoding, fitness S on
          geometric worlds and [GMS] f1/f2 on grid worlds (parameter \c fitness).
        - r6 is one scalar per gazelle (as in the original code); ri1..ri6 are drawn per gazelle.
        - male_gazelle is updated after the merge at the end of each iteration.

        State spaces (docs/spaces.md): as "SMA", "LRSMA" and "MGO" (no [GMS] operator) it runs on any
        RealVectorStateSpace and on SE(2), DubinsStateSpace, ReedsSheppStateSpace, SE(3) and compound spaces
        of R^k, SO(2) and SO(3) (PopulationPlanner, StateParametrisation; there with decoding = polyline and
        the [LRSMA] fitness, the rules acting on the states' parametrisation); the [GMS] and -OPS variants
        are planar (their gms_* switches are refused elsewhere); other spaces are refused at setup(). */
    class MountainGazelle : public PopulationPlanner
    {
      public:
        explicit MountainGazelle(const ompl::base::SpaceInformationPtr &si);
        /** \brief The same algorithm under another name (e.g. "MGO-GMS"). */
        MountainGazelle(const ompl::base::SpaceInformationPtr &si, const std::string &name);

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;
        bool populationView(double *&x, double *&fitness) override;
        bool supportsGmsOperators() const override { return true; }
        /** \brief Sorts the population again and takes male_gazelle from it. */
        void populationChanged() override;

      private:
        /** \brief Stable sort of the N population rows by fitness; male_gazelle = the first. */
        void sortPopulation();
        double *row(std::vector<double> &pop, unsigned int i)
        {
            return pop.data() + std::size_t(i) * dimension();
        }
        /** \brief One of the four coefficient vectors, uniformly. */
        const double *cofR();

        /** \brief Population (N rows) followed by the offspring (4N rows). */
        std::vector<double> pool_;
        std::vector<double> poolFit_;
        std::vector<unsigned int> order_;
        std::vector<double> sorted_, sortedFit_;
        std::vector<double> male_;
        std::vector<double> cof_;
        std::vector<double> bh_, f_, dv_;
        std::vector<unsigned int> perm_;
    };
} // namespace mhplan

#endif
