// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/lattice/AStar.h"

#include <cmath>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr double kSqrt2 = LatticeMoves::kSqrt2;
        constexpr const int (&kDx)[8] = LatticeMoves::kDx;
        constexpr const int (&kDy)[8] = LatticeMoves::kDy;
    } // namespace

    AStar::AStar(const ob::SpaceInformationPtr &si) : LatticePlanner(si, "AStar") {}

    double AStar::heuristic(LatticeNode n) const
    {
        const double a = std::fabs(lattice_.column(n) - goalU_);
        const double b = std::fabs(lattice_.row(n) - goalV_);
        const double sp = lattice_.spacing();
        return sp * (std::max(a, b) + (kSqrt2 - 1.0) * std::min(a, b)) - goalSlack_;
    }

    LatticePlanner::SearchResult AStar::search(const ob::PlannerTerminationCondition &ptc,
                                               unsigned long maxExpansions)
    {
        return lattice_.kind() == LatticeKind::GridCells ? run<true>(ptc, maxExpansions)
                                                         : run<false>(ptc, maxExpansions);
    }

    template <bool GridCells>
    LatticePlanner::SearchResult AStar::run(const ob::PlannerTerminationCondition &ptc,
                                            unsigned long maxExpansions)
    {
        // Grid cells are cheap to expand: test the condition less often than on sampled lattices, where
        // every expansion may call the motion validator eight times.
        constexpr unsigned long checkMask = GridCells ? 1023 : 63;
        const int stride = lattice_.stride();
        const LatticeMoves moves(lattice_);
        const int *offset = moves.offset;
        std::uint8_t *flags = lattice_.flags();
        double *g = g_.data();
        LatticeNode *parent = parent_.data();
        const double sp = lattice_.spacing();
        const double *stepCost = moves.stepCost;
        const double k = (kSqrt2 - 1.0) * sp;
        const double gu = goalU_, gv = goalV_, slack = goalSlack_;
        const auto h = [=](int i, int j)
        {
            const double a = std::fabs(i - gu), b = std::fabs(j - gv);
            return (a > b ? sp * a + k * b : sp * b + k * a) - slack;
        };
        const LatticeNode goal = goalNode_;

        unsigned long done = 0;
        while (!open_.empty())
        {
            LatticeOpenList::Item top;
            SearchResult stop;
            if (!beginExpansion(ptc, checkMask, maxExpansions, done, top, stop))
                return stop;
            const LatticeNode s = top.node;

            if ((flags[s] & Lattice::kGoalLink) != 0 && !open_.closed(goal))
            {
                const double ng = top.g + goalLinkCost(s);
                if (open_.unseen(goal) || ng < g[goal])
                {
                    g[goal] = ng;
                    parent[goal] = s;
                    open_.push(goal, ng, ng);
                }
            }

            const int i = lattice_.column(s), j = lattice_.row(s);
            const Vec2 ps = GridCells ? Vec2() : lattice_.position(s);
            for (int d = 0; d < 8; ++d)
            {
                const LatticeNode n = s + offset[d];
                const std::uint32_t where = open_.where(n);
                if (where == LatticeOpenList::kClosed)
                    continue;
                const bool diagonal = d >= 4;
                if (GridCells)
                {
                    // MovingAI: the target cell free, and for a diagonal both side cells too.
                    if ((flags[n] & Lattice::kBlocked) != 0)
                        continue;
                    if (diagonal &&
                        ((flags[s + kDx[d]] | flags[s + kDy[d] * stride]) & Lattice::kBlocked) != 0)
                        continue;
                }
                else if (!lattice_.nodeFree(n))
                    continue;
                const double ng = top.g + stepCost[diagonal ? 1 : 0];
                if (where != LatticeOpenList::kUnseen && ng >= g[n])
                    continue;
                if (!GridCells && !lattice_.motionValid(ps, lattice_.position(n)))
                    continue;
                g[n] = ng;
                parent[n] = s;
                open_.push(n, ng + h(i + kDx[d], j + kDy[d]), ng);
            }
        }
        return SearchResult::Exhausted;
    }
} // namespace mhplan
