// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/memetic/MemeticPlanner.h"

#include "ompl_planners/common/PlannerSupport.h"
#include "src/base/Parameters.h"
#include "src/collision/Validity.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Exception.h>
#include <ompl/util/String.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <typeinfo>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    void MemeticPlanner::setup()
    {
        ob::Planner::setup();
        const ob::StateSpacePtr &ss = si_->getStateSpace();
        const auto *space = dynamic_cast<const ob::RealVectorStateSpace *>(ss.get());
        if (space == nullptr || space->getDimension() != 2)
        {
            // Any other space: the state mode (docs/spaces.md, "The memetic planners off the plane").
            setupStateMode();
            return;
        }
        stateMode_ = false;
        const ob::RealVectorBounds &b = space->getBounds();
        for (unsigned int j = 0; j < 2; ++j)
            if (!std::isfinite(b.low[j]) || !std::isfinite(b.high[j]) || b.low[j] >= b.high[j])
                refuseSetup("needs finite bounds low < high on both coordinates");
    }

    void MemeticPlanner::clear()
    {
        PlannerBase::clear(); // the PlannerData states, best cost, iterations, evaluations
        clearAlgorithm();
        pop_.clear();
        problemReady_ = false;
        started_ = false;
        haveSolution_ = false;
        bestPath_.clear();
        closest_.clear();
        polished_.clear();
        strictFallback_.clear();
        firstRaw_.clear();
        firstStrict_.clear();
        strictFallbackCost_ = std::numeric_limits<double>::quiet_NaN();
        bestStates_.clear();
        closestStates_.clear();
        polishedStates_.clear();
        perturbStep_ = 0.01;
        level_ = 0;
        noPath_ = false;
        fillCut_ = false;
        walks_ = 0;
        connectFailures_ = 0;
        sinceImprovement_ = 0;
        generationInEpoch_ = 0;
        restarts_ = 0;
        if (toolkit_)
        {
            toolkit_->resetCounts();
            toolkit_->clearCache();
            toolkit_->roadmapClear();
        }
        roadmapSamples_ = kRoadmapSamples;
        roadmapPaths_ = 0;
        roadmapAlive_ = true;
        roadmapStale_ = true;
        denseRoadmap_ = false;
        if (stateToolkit_)
            stateToolkit_->resetCounts();
        stateChecks_ = 0;
        cacheHits_ = 0;
        improvements_ = 0;
        motionChecks_ = 0;
    }

    bool MemeticPlanner::prepareProblem()
    {
        const ob::State *start = nullptr, *goal = nullptr;
        if (!startAndGoal(start, goal))
            return false;
        if (stateMode_)
            return prepareStateProblem(start, goal);
        start_ = statePosition(start);
        goal_ = statePosition(goal);
        const auto &b = si_->getStateSpace()->as<ob::RealVectorStateSpace>()->getBounds();
        const Box box{b.low[0], b.high[0], b.low[1], b.high[1]};
        scale_ = std::max(box.width(), box.height());
        if (!toolkit_)
            toolkit_ = std::make_unique<MemeticToolkit>(si_, rng_);
        toolkit_->setBounds(box);
        toolkit_->setBisections(bisections_);
        const double margin = marginDistance(), spacing = margin > 0.0 ? margin / validatorMargin_ : 0.0;
        toolkit_->setMargin(margin, validatorClearance_ * spacing, validatorMinClearance_ * spacing);
        toolkit_->setFineCheck(spacing, validatorFineStep_ * spacing);
        toolkit_->setFixedPoints(start_, goal_);
        toolkit_->resetCounts();
        toolkit_->clearCache(); // the margin and the fixed points are part of every cached verdict
        toolkit_->roadmapClear();
        seedRng();
        closestDistance_ = std::numeric_limits<double>::infinity();
        closest_ = {start_};
        OMPL_INFORM("%s: seed %lu, N = %u", getName().c_str(),
                    static_cast<unsigned long>(rng_.getLocalSeed()), populationSize_);
        problemReady_ = true;
        return true;
    }

    double MemeticPlanner::pathCost(const MemeticPath &path)
    {
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        if (!opt)
            return MemeticToolkit::length(path);
        ob::Cost c = opt->identityCost();
        ob::State *costA = scratchState(0), *costB = scratchState(1);
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            setStatePosition(costA, path[i - 1]);
            setStatePosition(costB, path[i]);
            c = opt->combineCosts(c, opt->motionCost(costA, costB));
        }
        return c.value();
    }

    bool MemeticPlanner::improves(double cost)
    {
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        const ob::Cost c(cost);
        const bool better =
            !haveSolution_ || (opt ? opt->isCostBetterThan(c, bestCostObj_) : cost < bestCostObj_.value());
        if (!better)
            return false;
        if (haveSolution_ && bestCostObj_.value() - cost <= 1e-12 * std::abs(cost))
            return false; // rounding noise is not an improvement
        haveSolution_ = true;
        bestCostObj_ = c;
        bestCostValue_ = cost;
        ++improvements_;
        publishCounts();
        return true;
    }

    bool MemeticPlanner::improvesOn(double cost) const
    {
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        return !haveSolution_ ||
               (opt ? opt->isCostBetterThan(ob::Cost(cost), bestCostObj_) : cost < bestCostObj_.value());
    }

    void MemeticPlanner::record(const MemeticPath &path, double cost)
    {
        if (!improves(cost))
            return;
        bestPath_ = path;
        reportImprovementOf(
            bestPath_.size(), [this](ob::State *s, std::size_t i) { setStatePosition(s, bestPath_[i]); },
            bestCostObj_);
    }

    double MemeticPlanner::evaluate(const MemeticPath &path, const MemeticPath *raw)
    {
        ++evaluationCount_;
        const double c = pathCost(path);
        if (toolkit_->margin() > 0.0 && !toolkit_->strict() && improvesOn(c))
        {
            // The search runs on the motion validator alone; a path is reported only when it passes the
            // validator margin too (pushed clear of the obstacles it touches; docs/variants.md).
            // A path that cannot be made to pass counts as invalid, so that the search leaves a way round
            // that only the validator's gaps allow.
            MemeticPath q = path;
            if (!strictCopy(q))
            {
                // Tight paths round many corners (a maze) resist the pushes; the path before its local search
                // (raw) is tightened again under the margin instead, which keeps the clearance by
                // construction.
                const bool known = raw != nullptr && !firstStrict_.empty() && *raw == firstRaw_;
                if (known)
                    q = firstStrict_; // finishWalk() tightened the first path so already
                else if (stopRequested() || raw == nullptr || !strictTighten(*raw, q))
                    return stopRequested() ? c : std::numeric_limits<double>::infinity();
                strictFallback_ = q;
                strictFallbackCost_ = c;
            }
            record(q, pathCost(q));
            return c;
        }
        record(path, c);
        return c;
    }

    bool MemeticPlanner::strictCopy(MemeticPath &path)
    {
        const MemeticPath loose = path;
        std::size_t refused = 0;
        if (toolkit_->makeStrict(path, stop_, &refused))
            return true;
        // A tightened path threads gaps with segments that touch an obstacle on each side (an inner tangent
        // between two discs): the margin finds obstacles on both sides and cannot tell which way to push.
        // Halved, each segment touches one obstacle, and its ends are pushed away from it (docs/variants.md,
        // "Checks"); without this retry the way through the gap counted as invalid. The retry mends a few
        // such segments; where many stay refused (a loose path through a maze's diagonal pinches, which no
        // push undoes) it never succeeded, and it cost as much again (docs/variants.md).
        if (stopRequested() || refused > kHalvingMostRefused)
            return false;
        path.clear();
        path.push_back(loose.front());
        for (std::size_t i = 1; i < loose.size(); ++i)
        {
            // A midpoint inside an obstacle (the loose segment crosses a corner between the validator's
            // samples) would make both halves motions the validator refuses: that segment stays whole, and
            // the margin's rounds mend it beside the crossing.
            const Vec2 mid = (loose[i - 1] + loose[i]) * 0.5;
            if (toolkit_->pointValid(mid))
                path.push_back(mid);
            path.push_back(loose[i]);
        }
        return toolkit_->makeStrict(path, stop_);
    }

    bool MemeticPlanner::strictTighten(const MemeticPath &raw, MemeticPath &out)
    {
        out = raw;
        if (!strictCopy(out))
            return false;
        const MemeticToolkit::StrictScope strict(*toolkit_);
        // Coarse pull steps (kRetryBisections halvings of each move instead of bisections): this retry has
        // only to bring the path near its class's tight path under the margin, which the elite polish then
        // tightens precisely; every strict verdict of a move costs the margin's close checks
        // (docs/variants.md).
        // Restored however tighten() ends (a user's checker may throw out of it).
        struct BisectionsRestore
        {
            MemeticToolkit &toolkit;
            unsigned int bisections;
            ~BisectionsRestore() { toolkit.setBisections(bisections); }
        } restore{*toolkit_, bisections_};
        toolkit_->setBisections(std::min(bisections_, kRetryBisections));
        // Each pass's path is reported as soon as it passes the fine check too (a millisecond against a
        // pass's tens on a maze): the retry's first passes already bring it within a percent or so.
        toolkit_->tighten(out, coarseTurn_, 1e-4, 30, stop_, 4000, false,
                          [this](const MemeticPath &pass)
                          {
                              if (!improvesOn(pathCost(pass)))
                                  return;
                              MemeticPath q = pass;
                              if (toolkit_->makeStrict(q, stop_))
                                  record(q, pathCost(q));
                          });
        // The margin and the fine check, as every reported path (docs/variants.md, "The fine check").
        return !stopRequested() && toolkit_->makeStrict(out, stop_);
    }

    bool MemeticPlanner::improveAndEvaluate(Individual &ind)
    {
        if (stateMode_)
            return improveAndEvaluateStates(ind);
        MemeticPath p = ind.path;
        toolkit_->tighten(p, coarseTurn_, 1e-4, 30, stop_);
        if (stopRequested())
            return false;
        ind.path.swap(p);
        // Every operator checks the segments it makes; this pass guards the joints on split segments under a
        // sampling motion validator (which may refuse a piece of a segment it accepted).
        if (!toolkit_->pathValid(ind.path))
        {
            ind.cost = std::numeric_limits<double>::infinity();
            MemeticToolkit::resample(ind.path, 16, ind.signature);
            return true;
        }
        ind.cost = evaluate(ind.path, &p);
        MemeticToolkit::resample(ind.path, 16, ind.signature);
        return true;
    }

    MemeticToolkit::WalkResult MemeticPlanner::walk(MemeticPath &path, const Vec2 &from, const Vec2 &to,
                                                    double noise, double weight)
    {
        while (true)
        {
            // Powers of two (in the space's units): the levels nest, and they align with grid maps whose
            // cells are a power of two wide (1 m, 0.5 m, ...) when the start is at a cell centre.
            const double h = std::pow(2.0, std::floor(std::log2(scale_ / 16.0)) - double(level_));
            const MemeticToolkit::WalkResult r = toolkit_->randomWalk(
                path, from, to, h, noise, walkExpansions_, stop_, closest_, closestDistance_, weight);
            if (r != MemeticToolkit::WalkResult::Exhausted)
                return r;
            if (level_ + 1 >= latticeLevels_)
                return r;
            ++level_;
        }
    }

    bool MemeticPlanner::walkIndividual(Individual &out)
    {
        if (noPath_)
            return false;
        if (stateMode_)
            return walkStateIndividual(out);
        if (roadmapIndividual(out))
            return finishWalk(out);
        if (stopRequested())
            return false;
        const double noise = walks_ == 0 ? 0.0 : rng_.uniformReal(0.0, walkNoise_);
        const Box &box = toolkit_->bounds();
        toolkit_->randomiseField(std::hypot(box.width(), box.height()));
        // Every other walk after the first passes a random via point (valid, within the box around start and
        // goal widened by half their distance): a different homotopy class by construction.
        bool viaWalk = walks_ > 0 && rng_.uniform01() < 0.5;
        ++walks_;
        Vec2 via;
        if (viaWalk)
        {
            // Near the straight line: along it uniformly, off it by up to 0.3 of the start-goal distance.
            viaWalk = false;
            const Vec2 line = goal_ - start_;
            const double d = norm(line);
            const Vec2 normal = d > 0.0 ? Vec2(-line.y / d, line.x / d) : Vec2(0.0, 1.0);
            for (int k = 0; k < 20 && !viaWalk; ++k)
            {
                via =
                    start_ + line * rng_.uniformReal(0.15, 0.85) + normal * (d * rng_.uniformReal(-0.3, 0.3));
                viaWalk = toolkit_->pointValid(via);
            }
        }
        MemeticToolkit::WalkResult r;
        if (viaWalk)
        {
            MemeticPath second;
            const double keepDistance = closestDistance_;
            r = walk(out.path, start_, via, noise, walkWeight_);
            closestDistance_ = keepDistance; // the approximate solution is about the goal, not the via point
            if (r == MemeticToolkit::WalkResult::Found)
            {
                r = walk(second, via, goal_, noise, walkWeight_);
                if (r == MemeticToolkit::WalkResult::Found)
                    out.path.insert(out.path.end(), second.begin() + 1, second.end());
            }
            if (r == MemeticToolkit::WalkResult::Exhausted)
                r = MemeticToolkit::WalkResult::Budget; // the via point may be enclosed: not a verdict
        }
        else
        {
            r = walk(out.path, start_, goal_, noise, walkWeight_);
            if (r == MemeticToolkit::WalkResult::Exhausted)
            {
                noPath_ = true;
                OMPL_INFORM("%s: no walk reaches the goal at the finest lattice step", getName().c_str());
            }
        }
        if (r != MemeticToolkit::WalkResult::Found)
            return false;
        return finishWalk(out);
    }

    double MemeticPlanner::informedBound() const
    {
        // Path length only: then no path through q is shorter than |start q| + |q goal| (docs/variants.md).
        // The planar roadmap measures |start q| in the plane: only where the space's distance is the plane's
        // (a RealVectorStateSpace itself; a user's subclass may count otherwise, e.g. cells of a map). The
        // state mode measures with the space's own distance, the objective's.
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        const bool length =
            !opt || dynamic_cast<const ob::PathLengthOptimizationObjective *>(opt.get()) != nullptr;
        const ob::StateSpace &space = *si_->getStateSpace();
        const bool euclidean = stateMode_ || typeid(space) == typeid(ob::RealVectorStateSpace);
        return length && euclidean && haveSolution_ ? bestCostObj_.value()
                                                    : std::numeric_limits<double>::infinity();
    }

    bool MemeticPlanner::roadmapIndividual(Individual &out)
    {
        // First paths from a lazy roadmap (docs/variants.md, "First paths: a lazy roadmap"): up to 2 N
        // routes per (re)start, each another way round (penalties); the lattice walks take over when the
        // roadmap has no route, and the next epoch's roadmap has twice the samples. The very first route
        // comes from a small roadmap (kRoadmapFirst samples, a few milliseconds); then the roadmap grows to
        // roadmapSamples_ new samples inside the first path's informed set.
        const RoadmapStep step = nextRoadmapRoute(
            toolkit_->roadmapSize() == 0, kRoadmapFirst, roadmapSamples_,
            [&](unsigned int samples)
            {
                toolkit_->roadmapGrow(samples, start_, goal_, informedBound());
                return true;
            },
            [&](unsigned int maxInvalid) { return toolkit_->roadmapPath(out.path, maxInvalid, stop_); }, 100);
        if (step == RoadmapStep::GaveUp)
            roadmapSamples_ = std::min(kRoadmapMaxSamples, 2 * roadmapSamples_);
        return step == RoadmapStep::Route;
    }

    MemeticPlanner::RoadmapStep
    MemeticPlanner::nextRoadmapRoute(bool first, unsigned int firstSamples, unsigned int samples,
                                     const std::function<bool(unsigned int)> &grow,
                                     const std::function<bool(unsigned int)> &route,
                                     unsigned int fullRefusals)
    {
        if (!roadmapAlive_ || roadmapPaths_ >= 2 * populationSize_)
            return RoadmapStep::None;
        if (roadmapStale_)
        {
            if (!grow(first ? firstSamples : samples))
                return RoadmapStep::None;
            roadmapStale_ = false;
            smallRoadmap_ = first;
        }
        // Refused routes before the roadmap is given up (a roadmap cut in two refuses route after route).
        if (route(smallRoadmap_ ? 20 : fullRefusals))
        {
            ++roadmapPaths_;
            ++walks_;
            if (smallRoadmap_)
                roadmapStale_ = true; // the next route from the full roadmap
            return RoadmapStep::Route;
        }
        if (stopRequested())
            return RoadmapStep::None;
        if (smallRoadmap_)
        {
            // The small roadmap had no route (cluttered worlds): another way this time, the full roadmap
            // next.
            roadmapStale_ = true;
            smallRoadmap_ = false;
            return RoadmapStep::None;
        }
        roadmapAlive_ = false;
        return RoadmapStep::GaveUp;
    }

    bool MemeticPlanner::finishWalk(Individual &out)
    {
        if (!haveSolution_ && toolkit_->pathValid(out.path))
        {
            // The first path is reported at once: on huge worlds its local search takes a while.
            if (stopRequested())
                return false;
            evaluate(out.path);
            // Under the validator margin the first path is tightened under it at once, each pass reported
            // (strictTighten): where the loose local search then cuts what no push undoes (a maze's pinches)
            // this is the way to 1 % (docs/variants.md), and the loose search and the failed pushes came
            // first.
            MemeticPath q;
            if (toolkit_->margin() > 0.0 && !stopRequested() && strictTighten(out.path, q))
            {
                firstRaw_ = out.path;
                firstStrict_ = q;
                record(q, pathCost(q));
            }
        }
        return improveAndEvaluate(out) && std::isfinite(out.cost);
    }

    std::size_t MemeticPlanner::bestIndex() const
    {
        std::size_t best = 0;
        for (std::size_t i = 1; i < pop_.size(); ++i)
            if (pop_[i].cost < pop_[best].cost)
                best = i;
        return best;
    }

    double MemeticPlanner::signatureDistance(const Individual &a, const Individual &b)
    {
        double d = 0.0;
        for (std::size_t k = 0; k < a.signature.size() && k < b.signature.size(); ++k)
            d = std::max(d, distance(a.signature[k], b.signature[k]));
        return d;
    }

    bool MemeticPlanner::crowdingInsert(Individual &child)
    {
        if (pop_.empty())
            return false;
        std::size_t nearest = 0;
        double dn = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < pop_.size(); ++i)
        {
            const double d =
                stateMode_ ? stateSignatureDistance(child, pop_[i]) : signatureDistance(child, pop_[i]);
            if (d < dn)
            {
                dn = d;
                nearest = i;
            }
        }
        if (child.cost < pop_[nearest].cost)
        {
            std::swap(pop_[nearest], child);
            return true;
        }
        return false;
    }

    bool MemeticPlanner::fillPopulation()
    {
        const unsigned long startChecks = motionCheckTotal();
        while (pop_.size() < populationSize_ && !noPath_)
        {
            if (stopRequested())
                return false;
            // Huge worlds: start with what there is once the walks have cost kFillBudget motion checks
            // (deterministic, unlike a clock); the rest joins one per generation.
            if (pop_.size() >= 2 && motionCheckTotal() - startChecks > kFillBudget)
            {
                fillCut_ = true;
                return true;
            }
            Individual ind;
            if (walkIndividual(ind))
                // No polish before the population is complete: the roadmap's routes come in other homotopy
                // classes within milliseconds, each coarsely tightened to a fraction of a percent of its
                // class's optimum, while a polish of the first path (in whatever class it took) under the
                // validator margin cost a hundred times as much (docs/variants.md, "Checks").
                pop_.push_back(std::move(ind));
            else if (stopRequested())
                return false;
            else if (pop_.empty() || noPath_)
                return !noPath_ && !pop_.empty(); // try again next generation
        }
        return !pop_.empty();
    }

    bool MemeticPlanner::readyToStart() const
    {
        return pop_.size() == populationSize_ || (pop_.size() >= 2 && fillCut_) || (!pop_.empty() && noPath_);
    }

    void MemeticPlanner::polishElite()
    {
        if (pop_.empty())
            return;
        if (stateMode_)
        {
            polishEliteStates();
            return;
        }
        const std::size_t b = bestIndex();
        if (polished_.empty() || pop_[b].cost < polishedSource_)
        {
            // A new best individual: polish it from now on (its coarse version stays in the population),
            // under the validator margin (docs/variants.md), once it has been pushed clear of it.
            MemeticPath q = pop_[b].path;
            polishedSource_ = pop_[b].cost;
            if (strictCopy(q))
                polished_.swap(q);
            else if (!stopRequested() && pop_[b].cost == strictFallbackCost_ && !strictFallback_.empty())
                polished_ = strictFallback_; // evaluate() tightened its raw path under the margin
            else if (!stopRequested())
                pop_[b].cost = std::numeric_limits<double>::infinity(); // as an invalid path
        }
        if (polished_.empty())
            return;
        MemeticPath p = polished_;
        const MemeticToolkit::StrictScope strict(*toolkit_);
        toolkit_->tighten(p, fineTurn_, 1e-10, polishPasses_, stop_, 20000, true);
        if (stopRequested() || !toolkit_->makeStrict(p, stop_)) // the margin, and the fine check
            return;
        polished_.swap(p);
        evaluate(polished_);
    }

    void MemeticPlanner::eliteRewalks()
    {
        if (stateMode_)
        {
            eliteReconnects();
            return;
        }
        // First the tube reroutes (docs/variants.md): a roadmap drawn within a random radius of the best path
        // (1-6 % of its length) routes the tube's shortest way, in whatever class (a class a few obstacles
        // off the best one, beside it, not round a different side of the world); then the re-walks of a
        // piece. Either child gets the coarse local search and replaces the best individual when shorter.
        for (const bool tube : {true, false})
            for (unsigned int k = 0; k < (tube ? tubeReroutes_ : eliteRewalks_) && !pop_.empty(); ++k)
            {
                if (stopRequested())
                    return;
                const std::size_t b = bestIndex();
                Individual child;
                bool made;
                if (tube)
                {
                    const double radius = MemeticToolkit::length(pop_[b].path) * rng_.uniformReal(0.01, 0.06);
                    made = toolkit_->tubeRoute(pop_[b].path, radius, kTubeSamples, 200, child.path, stop_);
                }
                else
                {
                    child.path = pop_[b].path;
                    made = toolkit_->rewalk(child.path, 0.3, walkNoise_, 4000, stop_);
                }
                if (!made)
                    continue;
                if (!improveAndEvaluate(child))
                    return;
                if (child.cost < pop_[b].cost)
                {
                    pop_[b] = std::move(child);
                    populationChanged();
                }
            }
    }

    void MemeticPlanner::restart()
    {
        ++restarts_;
        const std::size_t b = bestIndex();
        Individual elite = pop_[b];
        pop_.clear();
        pop_.push_back(std::move(elite));
        sinceImprovement_ = 0;
        generationInEpoch_ = 0;
        // Restarts with memory: the next roadmap keeps the samples inside the incumbent's informed set and
        // adds twice as many as the last epoch drew.
        roadmapPaths_ = 0;
        roadmapAlive_ = true;
        roadmapStale_ = true;
        roadmapSamples_ = std::min(kRoadmapMaxSamples, 2 * roadmapSamples_);
    }

    ob::PlannerStatus MemeticPlanner::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        if (!problemReady_ && !prepareProblem())
            return inputFailure(); // INVALID_START or INVALID_GOAL
        ptc_ = &ptc;
        unsigned int done = 0;
        const ob::OptimizationObjectivePtr &opt = pdef_->getOptimizationObjective();
        auto satisfied = [&] { return haveSolution_ && opt && opt->isSatisfied(bestCostObj_); };
        if (!ptc())
        {
            fillPopulation();
            if (!started_ && readyToStart())
            {
                started_ = true;
                startAlgorithm();
            }
        }
        while (!ptc() && !satisfied() && (maxIterations_ == 0 || done < maxIterations_))
        {
            bool completed = true;
            const double before =
                haveSolution_ ? bestCostObj_.value() : std::numeric_limits<double>::infinity();
            if (!started_)
            {
                // The population is not ready yet (no path found so far, or interrupted): walk on.
                fillPopulation();
                polishElite();
                if (readyToStart())
                {
                    started_ = true;
                    startAlgorithm();
                }
            }
            else
            {
                ++generationInEpoch_;
                // The polish first: on huge worlds a generation may take long, the incumbent still improves.
                polishElite();
                eliteRewalks();
                if (pop_.size() < populationSize_ && !noPath_ && !stopRequested())
                {
                    Individual ind;
                    if (walkIndividual(ind))
                    {
                        pop_.push_back(std::move(ind));
                        populationChanged();
                    }
                }
                completed = !stopRequested() && generation(generationInEpoch_);
            }
            if (stopRequested())
                completed = false;
            if (!completed)
                break;
            ++iterationCount_;
            ++done;
            const double after =
                haveSolution_ ? bestCostObj_.value() : std::numeric_limits<double>::infinity();
            if (std::isfinite(before) && after < before - 1e-9 * before)
                sinceImprovement_ = 0;
            else
                ++sinceImprovement_;
            // 0 = auto: 3 generations in the planar mode, whose restarts rebuild a denser informed roadmap
            // (docs/variants.md), 40 in the state mode, whose restarts refill with walks.
            const unsigned int stagnation = stagnation_ != 0 ? stagnation_ : (stateMode_ ? 40u : 3u);
            if (started_ && sinceImprovement_ >= stagnation && !noPath_)
            {
                restart();
                fillCut_ = false;
                if (!fillPopulation() || !readyToStart())
                    started_ = false;
                else
                    restartAlgorithm();
            }
            publishCounts();
        }
        ptc_ = nullptr;
        publishCounts();
        bool exact = false, approximate = false;
        reportSolution(exact, approximate);
        OMPL_INFORM("%s: %lu generations, %lu evaluations, %lu motion checks, %lu restarts, best cost %s",
                    getName().c_str(), iterationCount(), evaluationCount(), motionCheckCount(), restarts_,
                    ompl::toString(bestCost()).c_str());
        if (exact)
            return ob::PlannerStatus::EXACT_SOLUTION;
        if (approximate)
            return ob::PlannerStatus::APPROXIMATE_SOLUTION;
        return ob::PlannerStatus::TIMEOUT;
    }

    unsigned long MemeticPlanner::motionCheckTotal() const
    {
        if (stateMode_)
            return stateToolkit_ ? stateToolkit_->motionChecks() : 0;
        return toolkit_ ? toolkit_->motionChecks() : 0;
    }

    void MemeticPlanner::publishCounts()
    {
        motionChecks_ = motionCheckTotal();
        if (!stateMode_ && toolkit_)
            cacheHits_ = toolkit_->cacheHits();
        if (stateMode_ && stateToolkit_)
        {
            stateChecks_ = stateToolkit_->stateChecks();
            cacheHits_ = stateToolkit_->cacheHits();
        }
    }

    void MemeticPlanner::reportSolution(bool &exact, bool &approximate)
    {
        exact = approximate = false;
        if (stateMode_)
        {
            reportStateSolution(exact, approximate);
            return;
        }
        const MemeticPath *points = haveSolution_ ? &bestPath_ : nullptr;
        if (points == nullptr && closest_.size() >= 1 && std::isfinite(closestDistance_))
            points = &closest_;
        if (points == nullptr)
            return;
        exact = haveSolution_;
        approximate = !exact;
        double difference = closestDistance_;
        MemeticPath prefix;
        if (approximate && toolkit_->margin() > 0.0)
        {
            // The approximate path passes what the reported exact ones pass (docs/variants.md).
            prefix = closest_;
            toolkit_->makeReportablePrefix(prefix);
            points = &prefix;
            difference = distance(prefix.back(), goal_);
        }
        addSolutionPath(
            points->size(), [points](ob::State *s, std::size_t i) { setStatePosition(s, (*points)[i]); },
            exact, bestCostObj_, difference);
    }

    void MemeticPlanner::getPlannerData(ob::PlannerData &data) const
    {
        if (stateMode_)
        {
            const StatePath &states = haveSolution_ ? bestStates_ : closestStates_;
            pathToPlannerData(
                data, states.size(), [&](ob::State *s, std::size_t i) { fillState(s, states[i]); },
                haveSolution_);
            return;
        }
        const MemeticPath &points = haveSolution_ ? bestPath_ : closest_;
        pathToPlannerData(
            data, points.size(), [&points](ob::State *s, std::size_t i) { setStatePosition(s, points[i]); },
            haveSolution_);
    }
} // namespace mhplan
