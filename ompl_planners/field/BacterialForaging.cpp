// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/field/BacterialForaging.h"
#include "mhplan/base/Parameters.h"

#include "mhplan/collision/Validity.h"

#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/String.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kChemotacticSteps{"chemotactic_steps", 1, 1, 100000,
                                               "Nc, chemotactic steps per reproduction"};
        constexpr ParamRange kSwimLength{"swim_length", 0, 1, 100000, "Ns, longest swim"};
        constexpr ParamRange kReproductionSteps{"reproduction_steps", 1, 1, 100000,
                                                "Nre, reproductions per elimination-dispersal event"};
        constexpr ParamRange kEliminationEvents{"elimination_events", 1, 1, 100000,
                                                "Ned, elimination-dispersal events per run"};
        constexpr ParamRange kEliminationProbability{"elimination_probability", 0, 0.01, 1,
                                                     "Ped, dispersal probability per bacterium and event"};
        constexpr ParamRange kStepSize{"step_size", 0.000001, 0.01, 1000, "C, the chemotactic step size"};
        constexpr ParamRange kImprovementThreshold{"improvement_threshold", 0, 1, 100000,
                                                   "F_improv: improvements that keep a direction (ATBFO)"};
        constexpr ParamRange kAttractDepth{"attract_depth", 0, 0.01, 1000000,
                                           "d_att of the cell-to-cell term"};
        constexpr ParamRange kAttractWidth{"attract_width", 0, 0.01, 1000000,
                                           "w_att of the cell-to-cell term"};
        constexpr ParamRange kRepelHeight{"repel_height", 0, 0.01, 1000000, "h_rep of the cell-to-cell term"};
        constexpr ParamRange kRepelWidth{"repel_width", 0, 0.01, 1000000, "w_rep of the cell-to-cell term"};
        constexpr ParamRange kRobotStep{"robot_step", 0.000001, 0.01, 1000000, "lambda, the robot's step"};
        constexpr ParamRange kGoalTolerance{"goal_tolerance", 0, 0.01, 1000000,
                                            "goal tolerance of the walk; 0 = robot_step"};
        constexpr ParamRange kSectorAngle{"sector_angle", 0, 1, 180,
                                          "half angle of the sector the bacteria start in (degrees)"};
        constexpr ParamRange kMaxSteps{"max_steps", 1, 1, 10000000, "robot step budget of a walk"};
    } // namespace

    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
    } // namespace

    BacterialForaging::BacterialForaging(const ob::SpaceInformationPtr &si, bool adaptiveTumble)
        : PopulationPlanner(si, adaptiveTumble ? "ATBFO" : "BFO",
                            PopulationDefaults{100, 30, 3, PathDecoding::Polyline}),
          adapter_(std::make_unique<Adapter>(*this)), onlineBestCost_(kInf)
    {
        colonySettings_.adaptiveTumble = adaptiveTumble;
        // BFO has no coefficient schedule: the base's schedule length T does not apply.
        params().remove("iterations");
        declareBfoParams();
        updateSpecs();

        // Replace the base's progress properties by mode-aware ones (same names).
        addPlannerProgressProperty("best cost REAL", [this]
                                   { return formatCost((online_ ? onlineBestCost_.load() : bestCost())); });
        addPlannerProgressProperty(
            "iterations INTEGER",
            [this] { return std::to_string(online_ ? onlineSteps_.load() : iterationCount()); });
        addPlannerProgressProperty(
            "fitness evaluations INTEGER",
            [this] { return std::to_string(online_ ? onlineEvaluations_.load() : evaluationCount()); });
    }

    BacterialForaging::~BacterialForaging()
    {
        if (stateA_ != nullptr)
            si_->freeState(stateA_);
        if (stateB_ != nullptr)
            si_->freeState(stateB_);
        freeStates(*si_, plannerDataStates_);
    }

    void BacterialForaging::declareBfoParams()
    {
        using BF = BacterialForaging;
        declareChoice(
            params(), this, "mode", &BF::setMode, &BF::getMode, "online,global",
            "online (a robot walk guided by the colony) or global (the colony optimises the whole path)");
        declareRanged<unsigned int>(params(), this, kChemotacticSteps, &BF::setChemotacticSteps,
                                    &BF::getChemotacticSteps);
        declareRanged<unsigned int>(params(), this, kSwimLength, &BF::setSwimLength, &BF::getSwimLength);
        declareRanged<unsigned int>(params(), this, kReproductionSteps, &BF::setReproductionSteps,
                                    &BF::getReproductionSteps);
        declareRanged<unsigned int>(params(), this, kEliminationEvents, &BF::setEliminationEvents,
                                    &BF::getEliminationEvents);
        declareRanged<double>(params(), this, kEliminationProbability, &BF::setEliminationProbability,
                              &BF::getEliminationProbability);
        declareRanged<double>(params(), this, kStepSize, &BF::setStepSize, &BF::getStepSize);
        declareSwitch(params(), this, "adaptive_tumble", &BF::setAdaptiveTumble, &BF::getAdaptiveTumble,
                      "ATBFO's adaptive tumble");
        declareRanged<unsigned int>(params(), this, kImprovementThreshold, &BF::setImprovementThreshold,
                                    &BF::getImprovementThreshold);
        declareSwitch(params(), this, "cell_to_cell", &BF::setCellToCell, &BF::getCellToCell,
                      "Passino's cell-to-cell attraction and repulsion");
        declareRanged<double>(params(), this, kAttractDepth, &BF::setAttractDepth, &BF::getAttractDepth);
        declareRanged<double>(params(), this, kAttractWidth, &BF::setAttractWidth, &BF::getAttractWidth);
        declareRanged<double>(params(), this, kRepelHeight, &BF::setRepelHeight, &BF::getRepelHeight);
        declareRanged<double>(params(), this, kRepelWidth, &BF::setRepelWidth, &BF::getRepelWidth);
        declareFieldParams(params_);
        declareRanged<double>(params(), this, kRobotStep, &BF::setRobotStep, &BF::getRobotStep);
        declareRanged<double>(params(), this, kGoalTolerance, &BF::setGoalTolerance, &BF::getGoalTolerance);
        declareRanged<double>(params(), this, kSectorAngle, &BF::setSectorAngle, &BF::getSectorAngle);
        declareRanged<unsigned int>(params(), this, kMaxSteps, &BF::setMaxSteps, &BF::getMaxSteps);
    }

    void BacterialForaging::updateSpecs()
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = !online_;
        specs_.canReportIntermediateSolutions = true; // online: the walk, once it reaches the goal
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
    }

    // ---------------------------------------------------------------------------------------------------
    // Parameters

    void BacterialForaging::setMode(const std::string &mode)
    {
        if (mode != "online" && mode != "global")
            throw std::invalid_argument("parameter 'mode' must be one of {online, global}; got '" + mode +
                                        "'");
        const bool online = mode == "online";
        if (online != online_)
        {
            clear();
            online_ = online;
            updateSpecs();
        }
    }

    void BacterialForaging::setChemotacticSteps(unsigned int n)
    {
        checkParameter(kChemotacticSteps, n);
        colonySettings_.chemotacticSteps = n;
    }

    void BacterialForaging::setSwimLength(unsigned int n)
    {
        checkParameter(kSwimLength, n);
        colonySettings_.swimLength = n;
    }

    void BacterialForaging::setReproductionSteps(unsigned int n)
    {
        checkParameter(kReproductionSteps, n);
        colonySettings_.reproductionSteps = n;
    }

    void BacterialForaging::setEliminationEvents(unsigned int n)
    {
        checkParameter(kEliminationEvents, n);
        colonySettings_.eliminationEvents = n;
    }

    void BacterialForaging::setEliminationProbability(double p)
    {
        checkParameter(kEliminationProbability, p);
        colonySettings_.eliminationProbability = p;
    }

    void BacterialForaging::setStepSize(double c)
    {
        checkParameter(kStepSize, c);
        colonySettings_.stepSize = c;
    }

    void BacterialForaging::setImprovementThreshold(unsigned int f)
    {
        checkParameter(kImprovementThreshold, f);
        colonySettings_.improvementThreshold = f;
    }

    void BacterialForaging::setAttractDepth(double v)
    {
        checkParameter(kAttractDepth, v);
        colonySettings_.attractDepth = v;
    }

    void BacterialForaging::setAttractWidth(double v)
    {
        checkParameter(kAttractWidth, v);
        colonySettings_.attractWidth = v;
    }

    void BacterialForaging::setRepelHeight(double v)
    {
        checkParameter(kRepelHeight, v);
        colonySettings_.repelHeight = v;
    }

    void BacterialForaging::setRepelWidth(double v)
    {
        checkParameter(kRepelWidth, v);
        colonySettings_.repelWidth = v;
    }

    void BacterialForaging::fieldChanged()
    {
        if (onlineReady_)
            clear();
    }

    void BacterialForaging::setRobotStep(double v)
    {
        checkParameter(kRobotStep, v);
        robotStep_ = v;
    }

    void BacterialForaging::setGoalTolerance(double v)
    {
        checkParameter(kGoalTolerance, v);
        goalTolerance_ = v;
    }

    void BacterialForaging::setSectorAngle(double deg)
    {
        checkParameter(kSectorAngle, deg);
        sectorAngle_ = deg;
    }

    void BacterialForaging::setMaxSteps(unsigned int n)
    {
        checkParameter(kMaxSteps, n);
        maxSteps_ = n;
    }

    // ---------------------------------------------------------------------------------------------------
    // Planner interface

    void BacterialForaging::setup()
    {
        PopulationPlanner::setup();
        if (online_)
            PotentialField::requireClearance(*si_, getName());
    }

    void BacterialForaging::clear()
    {
        PopulationPlanner::clear(); // calls clearPopulation()
        freeStates(*si_, plannerDataStates_);
        onlineReady_ = false;
        runActive_ = false;
        walk_.clear();
        walkState_ = WalkState::Walking;
        runBestKnown_ = false;
        onlineBestCost_ = kInf;
        onlineSteps_ = 0;
        onlineEvaluations_ = 0;
    }

    ob::PlannerStatus BacterialForaging::solve(const ob::PlannerTerminationCondition &ptc)
    {
        if (online_)
            return solveOnline(ptc);
        return PopulationPlanner::solve(ptc);
    }

    void BacterialForaging::getPlannerData(ob::PlannerData &data) const
    {
        if (!online_)
        {
            PopulationPlanner::getPlannerData(data);
            return;
        }
        ob::Planner::getPlannerData(data);
        addPathToPlannerData(
            *si_, walk_.size(), [this](ob::State *s, std::size_t i) { setStatePosition(s, walk_[i]); },
            walkState_ == WalkState::ReachedGoal, data, plannerDataStates_);
    }

    bool BacterialForaging::halt() const
    {
        if (online_)
            return onlinePtc_ == nullptr || (*onlinePtc_)();
        return stopRequested();
    }

    // ---------------------------------------------------------------------------------------------------
    // The colony (6.1, 6.2), shared by both modes

    /** \brief The colony's view of the planner: J, where bacteria land, the region and the stop test. */
    class BacterialForaging::Adapter : public ColonyProblem
    {
      public:
        explicit Adapter(BacterialForaging &planner) : planner_(planner) {}
        double cost(const double *x) override { return planner_.rawCost(x); }
        void randomPosition(double *x) override { planner_.randomBacterium(x); }
        void constrain(double *x) override { planner_.constrain(x); }
        bool halt() override { return planner_.halt(); }

      private:
        BacterialForaging &planner_;
    };

    void BacterialForaging::startColony(unsigned int d)
    {
        colony_.start(d, getPopulationSize(), *adapter_);
    }

    void BacterialForaging::randomBacterium(double *x)
    {
        if (!online_)
        {
            randomPosition(x);
            return;
        }
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

    void BacterialForaging::constrain(double *x) const
    {
        if (!online_)
        {
            clampToBounds(x);
            return;
        }
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

    double BacterialForaging::rawCost(const double *x)
    {
        if (!online_)
            return evaluate(x);
        const Vec2 p(x[0], x[1]);
        double j = potential_->cost(p);
        onlineEvaluations_ = potential_->evaluations();
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
    // Global mode (6.4): the PopulationPlanner hooks

    bool BacterialForaging::initialisePopulation()
    {
        startColony(dimension());
        return colony_.evaluateAll(*adapter_);
    }

    bool BacterialForaging::iterate(unsigned int /*t*/)
    {
        return colony_.step(*adapter_, rng_) != BacterialColony::Step::Interrupted;
    }

    void BacterialForaging::clearPopulation()
    {
        colony_.reset();
    }

    // ---------------------------------------------------------------------------------------------------
    // Online mode (6.3)

    bool BacterialForaging::prepareOnline()
    {
        if (!walkEndpoints(pis_, getName(), robot_, goal_))
            return false;
        seedUsed_ = getSeed();
        if (seedUsed_ != 0)
            rng_.setLocalSeed(static_cast<std::uint_fast32_t>(seedUsed_));
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
        onlineReady_ = true;
        OMPL_INFORM(
            "%s: online, seed %lu, S = %u, Nc = %u, Ns = %u, Nre = %u, Ned = %u, C = %g, lambda = %g, "
            "%s repulsion%s",
            getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), getPopulationSize(),
            colonySettings_.chemotacticSteps, colonySettings_.swimLength, colonySettings_.reproductionSteps,
            colonySettings_.eliminationEvents, colonySettings_.stepSize, robotStep_,
            toString(potential_->usedMode()).c_str(),
            colonySettings_.adaptiveTumble ? ", adaptive tumble" : "");
        finishWalkIfAtGoal();
        return true;
    }

    void BacterialForaging::finishWalkIfAtGoal()
    {
        const double tolerance = goalTolerance_ > 0.0 ? goalTolerance_ : robotStep_;
        if (!walkReachGoal(*si_, stateA_, stateB_, walk_, goal_, tolerance))
            return; // keep walking
        robot_ = walk_.back();
        walkState_ = WalkState::ReachedGoal;
    }

    void BacterialForaging::moveRobot()
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
        ++onlineSteps_;
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

    ob::PlannerStatus BacterialForaging::solveOnline(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (onlineReady_ && getSeed() != seedUsed_)
            clear(); // a new seed restarts the walk (PopulationPlanner::setSeed does the same)
        if (!onlineReady_ && !prepareOnline())
            return ob::PlannerStatus::INVALID_START;

        onlinePtc_ = &ptc;
        const unsigned int maxIterations = getMaxIterations();
        unsigned int done = 0;
        while (walkState_ == WalkState::Walking && !ptc() && (maxIterations == 0 || done < maxIterations))
        {
            if (!runActive_)
            {
                runBestKnown_ = false;
                startColony(2);
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
        onlinePtc_ = nullptr;
        return reportOnline();
    }

    ob::PlannerStatus BacterialForaging::reportOnline()
    {
        const ob::PlannerStatus status =
            reportWalk(si_, pdef_, getName(), walk_, walkState_ != WalkState::Walking,
                       walkState_ == WalkState::ReachedGoal, goal_, onlineBestCost_, this);
        if (status == ob::PlannerStatus::TIMEOUT)
            return status;
        const bool exact = status == ob::PlannerStatus::EXACT_SOLUTION;
        OMPL_INFORM("%s: %zu robot positions, %lu J evaluations, %s", getName().c_str(), walk_.size(),
                    onlineEvaluations_.load(),
                    exact ? "goal reached"
                          : (walkState_ == WalkState::Walking ? "walking" : "walk ended before the goal"));
        return status;
    }
} // namespace mhplan
