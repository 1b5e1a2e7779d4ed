// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' lazy roadmap on states (docs/spaces.md, "First paths: a lazy roadmap on
   states"): uniform valid states in the incumbent's informed set, directed k-nearest edges under the space's
   distance, A* routes under route penalties, only the edges of a found route checked (in their direction).
   Part of MemeticStateToolkit. */
#include "ompl_planners/memetic/MemeticStateToolkit.h"
#include "ompl_planners/memetic/RoadmapSearch.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace ob = ompl::base;

namespace mhplan
{
    void MemeticStateToolkit::roadmapClear()
    {
        rmPoints_.clear();
        rmEdges_.clear();
        rmOut_.clear();
        rmPenalty_.clear();
    }

    bool MemeticStateToolkit::roadmapGrow(unsigned int n, const StatePoint &start, const StatePoint &goal,
                                          double bound, const std::function<bool()> &stop)
    {
        // Keep the samples inside the informed set, add n new ones (rejected outside it before any check).
        StatePath points{start, goal};
        auto inside = [&](const StatePoint &q)
        { return !std::isfinite(bound) || distance(start, q) + distance(q, goal) < bound; };
        for (std::size_t i = 2; i < rmPoints_.size(); ++i)
            if (inside(rmPoints_[i]))
                points.push_back(rmPoints_[i]);
        StatePoint q;
        for (unsigned int k = 0, tries = 0; k < n && tries < 20 * n; ++tries)
        {
            if ((tries & 63u) == 0 && stop())
                return false;
            sampleUniform(q);
            if (!inside(q))
                continue;
            ++k;
            if (pointValid(q))
                points.push_back(q);
        }
        rmPoints_.swap(points);
        const std::size_t m = rmPoints_.size();
        const auto kn = std::min<std::size_t>(
            m - 1, static_cast<std::size_t>(std::ceil(std::exp(1.0) * (1.0 + 1.0 / param_.dimension()) *
                                                      std::log(double(std::max<std::size_t>(m, 2))))));
        rmEdges_.clear();
        rmOut_.assign(m, {});
        rmPenalty_.assign(m, 0.0);
        const ob::StateSpacePtr &space = si_->getStateSpace();
        const bool symmetric = space->hasSymmetricDistance() && space->hasSymmetricInterpolate();
        // On the car spaces the positions' distance bounds the path length from below (both ways): the
        // candidates are visited in order of it and the scan stops once it exceeds both k-th distances.
        std::vector<std::pair<double, std::uint32_t>> order, outs, ins;
        order.reserve(m);
        for (std::size_t i = 0; i < m; ++i)
        {
            if ((i & 15u) == 0 && stop())
                return false;
            order.clear();
            for (std::size_t j = 0; j < m; ++j)
                if (j != i)
                    order.emplace_back(positionBound_ ? std::hypot(rmPoints_[i][0] - rmPoints_[j][0],
                                                                   rmPoints_[i][1] - rmPoints_[j][1]) *
                                                            (1.0 - 1e-9)
                                                      : 0.0,
                                       static_cast<std::uint32_t>(j));
            if (positionBound_)
                std::sort(order.begin(), order.end());
            outs.clear();
            ins.clear();
            // Max-heaps of the k nearest (out: distance(i, j); in: distance(j, i)).
            for (const auto &[lb, j] : order)
            {
                if (positionBound_ && outs.size() >= kn && lb > outs.front().first &&
                    (symmetric || (ins.size() >= kn && lb > ins.front().first)))
                    break;
                const double dOut = distance(rmPoints_[i], rmPoints_[j]);
                if (outs.size() < kn || dOut < outs.front().first)
                {
                    outs.emplace_back(dOut, j);
                    std::push_heap(outs.begin(), outs.end());
                    if (outs.size() > kn)
                    {
                        std::pop_heap(outs.begin(), outs.end());
                        outs.pop_back();
                    }
                }
                if (symmetric)
                    continue;
                const double dIn = distance(rmPoints_[j], rmPoints_[i]);
                if (ins.size() < kn || dIn < ins.front().first)
                {
                    ins.emplace_back(dIn, j);
                    std::push_heap(ins.begin(), ins.end());
                    if (ins.size() > kn)
                    {
                        std::pop_heap(ins.begin(), ins.end());
                        ins.pop_back();
                    }
                }
            }
            const auto u = static_cast<std::uint32_t>(i);
            auto add = [&](std::uint32_t a, std::uint32_t b)
            {
                rmOut_[a].push_back(static_cast<std::uint32_t>(rmEdges_.size()));
                rmEdges_.push_back({a, b, segmentCost(rmPoints_[a], rmPoints_[b]), 0});
            };
            for (const auto &e : outs)
            {
                add(u, e.second);
                if (symmetric)
                    add(e.second, u); // duplicates are harmless: their checks hit the motion cache
            }
            for (const auto &e : ins)
                add(e.second, u);
        }
        return true;
    }

    bool MemeticStateToolkit::roadmapPath(StatePath &path, unsigned int maxInvalid,
                                          const std::function<bool()> &stop)
    {
        const std::size_t m = rmPoints_.size();
        if (m < 2)
            return false;
        // The space's distance to the goal bounds the remaining length from below: admissible for path length
        // only (other objectives: Dijkstra).
        const bool length =
            !opt_ || dynamic_cast<const ob::PathLengthOptimizationObjective *>(opt_.get()) != nullptr;
        std::vector<double> h(m, 0.0);
        if (length)
            for (std::size_t v = 0; v < m; ++v)
                h[v] = distance(rmPoints_[v], rmPoints_[1]);
        std::vector<double> g(m);
        std::vector<std::uint32_t> via(m);
        std::vector<std::uint32_t> nodes, edges;
        unsigned int refused = 0;
        while (true)
        {
            if (stop())
                return false;
            if (!penalisedRoadmapSearch(
                    rmOut_, rmEdges_, [](const RoadmapEdge &edge, std::uint32_t) { return edge.to; },
                    [](const RoadmapEdge &edge) { return edge.cost; }, h, rmPenalty_, g, via))
                return false; // the goal is cut off in the roadmap
            nodes.clear();
            edges.clear();
            for (std::uint32_t v = 1; v != 0; v = rmEdges_[via[v]].from)
            {
                nodes.push_back(v);
                edges.push_back(via[v]);
            }
            nodes.push_back(0);
            std::reverse(nodes.begin(), nodes.end());
            std::reverse(edges.begin(), edges.end());
            bool valid = true;
            for (const std::uint32_t id : edges)
            {
                RoadmapEdge &edge = rmEdges_[id];
                if (edge.state == 0)
                    edge.state = motionValid(rmPoints_[edge.from], rmPoints_[edge.to]) ? 1 : 2;
                valid = valid && edge.state == 1;
            }
            if (valid)
                break;
            if (++refused >= maxInvalid)
                return false;
        }
        path.clear();
        for (const std::uint32_t v : nodes)
            path.push_back(rmPoints_[v]);
        // Penalise the route and its neighbourhood: the next route takes another way.
        std::vector<char> hit(m, 0);
        for (const std::uint32_t v : nodes)
        {
            hit[v] = 1;
            for (const std::uint32_t id : rmOut_[v])
                hit[rmEdges_[id].to] = 1;
        }
        for (std::size_t v = 2; v < m; ++v)
            if (hit[v])
                rmPenalty_[v] += 1.0;
        return true;
    }
} // namespace mhplan
