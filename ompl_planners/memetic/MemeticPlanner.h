// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the machinery of the memetic (-MEM) improved variants: a population of feasible paths of any
   length, multi-resolution walks for initial paths, local search, elite polishing, restarts, best-so-far
   tracking and the intermediate-solution callback. An algorithm writes its update rule (generation()). */
#ifndef MHPLAN_MEMETIC_PLANNER_H
#define MHPLAN_MEMETIC_PLANNER_H

#include "ompl_planners/common/PlannerBase.h"
#include "ompl_planners/common/StateParametrisation.h"
#include "ompl_planners/memetic/MemeticStateToolkit.h"
#include "ompl_planners/memetic/MemeticToolkit.h"

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Term \e i >= 1 of Luby's universal restart sequence (1, 1, 2, 1, 1, 2, 4, 1, ...): the state
        mode's connection budgets (docs/spaces.md). */
    unsigned int lubyTerm(unsigned long i);

    /** \brief Base class of the memetic improved variants GA-MEM, SMA-MEM, MGO-MEM and LRSMA-MEM (not in
        any paper: mhplan's scalable, anytime versions of the update rules).

        Problem: a 2-dimensional ompl::base::RealVectorStateSpace with finite bounds (the planar mode: the
        lattice walks, pull moves and crossover joints below), or any other state space with a
        StateParametrisation (R^k, SE(2), Dubins, Reeds-Shepp, SE(3), compounds: the state mode of
        docs/spaces.md, "The memetic planners off the plane": the same population, local search, polish,
        restarts and update rules on paths of states, MemeticStateToolkit), any validity checker and motion
        validator, start and goal from the problem definition (the first start, one goal sample). The
        planner sees the problem only through the space information (bounds, sampler, interpolation,
        distance, isValid, checkMotion) and the optimization objective.

        Design (each choice stated as docs/conventions.md asks):
        - Encoding that grows with the problem: an individual is a feasible polyline of any number of
          waypoints (MemeticToolkit). Every individual is feasible by construction: it comes from a lattice
          walk checked by the motion validator, and every operator keeps feasibility (moves are accepted
          only when the motion validator accepts the changed segments).
        - Feasible initial population: \c population_size randomised lattice walks (MemeticToolkit::
          randomWalk, a new random cost field per walk of strength drawn in [0, \c walk_noise), heuristic
          weight \c walk_weight (weight 1, A*, was measured slower: on mazes it expands most of the lattice);
          the first walk is noiseless; every other later walk passes a random valid
       via point, uniformly along the start-goal line between 15 % and 85 % and off it by up to 0.3 of its
       length), each shortened by the local search. Multi-resolution: the lattice step starts at the largest
       power of two (in the space's units) not above 1/16 of the bounds' larger side (powers of two nest, and
       align with grid maps of power-of-two cells when the start is at a cell centre) and halves whenever a
       walk exhausts its lattice (no path at that resolution), at most \c lattice_levels times; the level
       reached is kept for later walks. A walk stops after \c walk_expansions nodes (then it is retried later
       with other noise).
        - Elite neighbourhood search: \c elite_rewalks times per generation a piece of the best individual
          is re-walked (MemeticToolkit::rewalk: another homotopy class nearby), tightened, and kept when
          shorter (a class-changing local improvement, like 2-opt in memetic TSP solvers). 0 for GA-MEM,
          whose mutation does this; 4 for the offset variants, whose update rules move within the
          neighbourhood of the reference.
        - Huge worlds: once the walks of a (re)start have cost 3e6 motion checks and there are at least 2
          individuals, the generations start and the rest of the population joins one walk per generation
          (a deterministic budget, so runs stay reproducible). The elite polish runs before each generation.
        - Memetic local search: every new individual is tightened with the coarse turn limit
          \c coarse_turn (MemeticToolkit::tighten, relative tolerance 1e-4, at most 30 passes); the best
          individual is polished after every generation with the fine limit \c fine_turn (tolerance 1e-10,
          \c polish_passes passes per generation, so the polish continues across generations: anytime
          refinement of the incumbent). The polish works on a copy: the population keeps coarse paths (few
          waypoints, cheap to vary, compared at the same level of refinement); a new best individual
          replaces the copy being polished.
        - Fitness = the optimization objective's cost of the path (path length by default); lower is better.
          No penalty terms: nothing infeasible is ever evaluated.
        - Anytime: with \c max_iterations = 0 the planner runs generations until the termination condition
          holds. When the best cost has not improved by more than 1e-9 (relative) for \c stagnation
          generations, the population restarts with elitism: the best individual stays, the others are
          replaced by fresh walks, the algorithm's schedule restarts with its length doubled
          (restartAlgorithm()), so schedules that depend on t/T need no time budget. The termination
          condition is tested before every evaluation and inside walks (every 64 nodes) and local searches
          (every pass and every 16 waypoints).
        - Every improvement of the best path is reported to the problem definition's intermediate-solution
          callback (reportImprovement()); progress properties \c best \c cost, \c iterations (generations),
          \c fitness \c evaluations (evaluated individuals) and \c motion \c checks are atomics.
        - When no walk reaches the goal (no path, or none found yet) each generation tries one more walk;
          the walked path that came closest to the goal is reported as an approximate solution.
        - Randomness only from the member ompl::RNG (seeded from OMPL's global seed, or from \c seed when
          it is not 0): the same seed gives the same run under an iteration budget. */
    class MemeticPlanner : public PlannerBase
    {
      public:
        MemeticPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name,
                       unsigned int populationSize);
        ~MemeticPlanner() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief Seed of this planner's RNG (SharedParameterRanges); a change after the problem was prepared
            starts afresh. Population size N and generations per solve() call (\c max_iterations, 0 = until
            the termination condition) are PlannerBase's. */
        void setSeed(unsigned long seed) override;
        /** \brief Largest priority noise of the walks (0..10). */
        void setWalkNoise(double noise);
        double getWalkNoise() const { return walkNoise_; }
        /** \brief Heuristic weight of the walks after the first (1..10). */
        void setWalkWeight(double w);
        double getWalkWeight() const { return walkWeight_; }
        /** \brief Node budget of one walk (1000..100000000). */
        void setWalkExpansions(unsigned int n);
        unsigned int getWalkExpansions() const { return walkExpansions_; }
        /** \brief Number of lattice resolutions (1..16). */
        void setLatticeLevels(unsigned int n);
        unsigned int getLatticeLevels() const { return latticeLevels_; }
        /** \brief Largest turn (rad) per waypoint after the coarse local search (0.01..3). */
        void setCoarseTurn(double x);
        double getCoarseTurn() const { return coarseTurn_; }
        /** \brief Largest turn (rad) per waypoint of the polished best path (0.001..1). */
        void setFineTurn(double x);
        double getFineTurn() const { return fineTurn_; }
        /** \brief Local-search passes of the elite polish per generation (1..100000). */
        void setPolishPasses(unsigned int n);
        unsigned int getPolishPasses() const { return polishPasses_; }
        /** \brief Re-walk trials on the best individual per generation (0..1000). */
        void setEliteRewalks(unsigned int n);
        unsigned int getEliteRewalks() const { return eliteRewalks_; }
        /** \brief Tube reroutes of the best individual per generation, in the plane (docs/variants.md, "The
            tube reroute"); 0: none. */
        void setTubeReroutes(unsigned int n);
        unsigned int getTubeReroutes() const { return tubeReroutes_; }
        /** \brief Generations without improvement before a restart with elitism (1..1000000; 0 = auto: 3 in
            the planar mode, 40 in the state mode). */
        void setStagnation(unsigned int n);
        unsigned int getStagnation() const { return stagnation_; }
        /** \brief Bisection steps of each pull move (4..40). */
        void setBisections(unsigned int n);
        unsigned int getBisections() const { return bisections_; }
        /** \brief The validator margin in sample spacings of OMPL's DiscreteMotionValidator (0..4; 0 = none;
            docs/variants.md, "No corner the validator cannot see"). */
        void setValidatorMargin(double m);
        double getValidatorMargin() const { return validatorMargin_; }
        /** \brief The clearance kept from obstacles the margin finds, in sample spacings (0.005..0.5; 0 =
            refuse a segment with an obstacle within the margin; docs/variants.md). */
        void setValidatorClearance(double c);
        double getValidatorClearance() const { return validatorClearance_; }
        /** \brief The smallest clearance, in sample spacings, the margin keeps in a passage with obstacles
            on both sides (validator_clearance halved while at or above it; 0 = never; docs/variants.md). */
        void setValidatorMinClearance(double c);
        double getValidatorMinClearance() const { return validatorMinClearance_; }
        /** \brief The step of the fine check of reported paths, in sample spacings (0.01..1; 0 = none;
            docs/variants.md, "The fine check"). */
        void setValidatorFineStep(double f);
        double getValidatorFineStep() const { return validatorFineStep_; }
        /** \brief Off the plane, with OMPL's DiscreteMotionValidator: the fine check's step along every
            motion of a reported path, in the validator's sample spacings (docs/spaces.md, "Margin"). */
        void setValidatorStateStep(double f);
        double getValidatorStateStep() const { return validatorStateStep_; }
        /** \brief The margin in the space's distance for the current motion validator: validator_margin x
            the validity-checking resolution x the maximum extent with a DiscreteMotionValidator, else 0. */
        double marginDistance() const;

        unsigned long motionCheckCount() const { return motionChecks_.load(); }
        /** \brief Validity-checker calls the planner made itself (state mode; the motion validator's own are
            not seen). */
        unsigned long stateCheckCount() const { return stateChecks_.load(); }
        /** \brief Motion checks answered from the segment cache instead of the validator (state mode). */
        unsigned long cacheHitCount() const { return cacheHits_.load(); }
        /** \brief Improvements of the best cost since the last clear(). */
        unsigned long improvementCount() const { return improvements_.load(); }
        /** \brief True when the planner runs in the state mode (any space but R^2). */
        bool stateMode() const { return stateMode_; }
        /** \brief Restarts with elitism since the last clear(). */
        unsigned long restartCount() const { return restarts_; }

      protected:
        /** \brief The incumbent's cost when the objective is path length and the space measures it as the
            roadmap does (then the informed set bounds every shorter path), else infinity. */
        double informedBound() const;

        struct Individual
        {
            MemeticPath path;
            double cost{0.0};
            /** \brief 16 points at equal arc length (for crowding). */
            MemeticPath signature;
            /** \brief State mode: the path and its 16 states at equal arc length. */
            StatePath states;
            StatePath stateSignature;
        };

        /** \brief Algorithm state after the population exists (called once per (re)start). */
        virtual void startAlgorithm() {}
        /** \brief One generation of the update rule on pop_; false when interrupted. \e t counts
            generations since the last (re)start, from 1. */
        virtual bool generation(unsigned long t) = 0;
        /** \brief A restart with elitism happened (pop_ refilled): restart schedules (double T). */
        virtual void restartAlgorithm() {}
        virtual void clearAlgorithm() {}
        /** \brief An individual joined pop_ outside generation() (a late walk): refresh the encoding. */
        virtual void populationChanged() {}

        bool stopRequested() const { return ptc_ == nullptr || (*ptc_)(); }
        const std::function<bool()> &stopFunction() const { return stop_; }

        /** \brief A fresh feasible individual from a walk (coarse local search applied), evaluated; false
            when no walk reached the goal (interrupted, budget, or no path at the finest resolution). */
        bool walkIndividual(Individual &out);
        /** \brief Coarse local search of \e ind.path, then evaluation (cost, signature); false when
            interrupted before the evaluation (ind unchanged then). */
        bool improveAndEvaluate(Individual &ind);
        /** \brief Objective cost of a path, counted as an evaluation; updates the best. \e raw: the path
            before its local search (a fallback under the validator margin, strictTighten). */
        double evaluate(const MemeticPath &path, const MemeticPath *raw = nullptr);
        /** \brief Index of the best individual of pop_. */
        std::size_t bestIndex() const;
        /** \brief Deterministic crowding: \e child replaces the most similar individual (signature distance)
            when it is cheaper; returns true when it entered the population. */
        bool crowdingInsert(Individual &child);
        /** \brief max over the signature points of the distance (similarity of two paths). */
        static double signatureDistance(const Individual &a, const Individual &b);

        MemeticToolkit &toolkit() { return *toolkit_; }
        MemeticStateToolkit &stateToolkit() { return *stateToolkit_; }
        /** \brief State mode: the cost of a path, counted as an evaluation; updates the best. */
        double evaluate(const StatePath &path);
        /** \brief State mode: the similarity of two individuals (max distance of their signature states). */
        double stateSignatureDistance(const Individual &a, const Individual &b);
        const Vec2 &startPoint() const { return start_; }
        const Vec2 &goalPoint() const { return goal_; }
        /** \brief The larger side of the bounds. */
        double scale() const { return scale_; }
        const MemeticPath &bestPath() const { return bestPath_; }
        bool haveSolution() const { return haveSolution_; }
        double coarseTurnLimit() const { return coarseTurn_; }

        std::vector<Individual> pop_;

      private:
        bool prepareProblem();
        /** \brief A walk from \e from to \e to, halving the lattice step on exhaustion (level_ persists). */
        MemeticToolkit::WalkResult walk(MemeticPath &path, const Vec2 &from, const Vec2 &to, double noise,
                                        double weight);
        /** \brief Fill pop_ with walks up to N (or, with at least 2 individuals, until the walks have cost
            kFillBudget motion checks); false when interrupted or no walk succeeded. */
        bool fillPopulation();
        /** \brief The population is complete, or cut short by the fill budget, or all the lattice offers. */
        bool readyToStart() const;
        static constexpr unsigned long kFillBudget = 3000000;
        /** \brief Halvings of each pull move in the raw path's strict tightening (strictTighten). */
        static constexpr unsigned int kRetryBisections = 3;
        /** \brief The most segments the margin may still refuse after makeStrict() for strictCopy() to try
           the halved path (measured: the retry succeeded with at most 5, never with more than 5). */
        static constexpr std::size_t kHalvingMostRefused = 16;
        /** \brief Samples of the first roadmap, and the most a roadmap draws per epoch. */
        static constexpr unsigned int kRoadmapSamples = 1500;
        static constexpr unsigned int kRoadmapFirst = 200;
        static constexpr unsigned int kRoadmapMaxSamples = 8000;
        /** \brief The next route of the lazy roadmap as a new path (planar); false when it has none. */
        bool roadmapIndividual(Individual &out);
        /** \brief What nextRoadmapRoute did: a route, none this time, or the roadmap given up. */
        enum class RoadmapStep
        {
            Route,
            None,
            GaveUp
        };
        /** \brief The lazy roadmap's schedule, one for both modes (docs/variants.md, "First paths: a lazy
            roadmap"): \e grow(samples) (re)builds the roadmap with that many new samples (false: stopped),
            \e route(maxInvalid) takes its next route (\e fullRefusals refused routes of the full roadmap
            give it up, 20 of the small one's); \e first: no roadmap yet. */
        RoadmapStep nextRoadmapRoute(bool first, unsigned int firstSamples, unsigned int samples,
                                     const std::function<bool(unsigned int)> &grow,
                                     const std::function<bool(unsigned int)> &route,
                                     unsigned int fullRefusals);
        /** \brief The first path is reported at once; then the coarse local search and the evaluation. */
        bool finishWalk(Individual &out);
        void polishElite();
        /** \brief \e path made to pass the validator margin (MemeticToolkit::makeStrict), retried once with
            every segment halved; false when it does not pass. */
        bool strictCopy(MemeticPath &path);
        /** \brief \e raw (a path before its local search) made to pass the margin and tightened under it
            (the coarse local search in the strict mode) into \e out; false when it does not pass. */
        bool strictTighten(const MemeticPath &raw, MemeticPath &out);
        /** \brief \c elite_rewalks re-walk trials on the best individual, greedy. */
        void eliteRewalks();
        void restart();
        void reportSolution(bool &exact, bool &approximate);
        void record(const MemeticPath &path, double cost);
        double pathCost(const MemeticPath &path);
        void publishCounts();
        /** \brief True when \e cost improves the best (then bestCostObj_ and the counters are updated). */
        /** \brief Would \e cost improve on the best (no bookkeeping)? */
        bool improvesOn(double cost) const;
        bool improves(double cost);
        unsigned long motionCheckTotal() const;

        // State mode (MemeticPlannerStates.cpp).
        void setupStateMode();
        bool prepareStateProblem(const ompl::base::State *start, const ompl::base::State *goal);
        bool walkStateIndividual(Individual &out);
        /** \brief The next route of the lazy roadmap on states as a new path; false when it has none. */
        bool roadmapStateIndividual(Individual &out);
        /** \brief A path from a randomised connection (through a random valid state every other time). */
        bool connectStateIndividual(Individual &out);
        bool improveAndEvaluateStates(Individual &ind);
        void polishEliteStates();
        void eliteReconnects();
        void reportStateSolution(bool &exact, bool &approximate);
        void fillState(ompl::base::State *s, const StatePoint &p) const;

        double walkNoise_{3.0};
        double walkWeight_{2.0};
        unsigned int walkExpansions_{400000};
        unsigned int latticeLevels_{8};
        double coarseTurn_{0.35};
        double fineTurn_{0.05};
        unsigned int polishPasses_{8};
        unsigned int stagnation_{0};
        unsigned int eliteRewalks_{0};
        unsigned int tubeReroutes_{1};
        /** \brief States drawn per tube reroute. */
        static constexpr unsigned int kTubeSamples = 1000;
        unsigned int bisections_{10};
        double validatorMargin_{0.5};
        double validatorClearance_{0.03};
        double validatorMinClearance_{0.001};
        double validatorFineStep_{0.25};
        double validatorStateStep_{0.01};

        const ompl::base::PlannerTerminationCondition *ptc_{nullptr};
        std::function<bool()> stop_;
        bool problemReady_{false};
        bool started_{false};
        Vec2 start_, goal_;
        double scale_{1.0};
        std::unique_ptr<MemeticToolkit> toolkit_;
        bool stateMode_{false};
        std::unique_ptr<StateParametrisation> param_;
        std::unique_ptr<MemeticStateToolkit> stateToolkit_;
        StatePoint startState_, goalState_;
        StatePath bestStates_, closestStates_, polishedStates_;
        /** \brief The step of MemeticStateToolkit::perturb on the polished path (a share of each range). */
        double perturbStep_{0.01};
        unsigned int level_{0};
        bool noPath_{false};
        bool fillCut_{false};
        unsigned long walks_{0};
        /** \brief State mode: connections that ran out of states (their budgets follow Luby's sequence,
            lubyTerm). */
        unsigned int connectFailures_{0};
        unsigned long sinceImprovement_{0};
        unsigned long generationInEpoch_{0};
        unsigned long restarts_{0};
        unsigned int roadmapSamples_{kRoadmapSamples};
        unsigned int roadmapPaths_{0};
        bool roadmapAlive_{true};
        bool roadmapStale_{true};
        bool smallRoadmap_{false};
        /** \brief The state mode's full roadmaps are dense (one gave up; docs/spaces.md). */
        bool denseRoadmap_{false};

        bool haveSolution_{false};
        ompl::base::Cost bestCostObj_;
        MemeticPath bestPath_;
        MemeticPath closest_;
        /** \brief The polished copy of the best individual and that individual's (coarse) cost. */
        MemeticPath polished_;
        /** \brief The last path evaluate() tightened under the margin from a raw path, and the (loose) cost
            of the individual it stands for (polishElite starts from it). */
        MemeticPath strictFallback_;
        /** \brief The first path and its strict tightening (finishWalk), for evaluate() to reuse. */
        MemeticPath firstRaw_, firstStrict_;
        double strictFallbackCost_{std::numeric_limits<double>::quiet_NaN()};
        double polishedSource_{0.0};
        double closestDistance_{0.0};

        std::atomic<unsigned long> motionChecks_{0};
        std::atomic<unsigned long> stateChecks_{0};
        std::atomic<unsigned long> cacheHits_{0};
        std::atomic<unsigned long> improvements_{0};
    };
} // namespace mhplan

#endif
