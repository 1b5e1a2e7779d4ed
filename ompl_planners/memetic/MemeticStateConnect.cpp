// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the randomised bidirectional connections of the memetic planners' state mode (docs/spaces.md,
   "The memetic planners off the plane"): two trees grown toward each other within a budget of states, each
   tree state kept with its OMPL state, so that a nearest-state scan computes the space's distance without
   converting coordinates. */
#include "ompl_planners/memetic/MemeticStateToolkit.h"

#include <ompl/datastructures/NearestNeighborsGNATNoThreadSafety.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr std::size_t kNoParent = std::numeric_limits<std::size_t>::max();
        /** \brief The index that stands for the connection's query state in its GNAT. */
        constexpr std::size_t kQuery = std::numeric_limits<std::size_t>::max() - 1;
    } // namespace

    MemeticStateToolkit::Connection::Connection(ob::SpaceInformationPtr space)
        : si(std::move(space)), query(si->allocState())
    {
    }

    MemeticStateToolkit::Connection::~Connection()
    {
        for (std::vector<Node> &tree : trees)
            for (Node &n : tree)
                si->freeState(n.s);
        si->freeState(query);
    }

    std::size_t MemeticStateToolkit::addNode(Connection &c, int t, const StatePoint &x, std::size_t parent)
    {
        ob::State *s = si_->allocState();
        toState(x, s);
        c.trees[t].push_back({x, parent, s});
        if (c.nn[t])
            c.nn[t]->add(c.trees[t].size() - 1);
        return c.trees[t].size() - 1;
    }

    bool MemeticStateToolkit::symmetricMotions() const
    {
        const ob::StateSpacePtr &space = si_->getStateSpace();
        return space->hasSymmetricDistance() && space->hasSymmetricInterpolate();
    }

    MemeticStateToolkit::ConnectResult MemeticStateToolkit::connect(
        StatePath &path, const StatePoint &from, const StatePoint &to, double range, unsigned int maxNodes,
        const Sampler &sample, const std::function<bool()> &stop, StatePath *closest, double *closestDistance)
    {
        if (motionValid(from, to))
        {
            path = {from, to};
            return ConnectResult::Found;
        }
        Connection c(si_);
        if (!car_.active() && symmetricMotions())
            for (int t = 0; t < 2; ++t)
            {
                // Exact nearest states in O(log n) per query on large trees (the planner's budgets reach
                // 80,000 states, docs/spaces.md); a linear scan would be quadratic in the tree.
                c.nn[t] = std::make_unique<ompl::NearestNeighborsGNATNoThreadSafety<std::size_t>>();
                const std::vector<Connection::Node> &tree = c.trees[t];
                const ob::State *query = c.query;
                c.nn[t]->setDistanceFunction(
                    [this, &tree, query](const std::size_t &i, const std::size_t &j) {
                        return dubins_.distance(*si_, i == kQuery ? query : tree[i].s,
                                                j == kQuery ? query : tree[j].s);
                    });
            }
        addNode(c, 0, from, kNoParent);
        addNode(c, 1, to, kNoParent);
        return grow(c, path, range, maxNodes, sample, stop, closest, closestDistance);
    }

    MemeticStateToolkit::ConnectResult MemeticStateToolkit::grow(Connection &c, StatePath &path, double range,
                                                                 std::size_t maxNodes, const Sampler &sample,
                                                                 const std::function<bool()> &stop,
                                                                 StatePath *closest, double *closestDistance)
    {

        // The nearest state of tree t to c.query: tree 0 grows from the start (motions parent -> child),
        // tree 1 from the goal (child -> parent), so the distance runs from the tree state in tree 0 and to
        // it in tree 1. With a symmetric distance and no car bounds: OMPL's GNAT (exact; its pivots come from
        // a generator of its own, which changes which of equal nearest states it returns, not the distance).
        // Else an exact scan (the first of equal nearest states, as OMPL's linear structure returns; GNAT is
        // not exact under an asymmetric distance). On the car spaces CarBounds bound the path length from
        // below (docs/spaces.md): states whose bound exceeds the best distance so far are skipped, which
        // saves most of the Dubins or Reeds-Shepp distances of a scan.
        std::vector<double> bound;
        // The scans also leave the nearest state's distance in \e nearestD (GNAT does not: NaN).
        double nearestD = 0.0;
        auto nearest = [&](int t, const StatePoint &target) -> std::size_t
        {
            nearestD = std::numeric_limits<double>::quiet_NaN();
            if (c.nn[t])
                return c.nn[t]->nearest(kQuery);
            const std::vector<Connection::Node> &tree = c.trees[t];
            const auto dist = [&](std::size_t i) {
                return t == 0 ? dubins_.distance(*si_, tree[i].s, c.query)
                              : dubins_.distance(*si_, c.query, tree[i].s);
            };
            std::size_t best = 0;
            double bestD = dist(0);
            if (!car_.active())
            {
                for (std::size_t i = 1; i < tree.size(); ++i)
                {
                    const double d = dist(i);
                    if (d < bestD)
                    {
                        bestD = d;
                        best = i;
                    }
                }
                nearestD = bestD;
                return best;
            }
            bound.resize(tree.size());
            const CarPose q(target[0], target[1], target[2]);
            auto pose = [&](std::size_t i) { return CarPose(tree[i].x[0], tree[i].x[1], tree[i].x[2]); };
            std::size_t m = 0;
            for (std::size_t i = 0; i < tree.size(); ++i)
            {
                // The basic bound holds either way; the tighter one is computed only where it may prune.
                bound[i] = car_.basic(CarPose(tree[i].x[0], tree[i].x[1], tree[i].x[2], false), q);
                if (bound[i] < bound[m])
                    m = i;
            }
            if (m != 0)
            {
                const double d = dist(m);
                if (d < bestD)
                {
                    bestD = d;
                    best = m;
                }
            }
            for (std::size_t i = 1; i < tree.size(); ++i)
            {
                if (i == m || bound[i] > bestD)
                    continue;
                if (car_.forward && (t == 0 ? car_.lower(pose(i), q) : car_.lower(q, pose(i))) > bestD)
                    continue;
                const double d = dist(i);
                if (d < bestD || (d == bestD && i < best))
                {
                    bestD = d;
                    best = i;
                }
            }
            nearestD = bestD;
            return best;
        };
        const StatePoint to = c.trees[1][0].x; // the goal tree's root
        // 0: blocked, 1: advanced, 2: reached the target. From the nearest tree state, or from \e from (a
        // state just added: a connection goes on from where it got).
        auto extend = [&](int t, const StatePoint &target, std::size_t &added,
                          std::size_t from = kNoParent) -> int
        {
            toState(target, c.query);
            const std::size_t n = from != kNoParent ? from : nearest(t, target);
            const StatePoint from0 = c.trees[t][n].x;
            // The scan's distance where it found n (one distance less per extension).
            const double d = from == kNoParent && !std::isnan(nearestD) ? nearestD
                             : t == 0 ? dubins_.distance(*si_, c.trees[t][n].s, c.query)
                                      : dubins_.distance(*si_, c.query, c.trees[t][n].s);
            const bool reach = d <= range;
            StatePoint q;
            if (reach)
                q = target;
            else
                interpolate(from0, target, range / d, q);
            if (!pointValid(q))
                return 0;
            if (!(t == 0 ? motionValid(from0, q) : motionValid(q, from0)))
                return 0;
            added = addNode(c, t, q, n);
            if (t == 0 && closest != nullptr && closestDistance != nullptr)
            {
                const double dg = dubins_.distance(*si_, c.trees[0][added].s, c.trees[1][0].s);
                if (dg < *closestDistance)
                {
                    *closestDistance = dg;
                    closest->clear();
                    for (std::size_t k = added; k != kNoParent; k = c.trees[0][k].parent)
                        closest->push_back(c.trees[0][k].x);
                    std::reverse(closest->begin(), closest->end());
                }
            }
            return reach ? 2 : 1;
        };
        // On a space whose motions are not reversible (Dubins) a tree grown from the goal would hold states
        // the goal is not reachable from: there only the start tree grows, and after each step it is extended
        // toward the goal itself until it reaches it or is blocked.
        const bool bidirectional = symmetricMotions();
        unsigned long attempts = 0;
        StatePoint r;
        while (c.size() < maxNodes && attempts < 20ul * maxNodes)
        {
            ++attempts;
            if (stop())
                return ConnectResult::Stopped;
            if (!sample(r))
                continue;
            std::size_t a = 0;
            if (!bidirectional)
            {
                if (extend(0, r, a) == 0)
                    continue;
                int res = 1;
                for (bool first = true; res == 1 && c.trees[0].size() < maxNodes; first = false)
                {
                    if (stop())
                        return ConnectResult::Stopped;
                    res = extend(0, to, a, first ? kNoParent : a);
                }
                if (res == 2)
                {
                    path.clear();
                    for (std::size_t k = a; k != kNoParent; k = c.trees[0][k].parent)
                        path.push_back(c.trees[0][k].x);
                    std::reverse(path.begin(), path.end());
                    return ConnectResult::Found;
                }
                continue;
            }
            const int t = c.next;
            c.next = 1 - c.next;
            if (extend(t, r, a) != 0)
            {
                const StatePoint target = c.trees[t][a].x;
                const int other = 1 - t;
                std::size_t b = 0;
                int res = 1;
                for (bool first = true; res == 1 && c.size() < maxNodes; first = false)
                {
                    if (stop())
                        return ConnectResult::Stopped;
                    res = extend(other, target, b, first ? kNoParent : b);
                }
                if (res == 2)
                {
                    const std::size_t s = t == 0 ? a : b, g = t == 0 ? b : a;
                    path.clear();
                    for (std::size_t k = s; k != kNoParent; k = c.trees[0][k].parent)
                        path.push_back(c.trees[0][k].x);
                    std::reverse(path.begin(), path.end());
                    for (std::size_t k = c.trees[1][g].parent; k != kNoParent; k = c.trees[1][k].parent)
                        path.push_back(c.trees[1][k].x);
                    return ConnectResult::Found;
                }
            }
        }
        return ConnectResult::Budget;
    }
} // namespace mhplan
