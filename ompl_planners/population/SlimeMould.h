// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Slime Mould Algorithm as an OMPL planner. */
#ifndef MHPLAN_SLIME_MOULD_H
#define MHPLAN_SLIME_MOULD_H

#include "ompl_planners/common/PopulationPlanner.h"

namespace mhplan
{
    /** \brief Slime Mould Algorithm (SMA): Li, Chen, Wang, Heidari, Mirjalili, "Slime mould algorithm: A new
        method for stochastic optimization", Future Generation Computer Systems 111:300-323, 2020
        (docs/algorithms.md section 4).

        As constructed (registry name "SMA") this is the original SMA in [LRSMA]'s path-planning framework
        ([LRSMA] sections 3 and 5.2, the SMA that [LRSMA] Table 3 compares with LRSMA): spline decoding of
        m = 3 waypoints, fitness S of docs/algorithms.md 1.2 on every world, no [GMS] operator. [GMS]'s own
        SMA is the registry name "SMA-GMS": the same update with the [GMS] operators where [GMS] puts them
        (PopulationPlanner's gms_* switches, gms_initial on) and the [GMS] fitness, maximised (1.3, 1.5).

        Each iteration: sort the population by fitness; weights W = 1 +- r log10((bF - S_i) / (bF - wF + eps)
        + 1) (plus for the better half by rank, minus for the rest); a = arctanh(1 - t/T), b = 1 - t/T; each
        slime mould is, with probability z, redrawn uniformly in the bounds, otherwise per coordinate j with
        p = tanh|S_i - DF|: X_j = X_best_j + vb_j (W_ij X_A_j - X_B_j) when r < p (A, B drawn afresh for every
        coordinate), else X_j = vc_j X_j; then clamp and evaluate (N evaluations per iteration).

        With the [GMS] fitness (\c fitness = gms) S_i, bF, wF and DF are the paper's maximised values f1 / f2
        (docs/algorithms.md 1.3): the population is ranked feasibility first, then f descending; bF, wF are
        the values of the first and last ranked; the weight ratio (bF - S_i) / (bF - wF) is clamped to [0, 1]
        (a feasible path may rank above an infeasible one of higher value; mhplan's choice), and p =
        tanh|S_i - DF| reads f values (near 1 / path length: p is small, unlike with S). See weightTerm().

        Choices where the spec leaves room (stated here as docs/conventions.md asks):
        - Defaults: N = 30, T = 30, z = 0.3 ([LRSMA] Table 2; the original paper's 0.03 is a parameter value),
          m = 3 waypoints, spline decoding, fitness lrsma (parameters \c decoding, \c fitness).
        - The population is updated in place, as in the original code (later individuals read already
          updated ones through X_A, X_B); DF / X_best are updated right after each evaluation round (the
          original does it at the start of the next iteration from the same values: same result).
        - t runs 1..T, so a = arctanh(1 - 1/T) is finite at the first iteration; at t = T, a = b = 0 and the
          non-elite coordinates collapse to 0 as in the original (the best-ever archive is unaffected).
        - Out-of-bounds coordinates are clamped.

        State spaces (docs/spaces.md): as "SMA", "LRSMA" and "MGO" (no [GMS] operator) it runs on any
        RealVectorStateSpace and on SE(2), DubinsStateSpace, ReedsSheppStateSpace, SE(3) and compound spaces
        of R^k, SO(2) and SO(3) (PopulationPlanner, StateParametrisation; there with decoding = polyline and
        the [LRSMA] fitness, the rules acting on the states' parametrisation); the [GMS] and -OPS variants
        are planar (their gms_* switches are refused elsewhere); other spaces are refused at setup(). */
    class SlimeMould : public PopulationPlanner
    {
      public:
        explicit SlimeMould(const ompl::base::SpaceInformationPtr &si);
        /** \brief The same algorithm (same defaults) under another name (e.g. "SMA-GMS", which the registry
            then configures, so benchmark logs tell variants apart). */
        SlimeMould(const ompl::base::SpaceInformationPtr &si, const std::string &name);

        /** \brief Probability z of a random restart of one slime mould (0..1). */
        void setZ(double z);
        double getZ() const { return z_; }

        /** \brief The log10 term of the weights W = 1 +- r * term for a slime mould of value \e s, with
            \e bF, \e wF the iteration's best and worst values: log10((bF - s) / (bF - wF) + 1), written for
            minimisation as the original, or, with \e maximise (the [GMS] fitness), for maximised values
            (best and worst turned; the ratio clamped to [0, 1]). */
        static double weightTerm(double bF, double wF, double s, bool maximise);
        /** \brief p = tanh|s - DF| of the update rule (\e best = DF). */
        static double oscillationProbability(double s, double best);

      protected:
        SlimeMould(const ompl::base::SpaceInformationPtr &si, const std::string &name,
                   const PopulationDefaults &defaults);

        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;
        bool populationView(double *&x, double *&fitness) override;
        bool supportsGmsOperators() const override { return true; }
        /** \brief Takes an improved individual into DF / X_best. */
        void populationChanged() override;

        /** \brief One SMA update and its evaluation round (commits only when not interrupted). */
        bool slimeMouldStep(unsigned int t);
        /** \brief Take the population's best into DF / X_best when it improves on DF. */
        void updateBest();

        double *row(std::vector<double> &pop, unsigned int i)
        {
            return pop.data() + std::size_t(i) * dimension();
        }
        const double *row(const std::vector<double> &pop, unsigned int i) const
        {
            return pop.data() + std::size_t(i) * dimension();
        }

        double z_{0.3};
        std::vector<double> x_, next_, weights_;
        /** \brief Fitness keys (minimised), and the values the update reads (score_: the same, or the
            maximised [GMS] f1 / f2). */
        std::vector<double> fit_, nextFit_, score_;
        std::vector<unsigned int> order_;
        std::vector<double> bestX_, vb_, vc_;
        /** \brief DF: the best fitness the algorithm steers by (LRSMA's annealing may make it worse). */
        double bestF_{0.0};

      private:
        void declareSlimeMouldParams();
    };
} // namespace mhplan

#endif
