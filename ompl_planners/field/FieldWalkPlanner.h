// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: what the two walks on the potential field (the APF descent and the online BFO / ATBFO) share. */
#ifndef MHPLAN_FIELD_WALK_PLANNER_H
#define MHPLAN_FIELD_WALK_PLANNER_H

#include "ompl_planners/common/PlannerBase.h"
#include "ompl_planners/field/PotentialField.h"

#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Base of the planners that walk a point robot from the start on the potential field J of
        PotentialField (ArtificialPotentialField, BacterialWalk): the field's parameters, the step length
        lambda (parameter named by the planner), \c goal_tolerance (0 = lambda), \c max_steps (the step budget
        of a walk), \c max_iterations (steps per solve() call), the refusal of a problem without clearance
        (setup()), the walk's end at the goal, its report (reportWalk()) and its planner data (the walk as a
        chain of vertices, the last a goal vertex once the goal is reached). Progress properties: \c best
        \c cost, \c iterations (robot steps), \c fitness \c evaluations (J evaluations). */
    class FieldWalkPlanner : public PlannerBase, public PotentialFieldSettings
    {
      public:
        /** \brief Refuses (before marking the planner set up) any space but a 2D RealVectorStateSpace and a
            validity checker that computes no clearance (PotentialField::requireClearance()). */
        void setup() override;
        void clear() override;
        /** \brief The walk as a chain of vertices (start first); the goal vertex once it is reached. */
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief lambda, the robot's step (1e-6..1e6). */
        void setWalkStep(double v);
        double getWalkStep() const { return walkStep_; }
        /** \brief Goal tolerance of the walk, 0 = lambda (parameter goal_tolerance, 0..1e6). */
        double getGoalTolerance() const { return goalTolerance_; }
        /** \brief Step budget of a walk (parameter max_steps, 1..10000000). */
        unsigned int getMaxSteps() const { return maxSteps_; }

        /** \brief The positions visited (start first). */
        const std::vector<Vec2> &walk() const { return walk_; }

      protected:
        /** \brief What the planner calls its parameters (descriptions for `mhplan planners`). */
        struct WalkParameterNames
        {
            const char *step;
            const char *stepDescription;
            const char *goalToleranceDescription;
            const char *maxStepsDescription;
            const char *maxIterationsDescription;
        };
        FieldWalkPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name, bool seeded,
                         const WalkParameterNames &names, unsigned int maxSteps);

        /** \brief True once the walk has reached the goal (its last point is the goal). */
        virtual bool reachedGoal() const = 0;
        /** \brief The field defines the walk: a change restarts it. */
        void fieldChanged() override;

        /** \brief Start and goal from the problem, the field configured, the walk reset to the start; false
            (OMPL_ERROR) without a valid start or a goal sample. */
        bool prepareWalk();
        /** \brief When the robot is within the goal tolerance of the goal and the segment to it is valid:
            append the goal, move the robot there and return true (walkReachGoal()). */
        bool reachGoal();
        /** \brief Add the walk to the problem definition (reportWalk()). */
        ompl::base::PlannerStatus reportWalkSolution(bool finished);

        std::unique_ptr<PotentialField> potential_;
        bool ready_{false};
        Vec2 robot_, goal_;
        std::vector<Vec2> walk_;

      private:
        const char *stepName_;
        double walkStep_{0.2};
        double goalTolerance_{0.0};
        unsigned int maxSteps_;
    };
} // namespace mhplan

#endif
