// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/FieldWalkPlanner.h"

#include "src/base/Parameters.h"
#include "src/collision/Validity.h"

#include <ompl/base/goals/GoalSampleableRegion.h>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kGoalTolerance{"goal_tolerance", 0, 0.01, 1000000, ""};
        constexpr ParamRange kMaxSteps{"max_steps", 1, 1, 10000000, ""};
        constexpr double kStepLow = 0.000001, kStepHigh = 1000000;
    } // namespace

    FieldWalkPlanner::FieldWalkPlanner(const ob::SpaceInformationPtr &si, const std::string &name,
                                       bool seeded, const WalkParameterNames &names, unsigned int maxSteps)
        : PlannerBase(si, name, seeded), stepName_(names.step), maxSteps_(maxSteps)
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = false;
        specs_.canReportIntermediateSolutions = true; // once, when the walk reaches the goal
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;

        using F = FieldWalkPlanner;
        declareFieldParams(params_);
        declareRanged<double>(params(), this, {names.step, kStepLow, 0.01, kStepHigh, names.stepDescription},
                              &F::setWalkStep, &F::getWalkStep);
        ParamRange range = kGoalTolerance;
        range.description = names.goalToleranceDescription;
        declareRangedField(params(), range, goalTolerance_);
        range = kMaxSteps;
        range.description = names.maxStepsDescription;
        declareRangedField(params(), range, maxSteps_);
        declareMaxIterations(names.maxIterationsDescription);
        declareProgress(true);
    }

    void FieldWalkPlanner::setWalkStep(double v)
    {
        checkParameterRange(stepName_, v, kStepLow, kStepHigh);
        walkStep_ = v;
    }

    void FieldWalkPlanner::setup()
    {
        // Refused before ob::Planner::setup() marks the planner set up (the planner contract).
        PotentialField::requireClearance(*si_, getName()); // also refuses any space but a 2D RealVector one
        ob::Planner::setup();
    }

    void FieldWalkPlanner::clear()
    {
        PlannerBase::clear();
        ready_ = false;
        walk_.clear();
    }

    void FieldWalkPlanner::fieldChanged()
    {
        if (ready_)
            clear();
    }

    void FieldWalkPlanner::getPlannerData(ob::PlannerData &data) const
    {
        pathToPlannerData(
            data, walk_.size(), [this](ob::State *s, std::size_t i) { setStatePosition(s, walk_[i]); },
            reachedGoal());
    }

    bool FieldWalkPlanner::prepareWalk()
    {
        if (!walkEndpoints(pis_, getName(), robot_, goal_))
            return false;
        if (!potential_)
            potential_ = std::make_unique<PotentialField>(si_);
        potential_->configure(field_, repulsion_, getName());
        potential_->setGoal(goal_);
        walk_.clear();
        walk_.push_back(robot_);
        return true;
    }

    bool FieldWalkPlanner::reachGoal()
    {
        const double tolerance = goalTolerance_ > 0.0 ? goalTolerance_ : walkStep_;
        if (!walkReachGoal(*si_, scratchState(0), scratchState(1), walk_, goal_, tolerance))
            return false;
        robot_ = walk_.back();
        return true;
    }

    ob::PlannerStatus FieldWalkPlanner::reportWalkSolution(bool finished)
    {
        return reportWalk(si_, pdef_, getName(), walk_, finished, reachedGoal(), goal_, bestCostValue_, this);
    }
} // namespace mhplan
