// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: Bacterial Foraging Optimization (BFO) and Adaptive-Tumble BFO (ATBFO) as an OMPL planner. */
#ifndef MHPLAN_BACTERIAL_FORAGING_H
#define MHPLAN_BACTERIAL_FORAGING_H

#include "mhplan/planners/common/PopulationPlanner.h"
#include "mhplan/planners/field/BacterialColony.h"
#include "mhplan/planners/field/PotentialField.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Bacterial Foraging Optimization (Passino, "Biomimicry of bacterial foraging for distributed
        optimization and control", IEEE Control Systems 22(3):52-67, 2002) and its adaptive-tumble variant
        for path planning of Abbas & Ali, "Path Planning of an Autonomous Mobile Robot using Enhanced
        Bacterial Foraging Optimization Algorithm" (2016) ([BFO]; docs/algorithms.md sections 6.1-6.4).

        Core BFO (6.1) on a cost J: for l < Ned, k < Nre, j < Nc, every bacterium i: tumble along a random
       unit direction phi (theta_i += C phi, evaluate), then swim (again C phi) while J improves, at most Ns
        times. The move is unconditional as in Passino's code (a worse last move is kept). Health = sum of J
        after each chemotactic step; after Nc steps the healthier half splits (two copies each), the rest
        dies; after Nre reproductions each bacterium is moved to a random position with probability Ped.
        Optional cell-to-cell term J_cc (parameter \c cell_to_cell, off by default as in [BFO]), added to J
        for the swim decisions and health, never to the best-position bookkeeping.

        ATBFO (6.2, parameter \c adaptive_tumble, on by default for the registry name "ATBFO"): a bacterium
        counts its improvements imp_count (J < J_last) in the swim (run) of each chemotactic step, the
        tumble move not counted ([BFO] Pseudo code 1), so at most Ns; when the count exceeds F_improv it keeps
       its direction for the next step; offspring inherit the direction and the flag at reproduction; a
       dispersed bacterium draws a fresh one.

        \c mode = online (the faithful default, 6.3): the robot (a point at the state's position) walks from
        the start. Each robot step is one full BFO run (Ned x Nre x Nc chemotactic steps) on the potential
        field J of PotentialField (xi, eta, d0, D_sense), with the S bacteria drawn uniformly (by area) in the
        sector of +-\c sector_angle degrees about the direction to the goal, up to D_sense from the robot
        (also where dispersed bacteria land). The robot then moves \c robot_step (lambda) toward the lowest
        J found during the run (phi_best = atan2, eqs 8-10); a step that fails si->checkMotion is halved up
        to 3 times, after which the walk fails there. Within \c goal_tolerance (0 = lambda) of the goal the
        final segment to the exact goal is added if it passes checkMotion (otherwise the walk goes on). The
        path is the sequence of robot positions.
        Choices where [BFO] is open:
        - The bacteria are confined to the robot's sensing disc: a move leaving it is projected back onto
          the disc (and into the bounds), as out-of-bounds coordinates are clamped in 1.1. Without it the
          bacteria drift up to Nc (Ns + 1) C = 5.6 m toward the goal, beyond what the robot senses.
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
        - Not an optimizing planner (specs: optimizingPaths false), no intermediate solutions; J is a local
          cost, the reported cost is the problem's objective of the walked path.

        \c mode = global (6.4): BFO over the waypoint encoding of 1.1 with PopulationPlanner's fitness
        ([LRSMA] S on geometric worlds, parameters \c waypoints, \c decoding, \c fitness ...). One iteration
        is one chemotactic step of the whole colony; after the Ned elimination-dispersal events the loops
        start again from the current colony (until the termination condition or \c max_iterations).
        Positions are clamped to the bounds; C is absolute (in metres per coordinate), so larger worlds want
        a larger \c step_size. Dispersal draws a uniform waypoint vector. An optimizing planner with
        intermediate solutions, as the other population planners.

        Defaults ([BFO] section 6): S = \c population_size = 100, Nc = 8, Ns = 6, Nre = 2, Ned = 1,
        Ped = 0.15, C = 0.1, xi = 0.1, eta = 0.06, d0 = 1.5, lambda = 0.2, F_improv = 3, D_sense = 1.2.
        Cell-to-cell (Passino): d_att = 0.1, w_att = 0.2, h_rep = 0.1, w_rep = 10.
        Progress properties: \c best \c cost (objective cost of the path; online: infinity until the goal
        is reached), \c iterations (online: robot steps; global: colony chemotactic steps), \c fitness
        \c evaluations (J evaluations). Randomness only from the member RNG (parameter \c seed or OMPL's
        global seed). The termination condition is tested before every evaluation, inside the swims too. */
    class BacterialForaging : public PopulationPlanner, public PotentialFieldSettings
    {
      public:
        /** \brief "BFO" (adaptive tumble off) or "ATBFO" (adaptive tumble on by default). */
        BacterialForaging(const ompl::base::SpaceInformationPtr &si, bool adaptiveTumble = false);
        ~BacterialForaging() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief "online" (6.3) or "global" (6.4). */
        void setMode(const std::string &mode);
        std::string getMode() const { return online_ ? "online" : "global"; }
        /** \brief Nc, chemotactic steps per reproduction (1..100000). */
        void setChemotacticSteps(unsigned int n);
        unsigned int getChemotacticSteps() const { return colonySettings_.chemotacticSteps; }
        /** \brief Ns, maximal swim length (0..100000). */
        void setSwimLength(unsigned int n);
        unsigned int getSwimLength() const { return colonySettings_.swimLength; }
        /** \brief Nre, reproduction steps per elimination-dispersal event (1..100000). */
        void setReproductionSteps(unsigned int n);
        unsigned int getReproductionSteps() const { return colonySettings_.reproductionSteps; }
        /** \brief Ned, elimination-dispersal events per run (1..100000). */
        void setEliminationEvents(unsigned int n);
        unsigned int getEliminationEvents() const { return colonySettings_.eliminationEvents; }
        /** \brief Ped, probability of dispersal per bacterium and event (0..1). */
        void setEliminationProbability(double p);
        double getEliminationProbability() const { return colonySettings_.eliminationProbability; }
        /** \brief C, the chemotactic step size (1e-6..1000). */
        void setStepSize(double c);
        double getStepSize() const { return colonySettings_.stepSize; }
        /** \brief ATBFO's adaptive tumble on or off. */
        void setAdaptiveTumble(bool on) { colonySettings_.adaptiveTumble = on; }
        bool getAdaptiveTumble() const { return colonySettings_.adaptiveTumble; }
        /** \brief F_improv: a direction is kept when a step makes more improvements (0..100000). */
        void setImprovementThreshold(unsigned int f);
        unsigned int getImprovementThreshold() const { return colonySettings_.improvementThreshold; }
        /** \brief Passino's cell-to-cell attraction/repulsion term on or off. */
        void setCellToCell(bool on) { colonySettings_.cellToCell = on; }
        bool getCellToCell() const { return colonySettings_.cellToCell; }
        /** \brief d_att (0..1e6). */
        void setAttractDepth(double v);
        double getAttractDepth() const { return colonySettings_.attractDepth; }
        /** \brief w_att (0..1e6). */
        void setAttractWidth(double v);
        double getAttractWidth() const { return colonySettings_.attractWidth; }
        /** \brief h_rep (0..1e6). */
        void setRepelHeight(double v);
        double getRepelHeight() const { return colonySettings_.repelHeight; }
        /** \brief w_rep (0..1e6). */
        void setRepelWidth(double v);
        double getRepelWidth() const { return colonySettings_.repelWidth; }
        /** \brief lambda, the robot's step (1e-6..1e6). */
        void setRobotStep(double v);
        double getRobotStep() const { return robotStep_; }
        /** \brief Goal tolerance of the walk, 0 = lambda (0..1e6). */
        void setGoalTolerance(double v);
        double getGoalTolerance() const { return goalTolerance_; }
        /** \brief Half angle in degrees of the sector the bacteria start in (0..180). */
        void setSectorAngle(double deg);
        double getSectorAngle() const { return sectorAngle_; }
        /** \brief Robot step budget of a walk (1..10000000). */
        void setMaxSteps(unsigned int n);
        unsigned int getMaxSteps() const { return maxSteps_; }

        /** \brief Online mode: the robot positions walked so far (start first). */
        const std::vector<Vec2> &walk() const { return walk_; }
        /** \brief Online mode: true when the walk has ended (goal, failure or budget). */
        bool walkFinished() const { return walkState_ != WalkState::Walking; }

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;

      private:
        enum class WalkState
        {
            Walking,
            ReachedGoal,
            Failed,
            BudgetSpent
        };

        void declareBfoParams();
        /** \brief The field defines the online cost: a change restarts the walk. */
        void fieldChanged() override;
        void updateSpecs();
        bool halt() const;

        /** \brief Size the colony for dimension \e d and draw every bacterium (not evaluated yet). */
        void startColony(unsigned int d);
        double rawCost(const double *x);
        void randomBacterium(double *x);
        void constrain(double *x) const;

        ompl::base::PlannerStatus solveOnline(const ompl::base::PlannerTerminationCondition &ptc);
        bool prepareOnline();
        void moveRobot();
        void finishWalkIfAtGoal();
        ompl::base::PlannerStatus reportOnline();

        // Parameters.
        bool online_{true};
        /** \brief Passino's loops and ATBFO's adaptive tumble, read by colony_. */
        ColonySettings colonySettings_;
        double robotStep_{0.2};
        double goalTolerance_{0.0};
        double sectorAngle_{45.0};
        unsigned int maxSteps_{2000};

        // The colony (both modes), searching through adapter_.
        class Adapter;
        std::unique_ptr<Adapter> adapter_;
        BacterialColony colony_{colonySettings_};

        // Online walk.
        const ompl::base::PlannerTerminationCondition *onlinePtc_{nullptr};
        std::unique_ptr<PotentialField> potential_;
        bool onlineReady_{false};
        /** \brief The seed parameter the walk was prepared with (a new seed restarts it, as in the base). */
        unsigned long seedUsed_{0};
        bool runActive_{false};
        Vec2 robot_, goal_;
        std::vector<Vec2> walk_;
        WalkState walkState_{WalkState::Walking};
        bool runBestKnown_{false};
        double runBestCost_{0.0};
        Vec2 runBest_;
        ompl::base::State *stateA_{nullptr};
        ompl::base::State *stateB_{nullptr};
        /** \brief The states handed to PlannerData by getPlannerData() (it keeps pointers), freed by clear().
         */
        mutable std::vector<ompl::base::State *> plannerDataStates_;

        std::atomic<double> onlineBestCost_;
        std::atomic<unsigned long> onlineSteps_{0};
        std::atomic<unsigned long> onlineEvaluations_{0};
    };
} // namespace mhplan

#endif
