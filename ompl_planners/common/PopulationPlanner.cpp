// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/PopulationPlanner.h"
#include "src/base/Parameters.h"
#include "ompl_planners/common/PlannerSupport.h"

#include "src/collision/GridCollision.h"
#include "ompl_planners/common/Operators.h"
#include "src/collision/Validity.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Exception.h>
#include <ompl/util/String.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{

    PopulationPlanner::PopulationPlanner(const ob::SpaceInformationPtr &si, const std::string &name,
                                         const PopulationDefaults &defaults)
        : PlannerBase(si, name, true), iterations_(defaults.iterations), waypoints_(defaults.waypoints),
          decoding_(defaults.decoding), decodingAuto_(defaults.decoding == PathDecoding::Spline)
    {
        if (const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si_->getStateSpace().get()))
            spaceDim_ = std::max(1u, space->getDimension());
        else
        {
            // Another space (docs/spaces.md): its parametrisation's dimension when it has one; setup()
            // refuses it otherwise.
            realVector_ = false;
            std::string why;
            if (const auto p = StateParametrisation::create(si_->getStateSpace(), why))
                spaceDim_ = p->dimension();
        }
        lower_.assign(spaceDim_, 0.0);
        upper_.assign(spaceDim_, 0.0);
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = true;
        specs_.canReportIntermediateSolutions = true;
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;

        declarePopulationSize(defaults.populationSize, "N, individuals (candidate paths) per iteration");
        declareMaxIterations("iterations per solve() call; 0 = until the time limit (the schedule restarts "
                             "after T)");
        declareParameters();
        declareProgress(true);
    }

    PopulationPlanner::~PopulationPlanner()
    {
        freeBestStates();
    }

    void PopulationPlanner::freeBestStates()
    {
        freeStates(*si_, bestFeasibleStates_);
        freeStates(*si_, bestInfeasibleStates_);
    }

    void PopulationPlanner::invalidate()
    {
        // Structural parameters change the meaning of the population: start afresh.
        if (problemReady_ || initialised_)
            clear();
    }

    void PopulationPlanner::checkSpace()
    {
        const ob::StateSpacePtr &ss = si_->getStateSpace();
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(ss.get());
        if (space == nullptr)
        {
            checkStateSpace();
            return;
        }
        realVector_ = true;
        const unsigned int k = space->getDimension();
        if (k == 0)
            refuseSetup("needs a RealVectorStateSpace of dimension at least 1; got dimension 0");
        const ob::RealVectorBounds &b = space->getBounds();
        for (unsigned int j = 0; j < k; ++j)
            if (!std::isfinite(b.low[j]) || !std::isfinite(b.high[j]) || b.low[j] > b.high[j])
            {
                std::ostringstream msg;
                msg << std::setprecision(12) << "needs finite bounds low <= high on every coordinate of the "
                    << "RealVectorStateSpace (waypoints are drawn uniformly in them); coordinate " << j
                    << " has [" << b.low[j] << ", " << b.high[j] << "]";
                refuseSetup(msg.str());
            }
        if (k != spaceDim_)
            invalidate();
        spaceDim_ = k;
        lower_.assign(b.low.begin(), b.low.end());
        upper_.assign(b.high.begin(), b.high.end());
    }

    void PopulationPlanner::checkStateSpace()
    {
        // A space other than R^k (docs/spaces.md): waypoints are states, through a parametrisation.
        const ob::StateSpacePtr &ss = si_->getStateSpace();
        std::string why;
        std::unique_ptr<StateParametrisation> fresh = StateParametrisation::create(ss, why);
        if (!fresh)
            refuseSetup("cannot plan on the state space '" + ss->getName() + "': " + why +
                        " (docs/spaces.md)");
        const std::string on = " on the state space '" + ss->getName() + "' (not a RealVectorStateSpace)";
        if (decoding_ == PathDecoding::Spline && !decodingAuto_)
            refuseSetup(
                "parameter 'decoding' = 'spline' splines each coordinate in R^k; it is not supported" + on +
                ", whose waypoints are joined by the space's own interpolation: set "
                "decoding=polyline or auto (docs/spaces.md)");
        if (fitnessName_ == "gms")
            refuseSetup("parameter 'fitness' = 'gms' (the [GMS] f1/f2: turning angles and clearances of "
                        "straight segments) is not supported" +
                        on + ": set fitness=lrsma or auto (docs/spaces.md)");
        // The space is the planner's for good, but its bounds may have changed: a repeated setup() of a
        // prepared query starts the search afresh with the new parametrisation.
        invalidate();
        stateFitness_.reset();
        param_ = std::move(fresh);
        realVector_ = false;
        spaceDim_ = param_->dimension();
        lower_.resize(spaceDim_);
        upper_.resize(spaceDim_);
        for (unsigned int j = 0; j < spaceDim_; ++j)
        {
            lower_[j] = param_->lower(j);
            upper_[j] = param_->upper(j);
        }
    }

    void PopulationPlanner::setup()
    {
        ob::Planner::setup();
        checkSpace();
        checkGmsSwitches();
    }

    void PopulationPlanner::clear()
    {
        PlannerBase::clear();
        clearPopulation();
        freeBestStates();
        problemReady_ = false;
        initialised_ = false;
        haveFeasible_ = false;
        haveInfeasible_ = false;
        bestFeasiblePath_.clear();
        bestInfeasiblePath_.clear();
        gmsOps_.reset();
        epochStart_ = 0;
        epochLength_ = 0;
        sinceImprovement_ = 0;
        restarts_ = 0;
    }

    bool PopulationPlanner::prepareProblem()
    {
        checkSpace();
        const unsigned int k = spaceDim_;
        const ob::State *start = nullptr, *goal = nullptr;
        if (!startAndGoal(start, goal))
            return false;
        if (!realVector_)
            return prepareStateProblem(start, goal);
        const double *sv = start->as<ob::RealVectorStateSpace::StateType>()->values;
        startX_.assign(sv, sv + k);
        const double *gv = goal->as<ob::RealVectorStateSpace::StateType>()->values;
        goalX_.assign(gv, gv + k);
        start_ = Vec2(startX_[0], k > 1 ? startX_[1] : 0.0);
        goal_ = Vec2(goalX_[0], k > 1 ? goalX_[1] : 0.0);

        FitnessKind kind = FitnessKind::LengthPenalty;
        if (fitnessName_ == "auto")
        {
            const auto *checker =
                dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get());
            if (checker != nullptr &&
                dynamic_cast<const GridCollisionModel *>(checker->model().get()) != nullptr)
                kind = FitnessKind::FeasibleInfeasible;
        }
        else
            kind = parseFitnessKind(fitnessName_);
        if (!fitness_)
            fitness_ = std::make_unique<PathFitness>(si_);
        fitness_->configure(kind, weights_);
        decoder_.configure(startX_.data(), goalX_.data(), k, waypoints_, decoding_, splineSamples_);
        bestFeasiblePath_.reserve(std::size_t(std::max(256u, splineSamples_)) * k);
        bestInfeasiblePath_.reserve(std::size_t(std::max(256u, splineSamples_)) * k);
        seedRng();
        const PenaltyMode mode = fitness_->penaltyMode();
        OMPL_INFORM("%s: seed %lu, N = %u, T = %u, m = %u waypoints in R^%u, %s decoding, %s fitness%s",
                    getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), getPopulationSize(),
                    iterations_, waypoints_, k, toString(decoding_).c_str(), toString(kind).c_str(),
                    mode == PenaltyMode::ExactCircles ? " (exact circle formula)"
                    : mode == PenaltyMode::ValidityOnly
                        ? " (the validity checker computes no clearance: the penalty counts invalid samples)"
                        : "");
        problemReady_ = true;
        return true;
    }

    bool PopulationPlanner::prepareStateProblem(const ob::State *start, const ob::State *goal)
    {
        const unsigned int n = spaceDim_;
        param_->setReference(start);
        startX_.assign(n, 0.0);
        goalX_.assign(n, 0.0);
        param_->toVector(start, startX_.data());
        param_->toVector(goal, goalX_.data());
        for (unsigned int j = 0; j < n; ++j)
        {
            lower_[j] = param_->lower(j);
            upper_[j] = param_->upper(j);
        }
        start_ = Vec2(startX_[0], n > 1 ? startX_[1] : 0.0);
        goal_ = Vec2(goalX_[0], n > 1 ? goalX_[1] : 0.0);
        // Every state of the search is allocated here, once per query (docs/spaces.md).
        stateFitness_ = std::make_unique<StatePathFitness>(si_, *param_);
        stateFitness_->configure(start, goal, waypoints_, splineSamples_, weights_);
        freeBestStates();
        for (unsigned int i = 0; i < waypoints_ + 2; ++i)
        {
            bestFeasibleStates_.push_back(si_->allocState());
            bestInfeasibleStates_.push_back(si_->allocState());
        }
        seedRng();
        OMPL_INFORM("%s: seed %lu, N = %u, T = %u, m = %u waypoint states of the space '%s' (%u coordinates "
                    "each), polyline decoding by the space's interpolation, lrsma fitness%s",
                    getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), getPopulationSize(),
                    iterations_, waypoints_, si_->getStateSpace()->getName().c_str(), n,
                    stateFitness_->penaltyMode() == PenaltyMode::ValidityOnly
                        ? " (the validity checker computes no clearance: the penalty counts invalid samples)"
                        : "");
        problemReady_ = true;
        return true;
    }

    ob::PlannerStatus PopulationPlanner::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (!problemReady_ && !prepareProblem())
            return inputFailure(); // INVALID_START or INVALID_GOAL

        ptc_ = &ptc;
        if (!initialised_ && !ptc())
            initialised_ = initialisePopulation() && applyGmsInitial();
        unsigned int done = 0;
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        auto satisfied = [&] { return haveFeasible_ && opt && opt->isSatisfied(bestFeasibleCost_); };
        if (epochLength_ == 0)
            epochLength_ = iterations_;
        // Anytime restarts only without an iteration budget (so iteration-bounded runs are unchanged).
        const unsigned int maxIterations = getMaxIterations();
        const bool restarts = stagnationRestart_ > 0 && maxIterations == 0;
        if (!restarts)
            epochLength_ = iterations_;
        while (initialised_ && !ptc() && !satisfied() && (maxIterations == 0 || done < maxIterations))
        {
            // Without restarts epochStart_ = 0 and epochLength_ = T: t cycles through 1..T as before.
            const auto t =
                static_cast<unsigned int>((iterationCount_.load() - epochStart_) % epochLength_) + 1;
            const double before = bestCostValue_.load();
            if (!iterate(t))
                break;
            ++iterationCount_;
            ++done;
            if (gmsOperatorsEnabled() && !applyGmsOperators())
                break;
            if (restarts && !restartOnStagnation(before))
                break;
        }
        ptc_ = nullptr;

        bool exact = false, approximate = false;
        reportSolution(exact, approximate);
        OMPL_INFORM("%s: %lu iterations, %lu fitness evaluations, %lu restarts, best cost %s",
                    getName().c_str(), iterationCount(), evaluationCount(), restarts_,
                    ompl::toString(bestCost()).c_str());
        if (exact)
            return ob::PlannerStatus::EXACT_SOLUTION;
        if (approximate)
            return ob::PlannerStatus::APPROXIMATE_SOLUTION;
        return ob::PlannerStatus::TIMEOUT;
    }

    bool PopulationPlanner::restartOnStagnation(double before)
    {
        const double now = bestCostValue_.load();
        if (std::isfinite(now) && !(now >= before - 1e-9 * std::abs(now)))
            sinceImprovement_ = 0;
        else
            ++sinceImprovement_;
        if (sinceImprovement_ < stagnationRestart_)
            return true;
        // Diversify: a fresh population (the best path found so far stays archived and reported), and the
        // schedule starts again with twice the length.
        sinceImprovement_ = 0;
        ++restarts_;
        clearPopulation();
        epochStart_ = iterationCount_.load();
        epochLength_ = std::min<unsigned long>(2ul * epochLength_, 1ul << 30);
        initialised_ = !stopRequested() && initialisePopulation() && applyGmsInitial();
        return initialised_;
    }

    void PopulationPlanner::randomPosition(double *x)
    {
        if (!realVector_)
        {
            for (unsigned int w = 0; w < waypoints_; ++w)
                param_->sample(rng_, x + std::size_t(w) * spaceDim_);
            return;
        }
        for (unsigned int j = 0; j < dimension(); ++j)
            x[j] = rng_.uniformReal(lower(j), upper(j));
    }

    void PopulationPlanner::clampToBounds(double *x) const
    {
        if (!realVector_)
        {
            for (unsigned int w = 0; w < waypoints_; ++w)
                param_->enforce(x + std::size_t(w) * spaceDim_);
            return;
        }
        for (unsigned int j = 0; j < dimension(); ++j)
            x[j] = std::min(std::max(x[j], lower(j)), upper(j));
    }

    double PopulationPlanner::evaluate(const double *x)
    {
        if (!realVector_)
        {
            const FitnessResult r = stateFitness_->evaluate(x);
            recordStates(r, stateFitness_->path());
            return r.fitness;
        }
        decoder_.decode(x);
        const PointsView path = decoder_.pathView();
        const FitnessResult r = fitness_->evaluate(path, decoder_.samplesView());
        record(r, path);
        return r.fitness;
    }

    double PopulationPlanner::evaluatePath(const std::vector<Vec2> &path)
    {
        if (!realVector_)
            throw std::logic_error(getName() + ": evaluatePath() takes points of R^2; the space '" +
                                   si_->getStateSpace()->getName() + "' is not a RealVectorStateSpace");
        if (spaceDim_ != 2)
            throw std::logic_error(getName() +
                                   ": evaluatePath() takes planar points; the space has dimension " +
                                   std::to_string(spaceDim_) + " (use evaluatePoints())");
        planarPath_.resize(2 * path.size());
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            planarPath_[2 * i] = path[i].x;
            planarPath_[2 * i + 1] = path[i].y;
        }
        return evaluatePoints({planarPath_.data(), path.size(), 2});
    }

    double PopulationPlanner::evaluatePoints(const PointsView &path)
    {
        if (!realVector_)
            throw std::logic_error(getName() + ": evaluatePoints() takes points of R^k; the space '" +
                                   si_->getStateSpace()->getName() + "' is not a RealVectorStateSpace");
        const FitnessResult r = fitness_->evaluate(path, path);
        record(r, path);
        return r.fitness;
    }

    void PopulationPlanner::toState(ob::State *state, const std::vector<double> &points, std::size_t i) const
    {
        const auto begin = points.begin() + static_cast<std::ptrdiff_t>(i * spaceDim_);
        std::copy(begin, begin + spaceDim_, state->as<ob::RealVectorStateSpace::StateType>()->values);
    }

    void PopulationPlanner::record(const FitnessResult &r, const PointsView &path)
    {
        ++evaluationCount_;
        const double *begin = path.data, *end = path.data + path.size() * path.dim;
        if (r.feasible)
        {
            // The reported cost is the problem's objective, not the fitness.
            const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
            ob::Cost cost(r.length);
            if (opt)
            {
                cost = opt->identityCost();
                ob::State *costA = scratchState(0), *costB = scratchState(1);
                double *a = costA->as<ob::RealVectorStateSpace::StateType>()->values;
                double *b = costB->as<ob::RealVectorStateSpace::StateType>()->values;
                for (std::size_t i = 1; i < path.size(); ++i)
                {
                    std::copy(path[i - 1], path[i - 1] + path.dim, a);
                    std::copy(path[i], path[i] + path.dim, b);
                    cost = opt->combineCosts(cost, opt->motionCost(costA, costB));
                }
            }
            const bool better = !haveFeasible_ || (opt ? opt->isCostBetterThan(cost, bestFeasibleCost_)
                                                       : cost.value() < bestFeasibleCost_.value());
            if (better)
            {
                haveFeasible_ = true;
                bestFeasibleCost_ = cost;
                bestFeasiblePath_.assign(begin, end);
                bestCostValue_ = cost.value();
                fireIntermediate();
            }
        }
        else if (!haveInfeasible_ || r.fitness < bestInfeasibleFitness_)
        {
            haveInfeasible_ = true;
            bestInfeasibleFitness_ = r.fitness;
            bestInfeasibleViolation_ = r.violation;
            bestInfeasiblePath_.assign(begin, end);
        }
    }

    void PopulationPlanner::recordStates(const FitnessResult &r, const std::vector<ob::State *> &path)
    {
        ++evaluationCount_;
        if (r.feasible)
        {
            // The reported cost is the problem's objective of the states (path length: si->distance).
            const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
            ob::Cost cost(r.length);
            if (opt)
            {
                cost = opt->identityCost();
                for (std::size_t i = 1; i < path.size(); ++i)
                    cost = opt->combineCosts(cost, opt->motionCost(path[i - 1], path[i]));
            }
            const bool better = !haveFeasible_ || (opt ? opt->isCostBetterThan(cost, bestFeasibleCost_)
                                                       : cost.value() < bestFeasibleCost_.value());
            if (better)
            {
                haveFeasible_ = true;
                bestFeasibleCost_ = cost;
                for (std::size_t i = 0; i < path.size(); ++i)
                    si_->copyState(bestFeasibleStates_[i], path[i]);
                bestCostValue_ = cost.value();
                fireIntermediate();
            }
        }
        else if (!haveInfeasible_ || r.fitness < bestInfeasibleFitness_)
        {
            haveInfeasible_ = true;
            bestInfeasibleFitness_ = r.fitness;
            bestInfeasibleViolation_ = r.violation;
            for (std::size_t i = 0; i < path.size(); ++i)
                si_->copyState(bestInfeasibleStates_[i], path[i]);
        }
    }

    std::size_t PopulationPlanner::pathCount(bool feasible) const
    {
        if (realVector_)
            return (feasible ? bestFeasiblePath_ : bestInfeasiblePath_).size() / spaceDim_;
        return (feasible ? haveFeasible_ : haveInfeasible_)
                   ? (feasible ? bestFeasibleStates_ : bestInfeasibleStates_).size()
                   : 0;
    }

    void PopulationPlanner::pathState(bool feasible, ob::State *state, std::size_t i) const
    {
        if (realVector_)
            toState(state, feasible ? bestFeasiblePath_ : bestInfeasiblePath_, i);
        else
            si_->copyState(state, (feasible ? bestFeasibleStates_ : bestInfeasibleStates_)[i]);
    }

    void PopulationPlanner::fireIntermediate()
    {
        reportImprovementOf(
            pathCount(true), [this](ob::State *s, std::size_t i) { pathState(true, s, i); },
            bestFeasibleCost_);
    }

    void PopulationPlanner::reportSolution(bool &exact, bool &approximate)
    {
        exact = approximate = false;
        if (!haveFeasible_ && !haveInfeasible_)
            return;
        const bool feasible = haveFeasible_;
        exact = feasible;
        approximate = !exact;
        addSolutionPath(
            pathCount(feasible), [this, feasible](ob::State *s, std::size_t i) { pathState(feasible, s, i); },
            exact, bestFeasibleCost_, bestInfeasibleViolation_);
    }

    void PopulationPlanner::getPlannerData(ob::PlannerData &data) const
    {
        const bool feasible = haveFeasible_;
        pathToPlannerData(
            data, pathCount(feasible),
            [this, feasible](ob::State *s, std::size_t i) { pathState(feasible, s, i); }, true);
    }

} // namespace mhplan
