// SPDX-License-Identifier: BSD-3-Clause
/* PopulationPlanner: the switchable [GMS] operator steps (see the class doc; docs/algorithms.md 1.5): on the
   initial population (gms_initial), and after each iteration the path operators on the operated individuals
   with greedy re-insertion, the replacement of the worst, and the re-encoding of an operated polyline into m
   waypoints. */
#include "ompl_planners/common/PopulationPlanner.h"

#include "ompl_planners/common/Operators.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace mhplan
{
    void PopulationPlanner::prepareGmsOps()
    {
        if (gmsOps_)
            return;
        const Box box{lower_[0], upper_[0], lower_[1], upper_[1]};
        gmsOps_ =
            std::make_unique<PathOperators>(*fitness_, rng_, box, 0.01 * std::max(box.width(), box.height()));
        const std::size_t points = std::max<std::size_t>(
            2 * (waypoints_ + 2), (decoding_ == PathDecoding::Spline ? splineSamples_ : 0) + 2);
        gmsPath_.reserve(2 * points + 64);
        gmsCandidate_.assign(dimension(), 0.0);
        gmsOrder_.resize(populationSize_);
    }

    bool PopulationPlanner::applyGmsInitial()
    {
        double *x = nullptr, *f = nullptr;
        if (!gms_.initial || !realVector_ || spaceDim_ != 2 || !populationView(x, f))
            return true;
        prepareGmsOps();
        const unsigned int d = dimension();
        bool completed = true;
        for (unsigned int i = 0; i < populationSize_ && completed; ++i)
            completed = operateOn(x + std::size_t(i) * d, f[i], true);
        populationChanged();
        return completed;
    }

    bool PopulationPlanner::applyGmsOperators()
    {
        double *x = nullptr, *f = nullptr;
        if (!realVector_ || spaceDim_ != 2 || !populationView(x, f))
            return true; // setup() refuses this; never reached with the switches on
        const unsigned int n = populationSize_, d = dimension();
        prepareGmsOps();
        unsigned int best = 0;
        for (unsigned int i = 1; i < n; ++i)
            if (f[i] < f[best])
                best = i;
        bool completed = true;
        if (gms_.pathOperators())
            for (unsigned int i = 0; i < n && completed; ++i)
                if (gms_.scopeAll || i == best)
                    completed = operateOn(x + std::size_t(i) * d, f[i]);
        if (completed && gms_.replaceFraction > 0.0)
        {
            // Rank again (the operators may have changed fitness values), worst first.
            for (unsigned int i = 1; i < n; ++i)
                if (f[i] < f[best])
                    best = i;
            for (unsigned int i = 0; i < n; ++i)
                gmsOrder_[i] = i;
            // std::sort with an index tie-break: deterministic, and unlike std::stable_sort it allocates no
            // temporary buffer.
            std::sort(gmsOrder_.begin(), gmsOrder_.end(),
                      [f](unsigned int a, unsigned int b) { return f[a] > f[b] || (f[a] == f[b] && a < b); });
            const auto count = std::min<unsigned int>(
                n - 1, static_cast<unsigned int>(std::ceil(gms_.replaceFraction * n - 1e-9)));
            for (unsigned int k = 0, done = 0; k < n && done < count; ++k)
            {
                const unsigned int i = gmsOrder_[k];
                if (i == best)
                    continue;
                if (stopRequested())
                {
                    completed = false;
                    break;
                }
                double *xi = x + std::size_t(i) * d;
                randomPosition(xi);
                if (gms_.repair)
                    for (unsigned int w = 0; w < waypoints_; ++w)
                    {
                        Vec2 p(xi[2 * w], xi[2 * w + 1]);
                        gmsOps_->repairNode(p);
                        xi[2 * w] = p.x;
                        xi[2 * w + 1] = p.y;
                    }
                clampToBounds(xi);
                f[i] = evaluate(xi);
                ++done;
                // gms_initial: a new individual gets the initial population's operators too.
                if (gms_.initial && !operateOn(xi, f[i], true))
                {
                    completed = false;
                    break;
                }
            }
        }
        populationChanged();
        return completed;
    }

    bool PopulationPlanner::operateOn(double *x, double &fx, bool initial)
    {
        decoder_.decode(x);
        const PointsView path = decoder_.pathView();
        gmsPath_.clear();
        for (std::size_t i = 0; i < path.size(); ++i)
            gmsPath_.emplace_back(path[i][0], path[i][1]);
        // The initial step: [GMS]'s node repair, line-segment repair, node improvement; every iteration: the
        // switched-on operators in the GA's order.
        if (initial || gms_.repair)
        {
            gmsOps_->repairNodes(gmsPath_);
            gmsOps_->repairSegments(gmsPath_);
        }
        if (!initial && gms_.revise)
            gmsOps_->revise(gmsPath_);
        if (!initial && gms_.simplify)
            gmsOps_->simplify(gmsPath_);
        if (initial || gms_.improve)
            gmsOps_->improveNodes(gmsPath_);
        encodePath();
        clampToBounds(gmsCandidate_.data());
        if (stopRequested())
            return false;
        const double fc = evaluate(gmsCandidate_.data());
        if (fc < fx)
        {
            std::copy(gmsCandidate_.begin(), gmsCandidate_.end(), x);
            fx = fc;
        }
        return true;
    }

    void PopulationPlanner::encodePath()
    {
        const std::size_t m = waypoints_;
        std::vector<Vec2> &p = gmsPath_;
        if (p.size() < 2)
            return;
        if (p.size() - 2 <= m)
        {
            // Keep the interior points; halve the longest segment until there are m of them.
            while (p.size() - 2 < m)
            {
                std::size_t longest = 1;
                double len = -1.0;
                for (std::size_t i = 1; i < p.size(); ++i)
                {
                    const double l = distance(p[i - 1], p[i]);
                    if (l > len)
                    {
                        len = l;
                        longest = i;
                    }
                }
                const Vec2 mid = (p[longest - 1] + p[longest]) * 0.5;
                p.insert(p.begin() + static_cast<std::ptrdiff_t>(longest), mid);
            }
            for (std::size_t w = 0; w < m; ++w)
            {
                gmsCandidate_[2 * w] = p[w + 1].x;
                gmsCandidate_[2 * w + 1] = p[w + 1].y;
            }
            return;
        }
        // More interior points than waypoints: m points at equal arc length.
        double total = 0.0;
        for (std::size_t i = 1; i < p.size(); ++i)
            total += distance(p[i - 1], p[i]);
        std::size_t seg = 1;
        double before = 0.0; // arc length at p[seg - 1]
        for (std::size_t w = 0; w < m; ++w)
        {
            const double s = total * double(w + 1) / double(m + 1);
            while (seg + 1 < p.size() && before + distance(p[seg - 1], p[seg]) < s)
            {
                before += distance(p[seg - 1], p[seg]);
                ++seg;
            }
            const double l = distance(p[seg - 1], p[seg]);
            const double u = l > 0.0 ? std::min(1.0, std::max(0.0, (s - before) / l)) : 0.0;
            const Vec2 q = p[seg - 1] + (p[seg] - p[seg - 1]) * u;
            gmsCandidate_[2 * w] = q.x;
            gmsCandidate_[2 * w + 1] = q.y;
        }
    }

} // namespace mhplan
