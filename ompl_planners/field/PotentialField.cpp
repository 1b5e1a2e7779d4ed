// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/PotentialField.h"
#include "ompl_planners/common/PlannerSupport.h"

#include "src/base/Parameters.h"
#include "src/collision/Validity.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kAttractionGain{"attraction_gain", 0, 0.01, 1e6,
                                             "xi, gain of the goal attraction"};
        constexpr ParamRange kRepulsionGain{"repulsion_gain", 0, 0.01, 1e6,
                                            "eta, gain of the obstacle repulsion"};
        constexpr ParamRange kInfluenceDistance{"influence_distance", 1e-6, 0.1, 1e6,
                                                "d0, distance beyond which an obstacle does not repel"};
        constexpr ParamRange kSensingRange{"sensing_range", 1e-6, 0.1, 1e6,
                                           "D_sense, range of the obstacle sensing"};
    } // namespace

    RepulsionMode parseRepulsionMode(const std::string &name)
    {
        if (name == "sum")
            return RepulsionMode::Sum;
        if (name == "nearest")
            return RepulsionMode::Nearest;
        throw std::invalid_argument("parameter 'repulsion' must be one of {sum, nearest}; got '" + name +
                                    "'");
    }

    std::string toString(RepulsionMode mode)
    {
        return mode == RepulsionMode::Sum ? "sum" : "nearest";
    }

    void PotentialFieldSettings::setAttractionGain(double v)
    {
        storeChecked(kAttractionGain, field_.attractionGain, v);
        fieldChanged();
    }

    void PotentialFieldSettings::setRepulsionGain(double v)
    {
        storeChecked(kRepulsionGain, field_.repulsionGain, v);
        fieldChanged();
    }

    void PotentialFieldSettings::setInfluenceDistance(double v)
    {
        storeChecked(kInfluenceDistance, field_.influenceDistance, v);
        fieldChanged();
    }

    void PotentialFieldSettings::setSensingRange(double v)
    {
        storeChecked(kSensingRange, field_.sensingRange, v);
        fieldChanged();
    }

    void PotentialFieldSettings::setRepulsion(const std::string &mode)
    {
        repulsion_ = parseRepulsionMode(mode);
        fieldChanged();
    }

    void PotentialFieldSettings::declareFieldParams(ob::ParamSet &params)
    {
        using S = PotentialFieldSettings;
        declareRanged<double>(params, this, kAttractionGain, &S::setAttractionGain, &S::getAttractionGain);
        declareRanged<double>(params, this, kRepulsionGain, &S::setRepulsionGain, &S::getRepulsionGain);
        declareRanged<double>(params, this, kInfluenceDistance, &S::setInfluenceDistance,
                              &S::getInfluenceDistance);
        declareRanged<double>(params, this, kSensingRange, &S::setSensingRange, &S::getSensingRange);
        declareChoice(params, this, "repulsion", &S::setRepulsion, &S::getRepulsion, "sum,nearest",
                      "repulsion summed over every obstacle in range, or from the nearest only");
    }

    PotentialField::PotentialField(ob::SpaceInformationPtr si) : si_(std::move(si)) {}

    PotentialField::~PotentialField()
    {
        if (state_ != nullptr)
            si_->freeState(state_);
        if (other_ != nullptr)
            si_->freeState(other_);
    }

    void PotentialField::requireClearance(const ob::SpaceInformation &si, const std::string &who)
    {
        // Logged through OMPL's console as well as thrown, as every mhplan planner's setup() does.
        const auto refuse = [&](const std::string &what)
        {
            OMPL_ERROR("%s", what.c_str());
            throw ompl::Exception(what);
        };
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(si.getStateSpace().get());
        if (space == nullptr || space->getDimension() != 2)
            refuse(who + ": the potential field needs a 2D RealVectorStateSpace");
        const ob::StateValidityCheckerPtr &checker = si.getStateValidityChecker();
        if (!checker)
            refuse(who + ": the potential field needs a state validity checker");
        if (checker->getSpecs().clearanceComputationType == ob::StateValidityCheckerSpecs::NONE)
            refuse(who +
                   ": the state validity checker does not compute clearance "
                   "(StateValidityCheckerSpecs::clearanceComputationType == NONE); the potential field's "
                   "obstacle distance d(P) is the checker's clearance(), so it needs a checker that "
                   "reports it (e.g. mhplan::WorldValidityChecker)");
    }

    void PotentialField::configure(const PotentialFieldParameters &params, RepulsionMode mode,
                                   const std::string &who)
    {
        requireClearance(*si_, who);
        params_ = params;
        if (state_ == nullptr)
        {
            state_ = si_->allocState();
            other_ = si_->allocState();
        }
        analytic_ = nullptr;
        model_.reset();
        segmentModel_.reset();
        if (const auto *world =
                dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get()))
            segmentModel_ = world->model();
        usedMode_ = RepulsionMode::Nearest;
        if (mode == RepulsionMode::Sum)
        {
            const auto *checker =
                dynamic_cast<const WorldValidityChecker *>(si_->getStateValidityChecker().get());
            if (checker != nullptr)
            {
                analytic_ = dynamic_cast<const AnalyticCollisionModel *>(checker->model().get());
                if (analytic_ != nullptr)
                {
                    model_ = checker->model();
                    usedMode_ = RepulsionMode::Sum;
                }
            }
            if (usedMode_ != RepulsionMode::Sum)
                OMPL_INFORM(
                    "%s: repulsion 'sum' needs the analytic collision model's obstacle list; this checker "
                    "only reports the nearest obstacle's clearance: using 'nearest'",
                    who.c_str());
        }
        evaluations_ = 0;
    }

    bool PotentialField::segmentFree(const Vec2 &a, const Vec2 &b) const
    {
        if (segmentModel_)
            return segmentModel_->segmentValid(a, b);
        setStatePosition(state_, a);
        setStatePosition(other_, b);
        return si_->satisfiesBounds(other_) && si_->checkMotion(state_, other_);
    }

    double PotentialField::attraction(const Vec2 &p) const
    {
        return 0.5 * params_.attractionGain * squaredNorm(p - goal_);
    }

    double PotentialField::repulsionTerm(double d) const
    {
        if (d > params_.sensingRange)
            return 0.0;
        if (d <= 0.0)
            return std::numeric_limits<double>::infinity();
        return 0.5 * params_.repulsionGain * std::max(0.0, 1.0 / d - 1.0 / params_.influenceDistance);
    }

    double PotentialField::cost(const Vec2 &p) const
    {
        ++evaluations_;
        return usedMode_ == RepulsionMode::Sum ? sumCost(p) : nearestCost(p);
    }

    double PotentialField::nearestCost(const Vec2 &p) const
    {
        setStatePosition(state_, p);
        double d = 0.0;
        // The bounds first: a user's checker is never asked about a state outside them.
        if (!si_->satisfiesBounds(state_) || !si_->getStateValidityChecker()->isValid(state_, d))
            return std::numeric_limits<double>::infinity();
        return attraction(p) + repulsionTerm(d);
    }

    double PotentialField::sumCost(const Vec2 &p) const
    {
        // Exactly the analytic model's clearance, obstacle by obstacle (see AnalyticCollisionModel).
        if (!model_->inBounds(p))
            return std::numeric_limits<double>::infinity();
        const double r = model_->robotRadius();
        const double reach = params_.sensingRange + r;
        double repulsion = 0.0;
        for (const Circle &c : analytic_->circles())
        {
            const double d = distance(p, c.center) - c.radius - r;
            if (d < 0.0)
                return std::numeric_limits<double>::infinity();
            repulsion += repulsionTerm(d);
        }
        for (const Polygon &poly : analytic_->polygons())
        {
            const Box &b = poly.bbox;
            const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax});
            const double dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
            if (dx > reach || dy > reach)
                continue; // the polygon is farther than the box: out of range
            const double d = pointPolygonSignedDistance(p, poly.vertices) - r;
            if (d < 0.0)
                return std::numeric_limits<double>::infinity();
            repulsion += repulsionTerm(d);
        }
        return attraction(p) + repulsion;
    }

    bool walkEndpoints(ob::PlannerInputStates &pis, const std::string &who, Vec2 &start, Vec2 &goal)
    {
        const ob::State *s = pis.nextStart();
        if (s == nullptr)
        {
            OMPL_ERROR("%s: no valid start state", who.c_str());
            return false;
        }
        const ob::State *g = pis.nextGoal();
        if (g == nullptr)
        {
            OMPL_ERROR("%s: no goal state could be sampled", who.c_str());
            return false;
        }
        start = statePosition(s);
        goal = statePosition(g);
        return true;
    }

    bool walkReachGoal(const ob::SpaceInformation &si, ob::State *a, ob::State *b, std::vector<Vec2> &walk,
                       const Vec2 &goal, double tolerance)
    {
        const Vec2 robot = walk.back();
        if (distance(robot, goal) > tolerance)
            return false;
        if (robot != goal)
        {
            setStatePosition(a, robot);
            setStatePosition(b, goal);
            if (!si.checkMotion(a, b))
                return false;
            walk.push_back(goal);
        }
        return true;
    }

    ob::PlannerStatus reportWalk(const ob::SpaceInformationPtr &si, const ob::ProblemDefinitionPtr &pdef,
                                 const std::string &who, const std::vector<Vec2> &walk, bool finished,
                                 bool reachedGoal, const Vec2 &goal, std::atomic<double> &bestCost,
                                 const ob::Planner *planner)
    {
        if (walk.size() < 2 && !finished)
            return ob::PlannerStatus::TIMEOUT;
        auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
        ob::State *s = si->allocState();
        for (const Vec2 &p : walk)
        {
            setStatePosition(s, p);
            path->append(s);
        }
        si->freeState(s);
        bool exact = reachedGoal;
        // Every step passed checkMotion when it was taken; check again so that the report cannot lie.
        for (std::size_t i = 1; exact && i < path->getStateCount(); ++i)
            exact = si->checkMotion(path->getState(i - 1), path->getState(i));
        ob::PlannerSolution solution(path);
        solution.setPlannerName(who);
        const ob::OptimizationObjectivePtr &opt = pdef->getOptimizationObjective();
        if (exact)
        {
            const ob::Cost cost = opt ? path->cost(opt) : ob::Cost(path->length());
            const bool improved = cost.value() < bestCost.load();
            bestCost = cost.value();
            if (planner != nullptr && improved)
                reportImprovement(
                    planner, pdef, *si, walk.size(),
                    [&walk](ob::State *st, std::size_t i) { setStatePosition(st, walk[i]); }, cost);
            if (opt)
                solution.setOptimized(opt, cost, opt->isSatisfied(cost));
        }
        else
            solution.setApproximate(std::max(distance(walk.back(), goal), 1e-12));
        pdef->addSolutionPath(solution);
        return exact ? ob::PlannerStatus::EXACT_SOLUTION : ob::PlannerStatus::APPROXIMATE_SOLUTION;
    }
} // namespace mhplan
