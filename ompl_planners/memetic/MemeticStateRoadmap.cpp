// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' lazy roadmap on states (docs/spaces.md, "First paths: a lazy roadmap on
   states"): uniform valid states in the incumbent's informed set, directed k-nearest edges under the space's
   distance (found with lower bounds: pivots, and the car bounds on the Dubins and Reeds-Shepp spaces), A*
   routes under route penalties, only the edges of a found route checked (in their direction). Part of
   MemeticStateToolkit. */
#include "ompl_planners/memetic/CarBounds.h"
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
    /** \brief Lower bounds of the space's distance between the roadmap's states, for its k-nearest search
        (docs/spaces.md, "First paths: a lazy roadmap on states"). Pivots (LAESA): the distances from and to
        a few far-apart states are computed once; since the distance is a shortest length, the directed
        triangle inequality d(a, c) <= d(a, b) + d(b, c) bounds every other one from below: d(i, j) >=
        d(i, p) - d(j, p) and d(i, j) >= d(p, j) - d(p, i) (so also under Dubins' asymmetric distance). On
        the car spaces also CarBounds::lower(). */
    class MemeticStateToolkit::RoadmapBounds
    {
      public:
        RoadmapBounds(const ob::SpaceInformationPtr &si, const StateParametrisation &param,
                      const StatePath &points, bool symmetric, const DubinsGuard &dubins)
            : si_(si), m_(points.size()), symmetric_(symmetric), car_(si->getStateSpace().get()),
              dubins_(dubins)
        {
            states_.reserve(m_);
            for (const StatePoint &p : points)
            {
                states_.push_back(si_->allocState());
                param.fromVector(p.data(), states_.back());
                if (car_.active())
                    poses_.emplace_back(p[0], p[1], p[2]);
            }
            // OMPL's symmetric Dubins distance (the shorter direction) need not meet the triangle
            // inequality: no pivots there.
            const bool pivots = !(car_.active() && !car_.forward && symmetric_ &&
                                  dynamic_cast<const ob::DubinsStateSpace *>(si_->getStateSpace().get()));
            // Farthest-first pivots (under the larger of the two directions), the start first.
            std::vector<double> spread(m_, std::numeric_limits<double>::infinity());
            std::size_t next = 0;
            for (std::size_t p = 0; pivots && p < std::min(m_, kPivots); ++p)
            {
                const std::size_t base = to_.size();
                to_.resize(base + m_);
                from_.resize(symmetric_ ? 0 : base + m_);
                for (std::size_t x = 0; x < m_; ++x)
                {
                    to_[base + x] = distance(next, x);
                    if (!symmetric_)
                        from_[base + x] = distance(x, next);
                    spread[x] = std::min(spread[x], symmetric_ ? to_[base + x]
                                                               : std::max(to_[base + x], from_[base + x]));
                }
                next = std::size_t(std::max_element(spread.begin(), spread.end()) - spread.begin());
                ++pivots_;
            }
        }

        ~RoadmapBounds()
        {
            for (ob::State *s : states_)
                si_->freeState(s);
        }
        RoadmapBounds(const RoadmapBounds &) = delete;
        RoadmapBounds &operator=(const RoadmapBounds &) = delete;

        /** \brief The space's distance from state \e i to state \e j (counted). */
        double distance(std::size_t i, std::size_t j)
        {
            ++evaluations_;
            return dubins_.distance(*si_, states_[i], states_[j]);
        }

        /** \brief The pivots' lower bounds of distance(i, j) into \e out[j] and of distance(j, i) into
            \e in[j] (shrunk for rounding: never above the distance). */
        void pivotBounds(std::size_t i, std::vector<double> &out, std::vector<double> &in) const
        {
            std::fill(out.begin(), out.end(), 0.0);
            std::fill(in.begin(), in.end(), 0.0);
            for (std::size_t p = 0; p < pivots_; ++p)
            {
                const double *to = to_.data() + p * m_;
                const double ti = to[i];
                if (symmetric_)
                {
                    for (std::size_t j = 0; j < m_; ++j)
                        out[j] = std::max(out[j], std::abs(ti - to[j]));
                    continue;
                }
                const double *fr = from_.data() + p * m_;
                const double fi = fr[i];
                for (std::size_t j = 0; j < m_; ++j)
                {
                    out[j] = std::max(out[j], std::max(fi - fr[j], to[j] - ti));
                    in[j] = std::max(in[j], std::max(fr[j] - fi, ti - to[j]));
                }
            }
            for (std::size_t j = 0; j < m_; ++j)
            {
                out[j] = out[j] * (1.0 - 1e-9) - 1e-12;
                in[j] = symmetric_ ? out[j] : in[j] * (1.0 - 1e-9) - 1e-12;
            }
        }

        /** \brief CarBounds::basic() between states i and j (0 off the car spaces). */
        double carBasic(std::size_t i, std::size_t j) const
        {
            return car_.active() ? car_.basic(poses_[i], poses_[j]) : 0.0;
        }
        /** \brief CarBounds::lower() of distance(i, j) (0 off the car spaces). */
        double carLower(std::size_t i, std::size_t j) const
        {
            return car_.active() ? car_.lower(poses_[i], poses_[j]) : 0.0;
        }

        unsigned long evaluations() const { return evaluations_; }

      private:
        static constexpr std::size_t kPivots = 16;
        ob::SpaceInformationPtr si_;
        std::size_t m_;
        bool symmetric_;
        CarBounds car_;
        const DubinsGuard &dubins_;
        std::vector<ob::State *> states_;
        std::vector<CarPose> poses_;
        std::vector<double> to_, from_;
        std::size_t pivots_{0};
        unsigned long evaluations_{0};
    };

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
        // Path length: an edge's cost is the distance the neighbour search computed.
        const bool length =
            !opt_ || dynamic_cast<const ob::PathLengthOptimizationObjective *>(opt_.get()) != nullptr;
        RoadmapBounds bounds(si_, param_, rmPoints_, symmetric, dubins_);
        std::vector<double> lbOut(m), lbIn(m);
        std::vector<std::pair<double, std::uint32_t>> order, outs, ins;
        order.reserve(m);
        // Max-heaps of the k nearest (out: distance(i, j); in: distance(j, i)); a candidate's distance is
        // computed only when its lower bound could beat the k-th one.
        auto offer = [kn](std::vector<std::pair<double, std::uint32_t>> &heap, double d, std::uint32_t j)
        {
            if (heap.size() >= kn && !(d < heap.front().first))
                return;
            heap.emplace_back(d, j);
            std::push_heap(heap.begin(), heap.end());
            if (heap.size() > kn)
            {
                std::pop_heap(heap.begin(), heap.end());
                heap.pop_back();
            }
        };
        auto beaten = [kn](const std::vector<std::pair<double, std::uint32_t>> &heap, double lb)
        { return heap.size() >= kn && lb >= heap.front().first; };
        for (std::size_t i = 0; i < m; ++i)
        {
            if ((i & 15u) == 0 && stop())
            {
                // Interrupted: the roadmap is left as it was (its samples; the next call rebuilds its
                // edges). Keeping the new samples made every interrupted call add more, so that under short
                // budgets (OMPL's planner tests solve for 1 ms, 10 ms, 0.1 s) the roadmap outgrew what a
                // call could finish and the planner stopped checking anything (tests/test_ompl_protocols).
                rmPoints_.swap(points);
                rmEdges_.clear();
                rmOut_.clear();
                rmPenalty_.clear();
                return false;
            }
            bounds.pivotBounds(i, lbOut, lbIn);
            // Each direction scans the candidates in the order of their bound (pivots, the basic car bound)
            // and stops at the first one that cannot beat its k-th distance: no later candidate can. The
            // tighter car bound (Dubins) is computed only for a candidate reached.
            auto scan = [&](const std::vector<double> &lb,
                            std::vector<std::pair<double, std::uint32_t>> &heap, bool out)
            {
                order.clear();
                for (std::size_t j = 0; j < m; ++j)
                    if (j != i)
                        order.emplace_back(std::max(lb[j], bounds.carBasic(i, j)),
                                           static_cast<std::uint32_t>(j));
                // Only the 2 k lowest sorted: past them the k-th distance is near its last value.
                const std::size_t head = std::min(order.size(), 2 * kn);
                std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(head), order.end());
                std::sort(order.begin(), order.begin() + std::ptrdiff_t(head));
                heap.clear();
                for (std::size_t q = 0; q < order.size(); ++q)
                {
                    const auto [bound, j] = order[q];
                    if (beaten(heap, bound))
                    {
                        if (q < head)
                            break; // every later bound is at least this one
                        continue;
                    }
                    if (!beaten(heap, out ? bounds.carLower(i, j) : bounds.carLower(j, i)))
                        offer(heap, out ? bounds.distance(i, j) : bounds.distance(j, i), j);
                }
            };
            scan(lbOut, outs, true);
            ins.clear();
            if (!symmetric)
                scan(lbIn, ins, false);
            const auto u = static_cast<std::uint32_t>(i);
            auto add = [&](std::uint32_t a, std::uint32_t b, double d)
            {
                rmOut_[a].push_back(static_cast<std::uint32_t>(rmEdges_.size()));
                rmEdges_.push_back({a, b, length ? d : segmentCost(rmPoints_[a], rmPoints_[b]), 0});
            };
            // Nearest first, ties by index: the edges do not depend on the scan's order.
            std::sort(outs.begin(), outs.end());
            std::sort(ins.begin(), ins.end());
            for (const auto &e : outs)
            {
                add(u, e.second, e.first);
                if (symmetric)
                    add(e.second, u, e.first); // duplicates are harmless: their checks hit the motion cache
            }
            for (const auto &e : ins)
                add(e.second, u, e.first);
        }
        roadmapDistances_ += bounds.evaluations();
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
            if (valid && strictRoutes_ && strictNeeded())
            {
                for (const std::uint32_t id : edges)
                {
                    // Verdicts cached (strictFailure): a later route through the same edge costs nothing.
                    RoadmapEdge &edge = rmEdges_[id];
                    if (strictFailure(rmPoints_[edge.from], rmPoints_[edge.to]) >= 0.0)
                    {
                        edge.state = 2;
                        valid = false;
                    }
                }
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
