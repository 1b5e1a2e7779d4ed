// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/ArtificialPotentialField.h"
#include "src/base/Parameters.h"

#include "src/collision/Validity.h"

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
        constexpr ParamRange kDirections{"directions", 3, 1, 3600,
                                         "sampled directions per step (descent = directions)"};
        constexpr ParamRange kGradientSpacing{
            "gradient_spacing", 0.000000001, 0.0001, 1,
            "finite-difference spacing of the gradient (descent = gradient)"};
        constexpr ParamRange kStallSteps{"stall_steps", 1, 1, 1000000,
                                         "steps without improvement that end the descent"};
        constexpr ParamRange kStallTolerance{"stall_tolerance", 0, 0.000001, 1000000,
                                             "improvement of the potential that counts"};
    } // namespace

    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
    } // namespace

    ArtificialPotentialField::ArtificialPotentialField(const ob::SpaceInformationPtr &si)
        : FieldWalkPlanner(si, "APF", false,
                           {"step_size", "lambda, the step length", "goal tolerance; 0 = step_size",
                            "step budget of a descent", "steps per solve() call; 0 = no limit"},
                           100000)
    {
        using A = ArtificialPotentialField;
        declareChoice(params(), this, "descent", &A::setDescent, &A::getDescent, "directions,gradient",
                      "step along the best of sampled directions, or along the numerical gradient");
        declareRanged<unsigned int>(params(), this, kDirections, &A::setDirections, &A::getDirections);
        declareRanged<double>(params(), this, kGradientSpacing, &A::setGradientSpacing,
                              &A::getGradientSpacing);
        declareRanged<unsigned int>(params(), this, kStallSteps, &A::setStallSteps, &A::getStallSteps);
        declareRanged<double>(params(), this, kStallTolerance, &A::setStallTolerance, &A::getStallTolerance);
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
        storeChecked(kDirections, directions_, n);
    }

    void ArtificialPotentialField::setGradientSpacing(double h)
    {
        storeChecked(kGradientSpacing, gradientSpacing_, h);
    }

    void ArtificialPotentialField::setStallSteps(unsigned int n)
    {
        storeChecked(kStallSteps, stallSteps_, n);
    }

    void ArtificialPotentialField::setStallTolerance(double v)
    {
        storeChecked(kStallTolerance, stallTolerance_, v);
    }

    void ArtificialPotentialField::clear()
    {
        FieldWalkPlanner::clear();
        state_ = State::Descending;
    }

    bool ArtificialPotentialField::prepare()
    {
        if (!prepareWalk())
            return false;
        currentCost_ = bestCost_ = potential_->cost(robot_);
        evaluationCount_ = potential_->evaluations();
        sinceImprovement_ = 0;
        state_ = State::Descending;
        ready_ = true;
        OMPL_INFORM("%s: %s descent, lambda = %g, %s repulsion", getName().c_str(), getDescent().c_str(),
                    getStepSize(), toString(potential_->usedMode()).c_str());
        finishIfAtGoal();
        return true;
    }

    void ArtificialPotentialField::finishIfAtGoal()
    {
        if (reachGoal())
            state_ = State::ReachedGoal;
    }

    bool ArtificialPotentialField::tryMove(const Vec2 &next)
    {
        ob::State *a = scratchState(0), *b = scratchState(1);
        setStatePosition(a, robot_);
        setStatePosition(b, next);
        if (!si_->satisfiesBounds(b) || !si_->checkMotion(a, b))
            return false;
        robot_ = next;
        walk_.push_back(next);
        return true;
    }

    bool ArtificialPotentialField::step(const ob::PlannerTerminationCondition &ptc)
    {
        const double stepSize = getWalkStep();
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
                const Vec2 p(robot_.x + stepSize * std::cos(a), robot_.y + stepSize * std::sin(a));
                const double j = potential_->cost(p);
                if (j < kInf)
                    candidates_.emplace_back(j, k);
            }
            // Lowest J first; ties keep the direction order (straight to the goal first).
            std::sort(candidates_.begin(), candidates_.end());
            for (const auto &c : candidates_)
            {
                const double a = heading + 2.0 * kPi * c.second / directions_;
                if (tryMove({robot_.x + stepSize * std::cos(a), robot_.y + stepSize * std::sin(a)}))
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
                double len = stepSize;
                for (int attempt = 0; attempt <= 3 && !moved; ++attempt, len *= 0.5)
                    moved = tryMove({robot_.x - len * gx / g, robot_.y - len * gy / g});
                if (moved)
                    nextCost = potential_->cost(robot_);
            }
        }
        evaluationCount_ = potential_->evaluations();
        ++iterationCount_;
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
        else if (walk_.size() - 1 >= getMaxSteps())
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
        while (state_ == State::Descending && !ptc() &&
               (getMaxIterations() == 0 || done < getMaxIterations()))
        {
            if (!step(ptc))
                break;
            ++done;
        }
        return report();
    }

    ob::PlannerStatus ArtificialPotentialField::report()
    {
        return reportWalkSolution(state_ != State::Descending);
    }
} // namespace mhplan
