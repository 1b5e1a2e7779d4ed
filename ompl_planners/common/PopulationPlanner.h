// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the machinery every population-based planner shares (docs/algorithms.md 1.1-1.2): parameters, the
   waypoint encoding, fitness, evaluation counting, best-so-far tracking, progress properties, termination
   checks and solution reporting. An algorithm only writes its initialisation and its update rules. */
#ifndef MHPLAN_POPULATION_PLANNER_H
#define MHPLAN_POPULATION_PLANNER_H

#include "ompl_planners/common/Fitness.h"
#include "ompl_planners/common/GmsSettings.h"
#include "ompl_planners/common/PlannerBase.h"
#include "ompl_planners/common/PathEncoding.h"
#include "ompl_planners/common/StateParametrisation.h"
#include "ompl_planners/common/StatePathFitness.h"
#include "src/base/Parameters.h"

#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    class PathOperators;

    /** \brief Defaults a concrete planner passes to PopulationPlanner. */
    struct PopulationDefaults
    {
        unsigned int populationSize{30};
        /** \brief Length T of the coefficient schedules (the papers' iteration budget). */
        unsigned int iterations{30};
        unsigned int waypoints{3};
        /** \brief Spline makes the default "auto": the spline in R^k, the space's interpolation on other
           spaces (docs/spaces.md). */
        PathDecoding decoding{PathDecoding::Polyline};
    };

    /** \brief Base class of mhplan's metaheuristic planners.

        Problem: any ompl::base::RealVectorStateSpace of dimension k >= 1 with finite bounds (the planar
        worlds are k = 2), and any other state space StateParametrisation supports (SO(2), SO(3) and compound
        spaces of them with R^k: SE(2), DubinsStateSpace, ReedsSheppStateSpace, SE(3); docs/spaces.md), with
        the user's own validity checker and motion validator; start and goal from the problem definition
        (the first start state, one goal sample). On those other spaces a waypoint is a state, the update
        rules act on its coordinates (StateParametrisation: angles unwrapped relative to the start's,
        rotation vectors in the tangent space at the start's rotation), the path is start, waypoints, goal
        joined by the space's interpolation, its length the sum of si->distance() over the segments, and
        the fitness is [LRSMA]'s S on states interpolated along it (StatePathFitness); decoding "spline",
        fitness "gms", the [GMS] operators and evaluatePath()/evaluatePoints() are R^k only and refused
        there by setup() naming the parameter; a repeated setup() after a solve() starts the search over there
        (the parametrisation is built afresh). On a RealVectorStateSpace nothing of this runs: the R^k code
        below is used unchanged. A candidate is the waypoint vector
        of docs/algorithms.md 1.1 generalised to R^k: m waypoints of k coordinates, dimension() = m k, each
        coordinate bounded by the space's bounds on it (see WaypointDecoder; the spline decoding splines
        each coordinate against t, in any dimension), or any list of points (evaluatePath(), used by the
        GA); its fitness is a PathFitness ([LRSMA] S or [GMS] f1/f2, parameter \c fitness; \c auto picks
        [GMS] on grid worlds and [LRSMA] otherwise; see PathFitness for what the penalty measures with a
        checker that computes no clearance). The base class tracks, independently of the algorithm, the best
        feasible path ever evaluated by the problem's optimization objective (the reported cost; path length
        by default) and the best infeasible one by fitness.

        Unsupported problems are refused by setup(), which throws ompl::Exception with a message naming the
        planner and what it needs (a RealVectorStateSpace with finite bounds; a concrete planner may add its
        own needs, e.g. the GA's planar encoding) and leaves the planner not set up; solve() calls setup()
        through checkValidity(), so it throws the same exception. The message is also logged with OMPL_ERROR.
        (OMPL itself throws ompl::Exception from setup() for missing prerequisites, e.g. a missing projection
        or validity checker; an exception cannot be overlooked the way a status code can.)

        solve(): a first call draws and evaluates the initial population; each call then runs iterations
        until the termination condition holds or \c max_iterations further iterations (0 = no limit) are
        done, so a second call continues the search; clear() forgets everything. The termination condition
        is tested before every fitness evaluation (stopRequested()); an interrupted iteration is discarded,
        its evaluations still count. The coefficient schedules use t = 1..T with T = \c iterations; runs
        longer than T restart the schedule (t cycles; mhplan's choice, the papers stop at T).

        Reports an exact solution when the best path passes the motion validator on every segment, else an
        approximate one (the best valid prefix of the path of best fitness, docs/conventions.md). The
        intermediate-solution callback fires on each improvement of the best feasible path. Progress
        properties \c best \c cost (of the best feasible path, infinity before one exists), \c iterations
        and \c fitness \c evaluations are atomics, safe to read from the benchmark's sampling thread.

        Randomness comes only from the member ompl::RNG (seeded from OMPL's global seed at construction, or
        from the parameter \c seed when it is not 0). No heap allocation per fitness evaluation.

        Switchable [GMS] operators (docs/algorithms.md 1.5; all off by default, and then no operator code
        runs and no random number is drawn: the original algorithms (registry SMA, MGO, LRSMA) run without
        them; the faithful [GMS] SMA and MGO (registry SMA-GMS, MGO-GMS) switch on gms_initial, gms_revise,
        gms_simplify, scope "all" and gms_replace_fraction 0.1, where [GMS] puts its operators):
        \c gms_initial (bool: node repair, line-segment repair and node improvement on every individual of
        the initial population, after a stagnation restart too, and on every replacement individual; greedy
        re-insertion as below),
        \c gms_repair (bool: node repair + line-segment repair), \c gms_revise (bool), \c gms_simplify (bool),
        \c gms_improve (bool: node improvement), \c gms_scope ("best" or "all") and \c gms_replace_fraction
        ([0, 1], 0 = off). They act on the fixed-length waypoint encoding as follows, after every completed
        iteration of the algorithm:
        - for the iteration's best individual (scope "best") or for every individual (scope "all"): decode
          it (the polyline start, waypoints, goal; with the spline decoding, the polyline through the spline
          samples), apply the switched-on operators in the GA's order (repair, revision, simplification,
          node improvement) to that list of points, re-encode it into m waypoints and evaluate it with the
          normal fitness (one counted evaluation). Re-encoding: when the operated polyline has c <= m interior
          points they are kept and m - c points are added by halving the longest segment repeatedly (with
          the polyline decoding this is the same geometric path); when c > m, m points at equal arc length
          along it. The result replaces the individual only when its fitness is strictly better (greedy),
          so the algorithm's own dynamics are untouched apart from better individuals;
        - replacement: the ceil(fraction N) worst individuals (never the best one) are redrawn uniformly in
          the bounds (node-repaired first when \c gms_repair is on) and evaluated.
        The algorithm is then told (populationChanged()) so that it refreshes its elite / ranking. The
        termination condition is tested before every evaluation of this step; when it fires the step stops
        there (what was already accepted stays; the iteration counts as completed). Only algorithms that
        expose their population (populationView(): SMA, LRSMA, MGO) support the switches, and only in the
        plane (the operators are planar, see PathOperators): setup() refuses the switches otherwise, naming
        the parameter. Buffers: the operated point list, the re-encoded candidate and the ranking are members
        reserved once; the operators' inserts into the point list may grow it the first time only. */
    class PopulationPlanner : public PlannerBase
    {
      public:
        PopulationPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name,
                          const PopulationDefaults &defaults);
        ~PopulationPlanner() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        /** \brief The reported path (best feasible, else best infeasible) as a chain of vertices from a start
            to a goal vertex; the states belong to the planner until clear() or its destruction. */
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief Population size N (SharedParameterRanges); a change starts the search afresh. */
        void setPopulationSize(unsigned int n) override;
        /** \brief Schedule length T of the algorithm's coefficients (1..1000000). */
        void setIterations(unsigned int t);
        unsigned int getIterations() const { return iterations_; }
        /** \brief Number m of intermediate waypoints (1..100). */
        void setWaypoints(unsigned int m);
        unsigned int getWaypoints() const { return waypoints_; }
        /** \brief "polyline", "spline" or "auto" (spline in R^k; on other spaces waypoint states joined by
           the space's interpolation, docs/spaces.md). */
        void setDecoding(const std::string &decoding);
        std::string getDecoding() const { return decodingAuto_ ? "auto" : toString(decoding_); }
        /** \brief Number n of interpolation points (2..100000). */
        void setSplineSamples(unsigned int n);
        unsigned int getSplineSamples() const { return splineSamples_; }
        /** \brief "auto", "lrsma" or "gms". */
        void setFitness(const std::string &fitness);
        std::string getFitness() const { return fitnessName_; }
        /** \brief The fitness weights (parameters length_weight, penalty_weight, distance_weight,
            safety_weight, smoothness_weight, safe_distance, infeasible_length_weight, crossing_weight,
            infeasible_base; their ranges in PopulationParameters.cpp); a change starts the search afresh. */
        const FitnessWeights &fitnessWeights() const { return weights_; }
        /** \brief Anytime restarts (0 = off, the default; the improved variants switch them on): without an
            iteration budget (max_iterations = 0), after this many iterations without an improvement of the
            best feasible cost the population is drawn afresh (the best path stays archived and reported) and
            the coefficient schedule restarts with twice its previous length (T, 2T, 4T, ...), so that a long
            time limit is used by ever longer runs instead of a collapsed population (0..1000000). */
        void setStagnationRestart(unsigned int n);
        unsigned int getStagnationRestart() const { return stagnationRestart_; }
        /** \brief Restarts since the last clear(). */
        unsigned long restartCount() const { return restarts_; }
        /** \brief Seed of this planner's RNG (SharedParameterRanges); a change starts the search afresh. */
        void setSeed(unsigned long seed) override;

        /** \brief The [GMS] operator switches (parameters gms_*, see the class doc); throws
            std::invalid_argument naming the parameter when one is out of range (GmsSettings::check()). */
        void setGmsSettings(const GmsSettings &settings);
        const GmsSettings &gmsSettings() const { return gms_; }
        /** \brief True when any [GMS] operator switch is on. */
        bool gmsOperatorsEnabled() const { return gms_.enabled(); }

        /** \brief True when the space is a RealVectorStateSpace (the R^k encoding of docs/algorithms.md 1.1);
            false on the other supported spaces (docs/spaces.md). Valid after setup(). */
        bool onRealVectorSpace() const { return realVector_; }
        /** \brief The state parametrisation in use (null on a RealVectorStateSpace and before setup()). */
        const StateParametrisation *parametrisation() const { return realVector_ ? nullptr : param_.get(); }

        /** \brief The fitness actually in use (after resolving "auto"); valid after the first solve(). */
        FitnessKind fitnessKind() const
        {
            return !realVector_ || !fitness_ ? FitnessKind::LengthPenalty : fitness_->kind();
        }
        /** \brief How the [LRSMA] penalty measures a sample point (see PathFitness); valid after the first
            solve(). */
        PenaltyMode penaltyMode() const
        {
            if (!realVector_)
                return stateFitness_ ? stateFitness_->penaltyMode() : PenaltyMode::Clearance;
            return fitness_ ? fitness_->penaltyMode() : PenaltyMode::Clearance;
        }

      protected:
        /** \brief Draw and evaluate the initial population; false when interrupted (it is redrawn next call).
         */
        virtual bool initialisePopulation() = 0;
        /** \brief One iteration with schedule index t in 1..T; false when interrupted. */
        virtual bool iterate(unsigned int t) = 0;
        /** \brief Forget the algorithm's state (called by clear()). */
        virtual void clearPopulation() = 0;

        /** \brief The population for the [GMS] operators: \e x = N rows of dimension() values, \e fitness =
            their N fitness values, both writable; false (the default) when the algorithm does not expose
            one, and then setup() refuses the gms_* switches. Called only after initialisePopulation(). */
        virtual bool populationView(double *&x, double *&fitness)
        {
            x = fitness = nullptr;
            return false;
        }
        /** \brief True when the algorithm implements populationView() (checked by setup()). */
        virtual bool supportsGmsOperators() const { return false; }
        /** \brief Called after the [GMS] operators changed individuals of populationView() (refresh the
           elite, the ranking). */
        virtual void populationChanged() {}

        /** \brief True when the current solve() must stop (tests the termination condition). */
        bool stopRequested() const { return ptc_ == nullptr || (*ptc_)(); }

        /** \brief Decode and evaluate a waypoint vector (dimension() values); updates counts and bests. */
        double evaluate(const double *x);
        /** \brief Evaluate an explicit planar path (start ... goal; k = 2 only); updates counts and bests. */
        double evaluatePath(const std::vector<Vec2> &path);
        /** \brief Evaluate an explicit path of spaceDimension() coordinates per point (start ... goal);
            updates counts and bests. */
        double evaluatePoints(const PointsView &path);

        /** \brief Uniform random waypoint vector in the bounds. */
        void randomPosition(double *x);
        /** \brief Clamp every coordinate to the bounds (docs/algorithms.md 1.1). */
        void clampToBounds(double *x) const;

        /** \brief m k: the waypoints times the state space's dimension. */
        unsigned int dimension() const { return spaceDim_ * waypoints_; }
        /** \brief k, the dimension of the RealVectorStateSpace, or the coordinates per state of its
            parametrisation on other spaces (2 until known). */
        unsigned int spaceDimension() const { return spaceDim_; }
        /** \brief Lower bound of candidate coordinate j (the space's bound on coordinate j mod k). */
        double lower(unsigned int j) const { return lower_[j % spaceDim_]; }
        /** \brief Upper bound of candidate coordinate j. */
        double upper(unsigned int j) const { return upper_[j % spaceDim_]; }
        /** \brief First two coordinates of the start (the planar start). */
        const Vec2 &startPoint() const { return start_; }
        /** \brief First two coordinates of the goal (the planar goal). */
        const Vec2 &goalPoint() const { return goal_; }
        /** \brief The start's k coordinates (valid once solve() has prepared the problem; on other spaces
            its parametrisation). */
        const double *startCoordinates() const { return startX_.data(); }
        /** \brief The goal's k coordinates. */
        const double *goalCoordinates() const { return goalX_.data(); }
        PathFitness &fitness() { return *fitness_; }

        /** \brief Mark the structure (population size, dimension, decoding) changed: clear() on next solve.
         */
        void invalidate();

      private:
        /** \brief Declare the parameters on params() (PopulationParameters.cpp). */
        void declareParameters();
        /** \brief Read the space's dimension and bounds; refuseSetup() when they are unsupported. */
        void checkSpace();
        /** \brief checkSpace() for a space other than R^k: its parametrisation, or refuseSetup(). */
        void checkStateSpace();
        bool prepareProblem();
        void record(const FitnessResult &r, const PointsView &path);
        /** \brief record() for a decoded path of states (spaces other than R^k). */
        void recordStates(const FitnessResult &r, const std::vector<ompl::base::State *> &path);
        /** \brief Points of the reported path (best feasible when \e feasible, else best infeasible). */
        std::size_t pathCount(bool feasible) const;
        /** \brief Write point \e i of that path into \e state. */
        void pathState(bool feasible, ompl::base::State *state, std::size_t i) const;
        /** \brief prepareProblem() on a space other than R^k. */
        bool prepareStateProblem(const ompl::base::State *start, const ompl::base::State *goal);
        void freeBestStates();
        /** \brief Write point \e i of \e points into \e state. */
        void toState(ompl::base::State *state, const std::vector<double> &points, std::size_t i) const;
        void reportSolution(bool &exact, bool &approximate);
        void fireIntermediate();
        /** \brief The stagnation restart after an iteration whose best cost was \e before (see
            setStagnationRestart()); false when the redrawn population was interrupted. */
        bool restartOnStagnation(double before);
        /** \brief The [GMS] operator step after an iteration (see the class doc; GmsStep.cpp); false when
            interrupted. */
        bool applyGmsOperators();
        /** \brief gms_initial's step on the whole population after initialisePopulation() (true at once when
            the switch is off); false when interrupted. */
        bool applyGmsInitial();
        /** \brief Build the operators and the step's buffers once per problem. */
        void prepareGmsOps();
        /** \brief Operators on one individual (\e initial: gms_initial's repair, segment repair and node
            improvement; else the per-iteration switches), greedy re-insertion; false when interrupted. */
        bool operateOn(double *x, double &fx, bool initial = false);
        /** \brief Re-encode gmsPath_ into m waypoints in gmsCandidate_. */
        void encodePath();
        /** \brief setup()'s check of the gms_* switches (refuseSetup() naming the parameter). */
        void checkGmsSwitches();

        unsigned int iterations_;
        unsigned int waypoints_;
        PathDecoding decoding_;
        /** \brief decoding = auto: decoding_ is Spline, used in R^k only. */
        bool decodingAuto_;
        unsigned int splineSamples_{100};
        std::string fitnessName_{"auto"};
        FitnessWeights weights_;
        unsigned int stagnationRestart_{0};
        unsigned long epochStart_{0};
        unsigned long epochLength_{0};
        unsigned long sinceImprovement_{0};
        unsigned long restarts_{0};

        const ompl::base::PlannerTerminationCondition *ptc_{nullptr};
        bool problemReady_{false};
        bool initialised_{false};
        unsigned int spaceDim_{2};
        Vec2 start_, goal_;
        std::vector<double> startX_, goalX_;
        std::vector<double> lower_{0.0, 0.0};
        std::vector<double> upper_{0.0, 0.0};
        /** \brief False on spaces other than RealVectorStateSpace, which then use param_ and stateFitness_
            (docs/spaces.md); every R^k member below is then unused. */
        bool realVector_{true};
        std::unique_ptr<StateParametrisation> param_;
        std::unique_ptr<StatePathFitness> stateFitness_;
        /** \brief Best paths as states (m + 2 each, allocated once per query; spaces other than R^k). */
        std::vector<ompl::base::State *> bestFeasibleStates_, bestInfeasibleStates_;
        WaypointDecoder decoder_;
        std::unique_ptr<PathFitness> fitness_;
        bool haveFeasible_{false};
        ompl::base::Cost bestFeasibleCost_;
        /** \brief Best paths as flat point lists (k values per point). */
        std::vector<double> bestFeasiblePath_;
        bool haveInfeasible_{false};
        double bestInfeasibleFitness_{0.0};
        double bestInfeasibleViolation_{0.0};
        std::vector<double> bestInfeasiblePath_;
        /** \brief Reused buffer of evaluatePath(). */
        std::vector<double> planarPath_;
        bool improved_{false};

        GmsSettings gms_;
        std::unique_ptr<PathOperators> gmsOps_;
        std::vector<Vec2> gmsPath_;
        std::vector<double> gmsCandidate_;
        std::vector<unsigned int> gmsOrder_;
    };
} // namespace mhplan

#endif
