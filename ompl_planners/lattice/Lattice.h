// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the 8-connected lattice, the open list and the planner skeleton shared by the graph-search
   baselines (A* and Theta*). */
#ifndef MHPLAN_LATTICE_H
#define MHPLAN_LATTICE_H

#include "mhplan/base/Geometry.h"

#include <ompl/base/Planner.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace mhplan
{
    class OccupancyGrid;

    /** \brief Node index of a Lattice (padded row-major index; see Lattice). */
    using LatticeNode = std::uint32_t;

    /** \brief What the nodes of a Lattice are. */
    enum class LatticeKind
    {
        GridCells, ///< the cells of an occupancy grid (point robot, MovingAI move rules, no validator calls)
        Sampled    ///< a regular lattice of points, validity by the SpaceInformation (lazy, cached)
    };

    /** \brief A lattice node joined to a point that is not a node (start or goal) by a validated segment. */
    struct LatticeLink
    {
        /** \brief The lattice node. */
        LatticeNode node{0};
        /** \brief Euclidean length of the segment (0 when the point is the node's position). */
        double cost{0.0};
    };

    /** \brief An 8-connected lattice over a 2D RealVectorStateSpace problem.

        Nodes (i, j), 0 <= i < width(), 0 <= j < height(), sit at base + (i + offset, j + offset) * spacing
        (offset 0.5 for grid cells, so that positions equal OccupancyGrid::cellCenter bit for bit). They are
       stored with a one-node border of blocked padding, so a node's eight neighbours are at fixed index
       offsets and need no bounds checks: id(i, j) = (j + 1) * stride() + i + 1.

        - GridCells: the nodes are the cell centres of an occupancy grid; a node is free when its cell is. A
          straight move joins two free cells (cost: one cell size), a diagonal move needs both side cells
          free as well (cost: sqrt 2 cell sizes), as in the MovingAI benchmarks. Such moves are valid for the
          exact grid collision model of a point robot, so they need no motion-validator call.
        - Sampled: a node is free when the SpaceInformation says its state is valid (evaluated on first use,
          then cached); an edge is valid when SpaceInformation::checkMotion accepts it (the planner asks).

        Start and goal points that are not nodes are joined to nearby nodes by validated segments (connect()).
        Counts its validity and motion checks. Not thread-safe (one per planner). */
    class Lattice
    {
      public:
        /** \brief The node's flags: known free, blocked, joined to the goal. */
        static constexpr std::uint8_t kFree = 1;
        static constexpr std::uint8_t kBlocked = 2;
        static constexpr std::uint8_t kGoalLink = 4;

        Lattice() = default;
        ~Lattice();
        Lattice(const Lattice &) = delete;
        Lattice &operator=(const Lattice &) = delete;

        /** \brief The cells of \e grid as nodes (GridCells); checks go to \e si. */
        void buildFromGrid(const ompl::base::SpaceInformationPtr &si, const OccupancyGrid &grid);
        /** \brief A nx x ny lattice of points at origin + (i, j) * spacing (Sampled); throws
            std::invalid_argument when it would have more than kMaxNodes nodes. */
        void buildSampled(const ompl::base::SpaceInformationPtr &si, const Vec2 &origin, double spacing,
                          double nx, double ny);
        /** \brief Forget every cached validity and goal link (the lattice itself stays). */
        void resetFlags();

        /** \brief Largest number of nodes a lattice may have. */
        static constexpr std::size_t kMaxNodes = 100000000;

        LatticeKind kind() const { return kind_; }
        /** \brief Nodes across. */
        int width() const { return width_; }
        /** \brief Nodes up. */
        int height() const { return height_; }
        /** \brief Index distance between vertically adjacent nodes. */
        int stride() const { return width_ + 2; }
        /** \brief Number of node indices, padding included (ids are below this). */
        std::size_t size() const { return flags_.size(); }
        /** \brief Distance between adjacent nodes. */
        double spacing() const { return spacing_; }
        /** \brief Position of node (0, 0). */
        Vec2 origin() const { return {base_.x + offset_ * spacing_, base_.y + offset_ * spacing_}; }
        /** \brief True when a lattice has been built. */
        bool built() const { return !flags_.empty(); }

        LatticeNode id(int i, int j) const { return static_cast<LatticeNode>((j + 1) * stride() + i + 1); }
        int column(LatticeNode n) const { return static_cast<int>(n % static_cast<unsigned>(stride())) - 1; }
        int row(LatticeNode n) const { return static_cast<int>(n / static_cast<unsigned>(stride())) - 1; }
        Vec2 position(LatticeNode n) const
        {
            return {base_.x + (column(n) + offset_) * spacing_, base_.y + (row(n) + offset_) * spacing_};
        }
        /** \brief Fractional lattice coordinates of a point. */
        double latticeX(double x) const { return (x - base_.x) / spacing_ - offset_; }
        double latticeY(double y) const { return (y - base_.y) / spacing_ - offset_; }

        /** \brief The flag array (indexed by node). */
        std::uint8_t *flags() { return flags_.data(); }
        const std::uint8_t *flags() const { return flags_.data(); }

        /** \brief True when the node is free (evaluates and caches its validity on first use). */
        bool nodeFree(LatticeNode n)
        {
            const std::uint8_t f = flags_[n];
            if ((f & (kFree | kBlocked)) != 0)
                return (f & kFree) != 0;
            return evaluateNode(n);
        }

        /** \brief SpaceInformation::checkMotion between two positions (counted). */
        bool motionValid(const Vec2 &a, const Vec2 &b);

        /** \brief The nodes a point is joined to, by validated segments. GridCells: the free cells whose
           closed squares contain \e p (just its cell when \e p is a cell centre). Sampled: the free corners
           of the lattice square containing \e p. When none of these can be joined, the rings of nodes around
           \e p are searched outwards and the first ring with any joinable node is taken. Returns false when
           \e ptc stopped the ring search (\e out is then incomplete). */
        bool connect(const Vec2 &p, const ompl::base::PlannerTerminationCondition &ptc,
                     std::vector<LatticeLink> &out);

        /** \brief Validity checks made since the last resetCounts(). */
        unsigned long validityChecks() const { return validityChecks_; }
        /** \brief Motion checks made since the last resetCounts(). */
        unsigned long motionChecks() const { return motionChecks_; }
        void resetCounts() { validityChecks_ = motionChecks_ = 0; }

      private:
        bool evaluateNode(LatticeNode n);
        void releaseStates();
        void joinIfValid(const Vec2 &p, int i, int j, std::vector<LatticeLink> &out);

        LatticeKind kind_{LatticeKind::Sampled};
        ompl::base::SpaceInformationPtr si_;
        int width_{0};
        int height_{0};
        double spacing_{1.0};
        Vec2 base_;
        double offset_{0.0};
        std::vector<std::uint8_t> flags_;
        /** \brief GridCells: the flags of a fresh search (blocked padding, free and blocked cells). */
        std::vector<std::uint8_t> initialFlags_;
        ompl::base::State *stateA_{nullptr};
        ompl::base::State *stateB_{nullptr};
        unsigned long validityChecks_{0};
        unsigned long motionChecks_{0};
    };

    /** \brief Open and closed sets of a best-first search over a Lattice's nodes (plus virtual ones): a
       binary min-heap on f with ties broken towards larger g, and one flat array that says for each node
       whether it is unseen, closed, or where it sits in the heap (decrease-key in O(log n)). No allocation
       per node; reset() costs one pass over the array. */
    class LatticeOpenList
    {
      public:
        static constexpr std::uint32_t kUnseen = 0xFFFFFFFFu;
        static constexpr std::uint32_t kClosed = 0xFFFFFFFEu;

        /** \brief One heap entry. */
        struct Item
        {
            double f;
            double g;
            LatticeNode node;
        };

        /** \brief Make every one of \e nodes nodes unseen and the heap empty. */
        void reset(std::size_t nodes)
        {
            where_.assign(nodes, kUnseen);
            heap_.clear();
        }
        bool empty() const { return heap_.empty(); }
        std::size_t openCount() const { return heap_.size(); }
        /** \brief kUnseen, kClosed, or the node's heap position. */
        std::uint32_t where(LatticeNode n) const { return where_[n]; }
        bool unseen(LatticeNode n) const { return where_[n] == kUnseen; }
        bool closed(LatticeNode n) const { return where_[n] == kClosed; }
        /** \brief Mark a node closed without it ever being open (the virtual start). */
        void close(LatticeNode n) { where_[n] = kClosed; }

        /** \brief Insert an unseen node, or lower the key of an open one (the caller checked that \e g
            improves). */
        void push(LatticeNode n, double f, double g)
        {
            std::uint32_t pos = where_[n];
            if (pos == kUnseen)
            {
                pos = static_cast<std::uint32_t>(heap_.size());
                heap_.push_back({f, g, n});
            }
            siftUp(pos, {f, g, n});
        }

        /** \brief Remove and return the best item; its node becomes closed. */
        Item pop()
        {
            const Item top = heap_.front();
            where_[top.node] = kClosed;
            const Item last = heap_.back();
            heap_.pop_back();
            if (!heap_.empty())
                siftDown(0, last);
            return top;
        }

        /** \brief Bytes held per node by the flat array. */
        static constexpr std::size_t bytesPerNode() { return sizeof(std::uint32_t); }
        /** \brief Bytes per heap entry. */
        static constexpr std::size_t bytesPerOpenNode() { return sizeof(Item); }

      private:
        static bool before(const Item &a, const Item &b) { return a.f < b.f || (a.f == b.f && a.g > b.g); }

        void siftUp(std::uint32_t pos, const Item item)
        {
            while (pos > 0)
            {
                const std::uint32_t parent = (pos - 1) >> 1;
                if (!before(item, heap_[parent]))
                    break;
                heap_[pos] = heap_[parent];
                where_[heap_[pos].node] = pos;
                pos = parent;
            }
            heap_[pos] = item;
            where_[item.node] = pos;
        }

        void siftDown(std::uint32_t pos, const Item item)
        {
            const auto n = static_cast<std::uint32_t>(heap_.size());
            for (;;)
            {
                std::uint32_t child = 2 * pos + 1;
                if (child >= n)
                    break;
                if (child + 1 < n && before(heap_[child + 1], heap_[child]))
                    ++child;
                if (!before(heap_[child], item))
                    break;
                heap_[pos] = heap_[child];
                where_[heap_[pos].node] = pos;
                pos = child;
            }
            heap_[pos] = item;
            where_[item.node] = pos;
        }

        std::vector<Item> heap_;
        std::vector<std::uint32_t> where_;
    };

    /** \brief Base class of the lattice search planners (AStar, ThetaStar): parameters, the problem set-up
        (which lattice, start and goal links), search state, progress properties and solution reporting. A
        subclass writes only its search loop (search()).

        Problem: a 2D ompl::base::RealVectorStateSpace; the first start state and one goal sample. The
        lattice (parameter \c lattice): \c auto uses the cells of the occupancy grid when the validity checker
        is a mhplan::WorldValidityChecker over a mhplan::GridCollisionModel with a point robot, and a Sampled
        lattice otherwise; \c sampled always uses a Sampled lattice of spacing \c resolution (0 = automatic:
        the cell size on grid worlds, with nodes at the cell centres, else 1/100 of the larger extent of the
        bounds), centred in the bounds. Start and goal are virtual nodes joined to the lattice by validated
        segments (Lattice::connect).

        solve(): the first call sets the problem up; the search then runs until the goal is reached, the open
        list is empty, the termination condition holds (tested every 64 expansions, every 1024 on grid cells)
        or \c max_iterations further expansions are done (0 = no limit); a later call continues an
        interrupted search, and after the goal was reached re-reports the same path. clear() forgets
        everything. Deterministic: no random numbers.

        Reports an exact solution when the path reaches the goal and passes SpaceInformation::checkMotion on
        every segment (with collinear lattice moves merged into one segment), else an approximate one: the
        path to the expanded node with the smallest heuristic value. The reported cost is the problem's
        optimization objective's cost of the path (the search itself minimises path length). The
        intermediate-solution callback fires once, when the goal is reached. Progress properties \c best
        \c cost (infinity before a solution), \c iterations (node expansions) and \c motion \c checks are
        atomics, safe to read from the benchmark's sampling thread. */
    class LatticePlanner : public ompl::base::Planner
    {
      public:
        LatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);
        ~LatticePlanner() override;

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        /** \brief Refuses (OMPL_ERROR, then ompl::Exception) a space other than a 2D RealVectorStateSpace. */
        void setup() override;
        void clear() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** \brief Spacing of a Sampled lattice; 0 = automatic (0..1e6). */
        void setResolution(double r);
        double getResolution() const { return resolution_; }
        /** \brief "auto" (grid cells on grid worlds) or "sampled". */
        void setLattice(const std::string &lattice);
        std::string getLattice() const { return latticeName_; }
        /** \brief Node expansions per solve() call, 0 = until the search ends (0..1e9). */
        void setMaxIterations(unsigned int n);
        unsigned int getMaxIterations() const { return maxIterations_; }

        /** \brief Objective cost of the solution (infinity before one is found). */
        double bestCost() const { return bestCostValue_.load(); }
        /** \brief Node expansions since the last clear(). */
        unsigned long iterationCount() const { return iterationCount_.load(); }
        /** \brief Motion-validator calls since the last clear(). */
        unsigned long motionCheckCount() const { return motionCheckCount_.load(); }
        /** \brief The lattice in use (built by the first solve()). */
        const Lattice &lattice() const { return lattice_; }
        /** \brief Bytes of search state per lattice node, padding included: flags and their initial copy,
            open-list index, g, parent (18); each open node costs LatticeOpenList::bytesPerOpenNode() more. */
        static constexpr std::size_t bytesPerNode()
        {
            return 2 * sizeof(std::uint8_t) + LatticeOpenList::bytesPerNode() + sizeof(double) +
                   sizeof(LatticeNode);
        }

      protected:
        /** \brief How a call of search() ended. */
        enum class SearchResult
        {
            Found,       ///< the goal node was taken from the open list
            Exhausted,   ///< the open list ran empty: no path on this lattice
            Interrupted, ///< the termination condition holds
            Budget       ///< \c max_iterations expansions done in this call
        };

        /** \brief Continue the search (open list, g and parents as left by the last call) until it ends;
            at most \e maxExpansions expansions (0 = no limit). Count expansions with countExpansion() and
            publish counters with publishCounts() at least every time \e ptc is tested. */
        virtual SearchResult search(const ompl::base::PlannerTerminationCondition &ptc,
                                    unsigned long maxExpansions) = 0;
        /** \brief The search's heuristic (lower bound of the remaining length) at a lattice node. */
        virtual double heuristic(LatticeNode n) const = 0;

        /** \brief Remember an expanded node as the approximate solution when \e h is the smallest so far. */
        void noteExpanded(LatticeNode n, double h)
        {
            if (h < bestApproxH_)
            {
                bestApproxH_ = h;
                bestApprox_ = n;
            }
        }
        /** \brief Cost of the link from goal-linked node \e n to the goal. */
        double goalLinkCost(LatticeNode n) const;
        /** \brief Position of any search node (lattice or virtual). */
        Vec2 nodePosition(LatticeNode n) const
        {
            return n == startNode_ ? startPos_ : n == goalNode_ ? goalPos_ : lattice_.position(n);
        }
        /** \brief Copy the expansion and motion-check counts to the progress atomics. */
        void publishCounts()
        {
            iterationCount_.store(expansions_, std::memory_order_relaxed);
            motionCheckCount_.store(lattice_.motionChecks(), std::memory_order_relaxed);
        }

        Lattice lattice_;
        LatticeOpenList open_;
        /** \brief Path length from the start (valid for nodes that are not unseen). */
        std::vector<double> g_;
        /** \brief Predecessor on the best known path (valid for nodes that are not unseen). */
        std::vector<LatticeNode> parent_;
        /** \brief The virtual start and goal nodes (lattice_.size() and lattice_.size() + 1). */
        LatticeNode startNode_{0};
        LatticeNode goalNode_{0};
        Vec2 startPos_, goalPos_;
        /** \brief The goal in fractional lattice coordinates. */
        double goalU_{0.0}, goalV_{0.0};
        /** \brief Octile heuristic correction: max over goal links of (octile - Euclidean) link length, so
            that spacing * octile(node, goal) - slack is consistent (see AStar). */
        double goalSlack_{0.0};
        std::vector<LatticeLink> goalLinks_;
        /** \brief Expansions since clear() (published to the progress property by publishCounts()). */
        unsigned long expansions_{0};

      private:
        bool prepareProblem(const ompl::base::PlannerTerminationCondition &ptc,
                            ompl::base::PlannerStatus &status);
        void buildLattice();
        std::vector<LatticeNode> nodeChain(LatticeNode last) const;
        std::vector<Vec2> chainPoints(const std::vector<LatticeNode> &chain) const;
        double objectiveCost(const std::vector<Vec2> &points, ompl::base::Cost &cost);
        void reportPath(const std::vector<Vec2> &points, bool exact, double difference);

        double resolution_{0.0};
        std::string latticeName_{"auto"};
        unsigned int maxIterations_{0};

        bool problemReady_{false};
        bool linksReady_{false};
        bool finished_{false};
        bool found_{false};
        std::vector<Vec2> solution_;
        bool solutionExact_{false};
        double solutionDifference_{0.0};
        ompl::base::Cost solutionCost_;
        LatticeNode bestApprox_{0};
        double bestApproxH_{std::numeric_limits<double>::infinity()};
        ompl::base::State *costA_{nullptr};
        ompl::base::State *costB_{nullptr};
        /** \brief States handed to PlannerData (it keeps the pointers): owned here until clear(). */
        mutable std::vector<ompl::base::State *> plannerDataStates_;

        std::atomic<double> bestCostValue_;
        std::atomic<unsigned long> iterationCount_{0};
        std::atomic<unsigned long> motionCheckCount_{0};
    };
} // namespace mhplan

#endif
