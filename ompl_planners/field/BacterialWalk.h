// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the online BFO / ATBFO of [BFO], a robot walk guided by a bacterial colony on a potential field
   (docs/algorithms.md 6.1-6.3). */
#ifndef MHPLAN_BACTERIAL_WALK_H
#define MHPLAN_BACTERIAL_WALK_H

#include "ompl_planners/field/BacterialColony.h"
#include "ompl_planners/field/ColonyParameters.h"
#include "ompl_planners/field/FieldWalkPlanner.h"

#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Bacterial Foraging Optimization (Passino, "Biomimicry of bacterial foraging for distributed
        optimization and control", IEEE Control Systems 22(3):52-67, 2002) and its adaptive-tumble variant
        for path planning of Abbas & Ali, "Path Planning of an Autonomous Mobile Robot using Enhanced
        Bacterial Foraging Optimization Algorithm" (2016) ([BFO]), as [BFO] runs them: online (registry names
        "BFO" and "ATBFO"; the global search over waypoint vectors is BacterialForaging, "BFO-GLOBAL").

        The colony (docs/algorithms.md 6.1, 6.2; see BacterialColony): Ned x Nre x Nc chemotactic steps of
        tumbles and swims on a cost J, reproduction of the healthier half, dispersal with probability Ped;
        ATBFO (\c adaptive_tumble, on for "ATBFO") keeps a direction after more than F_improv improving swims.

        The walk (6.3): the robot (a point at the state's position) walks from the start. Each robot step is
        one full colony run on the potential field J of PotentialField (xi, eta, d0, D_sense), with the S
        (\c population_size) bacteria drawn uniformly (by area) in the sector of +-\c sector_angle degrees
        about the direction to the goal, up to D_sense from the robot (also where dispersed bacteria land).
        The robot then moves \c robot_step (lambda) toward the lowest J found during the run (phi_best =
        atan2, eqs 8-10); a step that fails si->checkMotion is halved up to 3 times, after which the walk
        fails there. Within \c goal_tolerance (0 = lambda) of the goal the final segment to the exact goal is
        added if it passes checkMotion (otherwise the walk goes on). The path is the sequence of robot
        positions. Choices where [BFO] is open:
        - The bacteria are confined to the robot's sensing disc: a move leaving it is projected back onto
          the disc (and into the bounds). Without it the bacteria drift up to Nc (Ns + 1) C = 5.6 m toward the
          goal, beyond what the robot senses.
        - The robot senses only what it sees: a bacterium whose straight segment from the robot is not free
          (PotentialField::segmentFree: behind an obstacle) costs +infinity, like one inside an obstacle.
          Without this, the lowest J in the disc often lies behind the obstacle being passed and the heading
          toward it runs into the obstacle (measured: the walk then stops at the first obstacle it grazes).
        - A position's J is cached between chemotactic steps (Passino re-evaluates it; same value), so
          evaluations count only the tumbles and swims; with cell-to-cell on, J_cc is recomputed each time.
        - The walk also ends after \c max_steps robot steps (a budget the paper leaves open).
        - Exact solution only when every segment of the walk passed checkMotion and the goal was reached;
          otherwise an approximate one (the walk so far, difference = distance from the robot to the goal).
        - A second solve() continues an interrupted walk; a finished walk (goal reached, failed step or
          budget spent) just reports the same solution again. \c max_iterations bounds the robot steps per
          solve() call (0 = until the goal, the termination condition or the end of the walk).
        - Not an optimizing planner (specs: optimizingPaths false); the intermediate-solution callback fires
          once, when the walk reaches the goal. J is a local cost; the reported cost is the problem's
          objective of the walked path.

        Problem: a 2D RealVectorStateSpace whose validity checker computes clearance (refused otherwise at
        setup(), see PotentialField). Defaults ([BFO] section 6): S = 100, Nc = 8, Ns = 6, Nre = 2, Ned = 1,
        Ped = 0.15, C = 0.1, xi = 0.1, eta = 0.06, d0 = 1.5, lambda = 0.2, F_improv = 3, D_sense = 1.2.
        Progress properties: \c best \c cost (infinity until the goal is reached), \c iterations (robot
        steps), \c fitness \c evaluations (J evaluations). Randomness only from the member RNG (parameter
        \c seed, or OMPL's global seed when it is 0). The termination condition is tested before every
        evaluation, inside the swims too. */
    class BacterialWalk : public FieldWalkPlanner, public ColonyParameters
    {
      public:
        /** \brief "BFO" (adaptive tumble off) or "ATBFO" (adaptive tumble on by default). */
        BacterialWalk(const ompl::base::SpaceInformationPtr &si, bool adaptiveTumble = false);
        ~BacterialWalk() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;

        /** \brief S, the bacteria of each colony run (SharedParameterRanges); a change restarts the walk. */
        void setPopulationSize(unsigned int n) override;
        /** \brief lambda, the robot's step (parameter \c robot_step, 1e-6..1e6). */
        void setRobotStep(double v) { setWalkStep(v); }
        double getRobotStep() const { return getWalkStep(); }
        /** \brief Half angle in degrees of the sector the bacteria start in (0..180). */
        void setSectorAngle(double deg);
        double getSectorAngle() const { return sectorAngle_; }

        /** \brief True when the walk has ended (goal, failure or budget). */
        bool walkFinished() const { return walkState_ != WalkState::Walking; }

      private:
        enum class WalkState
        {
            Walking,
            ReachedGoal,
            Failed,
            BudgetSpent
        };
        class Adapter;

        bool reachedGoal() const override { return walkState_ == WalkState::ReachedGoal; }
        bool halt() const { return ptc_ == nullptr || (*ptc_)(); }
        double rawCost(const double *x);
        void randomBacterium(double *x);
        void constrain(double *x) const;
        bool prepare();
        void moveRobot();
        void finishWalkIfAtGoal();
        ompl::base::PlannerStatus report();

        // Parameters (the colony's in ColonyParameters, the field's in PotentialFieldSettings, the walk's in
        // FieldWalkPlanner).
        double sectorAngle_{45.0};

        std::unique_ptr<Adapter> adapter_;
        BacterialColony colony_{colonySettings_};
        const ompl::base::PlannerTerminationCondition *ptc_{nullptr};
        /** \brief The seed parameter the walk was prepared with (a new seed restarts it). */
        unsigned long seedUsed_{0};
        bool runActive_{false};
        WalkState walkState_{WalkState::Walking};
        bool runBestKnown_{false};
        double runBestCost_{0.0};
        Vec2 runBest_;
    };
} // namespace mhplan

#endif
