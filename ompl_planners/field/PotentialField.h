// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the artificial potential field cost J = J_goal + J_obs of docs/algorithms.md 6.3 ([BFO] eqs 3-6,
   Khatib 1986), shared by the BFO online mode and the APF planner. */
#ifndef MHPLAN_POTENTIAL_FIELD_H
#define MHPLAN_POTENTIAL_FIELD_H

#include "src/collision/Collision.h"
#include "ompl_planners/common/PlannerSupport.h"

#include <ompl/base/GenericParam.h>
#include <ompl/base/Planner.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/SpaceInformation.h>

#include <atomic>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Gains and ranges of the potential field (defaults: [BFO] section 6). */
    struct PotentialFieldParameters
    {
        /** \brief xi: attraction gain of J_goal = 0.5 xi |P - P_T|^2. */
        double attractionGain{0.1};
        /** \brief eta: repulsion gain of J_obs = 0.5 eta (1/d - 1/d0). */
        double repulsionGain{0.06};
        /** \brief d0: distance of influence of an obstacle (the repulsive term is 0 beyond it). */
        double influenceDistance{1.5};
        /** \brief D_sense: only obstacles whose surface is within this distance of P repel. */
        double sensingRange{1.2};
    };

    /** \brief How the repulsive term is summed. */
    enum class RepulsionMode
    {
        /** \brief The spec's sum over every obstacle within range; needs the per-obstacle geometry (the
            analytic collision model). Falls back to Nearest with a warning when it is not reachable. */
        Sum,
        /** \brief Only the nearest obstacle, d(P) = the validity checker's clearance() (the common
            simplification; works with any checker that computes clearance). */
        Nearest
    };

    /** \brief Parse "sum" or "nearest"; throws std::invalid_argument naming the parameter 'repulsion'. */
    RepulsionMode parseRepulsionMode(const std::string &name);
    /** \brief "sum" or "nearest". */
    std::string toString(RepulsionMode mode);

    /** \brief The potential field's planner parameters, shared by every planner that descends on J (APF, the
        BFO online mode): a mixin holding PotentialFieldParameters and the RepulsionMode, with their validated
        setters (std::invalid_argument naming the parameter, its range and the value given) and
        declareFieldParams(), which declares them on a planner's ParamSet:

        | parameter          | range         | default |
        | attraction_gain    | 0 .. 1e6      | 0.1     |
        | repulsion_gain     | 0 .. 1e6      | 0.06    |
        | influence_distance | 1e-6 .. 1e6   | 1.5     |
        | sensing_range      | 1e-6 .. 1e6   | 1.2     |
        | repulsion          | sum, nearest  | sum     |

        Every successful set calls fieldChanged() (the planner restarts what the field defined there). */
    class PotentialFieldSettings
    {
      public:
        virtual ~PotentialFieldSettings() = default;

        /** \brief xi of J_goal (0..1e6). */
        void setAttractionGain(double v);
        /** \brief xi of J_goal. */
        double getAttractionGain() const { return field_.attractionGain; }
        /** \brief eta of J_obs (0..1e6). */
        void setRepulsionGain(double v);
        /** \brief eta of J_obs. */
        double getRepulsionGain() const { return field_.repulsionGain; }
        /** \brief d0 of J_obs (1e-6..1e6). */
        void setInfluenceDistance(double v);
        /** \brief d0 of J_obs. */
        double getInfluenceDistance() const { return field_.influenceDistance; }
        /** \brief D_sense (1e-6..1e6). */
        void setSensingRange(double v);
        /** \brief D_sense. */
        double getSensingRange() const { return field_.sensingRange; }
        /** \brief "sum" (over every obstacle in range, when reachable) or "nearest" (see PotentialField). */
        void setRepulsion(const std::string &mode);
        /** \brief "sum" or "nearest". */
        std::string getRepulsion() const { return toString(repulsion_); }

      protected:
        PotentialFieldSettings() = default;
        PotentialFieldSettings(const PotentialFieldSettings &) = default;
        PotentialFieldSettings &operator=(const PotentialFieldSettings &) = default;

        /** \brief Declare the five parameters of the table above on \e params (with their range suggestions).
         */
        void declareFieldParams(ompl::base::ParamSet &params);
        /** \brief Called after every successful set of a field parameter. */
        virtual void fieldChanged() = 0;

        /** \brief The gains and ranges. */
        PotentialFieldParameters field_;
        /** \brief The repulsion asked for. */
        RepulsionMode repulsion_{RepulsionMode::Sum};
    };

    /** \brief The APF cost of docs/algorithms.md 6.3 at a position P of a 2D RealVectorStateSpace problem:

        J(P) = 0.5 xi |P - P_T|^2 + sum over obstacles o with d_o(P) <= D_sense of 0.5 eta max(0, 1/d_o(P) -
        1/d0), and J(P) = +infinity when P is not a valid state (inside an obstacle, or the robot outside the
        bounds).

        Choices where the spec is open (docs/algorithms.md 6.3, 7):
        - d(P) is the distance from P to the obstacle's \b surface minus the robot radius, i.e. the
          signed clearance that mhplan's validity checker reports (exact for every mhplan collision model).
        - The spec's repulsive term is linear in (1/d - 1/d0) (not Khatib's square); it is clamped at 0 so
          that an obstacle between d0 and D_sense (possible only when D_sense > d0) never attracts.
        - RepulsionMode::Sum (default) sums exactly over every obstacle in range when the validity checker is
          a WorldValidityChecker over an AnalyticCollisionModel (the per-obstacle circles and polygons are
          public there). Any other checker (FCL, grid, foreign) only reports the nearest obstacle's
          clearance: then the nearest obstacle's term is used (Nearest), the common simplification of APF
          implementations; usedMode() tells which one is in effect. With the seed worlds' sparse circles the
          two differ only where two obstacles are both within D_sense of P.
        - A state at clearance exactly 0 (touching, valid for the checker) costs +infinity too (1/0).

        configure() refuses (std::invalid_argument) a checker whose specs say clearance is not computed
        (StateValidityCheckerSpecs::clearanceComputationType == NONE) and a state space that is not a 2D
        RealVectorStateSpace. cost() does not allocate; one preallocated state, so not thread-safe. */
    class PotentialField
    {
      public:
        explicit PotentialField(ompl::base::SpaceInformationPtr si);
        ~PotentialField();
        PotentialField(const PotentialField &) = delete;
        PotentialField &operator=(const PotentialField &) = delete;

        /** \brief Logs (OMPL_ERROR) and throws ompl::Exception, naming \e who, unless the space is a 2D
           RealVectorStateSpace and the validity checker computes clearance. */
        static void requireClearance(const ompl::base::SpaceInformation &si, const std::string &who);

        /** \brief Set gains and mode and inspect the validity checker (call after the problem's setup). */
        void configure(const PotentialFieldParameters &params, RepulsionMode mode, const std::string &who);
        /** \brief The target P_T of J_goal. */
        void setGoal(const Vec2 &goal) { goal_ = goal; }
        const Vec2 &goal() const { return goal_; }

        /** \brief J(P) (+infinity for an invalid position). Counts one evaluation. */
        double cost(const Vec2 &p) const;
        /** \brief True when the straight segment [a, b] is free (the collision model's exact segmentValid for
            mhplan's checkers, si->checkMotion otherwise). Not counted as an evaluation. */
        bool segmentFree(const Vec2 &a, const Vec2 &b) const;
        /** \brief J_goal(P). */
        double attraction(const Vec2 &p) const;
        /** \brief The repulsive contribution of one obstacle at surface distance \e d. */
        double repulsionTerm(double d) const;

        /** \brief Evaluations of cost() since the last configure() or resetEvaluations(). */
        unsigned long evaluations() const { return evaluations_; }
        void resetEvaluations() { evaluations_ = 0; }

        const PotentialFieldParameters &parameters() const { return params_; }
        /** \brief The repulsion actually in use (Nearest when Sum was asked but is not reachable). */
        RepulsionMode usedMode() const { return usedMode_; }

      private:
        double sumCost(const Vec2 &p) const;
        double nearestCost(const Vec2 &p) const;

        ompl::base::SpaceInformationPtr si_;
        ompl::base::State *state_{nullptr};
        ompl::base::State *other_{nullptr};
        /** \brief The collision model behind a WorldValidityChecker (exact segment checks), if any. */
        CollisionModelPtr segmentModel_;
        PotentialFieldParameters params_;
        RepulsionMode usedMode_{RepulsionMode::Nearest};
        Vec2 goal_;
        /** \brief Set in Sum mode: the analytic model whose obstacles are summed over. */
        const AnalyticCollisionModel *analytic_{nullptr};
        CollisionModelPtr model_;
        mutable unsigned long evaluations_{0};
    };

    /** \name The robot walk of the planners that descend on the field (APF, the BFO online mode)
        A walk is the list of robot positions, start first; its last entry is the robot. */
    /** @{ */

    /** \brief The start (first start state) and the goal (one goal sample) of \e pis as positions; false,
        with OMPL_ERROR naming \e who, when there is no valid start or no goal sample. */
    bool walkEndpoints(ompl::base::PlannerInputStates &pis, const std::string &who, Vec2 &start, Vec2 &goal);

    /** \brief When the robot (walk.back()) is within \e tolerance of \e goal and the segment to the exact
       goal passes si.checkMotion (checked with the scratch states \e a and \e b), append the goal (unless the
        robot is on it already) and return true; otherwise change nothing and return false. */
    bool walkReachGoal(const ompl::base::SpaceInformation &si, ompl::base::State *a, ompl::base::State *b,
                       std::vector<Vec2> &walk, const Vec2 &goal, double tolerance);

    /** \brief Add the walk to \e pdef as a solution named \e who: exact (with the objective's cost, also
        stored in \e bestCost) when \e reachedGoal and every segment passes checkMotion, else approximate
        (difference = distance from walk.back() to \e goal). TIMEOUT, adding nothing, when the walk has no
        step yet and is not \e finished. When \e planner is given and the exact walk is cheaper than
        \e bestCost was (the walk reached the goal: its one improvement), the intermediate-solution callback
        of \e pdef is called with it (reportImprovement()). */
    ompl::base::PlannerStatus reportWalk(const ompl::base::SpaceInformationPtr &si,
                                         const ompl::base::ProblemDefinitionPtr &pdef, const std::string &who,
                                         const std::vector<Vec2> &walk, bool finished, bool reachedGoal,
                                         const Vec2 &goal, std::atomic<double> &bestCost,
                                         const ompl::base::Planner *planner = nullptr);

    /** @} */
} // namespace mhplan

#endif
