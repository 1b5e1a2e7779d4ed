// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' segment verdicts in the plane: the segment cache and the validator margin
   (docs/variants.md, "No corner the validator cannot see" and "Checks"): a loose verdict (the motion
   validator alone) for the search, a strict one (the margin too) for every path the planner reports. Part of
   MemeticToolkit. */
#include "ompl_planners/memetic/MemeticToolkit.h"

#include "src/collision/Validity.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace mhplan
{
    namespace
    {
        // Cached verdicts: the motion validator's, and the margin's when it was asked for.
        constexpr char kInvalid = 0;
        constexpr char kValid = 1;       // the validator accepts, the margin not checked yet
        constexpr char kMarginValid = 2; // both accept
        constexpr char kMarginInvalid = 3;
    } // namespace

    bool MemeticToolkit::motionValid(const Vec2 &a, const Vec2 &b)
    {
        if (!inBounds(a) || !inBounds(b))
            return false;
        const bool strict = strict_ && margin_ > 0.0;
        // An unchanged segment is never checked twice (docs/variants.md, "Checks").
        const SegmentKey key{a.x, a.y, b.x, b.y};
        auto it = cache_.find(key);
        if (it == cache_.end())
        {
            ++motionChecks_;
            setStatePosition(a_, a);
            setStatePosition(b_, b);
            const bool valid = si_->checkMotion(a_, b_);
            if (cache_.size() >= (std::size_t(1) << 20))
                cache_.clear();
            it = cache_.emplace(key, valid ? kValid : kInvalid).first;
        }
        else if (it->second == kInvalid || !strict || it->second != kValid)
            ++cacheHits_;
        if (it->second == kInvalid)
            return false;
        if (!strict)
            return true;
        if (it->second == kValid)
            it->second = marginValid(a, b) ? kMarginValid : kMarginInvalid;
        return it->second == kMarginValid;
    }

    bool MemeticToolkit::marginValid(const Vec2 &a, const Vec2 &b)
    {
        // The validator margin (docs/variants.md, "No corner the validator cannot see"). Detection: the two
        // copies of the segment shifted by the margin m to either side are sampled every 2m (the validator's
        // spacing s at the default m = s / 2); an obstacle the segment touches or enters is crossed by the
        // copy on its side over a chord of at least 2m (a disc of radius R >= m, a corner of 90 degrees or
        // more), so some copy sample falls inside it. Nothing is refused for that: only there, within 2m
        // on either side along the segment, the segment is verified closely: its copies shifted by the
        // clearance c to either side are checked every 2c. A segment that touches or cuts an obstacle there
        // puts the copy on that side inside it over a chord of at least 2c, which those samples see. So
        // the path keeps about c from obstacles near it, and a passage wider than 2c stays usable (with the
        // plain sideways copies it had to be wider than 2m). The start and the goal are not shifted (the
        // copies fan out from them).
        const Vec2 d = b - a;
        const double l = norm(d);
        if (l <= 0.0)
            return true;
        const Vec2 n(-d.y / l, d.x / l);
        const double wa = a == fixedA_ || a == fixedB_ ? 0.0 : 1.0;
        const double wb = b == fixedA_ || b == fixedB_ ? 0.0 : 1.0;
        const auto shifted = [&](double t, double offset)
        { return a + d * t + n * (offset * ((1.0 - t) * wa + t * wb)); };
        ++marginChecks_;
        const double spacing = 2.0 * margin_;
        const auto samples = static_cast<unsigned int>(std::ceil(l / spacing));
        const double reach = spacing / l; // 2m along the segment, as a fraction of it
        windows_.clear();
        for (unsigned int k = 0; k <= samples; ++k)
        {
            const double t = double(k) / double(samples);
            bool near = false;
            for (const double side : {1.0, -1.0})
            {
                const Vec2 p = shifted(t, side * margin_);
                if (inBounds(p) && !checkPoint(p))
                    near = true;
            }
            if (!near)
                continue;
            const double lo = std::max(0.0, t - reach), hi = std::min(1.0, t + reach);
            if (!windows_.empty() && lo <= windows_.back().second)
                windows_.back().second = hi;
            else
                windows_.emplace_back(lo, hi);
        }
        if (clearance_ <= 0.0)
            return windows_.empty();
        for (const auto &w : windows_)
        {
            const auto fine = std::max(
                1u, static_cast<unsigned int>(std::ceil((w.second - w.first) * l / (2.0 * clearance_))));
            for (unsigned int k = 0; k <= fine; ++k)
            {
                const double t = w.first + (w.second - w.first) * double(k) / double(fine);
                for (const double side : {1.0, -1.0})
                {
                    const Vec2 p = shifted(t, side * clearance_);
                    if (inBounds(p) && !checkPoint(p))
                        return false;
                }
            }
        }
        return true;
    }

    bool MemeticToolkit::checkPoint(const Vec2 &p)
    {
        setStatePosition(c_, p);
        return si_->isValid(c_);
    }

    bool MemeticToolkit::makeStrict(MemeticPath &path, const std::function<bool()> &stop)
    {
        if (margin_ <= 0.0)
            return true;
        // A path tightened against the validator alone touches obstacles at its turning waypoints, on the
        // inner side of each turn. Push the waypoints of every segment the margin refuses outward (away from
        // the chord of their neighbours) by 2c, 4c, ... until every segment passes; a segment between the
        // start and the goal gets a midpoint, pushed to whichever side works.
        const StrictScope strict(*this);
        const double base = clearance_ > 0.0 ? 2.0 * clearance_ : margin_;
        for (unsigned int round = 0; round < 8; ++round)
        {
            bool all = true;
            for (std::size_t i = 1; i < path.size(); ++i)
            {
                if (motionValid(path[i - 1], path[i]))
                    continue;
                all = false;
                if (i == 1 && i + 1 == path.size())
                {
                    path.insert(path.begin() + 1, (path[0] + path[1]) * 0.5);
                    ++i;
                    continue;
                }
                for (const std::size_t j : {i - 1, i})
                    if (j > 0 && j + 1 < path.size())
                        pushOut(path, j, base * double(1u << round));
            }
            if (all)
                return true;
            if (stop())
                return false;
        }
        return pathValid(path);
    }

    void MemeticToolkit::pushOut(MemeticPath &path, std::size_t j, double step)
    {
        const Vec2 &u = path[j - 1], &w = path[j + 1], v = path[j];
        const Vec2 c = w - u;
        const double cc = dot(c, c);
        const double t = cc > 0.0 ? std::min(1.0, std::max(0.0, dot(v - u, c) / cc)) : 0.0;
        Vec2 dir = v - (u + c * t);
        double l = norm(dir);
        const bool straight = l <= 1e-12 * (1.0 + std::sqrt(cc));
        if (straight)
        {
            if (cc <= 0.0)
                return;
            dir = Vec2(-c.y, c.x);
            l = std::sqrt(cc);
        }
        for (const double side : {1.0, -1.0})
        {
            const Vec2 q = v + dir * (side * step / l);
            const bool was = strict_;
            strict_ = false; // a pushed waypoint need only be valid; the margin is asked of the next round
            const bool ok = pointValid(q) && motionValid(u, q) && motionValid(q, w);
            strict_ = was;
            if (ok)
            {
                path[j] = q;
                return;
            }
            if (!straight)
                return;
        }
    }
} // namespace mhplan
