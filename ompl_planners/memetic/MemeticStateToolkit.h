// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: path operators of the memetic (-MEM) planners on any state space with a parametrisation
   (docs/spaces.md, "The memetic planners off the plane"): randomised bidirectional connections on the state
   sampler and motion validator for feasible initial paths, local search through the space's interpolation,
   path crossover at close states, detour and re-connect mutations. */
#ifndef MHPLAN_MEMETIC_STATE_TOOLKIT_H
#define MHPLAN_MEMETIC_STATE_TOOLKIT_H

#include "ompl_planners/common/DubinsGuard.h"
#include "ompl_planners/common/StateParametrisation.h"
#include "ompl_planners/memetic/CarBounds.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/datastructures/NearestNeighbors.h>
#include <ompl/util/RandomNumbers.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

namespace mhplan
{
    /** \brief A waypoint: the StateParametrisation coordinates of a state. */
    using StatePoint = std::vector<double>;
    /** \brief A path of waypoints, consecutive ones joined by the space's interpolation. */
    using StatePath = std::vector<StatePoint>;

    /** \brief Path operators of the memetic planners on a state space other than the plane (docs/spaces.md,
        "The memetic planners off the plane"). Everything goes through the space information: the state
        sampler, the space's interpolate() and distance(), the validity checker (isValid) and the motion
        validator (checkMotion, in the path's direction, so asymmetric spaces such as Dubins are handled);
        costs are the optimization objective's motion costs.

        - connect(): a randomised bidirectional connection of two states: two trees (one from each end)
          grown alternately toward random states (the sampler, or a caller's local sampler) by steps of at
          most \e range along the space's interpolation, each new state checked by isValid() and its motion
          by checkMotion() (toward the goal tree's root for the goal tree); after each extension the other
          tree is extended toward the new state until it reaches it (joined) or is blocked. On a space whose
          distance or interpolation is not symmetric (Dubins) only the start tree grows, and after each step
          it is extended toward the goal until it reaches it or is blocked. Nearest neighbours by OMPL's GNAT
          on a space with a symmetric distance and no car bounds, else by a linear scan (exact under an
          asymmetric distance, pruned by the car bounds). A fresh random draw per call gives paths in
          different homotopy classes; the caller chooses the budget (the planner: Luby's sequence,
          docs/spaces.md).
        - tighten(): passes of greedy shortcut (the farthest later waypoint visible), pull moves (waypoint i
          moved toward the interpolation midpoint of its neighbours and toward each neighbour, the largest
          fraction found by bisection that keeps both adjacent motions valid and lowers the cost) and
          adaptive subdivision (the two motions at a waypoint that no pull move could move and whose detour
          excess (c(a,v) + c(v,b)) /
          c(a,b) - 1 exceeds 1 / cos(maxTurn / 2) - 1, the excess of a planar turn of maxTurn, get their
          interpolation midpoints inserted), until a pass gains less than \e relTol.
        - Motion checks are cached: a segment whose two end coordinates are bit-identical to one checked
          before is never checked again (motionChecks() counts the validator's calls, cacheHits() the
          answers from the cache, stateChecks() the isValid() calls made here).
        Not thread-safe. */
    class MemeticStateToolkit
    {
      public:
        MemeticStateToolkit(ompl::base::SpaceInformationPtr si, const StateParametrisation &param,
                            ompl::RNG &rng);
        ~MemeticStateToolkit();
        MemeticStateToolkit(const MemeticStateToolkit &) = delete;
        MemeticStateToolkit &operator=(const MemeticStateToolkit &) = delete;

        /** \brief The objective whose motion costs are the path cost (null: the space's distance). */
        void setObjective(ompl::base::OptimizationObjectivePtr opt) { opt_ = std::move(opt); }
        void setBisections(unsigned int n) { bisections_ = n; }
        /** \brief The validator margin (space distance, 0: none): a pull move the motion validator blocks
            stops this far short of the blocked position (docs/spaces.md). */
        void setMargin(double m) { margin_ = m; }
        /** \brief With a sampling motion validator: reported paths must pass the fine check, their motions
            followed at \e spacing (space distance) with the validity checker (0: off; docs/spaces.md). The
            search itself asks the motion validator alone. */
        void setFineSpacing(double spacing);
        /** \brief Whether reported paths must pass the fine check (a sampling validator). */
        bool strictNeeded() const { return strictSpacing_ > 0.0; }
        /** \brief With the fine check on: roadmapPath() also follows each edge of a route the validator
            accepted with the fine check, and refuses the edges that fail it (docs/spaces.md: where the
            checker's free space holds what the validator's samples cannot see, e.g. a mesh's inside, every
            route otherwise fails the fine check). Off after resetCounts(). */
        void setStrictRoutes(bool on) { strictRoutes_ = on; }
        bool strictRoutes() const { return strictRoutes_; }
        /** \brief Make \e path pass the fine check (docs/spaces.md): each motion is followed at the fine
            spacing (validator_state_step x the validator's sample spacing) with the validity checker; a
            motion that fails there gets a valid state drawn near its first failing state (positions within
            1, 2, 4, ... 32 margins; rotations, every other draw, within the same turn as the metric allows,
            else within the turn mendTurn() gives), kept when both new motions pass the validator and the
            fine check. False when a motion could not be mended (or when stopped). Verdicts cached. */
        bool makeStrict(StatePath &path, const std::function<bool()> &stop);
        /** \brief The number of leading states of \e path whose motions pass the fine check (all of them
            when none is needed). */
        std::size_t strictPrefix(const StatePath &path);

        unsigned int dimension() const { return param_.dimension(); }
        const StateParametrisation &parametrisation() const { return param_; }

        void toState(const StatePoint &p, ompl::base::State *s) const { param_.fromVector(p.data(), s); }
        void fromState(const ompl::base::State *s, StatePoint &p) const;

        /** \brief The validity checker's verdict. Counted. */
        bool pointValid(const StatePoint &p);
        /** \brief The motion validator's verdict on a -> b (cached). */
        bool motionValid(const StatePoint &a, const StatePoint &b);
        bool pathValid(const StatePath &path);
        /** \brief The objective's motion cost of a -> b. */
        double segmentCost(const StatePoint &a, const StatePoint &b);
        double cost(const StatePath &path);
        /** \brief The space's distance. */
        double distance(const StatePoint &a, const StatePoint &b);
        /** \brief The state at fraction \e t of the space's interpolation from \e a to \e b. */
        void interpolate(const StatePoint &a, const StatePoint &b, double t, StatePoint &out);

        unsigned long motionChecks() const { return motionChecks_; }
        unsigned long stateChecks() const { return stateChecks_; }
        unsigned long cacheHits() const { return cacheHits_; }
        /** \brief Zero the counts, forget the cached verdicts and the roadmap (a new problem). */
        void resetCounts();

        enum class ConnectResult
        {
            Found,
            Budget,
            Stopped
        };
        /** \brief Draws a state (coordinates) for connect(); false when it could not. */
        using Sampler = std::function<bool(StatePoint &)>;
        /** \brief A randomised bidirectional connection from \e from to \e to (class doc), at most
            \e maxNodes states in the two trees together. On Found \e path runs from \e from to \e to.
            \e closest / \e closestDistance: the start tree's state nearest to \e to seen so far. */
        ConnectResult connect(StatePath &path, const StatePoint &from, const StatePoint &to, double range,
                              unsigned int maxNodes, const Sampler &sample, const std::function<bool()> &stop,
                              StatePath *closest = nullptr, double *closestDistance = nullptr);
        /** \brief A uniform state (StateParametrisation::sample with the planner's RNG). */
        bool sampleUniform(StatePoint &out);
        /** \brief A state whose every coordinate is within \e d of \e near's (then StateParametrisation::
            enforce()). */
        bool sampleNear(const StatePoint &near, double d, StatePoint &out);
        /** \brief A state whose position coordinates are within \e d of \e near's and whose rotation
            coordinates are within \e turn (then StateParametrisation::enforce()). */
        void sampleAround(const StatePoint &near, double d, double turn, StatePoint &out);
        /** \brief The turn (radians) of a mend's draw whose positions move by up to \e d: pi d / L, L the
            largest range of the position coordinates (d where there are none). */
        double mendTurn(double d) const;
        /** \brief The space's maximum extent (si->getMaximumExtent()). */
        double extent() const;

        void shortcut(StatePath &path, const std::function<bool()> &stop);
        /** \brief Called with the path after the shortcut and after every pass of tighten() that changed it
            (valid, no costlier than before), and its cost (tighten() computes it anyway). */
        using PassReport = std::function<void(const StatePath &, double)>;
        /** \brief Local search (class doc); false when \e stop() interrupted it (the path stays valid and no
            costlier). \e afterPass, when given, sees the path after the shortcut and after every pass. */
        bool tighten(StatePath &path, double maxTurn, double relTol, unsigned int maxPasses,
                     const std::function<bool()> &stop, unsigned int maxPoints = 2000, bool precise = false,
                     const PassReport &afterPass = nullptr);

        /** \brief The best move of \e v toward \e target (bisection on the fraction) between \e a and \e b,
            stopped the margin short when blocked (both motions from the position it steps back to checked);
            true when one lowered the cost (\e v then moved, both its motions valid). tighten()'s pull move.
         */
        bool pullToward(const StatePoint &a, StatePoint &v, const StatePoint &b, const StatePoint &target,
                        unsigned int steps);
        /** \brief Random local search of the waypoints (a (1+1) evolution strategy per waypoint,
           docs/spaces.md): \e tries candidates per interior waypoint drawn with every coordinate within \e
           step x its parametrisation range of the waypoint's; a candidate's cost through its neighbours is
           computed first, and only one that lowers it is checked (isValid, then both motions). \e step
           doubles after a success and shrinks by 0.7 after a waypoint's failures, within [1e-6, 0.1]. False
           when nothing moved. */
        bool perturb(StatePath &path, double &step, unsigned int tries, const std::function<bool()> &stop);

        /** \brief The lazy roadmap of the state mode (docs/spaces.md, "First paths: a lazy roadmap on
           states"): forget every sample. */
        void roadmapClear();
        /** \brief Rebuild the roadmap on \e start, \e goal, the kept samples and \e n new valid ones
           (uniform, the parametrisation's draw), only inside the informed set of cost \e bound
           (distance(start, q) + distance(q, goal) < bound; infinity: everywhere); directed edges from every
           state to its k nearest (k = e (1 + 1/d) ln n, PRM*'s), and from its k nearest to it, none checked
           yet. False when stopped. */
        bool roadmapGrow(unsigned int n, const StatePoint &start, const StatePoint &goal, double bound,
                         const std::function<bool()> &stop);
        /** \brief The next route of the roadmap: the cheapest under the penalties (A*, the space's distance
           to the goal as heuristic when the objective is path length), its unknown edges checked by the
           motion validator in their direction (and by the fine check with setStrictRoutes()), refused ones
           removed, repeated; the route's states and their
            neighbours are penalised (an edge costs c (1 + (p_a + p_b) / 2)) so the next route goes another
            way. False when the goal is cut off, after \e maxInvalid refused routes, or when stopped. */
        bool roadmapPath(StatePath &path, unsigned int maxInvalid, const std::function<bool()> &stop);
        std::size_t roadmapSize() const { return rmPoints_.size(); }
        /** \brief The space's distances computed by roadmapGrow()'s nearest-state search (its pivots
            included) since resetCounts(). */
        unsigned long roadmapDistances() const { return roadmapDistances_; }

        /** \brief Crossover at states where \e a and \e b (resampled at 48 states each) pass within
            \e radius: a[..p] -> b[q..] or a[..p1] -> b[q1..q2] -> a[p2..], the joints checked. */
        bool splice(const StatePath &a, const StatePath &b, double radius, bool twoPoint, StatePath &child);
        /** \brief Replace a piece (span a random share up to \e scale of the cost) by two motions through a
            valid state drawn near its middle. */
        bool detour(StatePath &path, double scale);
        /** \brief Replace a piece by a new local connect() between its ends (states drawn near the piece). */
        bool reconnect(StatePath &path, double scale, unsigned int maxNodes,
                       const std::function<bool()> &stop);

        /** \brief \e n states at equal cost along \e path (first and last its ends), each with the index of
            the segment it lies on. */
        void resample(const StatePath &path, unsigned int n, StatePath &out,
                      std::vector<std::size_t> *segments);

      private:
        /** \brief Drop consecutive duplicates (zero-length motions a piece split at a waypoint leaves). */
        static void dedupe(StatePath &path);
        /** \brief One pass of drops and pull moves over the dirty waypoints; \e held marks those that could
            not move. */
        bool pullPass(StatePath &path, std::vector<char> &dirty, std::vector<char> &held,
                      const std::function<bool()> &stop, bool precise);
        bool subdivide(StatePath &path, std::vector<char> &dirty, const std::vector<char> &held,
                       double maxTurn, unsigned int maxPoints);
        /** \brief The piece between arc positions: the ends' states and the segments they lie on. */
        bool pickPiece(const StatePath &path, double scale, StatePoint &p1, std::size_t &seg1, StatePoint &p2,
                       std::size_t &seg2);

        /** \brief Two trees of a connection, one from each end (tree 0 from \e from, motions parent -> child;
            tree 1 from \e to, child -> parent), the tree that extends next. Each tree state keeps its OMPL
            state: the nearest-state scans compute the space's distance on them directly (docs/spaces.md). */
        struct Connection
        {
            /** \brief A tree state: its coordinates, its parent (none for the root) and the state itself,
               kept for the nearest-state distances (no conversion per distance). */
            struct Node
            {
                StatePoint x;
                std::size_t parent;
                ompl::base::State *s;
            };
            explicit Connection(ompl::base::SpaceInformationPtr si);
            ~Connection();
            Connection(const Connection &) = delete;
            Connection &operator=(const Connection &) = delete;

            ompl::base::SpaceInformationPtr si;
            std::vector<Node> trees[2];
            /** \brief On a space with a symmetric distance and no car bounds: OMPL's GNAT over each tree's
                indices (exact nearest states; kQuery stands for \e query), else none (a linear scan). */
            std::unique_ptr<ompl::NearestNeighbors<std::size_t>> nn[2];
            int next{0};
            ompl::base::State *query;

            std::size_t size() const { return trees[0].size() + trees[1].size(); }
        };
        /** \brief Grow \e c until its trees join (Found, \e path from tree 0's root to tree 1's), they hold
            \e maxNodes states, or stop() holds. */
        ConnectResult grow(Connection &c, StatePath &path, double range, std::size_t maxNodes,
                           const Sampler &sample, const std::function<bool()> &stop, StatePath *closest,
                           double *closestDistance);
        /** \brief Whether the space's distance and interpolation are symmetric (both trees of a connection
            grow; else only the start tree, docs/spaces.md). */
        bool symmetricMotions() const;
        /** \brief Append \e x to tree \e t of \e c (its state made by the parametrisation); its index. */
        std::size_t addNode(Connection &c, int t, const StatePoint &x, std::size_t parent);

        struct KeyHash
        {
            std::size_t operator()(const std::vector<double> &k) const;
        };

        ompl::base::SpaceInformationPtr si_;
        const StateParametrisation &param_;
        /** \brief Lower bounds of the Dubins and Reeds-Shepp distances (inactive on other spaces), used to
            prune nearest-state scans. */
        CarBounds car_;
        /** \brief Pairs OMPL 1.5.2's Dubins code would abort on (docs/spaces.md, "OMPL's Dubins assertions").
         */
        DubinsGuard dubins_;
        ompl::RNG &rng_;
        ompl::base::OptimizationObjectivePtr opt_;
        unsigned int bisections_{10};
        double margin_{0.0};
        double strictSpacing_{0.0};
        bool strictRoutes_{false};
        /** \brief The fine check of a -> b: -1 when every state passes, else the first failing fraction. */
        double strictFailure(const StatePoint &a, const StatePoint &b);
        std::unordered_map<std::vector<double>, double, KeyHash> strictCache_;
        ompl::base::State *a_{nullptr};
        ompl::base::State *b_{nullptr};
        ompl::base::State *c_{nullptr};
        unsigned long motionChecks_{0};
        unsigned long stateChecks_{0};
        unsigned long cacheHits_{0};
        std::unordered_map<std::vector<double>, bool, KeyHash> cache_;
        // The lazy roadmap: states (0 = start, 1 = goal), directed edges (state 0 unknown, 1 valid, 2
        // refused).
        struct RoadmapEdge
        {
            std::uint32_t from, to;
            double cost;
            char state;
        };
        StatePath rmPoints_;
        std::vector<RoadmapEdge> rmEdges_;
        std::vector<std::vector<std::uint32_t>> rmOut_;
        std::vector<double> rmPenalty_;
        unsigned long roadmapDistances_{0};
        class RoadmapBounds;
        std::vector<double> key_;
    };
} // namespace mhplan

#endif
