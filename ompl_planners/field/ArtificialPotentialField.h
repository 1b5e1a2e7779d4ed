// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the classic artificial potential field planner (descent on J) as an OMPL planner. */
#ifndef MHPLAN_ARTIFICIAL_POTENTIAL_FIELD_H
#define MHPLAN_ARTIFICIAL_POTENTIAL_FIELD_H

#include "ompl_planners/field/FieldWalkPlanner.h"

#include <string>
#include <utility>
#include <vector>

namespace mhplan
{
    /** \brief Artificial potential field planner (Khatib, "Real-time obstacle avoidance for manipulators and
        mobile robots", IJRR 5(1), 1986), with the cost of [BFO] eqs 3-6 (docs/algorithms.md 7): descent on
        J = J_goal + J_obs of PotentialField (xi, eta, d0, D_sense) in steps of length lambda.

        - \c descent = directions (default): the robot evaluates J at the 16 (parameter \c directions)
          points at distance lambda around it, the first one straight toward the goal, and moves to the
          lowest one whose motion passes si->checkMotion, even when it is higher than the current J (so that a
          local minimum shows as oscillation, caught by the stall rule below).
        - \c descent = gradient: central-difference gradient of J (spacing \c gradient_spacing), a step of
          lambda along -grad J; a step failing checkMotion is halved up to 3 times, then the descent is stuck
          (approximate solution).
        - Goal: within \c goal_tolerance (0 = lambda) of the goal, the final segment to the exact goal is
          added if it passes checkMotion: exact solution.
        - Local minimum: when the best J so far has not improved by more than \c stall_tolerance (1e-6) over
          \c stall_steps (50) steps, the descent stops with an approximate solution (the path so far,
          difference = distance to the goal). \c max_steps bounds a descent too.
        - Deterministic (no randomness). A second solve() continues an interrupted descent; a finished one
          reports the same solution again; \c max_iterations bounds the steps per solve() call (0 = until the
          goal, a stall or the termination condition, tested before every step and every J evaluation);
          clear() restarts from the start.
        - Not an optimizing planner; no intermediate solutions. Progress properties: \c best \c cost
          (objective cost of the path once the goal is reached, else infinity), \c iterations (steps),
          \c fitness \c evaluations (J evaluations).
        Refuses in setup() a validity checker that does not compute clearance (see PotentialField). */
    class ArtificialPotentialField : public FieldWalkPlanner
    {
      public:
        explicit ArtificialPotentialField(const ompl::base::SpaceInformationPtr &si);

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;

        /** \brief lambda, the step length (parameter \c step_size, 1e-6..1e6). */
        void setStepSize(double v) { setWalkStep(v); }
        double getStepSize() const { return getWalkStep(); }
        /** \brief "directions" or "gradient". */
        void setDescent(const std::string &descent);
        std::string getDescent() const { return gradient_ ? "gradient" : "directions"; }
        /** \brief Number of sampled directions (3..3600). */
        void setDirections(unsigned int n);
        unsigned int getDirections() const { return directions_; }
        /** \brief Finite-difference spacing of the gradient (1e-9..1). */
        void setGradientSpacing(double h);
        double getGradientSpacing() const { return gradientSpacing_; }
        /** \brief Steps without improvement of the best J that end the descent (1..1000000). */
        void setStallSteps(unsigned int n);
        unsigned int getStallSteps() const { return stallSteps_; }
        /** \brief Improvement of the best J that counts (0..1e6). */
        void setStallTolerance(double v);
        double getStallTolerance() const { return stallTolerance_; }

      private:
        enum class State
        {
            Descending,
            ReachedGoal,
            Stalled,
            Stuck,
            BudgetSpent
        };

        bool reachedGoal() const override { return state_ == State::ReachedGoal; }
        bool prepare();
        /** \brief One descent step; false when the termination condition interrupted it (nothing moved). */
        bool step(const ompl::base::PlannerTerminationCondition &ptc);
        bool tryMove(const Vec2 &next);
        void finishIfAtGoal();
        ompl::base::PlannerStatus report();

        bool gradient_{false};
        unsigned int directions_{16};
        double gradientSpacing_{1e-4};
        unsigned int stallSteps_{50};
        double stallTolerance_{1e-6};

        State state_{State::Descending};
        double currentCost_{0.0};
        double bestCost_{0.0};
        unsigned long sinceImprovement_{0};
        /** \brief (J, direction index) of the sampled directions, sorted each step. */
        std::vector<std::pair<double, unsigned int>> candidates_;
    };
} // namespace mhplan

#endif
