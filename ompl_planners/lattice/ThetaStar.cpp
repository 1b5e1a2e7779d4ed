// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/lattice/ThetaStar.h"

#include <cmath>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr const int (&kDx)[8] = LatticeMoves::kDx;
        constexpr const int (&kDy)[8] = LatticeMoves::kDy;
    } // namespace

    ThetaStar::ThetaStar(const ob::SpaceInformationPtr &si) : LatticePlanner(si, "ThetaStar") {}

    double ThetaStar::heuristic(LatticeNode n) const
    {
        return distance(lattice_.position(n), goalPos_);
    }

    void ThetaStar::relax(LatticeNode s, const Vec2 &ps, LatticeNode n, const Vec2 &pn, double edgeCost,
                          bool edgeKnownValid, double hn)
    {
        const bool unseen = open_.unseen(n);
        const LatticeNode p = parent_[s];
        const Vec2 pp = nodePosition(p);
        // Path 2: straight from s's parent. It is never longer than path 1, so if it does not improve n,
        // neither does path 1.
        const double g2 = g_[p] + distance(pp, pn);
        if (!unseen && g2 >= g_[n])
            return;
        if (lattice_.motionValid(pp, pn))
        {
            g_[n] = g2;
            parent_[n] = p;
            open_.push(n, g2 + hn, g2);
            return;
        }
        // Path 1: over the lattice edge from s.
        const double g1 = g_[s] + edgeCost;
        if (!unseen && g1 >= g_[n])
            return;
        if (!edgeKnownValid && !lattice_.motionValid(ps, pn))
            return;
        g_[n] = g1;
        parent_[n] = s;
        open_.push(n, g1 + hn, g1);
    }

    LatticePlanner::SearchResult ThetaStar::search(const ob::PlannerTerminationCondition &ptc,
                                                   unsigned long maxExpansions)
    {
        const bool gridCells = lattice_.kind() == LatticeKind::GridCells;
        const int stride = lattice_.stride();
        const LatticeMoves moves(lattice_);
        const int *offset = moves.offset;
        const std::uint8_t *flags = lattice_.flags();
        const double *stepCost = moves.stepCost;

        unsigned long done = 0;
        while (!open_.empty())
        {
            LatticeOpenList::Item top;
            SearchResult stop;
            if (!beginExpansion(ptc, 63, maxExpansions, done, top, stop))
                return stop;
            const LatticeNode s = top.node;
            const Vec2 ps = lattice_.position(s);

            if ((flags[s] & Lattice::kGoalLink) != 0 && !open_.closed(goalNode_))
                relax(s, ps, goalNode_, goalPos_, goalLinkCost(s), true, 0.0);

            for (int d = 0; d < 8; ++d)
            {
                const LatticeNode n = s + offset[d];
                if (open_.closed(n))
                    continue;
                const bool diagonal = d >= 4;
                if (gridCells)
                {
                    if ((flags[n] & Lattice::kBlocked) != 0)
                        continue;
                    if (diagonal &&
                        ((flags[s + kDx[d]] | flags[s + kDy[d] * stride]) & Lattice::kBlocked) != 0)
                        continue;
                }
                else if (!lattice_.nodeFree(n))
                    continue;
                const Vec2 pn = lattice_.position(n);
                relax(s, ps, n, pn, stepCost[diagonal ? 1 : 0], gridCells, distance(pn, goalPos_));
            }
        }
        return SearchResult::Exhausted;
    }
} // namespace mhplan
