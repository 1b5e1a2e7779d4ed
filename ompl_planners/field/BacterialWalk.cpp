// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/BacterialWalk.h"
#include "src/base/Parameters.h"
#include "ompl_planners/common/PlannerSupport.h"

#include "src/collision/Validity.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();

        constexpr ParamRange kSectorAngle{"sector_angle", 0, 1, 180,
                                          "half angle of the sector the bacteria start in (degrees)"};
    } // namespace

    /** \brief The colony's view of the walk: J, where bacteria land, the sensing disc and the stop test. */
    class BacterialWalk::Adapter : public ColonyProblem
    {
      public:
        explicit Adapter(BacterialWalk &walk) : walk_(walk) {}
        double cost(const double *x) override { return walk_.rawCost(x); }
        void randomPosition(double *x) override { walk_.randomBacterium(x); }
        void constrain(double *x) override { walk_.constrain(x); }
        bool halt() override { return walk_.halt(); }

      private:
        BacterialWalk &walk_;
    };

    BacterialWalk::BacterialWalk(const ob::SpaceInformationPtr &si, bool adaptiveTumble)
        : FieldWalkPlanner(si, adaptiveTumble ? "ATBFO" : "BFO", true,
                           {"robot_step", "lambda, the robot's step",
                            "goal tolerance of the walk; 0 = robot_step", "robot step budget of a walk",
                            "robot steps per solve() call; 0 = until the walk ends"},
                           2000),
          ColonyParameters(adaptiveTumble), adapter_(std::make_unique<Adapter>(*this))
    {
        declarePopulationSize(100, "S, bacteria of each colony run");
        declareColonyParams(params());
        declareRanged<double>(params(), this, kSectorAngle, &BacterialWalk::setSectorAngle,
                              &BacterialWalk::getSectorAngle);
    }

    BacterialWalk::~BacterialWalk() = default;

    // ---------------------------------------------------------------------------------------------------
    // Parameters

    void BacterialWalk::setPopulationSize(unsigned int n)
    {
        checkParameter(SharedParameterRanges::populationSize, n);
        if (n != getPopulationSize() && ready_)
            clear(); // the colony's size is fixed for a walk
        PlannerBase::setPopulationSize(n);
    }

    void BacterialWalk::setSectorAngle(double deg)
    {
        storeChecked(kSectorAngle, sectorAngle_, deg);
    }

    // ---------------------------------------------------------------------------------------------------
    // Planner interface

    void BacterialWalk::clear()
    {
        FieldWalkPlanner::clear();
        colony_.reset();
        runActive_ = false;
        walkState_ = WalkState::Walking;
        runBestKnown_ = false;
    }

    // ---------------------------------------------------------------------------------------------------
    // The colony's problem: J in the sensing disc

    void BacterialWalk::randomBacterium(double *x)
    {
        const Vec2 toGoal = goal_ - robot_;
        const double heading = squaredNorm(toGoal) > 0.0 ? std::atan2(toGoal.y, toGoal.x) : 0.0;
        const double half = sectorAngle_ * kPi / 180.0;
        const double angle = heading + rng_.uniformReal(-half, half);
        // Uniform by area in the sector.
        const double r = field_.sensingRange * std::sqrt(rng_.uniform01());
        x[0] = robot_.x + r * std::cos(angle);
        x[1] = robot_.y + r * std::sin(angle);
        constrain(x);
    }

    void BacterialWalk::constrain(double *x) const
    {
        const double dx = x[0] - robot_.x, dy = x[1] - robot_.y;
        const double d = std::hypot(dx, dy);
        if (d > field_.sensingRange)
        {
            const double s = field_.sensingRange / d;
            x[0] = robot_.x + dx * s;
            x[1] = robot_.y + dy * s;
        }
        const auto &b = si_->getStateSpace()->as<ob::RealVectorStateSpace>()->getBounds();
        x[0] = std::min(std::max(x[0], b.low[0]), b.high[0]);
        x[1] = std::min(std::max(x[1], b.low[1]), b.high[1]);
    }

    double BacterialWalk::rawCost(const double *x)
    {
        const Vec2 p(x[0], x[1]);
        double j = potential_->cost(p);
        evaluationCount_ = potential_->evaluations();
        // What the robot cannot see (behind an obstacle) it does not sense: +infinity.
        if (j < kInf && !potential_->segmentFree(robot_, p))
            j = kInf;
        if (j < kInf && (!runBestKnown_ || j < runBestCost_))
        {
            runBestKnown_ = true;
            runBestCost_ = j;
            runBest_ = p;
        }
        return j;
    }

    // ---------------------------------------------------------------------------------------------------
    // The walk (6.3)

    bool BacterialWalk::prepare()
    {
        if (!prepareWalk())
            return false;
        seedUsed_ = getSeed();
        seedRng();
        walk_.reserve(std::min<std::size_t>(getMaxSteps(), 4096) + 2);
        walkState_ = WalkState::Walking;
        runActive_ = false;
        ready_ = true;
        OMPL_INFORM(
            "%s: online, seed %lu, S = %u, Nc = %u, Ns = %u, Nre = %u, Ned = %u, C = %g, lambda = %g, "
            "%s repulsion%s",
            getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), getPopulationSize(),
            colonySettings_.chemotacticSteps, colonySettings_.swimLength, colonySettings_.reproductionSteps,
            colonySettings_.eliminationEvents, colonySettings_.stepSize, getRobotStep(),
            toString(potential_->usedMode()).c_str(),
            colonySettings_.adaptiveTumble ? ", adaptive tumble" : "");
        finishWalkIfAtGoal();
        return true;
    }

    void BacterialWalk::finishWalkIfAtGoal()
    {
        if (reachGoal())
            walkState_ = WalkState::ReachedGoal; // else keep walking
    }

    void BacterialWalk::moveRobot()
    {
        Vec2 heading = (runBestKnown_ ? runBest_ : goal_) - robot_;
        if (squaredNorm(heading) < 1e-24)
            heading = goal_ - robot_;
        const double phi = std::atan2(heading.y, heading.x);
        double step = getRobotStep();
        ob::State *stateA = scratchState(0), *stateB = scratchState(1);
        setStatePosition(stateA, robot_);
        bool moved = false;
        for (int attempt = 0; attempt <= 3 && !moved; ++attempt, step *= 0.5)
        {
            const Vec2 next(robot_.x + step * std::cos(phi), robot_.y + step * std::sin(phi));
            setStatePosition(stateB, next);
            if (si_->satisfiesBounds(stateB) && si_->checkMotion(stateA, stateB))
            {
                robot_ = next;
                walk_.push_back(next);
                moved = true;
            }
        }
        ++iterationCount_;
        if (!moved)
        {
            walkState_ = WalkState::Failed;
            OMPL_INFORM(
                "%s: the step toward (%g, %g) stays invalid after 3 halvings: the walk stops at (%g, %g)",
                getName().c_str(), runBest_.x, runBest_.y, robot_.x, robot_.y);
            return;
        }
        finishWalkIfAtGoal();
        if (walkState_ == WalkState::Walking && walk_.size() - 1 >= getMaxSteps())
        {
            walkState_ = WalkState::BudgetSpent;
            OMPL_INFORM("%s: step budget of %u spent", getName().c_str(), getMaxSteps());
        }
    }

    ob::PlannerStatus BacterialWalk::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (ready_ && getSeed() != seedUsed_)
            clear(); // a new seed restarts the walk
        if (!ready_ && !prepare())
            return ob::PlannerStatus::INVALID_START;

        ptc_ = &ptc;
        unsigned int done = 0;
        while (walkState_ == WalkState::Walking && !ptc() &&
               (getMaxIterations() == 0 || done < getMaxIterations()))
        {
            if (!runActive_)
            {
                runBestKnown_ = false;
                colony_.start(2, getPopulationSize(), *adapter_);
                runActive_ = true;
            }
            BacterialColony::Step r = BacterialColony::Step::StepDone;
            while (r == BacterialColony::Step::StepDone)
                r = colony_.step(*adapter_, rng_);
            if (r == BacterialColony::Step::Interrupted)
                break; // the run resumes at the same bacterium next time
            runActive_ = false;
            moveRobot();
            ++done;
        }
        ptc_ = nullptr;
        return report();
    }

    ob::PlannerStatus BacterialWalk::report()
    {
        const ob::PlannerStatus status = reportWalkSolution(walkState_ != WalkState::Walking);
        if (status == ob::PlannerStatus::TIMEOUT)
            return status;
        const bool exact = status == ob::PlannerStatus::EXACT_SOLUTION;
        OMPL_INFORM("%s: %zu robot positions, %lu J evaluations, %s", getName().c_str(), walk_.size(),
                    evaluationCount(),
                    exact ? "goal reached"
                          : (walkState_ == WalkState::Walking ? "walking" : "walk ended before the goal"));
        return status;
    }
} // namespace mhplan
