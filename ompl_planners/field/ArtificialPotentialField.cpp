// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/field/ArtificialPotentialField.h"
#include "mhplan/base/Parameters.h"

#include "mhplan/planners/common/PopulationPlanner.h"
#include "mhplan/collision/Validity.h"

#include <ompl/base/goals/GoalSampleableRegion.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kStepSize{"step_size", 0.000001, 0.01, 1000000, "lambda, the step length"};
        constexpr ParamRange kDirections{"directions", 3, 1, 3600,
                                         "sampled directions per step (descent = directions)"};
        constexpr ParamRange kGradientSpacing{
            "gradient_spacing", 0.000000001, 0.0001, 1,
            "finite-difference spacing of the gradient (descent = gradient)"};
        constexpr ParamRange kGoalTolerance{"goal_tolerance", 0, 0.01, 1000000,
                                            "goal tolerance; 0 = step_size"};
        constexpr ParamRange kStallSteps{"stall_steps", 1, 1, 1000000,
                                         "steps without improvement that end the descent"};
        constexpr ParamRange kStallTolerance{"stall_tolerance", 0, 0.000001, 1000000,
                                             "improvement of the potential that counts"};
        constexpr ParamRange kMaxIterations{"max_iterations", 0, 1, 10000000,
                                            "steps per solve() call; 0 = no limit"};
        constexpr ParamRange kMaxSteps{"max_steps", 1, 1, 10000000, "step budget of a descent"};
    } // namespace

    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
    } // namespace

    ArtificialPotentialField::ArtificialPotentialField(const ob::SpaceInformationPtr &si)
        : ob::Planner(si, "APF"), bestCostValue_(kInf)
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = false;
        specs_.canReportIntermediateSolutions = true; // the walk, once it reaches the goal
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;

        using A = ArtificialPotentialField;
        declareFieldParams(params_);
        declareRanged<double>(params(), this, kStepSize, &A::setStepSize, &A::getStepSize);
        declareChoice(params(), this, "descent", &A::setDescent, &A::getDescent, "directions,gradient",
                      "step along the best of sampled directions, or along the numerical gradient");
        declareRanged<unsigned int>(params(), this, kDirections, &A::setDirections, &A::getDirections);
        declareRanged<double>(params(), this, kGradientSpacing, &A::setGradientSpacing,
                              &A::getGradientSpacing);
        declareRanged<double>(params(), this, kGoalTolerance, &A::setGoalTolerance, &A::getGoalTolerance);
        declareRanged<unsigned int>(params(), this, kStallSteps, &A::setStallSteps, &A::getStallSteps);
        declareRanged<double>(params(), this, kStallTolerance, &A::setStallTolerance, &A::getStallTolerance);
        declareRanged<unsigned int>(params(), this, kMaxIterations, &A::setMaxIterations,
                                    &A::getMaxIterations);
        declareRanged<unsigned int>(params(), this, kMaxSteps, &A::setMaxSteps, &A::getMaxSteps);

        addPlannerProgressProperty("best cost REAL", [this] { return formatCost(bestCostValue_.load()); });
        addPlannerProgressProperty("iterations INTEGER", [this] { return std::to_string(steps_.load()); });
        addPlannerProgressProperty("fitness evaluations INTEGER",
                                   [this] { return std::to_string(evaluations_.load()); });
    }

    ArtificialPotentialField::~ArtificialPotentialField()
    {
        if (stateA_ != nullptr)
            si_->freeState(stateA_);
        if (stateB_ != nullptr)
            si_->freeState(stateB_);
        freeStates(*si_, plannerDataStates_);
    }

    void ArtificialPotentialField::fieldChanged()
    {
        if (ready_)
            clear();
    }

    void ArtificialPotentialField::setStepSize(double v)
    {
        checkParameter(kStepSize, v);
        stepSize_ = v;
    }

    void ArtificialPotentialField::setDescent(const std::string &descent)
    {
        if (descent != "directions" && descent != "gradient")
            throw std::invalid_argument("parameter 'descent' must be one of {directions, gradient}; got '" +
                                        descent + "'");
        gradient_ = descent == "gradient";
    }

    void ArtificialPotentialField::setDirections(unsigned int n)
    {
        checkParameter(kDirections, n);
        directions_ = n;
    }

    void ArtificialPotentialField::setGradientSpacing(double h)
    {
        checkParameter(kGradientSpacing, h);
        gradientSpacing_ = h;
    }

    void ArtificialPotentialField::setGoalTolerance(double v)
    {
        checkParameter(kGoalTolerance, v);
        goalTolerance_ = v;
    }

    void ArtificialPotentialField::setStallSteps(unsigned int n)
    {
        checkParameter(kStallSteps, n);
        stallSteps_ = n;
    }

    void ArtificialPotentialField::setStallTolerance(double v)
    {
        checkParameter(kStallTolerance, v);
        stallTolerance_ = v;
    }

    void ArtificialPotentialField::setMaxIterations(unsigned int n)
    {
        checkParameter(kMaxIterations, n);
        maxIterations_ = n;
    }

    void ArtificialPotentialField::setMaxSteps(unsigned int n)
    {
        checkParameter(kMaxSteps, n);
        maxSteps_ = n;
    }

    void ArtificialPotentialField::setup()
    {
        // Refused before ob::Planner::setup() marks the planner set up (the planner contract).
        PotentialField::requireClearance(*si_, getName()); // also refuses any space but a 2D RealVector one
        ob::Planner::setup();
    }

    void ArtificialPotentialField::clear()
    {
        ob::Planner::clear();
        freeStates(*si_, plannerDataStates_);
        ready_ = false;
        state_ = State::Descending;
        walk_.clear();
        bestCostValue_ = kInf;
        steps_ = 0;
        evaluations_ = 0;
    }

    bool ArtificialPotentialField::prepare()
    {
        if (!walkEndpoints(pis_, getName(), robot_, goal_))
            return false;
        if (!potential_)
            potential_ = std::make_unique<PotentialField>(si_);
        potential_->configure(field_, repulsion_, getName());
        potential_->setGoal(goal_);
        if (stateA_ == nullptr)
        {
            stateA_ = si_->allocState();
            stateB_ = si_->allocState();
        }
        walk_.clear();
        walk_.push_back(robot_);
        currentCost_ = bestCost_ = potential_->cost(robot_);
        evaluations_ = potential_->evaluations();
        sinceImprovement_ = 0;
        state_ = State::Descending;
        ready_ = true;
        OMPL_INFORM("%s: %s descent, lambda = %g, %s repulsion", getName().c_str(), getDescent().c_str(),
                    stepSize_, toString(potential_->usedMode()).c_str());
        finishIfAtGoal();
        return true;
    }

    void ArtificialPotentialField::finishIfAtGoal()
    {
        const double tolerance = goalTolerance_ > 0.0 ? goalTolerance_ : stepSize_;
        if (!walkReachGoal(*si_, stateA_, stateB_, walk_, goal_, tolerance))
            return;
        robot_ = walk_.back();
        state_ = State::ReachedGoal;
    }

    bool ArtificialPotentialField::tryMove(const Vec2 &next)
    {
        setStatePosition(stateA_, robot_);
        setStatePosition(stateB_, next);
        if (!si_->satisfiesBounds(stateB_) || !si_->checkMotion(stateA_, stateB_))
            return false;
        robot_ = next;
        walk_.push_back(next);
        return true;
    }

    bool ArtificialPotentialField::step(const ob::PlannerTerminationCondition &ptc)
    {
        double nextCost = kInf;
        bool moved = false;
        if (!gradient_)
        {
            const Vec2 toGoal = goal_ - robot_;
            const double heading = std::atan2(toGoal.y, toGoal.x);
            candidates_.clear();
            candidates_.reserve(directions_);
            for (unsigned int k = 0; k < directions_; ++k)
            {
                if (ptc())
                    return false;
                const double a = heading + 2.0 * kPi * k / directions_;
                const Vec2 p(robot_.x + stepSize_ * std::cos(a), robot_.y + stepSize_ * std::sin(a));
                const double j = potential_->cost(p);
                if (j < kInf)
                    candidates_.emplace_back(j, k);
            }
            // Lowest J first; ties keep the direction order (straight to the goal first).
            std::sort(candidates_.begin(), candidates_.end());
            for (const auto &c : candidates_)
            {
                const double a = heading + 2.0 * kPi * c.second / directions_;
                if (tryMove({robot_.x + stepSize_ * std::cos(a), robot_.y + stepSize_ * std::sin(a)}))
                {
                    nextCost = c.first;
                    moved = true;
                    break;
                }
            }
        }
        else
        {
            const double h = gradientSpacing_;
            if (ptc())
                return false;
            // Central differences; one-sided where one side is infinite (an obstacle or the bounds).
            auto derivative = [&](const Vec2 &e)
            {
                const double plus = potential_->cost(robot_ + e * h);
                const double minus = potential_->cost(robot_ - e * h);
                if (plus < kInf && minus < kInf)
                    return (plus - minus) / (2.0 * h);
                if (plus < kInf)
                    return (plus - currentCost_) / h;
                if (minus < kInf)
                    return (currentCost_ - minus) / h;
                return kInf;
            };
            const double gx = derivative({1.0, 0.0});
            const double gy = derivative({0.0, 1.0});
            const double g = std::hypot(gx, gy);
            if (std::isfinite(g) && g > 0.0)
            {
                double len = stepSize_;
                for (int attempt = 0; attempt <= 3 && !moved; ++attempt, len *= 0.5)
                    moved = tryMove({robot_.x - len * gx / g, robot_.y - len * gy / g});
                if (moved)
                    nextCost = potential_->cost(robot_);
            }
        }
        evaluations_ = potential_->evaluations();
        ++steps_;
        if (!moved)
        {
            state_ = State::Stuck;
            OMPL_INFORM("%s: no valid descent step from (%g, %g)", getName().c_str(), robot_.x, robot_.y);
            return true;
        }
        currentCost_ = nextCost;
        if (currentCost_ < bestCost_ - stallTolerance_)
        {
            bestCost_ = currentCost_;
            sinceImprovement_ = 0;
        }
        else
            ++sinceImprovement_;
        finishIfAtGoal();
        if (state_ != State::Descending)
            return true;
        if (sinceImprovement_ >= stallSteps_)
        {
            state_ = State::Stalled;
            OMPL_INFORM("%s: local minimum near (%g, %g): J has not improved by %g over %u steps",
                        getName().c_str(), robot_.x, robot_.y, stallTolerance_, stallSteps_);
        }
        else if (walk_.size() - 1 >= maxSteps_)
            state_ = State::BudgetSpent;
        return true;
    }

    ob::PlannerStatus ArtificialPotentialField::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        // The condition is tested before every evaluation of J, the first one (in prepare()) included.
        if (!ready_ && ptc())
            return ob::PlannerStatus::TIMEOUT;
        if (!ready_ && !prepare())
            return ob::PlannerStatus::INVALID_START;
        unsigned int done = 0;
        while (state_ == State::Descending && !ptc() && (maxIterations_ == 0 || done < maxIterations_))
        {
            if (!step(ptc))
                break;
            ++done;
        }
        return report();
    }

    ob::PlannerStatus ArtificialPotentialField::report()
    {
        return reportWalk(si_, pdef_, getName(), walk_, state_ != State::Descending,
                          state_ == State::ReachedGoal, goal_, bestCostValue_, this);
    }

    void ArtificialPotentialField::getPlannerData(ob::PlannerData &data) const
    {
        ob::Planner::getPlannerData(data);
        addPathToPlannerData(
            *si_, walk_.size(), [this](ob::State *s, std::size_t i) { setStatePosition(s, walk_[i]); },
            state_ == State::ReachedGoal, data, plannerDataStates_);
    }
} // namespace mhplan
