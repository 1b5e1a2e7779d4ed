// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the state mode of the memetic planners (docs/spaces.md, "The memetic planners off the plane"):
   MemeticPlanner on any state space with a StateParametrisation. */
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "ompl_planners/memetic/CarBounds.h"

#include "ompl_planners/common/PlannerSupport.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief Tree states of one connection of the walks (start to goal, or through a via state). */
        constexpr unsigned int kConnectNodes = 5000;
        /** \brief Tree states of one re-connect of a piece (mutation, elite re-connects). */
        constexpr unsigned int kReconnectNodes = 2000;
        /** \brief Samples of the first, small roadmap on states, the most one epoch's full roadmap draws,
            and the dense roadmap's, drawn once a full one gave up (the k-nearest search is quadratic in the
            samples: where a check is cheap and the distance dear, as on the car spaces, it would cost more
            than the checks). */
        constexpr unsigned int kStateRoadmapFirst = 200;
        constexpr unsigned int kStateRoadmapMax = 2000;
        constexpr unsigned int kStateRoadmapDense = 8000;
        /** \brief Refused routes before the dense roadmap is given up (100 for a sparser one, as in the
            plane). A refusal costs one motion check of a nearest neighbour's edge. */
        constexpr unsigned int kStateRoadmapRefusals = 1000;
        /** \brief Coarse passes of the local search of the first individual (10 for the others). */
        constexpr unsigned int kFirstCoarsePasses = 1;
    } // namespace

    unsigned int lubyTerm(unsigned long i)
    {
        // Term i >= 1 of 1, 1, 2, 1, 1, 2, 4, 1, 1, 2, 1, 1, 2, 4, 8, ...: 2^(k-1) where i = 2^k - 1, else
        // the term at i - 2^(k-1) + 1 for the k with 2^(k-1) <= i < 2^k - 1.
        for (;;)
        {
            unsigned int k = 1;
            while ((1ul << k) - 1 < i)
                ++k;
            if (i == (1ul << k) - 1)
                return 1u << (k - 1);
            i -= (1ul << (k - 1)) - 1;
        }
    }

    void MemeticPlanner::setupStateMode()
    {
        std::string why;
        std::unique_ptr<StateParametrisation> param = StateParametrisation::create(si_->getStateSpace(), why);
        if (!param)
            refuseSetup("cannot plan on the state space '" + si_->getStateSpace()->getName() + "': " + why +
                        " (supported: " + StateParametrisation::supportedSpaces() + ")");
        // A new parametrisation (the space's bounds may have changed): the search starts over.
        stateToolkit_.reset();
        param_ = std::move(param);
        stateMode_ = true;
        problemReady_ = false;
        clear();
    }

    void MemeticPlanner::fillState(ob::State *s, const StatePoint &p) const
    {
        param_->fromVector(p.data(), s);
    }

    bool MemeticPlanner::prepareStateProblem(const ob::State *start, const ob::State *goal)
    {
        param_->setReference(start);
        if (!stateToolkit_)
            stateToolkit_ = std::make_unique<MemeticStateToolkit>(si_, *param_, rng_);
        stateToolkit_->setObjective(pdef_->getOptimizationObjective());
        stateToolkit_->setBisections(bisections_);
        const double margin = marginDistance(), spacing = margin > 0.0 ? margin / validatorMargin_ : 0.0;
        stateToolkit_->setMargin(margin);
        stateToolkit_->setFineSpacing(validatorStateStep_ * spacing);
        stateToolkit_->resetCounts();
        stateToolkit_->fromState(start, startState_);
        stateToolkit_->fromState(goal, goalState_);
        // The scale of the offsets (OffsetMemeticPlanner): the largest coordinate range.
        scale_ = 0.0;
        for (unsigned int j = 0; j < param_->dimension(); ++j)
            scale_ = std::max(scale_, param_->upper(j) - param_->lower(j));
        if (!(scale_ > 0.0))
            scale_ = 1.0;
        seedRng();
        closestDistance_ = std::numeric_limits<double>::infinity();
        closestStates_ = {startState_};
        OMPL_INFORM("%s: seed %lu, N = %u, state mode on '%s'", getName().c_str(),
                    static_cast<unsigned long>(rng_.getLocalSeed()), populationSize_,
                    si_->getStateSpace()->getName().c_str());
        problemReady_ = true;
        return true;
    }

    double MemeticPlanner::evaluate(const StatePath &path)
    {
        // A path counts (and is recorded) only when the motion validator accepts every motion as it stands
        // (cached verdicts: nearly free). An operator's path may keep a piece of a motion the validator
        // accepted whole (the offset planners' way back along the reference from one of its resampled
        // states, a coarse pass's report before the pass's last check), and a sampling validator may refuse
        // the piece: such a path was reported, and OMPL's PathGeometric::check() refused it
        // (tests/test_memetic_spaces.cpp, OnOmplsOwnDubinsSpaceAsAUserBuildsIt).
        if (!stateToolkit_->pathValid(path))
            return std::numeric_limits<double>::infinity();
        ++evaluationCount_;
        const double c = stateToolkit_->cost(path);
        if (!improvesOn(c))
            return c;
        const StatePath *reported = &path;
        StatePath strict;
        if (stateToolkit_->strictNeeded())
        {
            // A sampling validator: a path is reported only when it passes the fine check (mended where it
            // does not); one that cannot be mended counts as invalid (docs/spaces.md).
            strict = path;
            if (!stateToolkit_->makeStrict(strict, stop_))
            {
                if (stopRequested())
                    return c;
                // No path yet and one the fine check refuses: from now on the roadmap's routes pass it too
                // (docs/spaces.md; OMPL.app's RandomPolygons: a robot inside a polygon touches no triangle,
                // so the validator's samples pass through the polygons and every route failed the fine
                // check).
                if (!haveSolution_)
                    stateToolkit_->setStrictRoutes(true);
                return std::numeric_limits<double>::infinity();
            }
            reported = &strict;
        }
        if (improves(reported == &path ? c : stateToolkit_->cost(*reported)))
        {
            bestStates_ = *reported;
            reportImprovementOf(
                bestStates_.size(), [this](ob::State *s, std::size_t i) { fillState(s, bestStates_[i]); },
                bestCostObj_);
        }
        return c;
    }

    double MemeticPlanner::stateSignatureDistance(const Individual &a, const Individual &b)
    {
        double d = 0.0;
        for (std::size_t k = 0; k < a.stateSignature.size() && k < b.stateSignature.size(); ++k)
            d = std::max(d, stateToolkit_->distance(a.stateSignature[k], b.stateSignature[k]));
        return d;
    }

    bool MemeticPlanner::improveAndEvaluateStates(Individual &ind)
    {
        MemeticStateToolkit &tk = *stateToolkit_;
        StatePath p = ind.states;
        // Coarse: at most 10 passes of 6 bisection steps (the polish refines the best path), 1 for the first
        // individual (the population empty): where checks are dear its passes held back the walks of other
        // classes (OMPL.app's Barriers: 10 passes of the first path took 2-3 s of 5, 3 passes 1-2 s,
        // docs/spaces.md).
        // Anytime: a pass that makes the path cheaper than the best is reported at once (docs/spaces.md: with
        // a mesh checker on OMPL.app's problems one coarse search of a long first path takes many seconds).
        // The last pass whose path evaluated as valid is kept: a later one the fine check cannot mend would
        // otherwise cost the individual and all its passes (OMPL.app's Barriers: 2.8 s of passes lost so).
        StatePath lastValid;
        double lastValidCost = std::numeric_limits<double>::infinity();
        const MemeticStateToolkit::PassReport report = [&](const StatePath &q, double cost)
        {
            if (improvesOn(cost) && std::isfinite(evaluate(q)))
            {
                lastValid = q;
                lastValidCost = cost;
            }
        };
        tk.tighten(p, coarseTurn_, 1e-3, pop_.empty() ? kFirstCoarsePasses : 10, stop_, 2000, false, report);
        if (stopRequested())
            return false;
        ind.states.swap(p);
        // Infinite when the validator refuses a motion (evaluate(): a piece of a motion it accepted whole) or
        // when the path would improve on the best and the fine check cannot mend it.
        ind.cost = evaluate(ind.states);
        if (!std::isfinite(ind.cost) && !lastValid.empty())
        {
            ind.states.swap(lastValid); // evaluated (and counted) when its pass reported it
            ind.cost = lastValidCost;
        }
        tk.resample(ind.states, 16, ind.stateSignature, nullptr);
        return true;
    }

    bool MemeticPlanner::roadmapStateIndividual(Individual &out)
    {
        // As the planar mode's roadmap (docs/spaces.md, "First paths: a lazy roadmap on states"): up to 2 N
        // routes per (re)start; the first from a small roadmap, the next from the full one, drawn inside the
        // incumbent's informed set; the connections take over when it has no route. A full roadmap that gives
        // up is followed at once by a dense one (kStateRoadmapDense new states, given up after
        // kStateRoadmapRefusals refused routes): OMPL.app's Barriers (a big robot that must turn between the
        // barriers) has no route among 1,500 states, and its connections' paths took the long way.
        MemeticStateToolkit &tk = *stateToolkit_;
        while (true)
        {
            const unsigned int samples =
                denseRoadmap_ ? kStateRoadmapDense : std::min(roadmapSamples_, kStateRoadmapMax);
            // Ten times the refused routes while there is no path and routes must pass the fine check
            // (setStrictRoutes): where the validator sees through the obstacles most routes cross one, and
            // each refusal removes only the edges that do (OMPL.app's RandomPolygons: 100 were used up before
            // a route went round them). Not once a path is known: on Barriers, whose checks are dear, the
            // refusals' fine checks then held back the dense roadmap (seed 1: 712 -> 1,067 at 5 s).
            const RoadmapStep step = nextRoadmapRoute(
                tk.roadmapSize() == 0, kStateRoadmapFirst, samples,
                [&](unsigned int n)
                { return tk.roadmapGrow(n, startState_, goalState_, informedBound(), stop_); },
                [&](unsigned int maxInvalid) { return tk.roadmapPath(out.states, maxInvalid, stop_); },
                (denseRoadmap_ ? kStateRoadmapRefusals : 100) *
                    (tk.strictRoutes() && !haveSolution_ ? 10 : 1));
            // Not on the car spaces: their distance (a Dubins or Reeds-Shepp word per pair) makes a dense
            // roadmap's k-nearest search cost more than its checks save (docs/spaces.md).
            if (step != RoadmapStep::GaveUp || denseRoadmap_ || stopRequested() ||
                CarBounds(si_->getStateSpace().get()).active())
                return step == RoadmapStep::Route;
            denseRoadmap_ = true;
            roadmapAlive_ = true;
            roadmapStale_ = true;
        }
    }

    bool MemeticPlanner::walkStateIndividual(Individual &out)
    {
        if (!roadmapStateIndividual(out))
        {
            if (stopRequested() || !connectStateIndividual(out))
                return false;
        }
        if (!haveSolution_ || improvesOn(stateToolkit_->cost(out.states)))
        {
            // The first path, and a walk's path that improves on the best, is reported at once, before its
            // local search (evaluate() checks its motions): where checks are dear the search's first pass
            // may not end within the budget (OMPL.app's Barriers: the dense roadmap's first route, 2.0 times
            // shorter than the best, was lost so at 5 s).
            if (stopRequested())
                return false;
            evaluate(out.states);
        }
        return improveAndEvaluateStates(out) && std::isfinite(out.cost);
    }

    bool MemeticPlanner::connectStateIndividual(Individual &out)
    {
        MemeticStateToolkit &tk = *stateToolkit_;
        const double range = 0.2 * tk.extent();
        const MemeticStateToolkit::Sampler uniform = [&tk](StatePoint &x) { return tk.sampleUniform(x); };
        // Once a path is known, every other connection passes a valid state drawn uniformly: another
        // homotopy class by construction. Not before: the two connections of such a walk have half the
        // budget each, and one of them must still find the passage (docs/spaces.md, "Budgets").
        bool viaWalk = haveSolution_ && rng_.uniform01() < 0.5;
        ++walks_;
        StatePoint via;
        if (viaWalk)
        {
            viaWalk = false;
            for (int k = 0; k < 20 && !viaWalk; ++k)
                viaWalk = tk.sampleUniform(via) && tk.pointValid(via);
        }
        // The budgets of connections that run out of states follow Luby's universal restart sequence (1, 1,
        // 2, 1, 1, 2, 4, ... times 5,000 states, at most 16 times): restarts suit a wall with a small hole,
        // large trees a long narrow passage (docs/spaces.md), and the sequence stays within a logarithmic
        // factor of the best fixed budget for either without knowing which it faces.
        const unsigned int nodes = kConnectNodes * std::min(lubyTerm(connectFailures_ + 1), 16u);
        MemeticStateToolkit::ConnectResult r;
        if (viaWalk)
        {
            StatePath second;
            r = tk.connect(out.states, startState_, via, range, nodes / 2, uniform, stop_);
            if (r == MemeticStateToolkit::ConnectResult::Found)
            {
                r = tk.connect(second, via, goalState_, range, nodes / 2, uniform, stop_, &closestStates_,
                               &closestDistance_);
                if (r == MemeticStateToolkit::ConnectResult::Found)
                    out.states.insert(out.states.end(), second.begin() + 1, second.end());
            }
        }
        else
            r = tk.connect(out.states, startState_, goalState_, range, nodes, uniform, stop_, &closestStates_,
                           &closestDistance_);
        if (r == MemeticStateToolkit::ConnectResult::Budget)
            ++connectFailures_;
        return r == MemeticStateToolkit::ConnectResult::Found;
    }

    void MemeticPlanner::polishEliteStates()
    {
        MemeticStateToolkit &tk = *stateToolkit_;
        const std::size_t b = bestIndex();
        if (polishedStates_.empty() || pop_[b].cost < polishedSource_)
        {
            polishedStates_ = pop_[b].states;
            polishedSource_ = pop_[b].cost;
        }
        StatePath p = polishedStates_;
        tk.tighten(p, fineTurn_, 1e-10, polishPasses_, stop_, 4000, true);
        // Then a random local search of the waypoints (cost first, docs/spaces.md): it moves headings and
        // positions together where the pull moves' straight-line moves in the parametrisation stall (the car
        // spaces).
        if (!stopRequested())
            tk.perturb(p, perturbStep_, 3, stop_);
        if (stopRequested() || !tk.pathValid(p))
            return;
        polishedStates_.swap(p);
        evaluate(polishedStates_);
    }

    void MemeticPlanner::eliteReconnects()
    {
        for (unsigned int k = 0; k < eliteRewalks_ && !pop_.empty(); ++k)
        {
            if (stopRequested())
                return;
            const std::size_t b = bestIndex();
            Individual child;
            child.states = pop_[b].states;
            if (!stateToolkit_->reconnect(child.states, 0.3, kReconnectNodes, stop_))
                continue;
            if (!improveAndEvaluateStates(child))
                return;
            if (child.cost < pop_[b].cost)
            {
                pop_[b] = std::move(child);
                populationChanged();
            }
        }
    }

    void MemeticPlanner::reportStateSolution(bool &exact, bool &approximate)
    {
        const StatePath *states = haveSolution_ ? &bestStates_ : nullptr;
        std::size_t count = haveSolution_ ? bestStates_.size() : 0;
        if (states == nullptr && !closestStates_.empty() && std::isfinite(closestDistance_))
        {
            // The connections' tree path passed the validator only: it is reported as far as it passes the
            // fine check too (docs/spaces.md, "Margin"); addSolutionPath then cuts it at its state nearest
            // the goal.
            states = &closestStates_;
            count = stateToolkit_->strictPrefix(closestStates_);
        }
        if (states == nullptr)
            return;
        exact = haveSolution_;
        approximate = !exact;
        addSolutionPath(
            count, [&](ob::State *s, std::size_t i) { fillState(s, (*states)[i]); }, exact, bestCostObj_,
            closestDistance_);
    }
} // namespace mhplan
