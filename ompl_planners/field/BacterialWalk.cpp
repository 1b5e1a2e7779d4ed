// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/field/BacterialWalk.h"
#include "mhplan/base/Parameters.h"
#include "mhplan/planners/common/PlannerSupport.h"

#include "mhplan/collision/Validity.h"

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

        constexpr ParamRange kPopulationSize{"population_size", 2, 1, 10000,
                                             "S, bacteria of each colony run"};
        constexpr ParamRange kMaxIterations{"max_iterations", 0, 1, 10000000,
                                            "robot steps per solve() call; 0 = until the walk ends"};
        constexpr ParamRange kSeed{"seed", 0, 1, 4294967295,
                                   "seed of this planner's RNG; 0 = drawn from OMPL's global seed"};
        constexpr ParamRange kRobotStep{"robot_step", 0.000001, 0.01, 1000000, "lambda, the robot's step"};
        constexpr ParamRange kGoalTolerance{"goal_tolerance", 0, 0.01, 1000000,
                                            "goal tolerance of the walk; 0 = robot_step"};
        constexpr ParamRange kSectorAngle{"sector_angle", 0, 1, 180,
                                          "half angle of the sector the bacteria start in (degrees)"};
        constexpr ParamRange kMaxSteps{"max_steps", 1, 1, 10000000, "robot step budget of a walk"};
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
        : ob::Planner(si, adaptiveTumble ? "ATBFO" : "BFO"), ColonyParameters(adaptiveTumble),
          adapter_(std::make_unique<Adapter>(*this)), bestCost_(kInf)
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = false;
        specs_.canReportIntermediateSolutions = true; // once, when the walk reaches the goal
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
        declareParams();
        addPlannerProgressProperty("best cost REAL", [this] { return formatCost(bestCost_.load()); });
        addPlannerProgressProperty("iterations INTEGER", [this] { return std::to_string(steps_.load()); });
        addPlannerProgressProperty("fitness evaluations INTEGER",
                                   [this] { return std::to_string(evaluations_.load()); });
    }

    BacterialWalk::~BacterialWalk()
    {
        if (stateA_ != nullptr)
            si_->freeState(stateA_);
        if (stateB_ != nullptr)
            si_->freeState(stateB_);
        freeStates(*si_, plannerDataStates_);
    }

    void BacterialWalk::declareParams()
    {
        using W = BacterialWalk;
        declareRanged<unsigned int>(params(), this, kPopulationSize, &W::setPopulationSize,
                                    &W::getPopulationSize);
        declareColonyParams(params());
        declareFieldParams(params_);
        declareRanged<double>(params(), this, kRobotStep, &W::setRobotStep, &W::getRobotStep);
        declareRanged<double>(params(), this, kGoalTolerance, &W::setGoalTolerance, &W::getGoalTolerance);
        declareRanged<double>(params(), this, kSectorAngle, &W::setSectorAngle, &W::getSectorAngle);
        declareRanged<unsigned int>(params(), this, kMaxSteps, &W::setMaxSteps, &W::getMaxSteps);
        declareRanged<unsigned int>(params(), this, kMaxIterations, &W::setMaxIterations,
                                    &W::getMaxIterations);
        declareRanged<unsigned long>(params(), this, kSeed, &W::setSeed, &W::getSeed);
    }

    // ---------------------------------------------------------------------------------------------------
    // Parameters

    void BacterialWalk::setPopulationSize(unsigned int n)
    {
        checkParameter(kPopulationSize, n);
        if (n != populationSize_ && ready_)
            clear(); // the colony's size is fixed for a walk
        populationSize_ = n;
    }

    void BacterialWalk::setMaxIterations(unsigned int n)
    {
        checkParameter(kMaxIterations, n);
        maxIterations_ = n;
    }

    void BacterialWalk::setSeed(unsigned long seed)
    {
        checkParameter(kSeed, static_cast<double>(seed));
        seed_ = seed;
    }

    void BacterialWalk::fieldChanged()
    {
        if (ready_)
            clear();
    }

    void BacterialWalk::setRobotStep(double v)
    {
        checkParameter(kRobotStep, v);
        robotStep_ = v;
    }

    void BacterialWalk::setGoalTolerance(double v)
    {
        checkParameter(kGoalTolerance, v);
        goalTolerance_ = v;
    }

    void BacterialWalk::setSectorAngle(double deg)
    {
        checkParameter(kSectorAngle, deg);
        sectorAngle_ = deg;
    }

    void BacterialWalk::setMaxSteps(unsigned int n)
    {
        checkParameter(kMaxSteps, n);
        maxSteps_ = n;
    }

    // ---------------------------------------------------------------------------------------------------
    // Planner interface

    void BacterialWalk::setup()
    {
        // Refused before ob::Planner::setup() marks the planner set up (the planner contract).
        PotentialField::requireClearance(*si_, getName()); // also refuses any space but a 2D RealVector one
        ob::Planner::setup();
    }

    void BacterialWalk::clear()
    {
        ob::Planner::clear();
        colony_.reset();
        freeStates(*si_, plannerDataStates_);
        ready_ = false;
        runActive_ = false;
        walk_.clear();
        walkState_ = WalkState::Walking;
        runBestKnown_ = false;
        bestCost_ = kInf;
        steps_ = 0;
        evaluations_ = 0;
    }

    void BacterialWalk::getPlannerData(ob::PlannerData &data) const
    {
        ob::Planner::getPlannerData(data);
        addPathToPlannerData(
            *si_, walk_.size(), [this](ob::State *s, std::size_t i) { setStatePosition(s, walk_[i]); },
            walkState_ == WalkState::ReachedGoal, data, plannerDataStates_);
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
        evaluations_ = potential_->evaluations();
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
        if (!walkEndpoints(pis_, getName(), robot_, goal_))
            return false;
        seedUsed_ = seed_;
        if (seed_ != 0)
            rng_.setLocalSeed(static_cast<std::uint_fast32_t>(seed_));
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
        walk_.reserve(std::min<std::size_t>(maxSteps_, 4096) + 2);
        walk_.push_back(robot_);
        walkState_ = WalkState::Walking;
        runActive_ = false;
        ready_ = true;
        OMPL_INFORM(
            "%s: online, seed %lu, S = %u, Nc = %u, Ns = %u, Nre = %u, Ned = %u, C = %g, lambda = %g, "
            "%s repulsion%s",
            getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), populationSize_,
            colonySettings_.chemotacticSteps, colonySettings_.swimLength, colonySettings_.reproductionSteps,
            colonySettings_.eliminationEvents, colonySettings_.stepSize, robotStep_,
            toString(potential_->usedMode()).c_str(),
            colonySettings_.adaptiveTumble ? ", adaptive tumble" : "");
        finishWalkIfAtGoal();
        return true;
    }

    void BacterialWalk::finishWalkIfAtGoal()
    {
        const double tolerance = goalTolerance_ > 0.0 ? goalTolerance_ : robotStep_;
        if (!walkReachGoal(*si_, stateA_, stateB_, walk_, goal_, tolerance))
            return; // keep walking
        robot_ = walk_.back();
        walkState_ = WalkState::ReachedGoal;
    }

    void BacterialWalk::moveRobot()
    {
        Vec2 heading = (runBestKnown_ ? runBest_ : goal_) - robot_;
        if (squaredNorm(heading) < 1e-24)
            heading = goal_ - robot_;
        const double phi = std::atan2(heading.y, heading.x);
        double step = robotStep_;
        setStatePosition(stateA_, robot_);
        bool moved = false;
        for (int attempt = 0; attempt <= 3 && !moved; ++attempt, step *= 0.5)
        {
            const Vec2 next(robot_.x + step * std::cos(phi), robot_.y + step * std::sin(phi));
            setStatePosition(stateB_, next);
            if (si_->satisfiesBounds(stateB_) && si_->checkMotion(stateA_, stateB_))
            {
                robot_ = next;
                walk_.push_back(next);
                moved = true;
            }
        }
        ++steps_;
        if (!moved)
        {
            walkState_ = WalkState::Failed;
            OMPL_INFORM(
                "%s: the step toward (%g, %g) stays invalid after 3 halvings: the walk stops at (%g, %g)",
                getName().c_str(), runBest_.x, runBest_.y, robot_.x, robot_.y);
            return;
        }
        finishWalkIfAtGoal();
        if (walkState_ == WalkState::Walking && walk_.size() - 1 >= maxSteps_)
        {
            walkState_ = WalkState::BudgetSpent;
            OMPL_INFORM("%s: step budget of %u spent", getName().c_str(), maxSteps_);
        }
    }

    ob::PlannerStatus BacterialWalk::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (ready_ && seed_ != seedUsed_)
            clear(); // a new seed restarts the walk
        if (!ready_ && !prepare())
            return ob::PlannerStatus::INVALID_START;

        ptc_ = &ptc;
        unsigned int done = 0;
        while (walkState_ == WalkState::Walking && !ptc() && (maxIterations_ == 0 || done < maxIterations_))
        {
            if (!runActive_)
            {
                runBestKnown_ = false;
                colony_.start(2, populationSize_, *adapter_);
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
        const ob::PlannerStatus status =
            reportWalk(si_, pdef_, getName(), walk_, walkState_ != WalkState::Walking,
                       walkState_ == WalkState::ReachedGoal, goal_, bestCost_, this);
        if (status == ob::PlannerStatus::TIMEOUT)
            return status;
        const bool exact = status == ob::PlannerStatus::EXACT_SOLUTION;
        OMPL_INFORM("%s: %zu robot positions, %lu J evaluations, %s", getName().c_str(), walk_.size(),
                    evaluations_.load(),
                    exact ? "goal reached"
                          : (walkState_ == WalkState::Walking ? "walking" : "walk ended before the goal"));
        return status;
    }
} // namespace mhplan
