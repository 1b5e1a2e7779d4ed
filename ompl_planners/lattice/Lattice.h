// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the 8-connected lattice the graph-search baselines (A* and Theta*) search; the open list is in
   LatticeOpenList.h, the planner skeleton in LatticePlanner.h. */
#ifndef MHPLAN_LATTICE_H
#define MHPLAN_LATTICE_H

#include "src/base/Geometry.h"

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
} // namespace mhplan

#endif
