// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the planner skeleton shared by the graph-search baselines (A* and Theta*). */
#ifndef MHPLAN_LATTICE_PLANNER_H
#define MHPLAN_LATTICE_PLANNER_H

#include "mhplan/planners/common/PlannerBase.h"
#include "mhplan/planners/lattice/Lattice.h"
#include "mhplan/planners/lattice/LatticeOpenList.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The eight moves of the 8-connected lattice, one table for A* and Theta*: four straight ones
        first, then the diagonals; node offsets by the lattice's stride and the two step lengths. */
    struct LatticeMoves
    {
        static constexpr double kSqrt2 = 1.41421356237309504880;
        static constexpr int kDx[8] = {1, -1, 0, 0, 1, -1, 1, -1};
        static constexpr int kDy[8] = {0, 0, 1, -1, 1, 1, -1, -1};

        explicit LatticeMoves(const Lattice &lattice)
            : stepCost{lattice.spacing(), lattice.spacing() * kSqrt2}
        {
            for (int d = 0; d < 8; ++d)
                offset[d] = kDy[d] * lattice.stride() + kDx[d];
        }
        /** \brief Node id difference of move d. */
        int offset[8];
        /** \brief Length of a straight (0) and of a diagonal (1) move. */
        double stepCost[2];
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
    class LatticePlanner : public PlannerBase
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
        /** \brief The head of every expansion of A* and Theta*: every checkMask + 1 expansions publish the
            counts and test \e ptc (Interrupted), stop after \e maxExpansions in this call (Budget, 0 = no
            limit), take the best node from the open list (Found when it is the goal). False with \e result
            when the search stops here; else the expansion of \e top is counted (\e done too) and noted. */
        bool beginExpansion(const ompl::base::PlannerTerminationCondition &ptc, unsigned long checkMask,
                            unsigned long maxExpansions, unsigned long &done, LatticeOpenList::Item &top,
                            SearchResult &result)
        {
            if ((expansions_ & checkMask) == 0)
            {
                publishCounts();
                if (ptc())
                {
                    result = SearchResult::Interrupted;
                    return false;
                }
            }
            if (maxExpansions != 0 && done >= maxExpansions)
            {
                result = SearchResult::Budget;
                return false;
            }
            top = open_.pop();
            if (top.node == goalNode_)
            {
                result = SearchResult::Found;
                return false;
            }
            ++expansions_;
            ++done;
            noteExpanded(top.node, top.f - top.g);
            return true;
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

        std::atomic<unsigned long> motionCheckCount_{0};
    };
} // namespace mhplan

#endif
