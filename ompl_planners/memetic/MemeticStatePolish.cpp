// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' local search on state paths (docs/spaces.md, the state mode): shortcuts,
   pulling waypoints toward their neighbours' connection, subdivision, the tightening passes built from them
   and the cost-first random perturbation of a polished path. */
#include "ompl_planners/memetic/MemeticStateToolkit.h"
#include "ompl_planners/memetic/PathShortcut.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace mhplan
{
    void MemeticStateToolkit::shortcut(StatePath &path, const std::function<bool()> &stop)
    {
        greedyShortcut(
            path, [this](const auto &a, const auto &b) { return motionValid(a, b); }, stop);
    }

    bool MemeticStateToolkit::pullToward(const StatePoint &a, StatePoint &v, const StatePoint &b,
                                         const StatePoint &target, unsigned int steps)
    {
        const double now = segmentCost(a, v) + segmentCost(v, b);
        StatePoint w;
        auto valid = [&](double t)
        {
            interpolate(v, target, t, w);
            return motionValid(a, w) && motionValid(w, b);
        };
        double lo = 0.0;
        if (valid(1.0))
            lo = 1.0;
        else
        {
            double hi = 1.0;
            for (unsigned int k = 0; k < steps; ++k)
            {
                const double mid = 0.5 * (lo + hi);
                if (valid(mid))
                    lo = mid;
                else
                    hi = mid;
            }
        }
        if (lo < 1.0 && margin_ > 0.0)
        {
            // Blocked: stay the margin (in the space's distance) short of the contact (docs/spaces.md). The
            // position stepped back to is checked too (the motions from a state between v and the
            // bisection's may meet what neither of theirs meets: free space need not be convex); when they
            // do, v stays.
            const double d = distance(v, target);
            lo = d > 0.0 ? lo - margin_ / d : 0.0;
            if (lo > 0.0 && !valid(lo))
                return false;
        }
        if (lo <= 0.0)
            return false;
        interpolate(v, target, lo, w);
        const double after = segmentCost(a, w) + segmentCost(w, b);
        if (!(after < now - 1e-12 * now))
            return false;
        v.swap(w);
        return true;
    }

    bool MemeticStateToolkit::pullPass(StatePath &path, std::vector<char> &dirty, std::vector<char> &held,
                                       const std::function<bool()> &stop, bool precise)
    {
        bool changed = false;
        std::vector<char> next(path.size(), 0);
        held.assign(path.size(), 0);
        const unsigned int steps = precise ? std::max(bisections_, 24u) : std::min(bisections_, 6u);
        StatePoint m;
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
        {
            if (!dirty[i])
                continue;
            if (stop())
                return changed;
            const StatePoint &a = path[i - 1], &b = path[i + 1];
            // A waypoint its neighbours see past is dropped (not one just inserted by the subdivision: it
            // lies on the motion its neighbours span, and is there for its neighbour's pull).
            if (dirty[i] != 2 && motionValid(a, b))
            {
                path.erase(path.begin() + static_cast<std::ptrdiff_t>(i));
                dirty.erase(dirty.begin() + static_cast<std::ptrdiff_t>(i));
                next.erase(next.begin() + static_cast<std::ptrdiff_t>(i));
                held.erase(held.begin() + static_cast<std::ptrdiff_t>(i));
                next[i - 1] = 1;
                if (i < next.size())
                    next[i] = 1;
                changed = true;
                --i;
                continue;
            }
            interpolate(a, b, 0.5, m);
            bool moved = pullToward(a, path[i], b, m, steps);
            moved = pullToward(a, path[i], b, a, steps) || moved;
            moved = pullToward(a, path[i], b, b, steps) || moved;
            if (moved)
            {
                changed = true;
                next[i - 1] = next[i] = next[i + 1] = 1;
            }
            else
                held[i] = 1; // held by a contact on one of its motions: subdivision may free it
        }
        next.front() = next.back() = 0;
        dirty.swap(next);
        return changed;
    }

    bool MemeticStateToolkit::subdivide(StatePath &path, std::vector<char> &dirty,
                                        const std::vector<char> &held, double maxTurn, unsigned int maxPoints)
    {
        if (path.size() < 3 || path.size() >= maxPoints || held.size() != path.size())
            return false;
        const double threshold = 1.0 / std::cos(0.5 * std::min(maxTurn, 3.0)) - 1.0;
        std::vector<char> sharp(path.size(), 0);
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
        {
            if (!held[i])
                continue;
            const double chord = segmentCost(path[i - 1], path[i + 1]);
            const double around = segmentCost(path[i - 1], path[i]) + segmentCost(path[i], path[i + 1]);
            sharp[i] = chord > 0.0 && around / chord - 1.0 > threshold;
        }
        StatePath out;
        std::vector<char> outDirty;
        bool split = false;
        StatePoint mid;
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            out.push_back(path[i]);
            outDirty.push_back(dirty[i] ? 1 : 0);
            if (i + 1 >= path.size() || !(sharp[i] || sharp[i + 1]) ||
                out.size() + (path.size() - i) >= maxPoints)
                continue;
            interpolate(path[i], path[i + 1], 0.5, mid);
            if (!motionValid(path[i], mid) || !motionValid(mid, path[i + 1]))
                continue;
            out.push_back(mid);
            outDirty.push_back(2);
            split = true;
        }
        if (split)
        {
            path.swap(out);
            dirty.swap(outDirty);
        }
        return split;
    }

    bool MemeticStateToolkit::tighten(StatePath &path, double maxTurn, double relTol, unsigned int maxPasses,
                                      const std::function<bool()> &stop, unsigned int maxPoints, bool precise,
                                      const PassReport &afterPass)
    {
        dedupe(path);
        shortcut(path, stop);
        std::vector<char> dirty(path.size(), 1), held;
        double len = cost(path);
        if (afterPass && !stop())
            afterPass(path, len);
        for (unsigned int pass = 0; pass < maxPasses; ++pass)
        {
            if (stop())
                return false;
            // Only waypoints the previous pass could not move are subdivided around.
            const bool split = subdivide(path, dirty, held, maxTurn, maxPoints);
            const bool changed = pullPass(path, dirty, held, stop, precise);
            const double now = cost(path);
            if (afterPass && changed && !stop())
                afterPass(path, now);
            if (!changed && !split)
                break;
            if (len - now < relTol * len && pass > 0)
                break;
            len = now;
        }
        return !stop();
    }

    bool MemeticStateToolkit::perturb(StatePath &path, double &step, unsigned int tries,
                                      const std::function<bool()> &stop)
    {
        // Cost first: the objective's motion costs are far cheaper than a motion check (a certified validator
        // steps along the whole motion), so a candidate that cannot lower the cost is never checked.
        bool changed = false;
        StatePoint w(param_.dimension());
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
        {
            if (stop())
                return changed;
            const StatePoint &a = path[i - 1], &b = path[i + 1];
            const double now = segmentCost(a, path[i]) + segmentCost(path[i], b);
            bool moved = false;
            for (unsigned int k = 0; k < tries && !moved; ++k)
            {
                for (unsigned int c = 0; c < param_.dimension(); ++c)
                {
                    const double d = step * (param_.upper(c) - param_.lower(c));
                    w[c] = path[i][c] + rng_.uniformReal(-d, d);
                }
                param_.enforce(w.data());
                const double after = segmentCost(a, w) + segmentCost(w, b);
                if (!(after < now - 1e-12 * now))
                    continue;
                if (!pointValid(w) || !motionValid(a, w) || !motionValid(w, b))
                    continue;
                path[i] = w;
                moved = true;
            }
            if (moved)
            {
                changed = true;
                step = std::min(0.1, 2.0 * step);
            }
            else
                step = std::max(1e-6, 0.7 * step);
        }
        return changed;
    }
} // namespace mhplan
