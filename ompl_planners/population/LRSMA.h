// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Levy-flight-rotation Slime Mould Algorithm as an OMPL planner. */
#ifndef MHPLAN_LRSMA_H
#define MHPLAN_LRSMA_H

#include "ompl_planners/population/SlimeMould.h"

namespace mhplan
{
    /** \brief The tolerance-based stagnation monitor of [LRSMA] eq 8 (docs/algorithms.md 5): tau(t) is read
        before it is updated, so with Tmax = 2 the rotation fires on the third consecutive iteration with
        dF < Fmin (then every third while the stagnation lasts). */
    class StagnationMonitor
    {
      public:
        StagnationMonitor(double fmin, unsigned int tmax) : fmin_(fmin), tmax_(tmax) {}
        /** \brief Feed dF = |F(t) - F(t-1)|; true when the population stagnates (rotate now). */
        bool update(double dF)
        {
            if (!(dF < fmin_))
            {
                tau_ = 0;
                return false;
            }
            if (tau_ < tmax_)
            {
                ++tau_;
                return false;
            }
            tau_ = 0;
            return true;
        }
        unsigned int tau() const { return tau_; }
        void reset() { tau_ = 0; }

      private:
        double fmin_;
        unsigned int tmax_;
        unsigned int tau_{0};
    };

    /** \brief Levy-flight-rotation SMA (LRSMA): Zheng et al., "Path Planning of Autonomous Mobile Robots
       Based on an Improved Slime Mould Algorithm", Drones 7(4):257, 2023, section 4 (docs/algorithms.md
       section 5).

        Each iteration: the SMA update (SlimeMould), then
        - variable-neighbourhood Levy flight on the elite (eqs 6-7, Mantegna): for index = 0, 1, 2,
          X_l = (1 + index r_l) (X_best + stepsize Levy(beta)), r_l ~ U(0, 0.5); the first X_l better than
          X_best replaces it;
        - tolerance-based stagnation monitor (eq 8, StagnationMonitor): dF = |F(t) - F(t-1)| of the steering
          best DF; both tests read tau(t) before it is updated: dF < Fmin and tau < Tmax: tau + 1; dF < Fmin
          and tau == Tmax: the rotation perturbation (eq 9), X_r = X + omega (R (.) X) / ||X||_2,
          omega ~ U(0.1, 1), R ~ U(-1, 1)^D, applied greedily to the best p_r fraction of the population,
          and tau = 0; dF >= Fmin: tau = 0. With Tmax = 2 the rotation comes on the third consecutive
          stagnant iteration (docs/algorithms.md 5, correction of 2026-12-01);
        - elite simulated annealing (4.3): X_best perturbed the same way; accepted when better, or when
          exp(-(DF_r - DF) / Temp) < rand (the paper's condition as written). The base class keeps the
          best-ever path for reporting, so an accepted worse elite never loses the solution.

        Choices where the spec leaves room:
        - Defaults ([LRSMA] Table 2): N = 30, T = 30, z = 0.3, Fmin = 1, p_r = 0.5, Tmax = 2, m = 3, spline
          decoding with n = 100 samples, fitness S (eta1 = 1, eta2 = 1000); beta = 1.5 and stepsize =
          0.01 (ub - lb) per coordinate (open in the paper); Temp = 1000.
        - The rotation uses the elementwise product R (.) X (parameter \c rotation_product = elementwise;
          "dot" gives the literal scalar reading R.X added to every coordinate).
        - The annealing step runs every iteration, after the stagnation monitor; F(t) is DF after the SMA
          update and the Levy flight. The rotated set is the best ceil(p_r N) by current fitness.
        - Every perturbed candidate is clamped to the bounds before evaluation.

        State spaces (docs/spaces.md): as "SMA", "LRSMA" and "MGO" (no [GMS] operator) it runs on any
        RealVectorStateSpace and on SE(2), DubinsStateSpace, ReedsSheppStateSpace, SE(3) and compound spaces
        of R^k, SO(2) and SO(3) (PopulationPlanner, StateParametrisation; there with decoding = polyline and
        the [LRSMA] fitness, the rules acting on the states' parametrisation); the [GMS] and -OPS variants
        are planar (their gms_* switches are refused elsewhere); other spaces are refused at setup(). */
    class LRSMA : public SlimeMould
    {
      public:
        explicit LRSMA(const ompl::base::SpaceInformationPtr &si);
        /** \brief The same algorithm under another name (e.g. "LRSMA-GMS"). */
        LRSMA(const ompl::base::SpaceInformationPtr &si, const std::string &name);

        /** \brief Levy exponent beta (0.1..1.99). */
        void setLevyBeta(double beta);
        double getLevyBeta() const { return beta_; }
        /** \brief Levy step size as a fraction of the bounds' extent per coordinate (0..1). */
        void setLevyStep(double step);
        double getLevyStep() const { return levyStep_; }
        /** \brief Fmin of the stagnation monitor (0..1e9). */
        void setStagnationTolerance(double fmin);
        double getStagnationTolerance() const { return fmin_; }
        /** \brief Tmax of the stagnation monitor (1..1000). */
        void setStagnationLimit(unsigned int tmax);
        unsigned int getStagnationLimit() const { return tmax_; }
        /** \brief p_r, the rotated fraction of the population (0..1). */
        void setRotationFraction(double pr);
        double getRotationFraction() const { return pr_; }
        /** \brief Temp of the elite annealing (1e-9..1e12). */
        void setTemperature(double temp);
        double getTemperature() const { return temperature_; }
        /** \brief "elementwise" (R (.) X) or "dot" (R . X). */
        void setRotationProduct(const std::string &product);
        std::string getRotationProduct() const { return elementwise_ ? "elementwise" : "dot"; }
        /** \brief Rotation perturbations of the population (stagnation events) since the last clear(). */
        unsigned long rotationCount() const { return rotations_; }

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;

      private:
        /** \brief out = X + omega (R (.) X) / ||X|| (or the dot reading), clamped. */
        void rotate(const double *x, double *out);
        double levy();

        double beta_{1.5};
        double levyStep_{0.01};
        double fmin_{1.0};
        unsigned int tmax_{2};
        double pr_{0.5};
        double temperature_{1000.0};
        bool elementwise_{true};

        double sigmaU_{0.0};
        StagnationMonitor monitor_{1.0, 2};
        unsigned long rotations_{0};
        double previousF_{0.0};
        std::vector<double> trial_;
        std::vector<unsigned int> rank_;
    };
} // namespace mhplan

#endif
