// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/common/PopulationPlanner.h"
#include "mhplan/planners/common/PlannerSupport.h"

#include "mhplan/collision/GridCollision.h"
#include "mhplan/planners/common/Operators.h"
#include "mhplan/collision/Validity.h"

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
    void checkParameterRange(const char *param, double value, double lo, double hi)
    {
        if (value >= lo && value <= hi)
            return;
        std::ostringstream msg;
        msg << std::setprecision(12) << "parameter '" << param << "' must be in [" << lo << ", " << hi
            << "]; got " << value;
        throw std::invalid_argument(msg.str());
    }

    PopulationPlanner::PopulationPlanner(const ob::SpaceInformationPtr &si, const std::string &name,
                                         const PopulationDefaults &defaults)
        : ob::Planner(si, name), populationSize_(defaults.populationSize), iterations_(defaults.iterations),
          waypoints_(defaults.waypoints), decoding_(defaults.decoding),
          bestCostValue_(std::numeric_limits<double>::infinity())
    {
        if (const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si_->getStateSpace().get()))
            spaceDim_ = std::max(1u, space->getDimension());
        lower_.assign(spaceDim_, 0.0);
        upper_.assign(spaceDim_, 0.0);
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = true;
        specs_.canReportIntermediateSolutions = true;
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;

        declareParam<unsigned int>("population_size", this, &PopulationPlanner::setPopulationSize,
                                   &PopulationPlanner::getPopulationSize, "2:1:10000");
        declareParam<unsigned int>("iterations", this, &PopulationPlanner::setIterations,
                                   &PopulationPlanner::getIterations, "1:1:1000000");
        declareParam<unsigned int>("max_iterations", this, &PopulationPlanner::setMaxIterations,
                                   &PopulationPlanner::getMaxIterations, "0:1:1000000");
        declareParam<unsigned int>("waypoints", this, &PopulationPlanner::setWaypoints,
                                   &PopulationPlanner::getWaypoints, "1:1:100");
        declareParam<std::string>("decoding", this, &PopulationPlanner::setDecoding,
                                  &PopulationPlanner::getDecoding, "polyline,spline");
        declareParam<unsigned int>("spline_samples", this, &PopulationPlanner::setSplineSamples,
                                   &PopulationPlanner::getSplineSamples, "2:1:100000");
        declareParam<std::string>("fitness", this, &PopulationPlanner::setFitness,
                                  &PopulationPlanner::getFitness, "auto,lrsma,gms");
        declareParam<double>("length_weight", this, &PopulationPlanner::setLengthWeight,
                             &PopulationPlanner::getLengthWeight, "0.:1.:1000000.");
        declareParam<double>("penalty_weight", this, &PopulationPlanner::setPenaltyWeight,
                             &PopulationPlanner::getPenaltyWeight, "0.:1.:1000000000.");
        declareParam<double>("distance_weight", this, &PopulationPlanner::setDistanceWeight,
                             &PopulationPlanner::getDistanceWeight, "0.:0.1:1000000.");
        declareParam<double>("safety_weight", this, &PopulationPlanner::setSafetyWeight,
                             &PopulationPlanner::getSafetyWeight, "0.:0.1:1000000.");
        declareParam<double>("smoothness_weight", this, &PopulationPlanner::setSmoothnessWeight,
                             &PopulationPlanner::getSmoothnessWeight, "0.:0.1:1000000.");
        declareParam<double>("safe_distance", this, &PopulationPlanner::setSafeDistance,
                             &PopulationPlanner::getSafeDistance, "0.000001:0.1:1000000.");
        declareParam<double>("infeasible_length_weight", this, &PopulationPlanner::setInfeasibleLengthWeight,
                             &PopulationPlanner::getInfeasibleLengthWeight, "0.:0.1:1000000.");
        declareParam<double>("crossing_weight", this, &PopulationPlanner::setCrossingWeight,
                             &PopulationPlanner::getCrossingWeight, "0.:0.1:1000000.");
        declareParam<unsigned long>("seed", this, &PopulationPlanner::setSeed, &PopulationPlanner::getSeed,
                                    "0:1:4294967295");
        declareParam<unsigned int>("stagnation_restart", this, &PopulationPlanner::setStagnationRestart,
                                   &PopulationPlanner::getStagnationRestart, "0:1:1000000");
        declareParam<unsigned int>("gms_repair", this, &PopulationPlanner::setGmsRepair,
                                   &PopulationPlanner::getGmsRepair, "0:1:1");
        declareParam<unsigned int>("gms_revise", this, &PopulationPlanner::setGmsRevise,
                                   &PopulationPlanner::getGmsRevise, "0:1:1");
        declareParam<unsigned int>("gms_simplify", this, &PopulationPlanner::setGmsSimplify,
                                   &PopulationPlanner::getGmsSimplify, "0:1:1");
        declareParam<unsigned int>("gms_improve", this, &PopulationPlanner::setGmsImprove,
                                   &PopulationPlanner::getGmsImprove, "0:1:1");
        declareParam<std::string>("gms_scope", this, &PopulationPlanner::setGmsScope,
                                  &PopulationPlanner::getGmsScope, "best,all");
        declareParam<double>("gms_replace_fraction", this, &PopulationPlanner::setGmsReplaceFraction,
                             &PopulationPlanner::getGmsReplaceFraction, "0.:0.05:1.");

        addPlannerProgressProperty("best cost REAL", [this] { return formatCost(bestCost()); });
        addPlannerProgressProperty("iterations INTEGER", [this] { return std::to_string(iterationCount()); });
        addPlannerProgressProperty("fitness evaluations INTEGER",
                                   [this] { return std::to_string(evaluationCount()); });
    }

    PopulationPlanner::~PopulationPlanner()
    {
        if (costA_ != nullptr)
            si_->freeState(costA_);
        if (costB_ != nullptr)
            si_->freeState(costB_);
        freeStates(*si_, plannerDataStates_);
    }

    void PopulationPlanner::setPopulationSize(unsigned int n)
    {
        checkParameterRange("population_size", n, 2, 10000);
        if (n != populationSize_)
            invalidate();
        populationSize_ = n;
    }

    void PopulationPlanner::setIterations(unsigned int t)
    {
        checkParameterRange("iterations", t, 1, 1000000);
        iterations_ = t;
    }

    void PopulationPlanner::setMaxIterations(unsigned int n)
    {
        checkParameterRange("max_iterations", n, 0, 1000000);
        maxIterations_ = n;
    }

    void PopulationPlanner::setWaypoints(unsigned int m)
    {
        checkParameterRange("waypoints", m, 1, 100);
        if (m != waypoints_)
            invalidate();
        waypoints_ = m;
    }

    void PopulationPlanner::setDecoding(const std::string &decoding)
    {
        const PathDecoding d = parsePathDecoding(decoding);
        if (d != decoding_)
            invalidate();
        decoding_ = d;
    }

    void PopulationPlanner::setSplineSamples(unsigned int n)
    {
        checkParameterRange("spline_samples", n, 2, 100000);
        if (n != splineSamples_)
            invalidate();
        splineSamples_ = n;
    }

    void PopulationPlanner::setFitness(const std::string &fitness)
    {
        if (fitness != "auto")
            parseFitnessKind(fitness); // validates
        if (fitness != fitnessName_)
            invalidate();
        fitnessName_ = fitness;
    }

    void PopulationPlanner::setLengthWeight(double w)
    {
        checkParameterRange("length_weight", w, 0.0, 1e6);
        weights_.lengthWeight = w;
        invalidate();
    }

    void PopulationPlanner::setPenaltyWeight(double w)
    {
        checkParameterRange("penalty_weight", w, 0.0, 1e9);
        weights_.penaltyWeight = w;
        invalidate();
    }

    void PopulationPlanner::setDistanceWeight(double w)
    {
        checkParameterRange("distance_weight", w, 0.0, 1e6);
        weights_.distanceWeight = w;
        invalidate();
    }

    void PopulationPlanner::setSafetyWeight(double w)
    {
        checkParameterRange("safety_weight", w, 0.0, 1e6);
        weights_.safetyWeight = w;
        invalidate();
    }

    void PopulationPlanner::setSmoothnessWeight(double w)
    {
        checkParameterRange("smoothness_weight", w, 0.0, 1e6);
        weights_.smoothnessWeight = w;
        invalidate();
    }

    void PopulationPlanner::setSafeDistance(double d)
    {
        checkParameterRange("safe_distance", d, 1e-6, 1e6);
        weights_.safeDistance = d;
        invalidate();
    }

    void PopulationPlanner::setInfeasibleLengthWeight(double w)
    {
        checkParameterRange("infeasible_length_weight", w, 0.0, 1e6);
        weights_.infeasibleLengthWeight = w;
        invalidate();
    }

    void PopulationPlanner::setCrossingWeight(double w)
    {
        checkParameterRange("crossing_weight", w, 0.0, 1e6);
        weights_.crossingWeight = w;
        invalidate();
    }

    void PopulationPlanner::setSeed(unsigned long seed)
    {
        checkParameterRange("seed", static_cast<double>(seed), 0.0, 4294967295.0);
        seed_ = seed;
        invalidate();
    }

    void PopulationPlanner::setStagnationRestart(unsigned int n)
    {
        checkParameterRange("stagnation_restart", n, 0, 1000000);
        stagnationRestart_ = n;
    }

    void PopulationPlanner::setGmsRepair(unsigned int on)
    {
        checkParameterRange("gms_repair", on, 0, 1);
        gmsRepair_ = on == 1;
        setup_ = false; // setup() checks the switches against the problem
    }

    void PopulationPlanner::setGmsRevise(unsigned int on)
    {
        checkParameterRange("gms_revise", on, 0, 1);
        gmsRevise_ = on == 1;
        setup_ = false;
    }

    void PopulationPlanner::setGmsSimplify(unsigned int on)
    {
        checkParameterRange("gms_simplify", on, 0, 1);
        gmsSimplify_ = on == 1;
        setup_ = false;
    }

    void PopulationPlanner::setGmsImprove(unsigned int on)
    {
        checkParameterRange("gms_improve", on, 0, 1);
        gmsImprove_ = on == 1;
        setup_ = false;
    }

    void PopulationPlanner::setGmsScope(const std::string &scope)
    {
        if (scope != "best" && scope != "all")
            throw std::invalid_argument("parameter 'gms_scope' must be 'best' or 'all'; got '" + scope + "'");
        gmsScopeAll_ = scope == "all";
    }

    void PopulationPlanner::setGmsReplaceFraction(double f)
    {
        checkParameterRange("gms_replace_fraction", f, 0.0, 1.0);
        gmsReplaceFraction_ = f;
        setup_ = false;
    }

    void PopulationPlanner::checkGmsSwitches()
    {
        if (!gmsOperatorsEnabled())
            return;
        std::string on;
        for (const auto &s :
             {std::make_pair("gms_repair", gmsRepair_), std::make_pair("gms_revise", gmsRevise_),
              std::make_pair("gms_simplify", gmsSimplify_), std::make_pair("gms_improve", gmsImprove_),
              std::make_pair("gms_replace_fraction", gmsReplaceFraction_ > 0.0)})
            if (s.second)
                on += (on.empty() ? "'" : ", '") + std::string(s.first) + "'";
        if (!supportsGmsOperators())
            refuseSetup(
                "the [GMS] operator switches (" + on +
                ") need an algorithm that exposes a waypoint population (SMA, LRSMA, MGO); this one does "
                "not: switch them off");
        if (spaceDim_ != 2)
            refuseSetup(
                "the [GMS] operator switches (" + on +
                ") are planar (node/segment repair, simplification, improvement work on 2D points); the "
                "space has dimension " +
                std::to_string(spaceDim_) + ": switch them off");
    }

    void PopulationPlanner::invalidate()
    {
        // Structural parameters change the meaning of the population: start afresh.
        if (problemReady_ || initialised_)
            clear();
    }

    void PopulationPlanner::refuseSetup(const std::string &message)
    {
        setup_ = false;
        const std::string text = getName() + ": " + message;
        OMPL_ERROR("%s", text.c_str());
        throw ompl::Exception(text);
    }

    void PopulationPlanner::checkSpace()
    {
        const ob::StateSpacePtr &ss = si_->getStateSpace();
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(ss.get());
        if (space == nullptr)
            refuseSetup(
                "needs an ompl::base::RealVectorStateSpace (a candidate path is a vector of waypoints "
                "in R^k); got the state space '" +
                ss->getName() + "'" + (ss->isCompound() ? ", a compound space" : "") +
                ". SO(2)/SO(3)/SE(2)/SE(3), compound and other spaces are not supported.");
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

    void PopulationPlanner::setup()
    {
        ob::Planner::setup();
        checkSpace();
        checkGmsSwitches();
    }

    void PopulationPlanner::clear()
    {
        ob::Planner::clear();
        clearPopulation();
        freeStates(*si_, plannerDataStates_);
        problemReady_ = false;
        initialised_ = false;
        haveFeasible_ = false;
        haveInfeasible_ = false;
        bestFeasiblePath_.clear();
        bestInfeasiblePath_.clear();
        gmsOps_.reset();
        bestCostValue_ = std::numeric_limits<double>::infinity();
        iterationCount_ = 0;
        evaluationCount_ = 0;
        epochStart_ = 0;
        epochLength_ = 0;
        sinceImprovement_ = 0;
        restarts_ = 0;
    }

    bool PopulationPlanner::prepareProblem()
    {
        checkSpace();
        const unsigned int k = spaceDim_;
        const ob::State *start = pis_.nextStart();
        if (start == nullptr)
        {
            OMPL_ERROR("%s: no valid start state", getName().c_str());
            return false;
        }
        const double *sv = start->as<ob::RealVectorStateSpace::StateType>()->values;
        startX_.assign(sv, sv + k);
        const ob::State *goal = pis_.nextGoal();
        if (goal == nullptr)
        {
            OMPL_ERROR("%s: no goal state could be sampled", getName().c_str());
            return false;
        }
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
        if (costA_ == nullptr)
        {
            costA_ = si_->allocState();
            costB_ = si_->allocState();
        }
        fitness_->configure(kind, weights_);
        decoder_.configure(startX_.data(), goalX_.data(), k, waypoints_, decoding_, splineSamples_);
        bestFeasiblePath_.reserve(std::size_t(std::max(256u, splineSamples_)) * k);
        bestInfeasiblePath_.reserve(std::size_t(std::max(256u, splineSamples_)) * k);
        if (seed_ != 0)
            rng_.setLocalSeed(static_cast<std::uint_fast32_t>(seed_));
        const PenaltyMode mode = fitness_->penaltyMode();
        OMPL_INFORM("%s: seed %lu, N = %u, T = %u, m = %u waypoints in R^%u, %s decoding, %s fitness%s",
                    getName().c_str(), static_cast<unsigned long>(rng_.getLocalSeed()), populationSize_,
                    iterations_, waypoints_, k, toString(decoding_).c_str(), toString(kind).c_str(),
                    mode == PenaltyMode::ExactCircles ? " (exact circle formula)"
                    : mode == PenaltyMode::ValidityOnly
                        ? " (the validity checker computes no clearance: the penalty counts invalid samples)"
                        : "");
        problemReady_ = true;
        return true;
    }

    ob::PlannerStatus PopulationPlanner::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (!problemReady_ && !prepareProblem())
            return ob::PlannerStatus::INVALID_START;

        ptc_ = &ptc;
        if (!initialised_ && !ptc())
            initialised_ = initialisePopulation();
        unsigned int done = 0;
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        auto satisfied = [&] { return haveFeasible_ && opt && opt->isSatisfied(bestFeasibleCost_); };
        if (epochLength_ == 0)
            epochLength_ = iterations_;
        // Anytime restarts only without an iteration budget (so iteration-bounded runs are unchanged).
        const bool restarts = stagnationRestart_ > 0 && maxIterations_ == 0;
        if (!restarts)
            epochLength_ = iterations_;
        while (initialised_ && !ptc() && !satisfied() && (maxIterations_ == 0 || done < maxIterations_))
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
        initialised_ = !stopRequested() && initialisePopulation();
        return initialised_;
    }

    void PopulationPlanner::randomPosition(double *x)
    {
        for (unsigned int j = 0; j < dimension(); ++j)
            x[j] = rng_.uniformReal(lower(j), upper(j));
    }

    void PopulationPlanner::clampToBounds(double *x) const
    {
        for (unsigned int j = 0; j < dimension(); ++j)
            x[j] = std::min(std::max(x[j], lower(j)), upper(j));
    }

    double PopulationPlanner::evaluate(const double *x)
    {
        decoder_.decode(x);
        const PointsView path = decoder_.pathView();
        const FitnessResult r = fitness_->evaluate(path, decoder_.samplesView());
        record(r, path);
        return r.fitness;
    }

    double PopulationPlanner::evaluatePath(const std::vector<Vec2> &path)
    {
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
                double *a = costA_->as<ob::RealVectorStateSpace::StateType>()->values;
                double *b = costB_->as<ob::RealVectorStateSpace::StateType>()->values;
                for (std::size_t i = 1; i < path.size(); ++i)
                {
                    std::copy(path[i - 1], path[i - 1] + path.dim, a);
                    std::copy(path[i], path[i] + path.dim, b);
                    cost = opt->combineCosts(cost, opt->motionCost(costA_, costB_));
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

    void PopulationPlanner::fireIntermediate()
    {
        reportImprovement(
            this, pdef_, *si_, bestFeasiblePath_.size() / spaceDim_,
            [this](ob::State *s, std::size_t i) { toState(s, bestFeasiblePath_, i); }, bestFeasibleCost_);
    }

    void PopulationPlanner::reportSolution(bool &exact, bool &approximate)
    {
        exact = approximate = false;
        const std::vector<double> *points = nullptr;
        if (haveFeasible_)
            points = &bestFeasiblePath_;
        else if (haveInfeasible_)
            points = &bestInfeasiblePath_;
        if (points == nullptr)
            return;
        auto path = std::make_shared<og::PathGeometric>(si_);
        ob::State *s = si_->allocState();
        for (std::size_t i = 0; i < points->size() / spaceDim_; ++i)
        {
            toState(s, *points, i);
            path->append(s);
        }
        si_->freeState(s);
        ob::PlannerSolution solution(path);
        solution.setPlannerName(getName());
        if (haveFeasible_)
        {
            const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
            if (opt)
                solution.setOptimized(opt, bestFeasibleCost_, opt->isSatisfied(bestFeasibleCost_));
            exact = true;
        }
        else
        {
            solution.setApproximate(std::max(bestInfeasibleViolation_, 1e-12));
            approximate = true;
        }
        pdef_->addSolutionPath(solution);
    }

    void PopulationPlanner::getPlannerData(ob::PlannerData &data) const
    {
        ob::Planner::getPlannerData(data);
        const std::vector<double> &points = haveFeasible_ ? bestFeasiblePath_ : bestInfeasiblePath_;
        addPathToPlannerData(
            *si_, points.size() / spaceDim_,
            [this, &points](ob::State *s, std::size_t i) { toState(s, points, i); }, true, data,
            plannerDataStates_);
    }

    bool PopulationPlanner::applyGmsOperators()
    {
        double *x = nullptr, *f = nullptr;
        if (spaceDim_ != 2 || !populationView(x, f))
            return true; // setup() refuses this; never reached with the switches on
        const unsigned int n = populationSize_, d = dimension();
        const bool pathOps = gmsRepair_ || gmsRevise_ || gmsSimplify_ || gmsImprove_;
        if (!gmsOps_)
        {
            const Box box{lower_[0], upper_[0], lower_[1], upper_[1]};
            gmsOps_ = std::make_unique<PathOperators>(*fitness_, rng_, box,
                                                      0.01 * std::max(box.width(), box.height()));
            const std::size_t points = std::max<std::size_t>(
                2 * (waypoints_ + 2), (decoding_ == PathDecoding::Spline ? splineSamples_ : 0) + 2);
            gmsPath_.reserve(2 * points + 64);
            gmsCandidate_.assign(d, 0.0);
            gmsOrder_.resize(n);
        }
        unsigned int best = 0;
        for (unsigned int i = 1; i < n; ++i)
            if (f[i] < f[best])
                best = i;
        bool completed = true;
        if (pathOps)
            for (unsigned int i = 0; i < n && completed; ++i)
                if (gmsScopeAll_ || i == best)
                    completed = operateOn(x + std::size_t(i) * d, f[i]);
        if (completed && gmsReplaceFraction_ > 0.0)
        {
            // Rank again (the operators may have changed fitness values), worst first.
            for (unsigned int i = 1; i < n; ++i)
                if (f[i] < f[best])
                    best = i;
            for (unsigned int i = 0; i < n; ++i)
                gmsOrder_[i] = i;
            // std::sort with an index tie-break: deterministic, and unlike std::stable_sort it allocates no
            // temporary buffer.
            std::sort(gmsOrder_.begin(), gmsOrder_.end(),
                      [f](unsigned int a, unsigned int b) { return f[a] > f[b] || (f[a] == f[b] && a < b); });
            const auto count = std::min<unsigned int>(
                n - 1, static_cast<unsigned int>(std::ceil(gmsReplaceFraction_ * n - 1e-9)));
            for (unsigned int k = 0, done = 0; k < n && done < count; ++k)
            {
                const unsigned int i = gmsOrder_[k];
                if (i == best)
                    continue;
                if (stopRequested())
                {
                    completed = false;
                    break;
                }
                double *xi = x + std::size_t(i) * d;
                randomPosition(xi);
                if (gmsRepair_)
                    for (unsigned int w = 0; w < waypoints_; ++w)
                    {
                        Vec2 p(xi[2 * w], xi[2 * w + 1]);
                        gmsOps_->repairNode(p);
                        xi[2 * w] = p.x;
                        xi[2 * w + 1] = p.y;
                    }
                clampToBounds(xi);
                f[i] = evaluate(xi);
                ++done;
            }
        }
        populationChanged();
        return completed;
    }

    bool PopulationPlanner::operateOn(double *x, double &fx)
    {
        decoder_.decode(x);
        const PointsView path = decoder_.pathView();
        gmsPath_.clear();
        for (std::size_t i = 0; i < path.size(); ++i)
            gmsPath_.emplace_back(path[i][0], path[i][1]);
        if (gmsRepair_)
        {
            gmsOps_->repairNodes(gmsPath_);
            gmsOps_->repairSegments(gmsPath_);
        }
        if (gmsRevise_)
            gmsOps_->revise(gmsPath_);
        if (gmsSimplify_)
            gmsOps_->simplify(gmsPath_);
        if (gmsImprove_)
            gmsOps_->improveNodes(gmsPath_);
        encodePath();
        clampToBounds(gmsCandidate_.data());
        if (stopRequested())
            return false;
        const double fc = evaluate(gmsCandidate_.data());
        if (fc < fx)
        {
            std::copy(gmsCandidate_.begin(), gmsCandidate_.end(), x);
            fx = fc;
        }
        return true;
    }

    void PopulationPlanner::encodePath()
    {
        const std::size_t m = waypoints_;
        std::vector<Vec2> &p = gmsPath_;
        if (p.size() < 2)
            return;
        if (p.size() - 2 <= m)
        {
            // Keep the interior points; halve the longest segment until there are m of them.
            while (p.size() - 2 < m)
            {
                std::size_t longest = 1;
                double len = -1.0;
                for (std::size_t i = 1; i < p.size(); ++i)
                {
                    const double l = distance(p[i - 1], p[i]);
                    if (l > len)
                    {
                        len = l;
                        longest = i;
                    }
                }
                const Vec2 mid = (p[longest - 1] + p[longest]) * 0.5;
                p.insert(p.begin() + static_cast<std::ptrdiff_t>(longest), mid);
            }
            for (std::size_t w = 0; w < m; ++w)
            {
                gmsCandidate_[2 * w] = p[w + 1].x;
                gmsCandidate_[2 * w + 1] = p[w + 1].y;
            }
            return;
        }
        // More interior points than waypoints: m points at equal arc length.
        double total = 0.0;
        for (std::size_t i = 1; i < p.size(); ++i)
            total += distance(p[i - 1], p[i]);
        std::size_t seg = 1;
        double before = 0.0; // arc length at p[seg - 1]
        for (std::size_t w = 0; w < m; ++w)
        {
            const double s = total * double(w + 1) / double(m + 1);
            while (seg + 1 < p.size() && before + distance(p[seg - 1], p[seg]) < s)
            {
                before += distance(p[seg - 1], p[seg]);
                ++seg;
            }
            const double l = distance(p[seg - 1], p[seg]);
            const double u = l > 0.0 ? std::min(1.0, std::max(0.0, (s - before) / l)) : 0.0;
            const Vec2 q = p[seg - 1] + (p[seg] - p[seg - 1]) * u;
            gmsCandidate_[2 * w] = q.x;
            gmsCandidate_[2 * w + 1] = q.y;
        }
    }

} // namespace mhplan
