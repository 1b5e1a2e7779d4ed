// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the memetic planners' segment verdicts in the plane: the segment cache and the validator margin
   (docs/variants.md, "No corner the validator cannot see" and "Checks"): a loose verdict (the motion
   validator alone) for the search, a strict one (the margin too) for every path the planner reports. Part of
   MemeticToolkit. */
#include "ompl_planners/memetic/MemeticToolkit.h"

#include "ompl_planners/memetic/detail/SegmentCaches.h"

#include "src/collision/Validity.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <utility>

namespace mhplan
{

    namespace
    {
        // Cached verdicts: the motion validator's, and the margin's when it was asked for.
        constexpr char kInvalid = 0;
        constexpr char kValid = 1;         // the validator accepts, the margin not checked yet
        constexpr char kMarginValid = 2;   // both accept
        constexpr char kMarginInvalid = 3; // the margin refuses (obstacles on both sides, or no clearance)
        constexpr char kFineValid = 4;     // the margin accepts, and so does the fine check
        constexpr char kFineInvalid = 5;   // the margin accepts, the fine check refuses (refusedAt)
        constexpr char kMarginNarrow = 6;  // kMarginInvalid, and the segment's own points near the refusal
                                           // are valid (a passage narrower than the smallest clearance)
        // 8 + 2k (+ 1): the margin refuses: an obstacle on the left (right) of a -> b within the clearance c
        // halved k times (the level at which only that side found one).
        constexpr char kMarginSided = 8;

    } // namespace

    bool MemeticToolkit::motionValid(const Vec2 &a, const Vec2 &b)
    {
        if (!inBounds(a) || !inBounds(b))
            return false;
        const bool strict = strict_ && margin_ > 0.0;
        // An unchanged segment is never checked twice (docs/variants.md, "Checks").
        const SegmentKey key{a.x, a.y, b.x, b.y};
        auto &verdicts = caches_->verdicts;
        auto it = verdicts.find(key);
        char *code = it == verdicts.end() ? nullptr : &it->second;
        if (code == nullptr)
        {
            ++motionChecks_;
            setStatePosition(a_, a);
            setStatePosition(b_, b);
            bool valid = si_->checkMotion(a_, b_);
            if (valid && margin_ > 0.0 && fineStep_ > 0.0 && spacing_ > 0.0)
            {
                // The search's own verdict looks closer next to both ends too: the fine check's samples
                // within s of each end (docs/variants.md, "The fine check"). A pull puts a bend against the
                // corner it wraps; the validator then tests the bend and the next state s away, so the search
                // pulled bends across corners (through the diagonal pinches of a maze's walls) that no push
                // of the margin could undo, and the path counted as invalid.
                const double l = distance(a, b);
                double t = 0.0;
                valid = l <= 2.0 * spacing_
                            ? fineCheck(a, b, t) // the two ends' stretches cover it
                            : fineCheck(a, b, t, 0.0, spacing_) && fineCheck(a, b, t, l - spacing_, l);
            }
            code = &remember(key, valid ? kValid : kInvalid);
        }
        else if (*code == kInvalid || !strict || *code != kValid)
            ++cacheHits_;
        if (*code == kInvalid)
            return false;
        if (!strict)
            return true;
        if (*code == kValid)
            *code = strictCode(a, b, key); // touches refusedAt only, so the pointer stays valid
        return *code == kMarginValid || *code == kFineValid;
    }

    char MemeticToolkit::strictCode(const Vec2 &a, const Vec2 &b, const SegmentKey &key)
    {
        // The margin's verdict of a segment the validator accepts, then the fine check near the hazards.
        char code = marginValid(a, b) ? kMarginValid
                    : hitSide_ == 0   ? kMarginInvalid
                                      : static_cast<char>(kMarginSided + 2 * hitLevel_ + (hitSide_ < 0));
        if (code != kMarginValid)
            caches_->refusedAt[key] = hitAt_;
        double t = 0.0;
        if (code == kMarginValid && !nearHazardsValid(a, b, t))
        {
            code = kFineInvalid;
            caches_->refusedAt[key] = t;
        }
        return code;
    }

    char &MemeticToolkit::remember(const SegmentKey &key, char code)
    {
        if (caches_->verdicts.size() >= (std::size_t(1) << 20))
        {
            caches_->verdicts.clear();
            caches_->refusedAt.clear();
        }
        return caches_->verdicts.emplace(key, code).first->second;
    }

    bool MemeticToolkit::nearHazardsValid(const Vec2 &a, const Vec2 &b, double &t)
    {
        // Where the fine check once failed (an obstacle the validator and the margin missed), every strict
        // verdict looks again with it: the samples of the fine check within s along the segment of each such
        // point within s of it (docs/variants.md, "The fine check"), so that the elite polish does not pull
        // the path back across what the fine check found.
        if (hazards_.empty() || fineStep_ <= 0.0)
            return true;
        const Vec2 d = b - a;
        const double ll = dot(d, d);
        if (ll <= 0.0)
            return true;
        const double l = std::sqrt(ll), r = spacing_;
        const double x0 = std::min(a.x, b.x) - r, x1 = std::max(a.x, b.x) + r;
        const double y0 = std::min(a.y, b.y) - r, y1 = std::max(a.y, b.y) + r;
        for (const Vec2 &h : hazards_)
        {
            if (h.x < x0 || h.x > x1 || h.y < y0 || h.y > y1)
                continue;
            const double u = std::min(1.0, std::max(0.0, dot(h - a, d) / ll));
            if (squaredNorm(a + d * u - h) > r * r)
                continue;
            if (!fineCheck(a, b, t, u * l - r, u * l + r))
                return false;
        }
        return true;
    }

    int MemeticToolkit::refusedSide(const Vec2 &a, const Vec2 &b, double &clearance) const
    {
        const auto it = caches_->verdicts.find(SegmentKey{a.x, a.y, b.x, b.y});
        if (it == caches_->verdicts.end() || it->second < kMarginSided)
            return 0;
        const int code = it->second - kMarginSided;
        clearance = std::ldexp(clearance_, -(code / 2));
        return code % 2 == 0 ? 1 : -1;
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
        // The copies fan out from a fixed end over min(s, l) (over the whole segment without s): beyond s
        // from the start and the goal they are at their full offset, so the chord argument holds there.
        const bool fa = a == fixedA_ || a == fixedB_, fb = b == fixedA_ || b == fixedB_;
        const double ramp = spacing_ > 0.0 ? std::min(spacing_, l) : l;
        const auto shifted = [&](double t, double offset)
        {
            double w = 1.0;
            if (fa)
                w = std::min(w, t * l / ramp);
            if (fb)
                w = std::min(w, (1.0 - t) * l / ramp);
            return a + d * t + n * (offset * w);
        };
        ++marginChecks_;
        hitSide_ = 0;
        hitLevel_ = 0;
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
        {
            if (!windows_.empty())
                hitAt_ = 0.5 * (windows_.front().first + windows_.front().second);
            return windows_.empty();
        }
        for (const auto &w : windows_)
        {
            // The clearance adapts to the passage (docs/variants.md, "validator_min_clearance"): where the
            // copies on both sides hit obstacles, the segment runs through a gap narrower than 2c; the
            // window is checked again with c halved (copies every c), down to the smallest clearance. A
            // segment that touches or enters an obstacle is refused at every level (the copy on that side
            // enters it over a chord of at least twice the level's clearance), so only the clearance kept
            // changes, never the guarantee.
            hitLevel_ = 0;
            for (double c = clearance_;; c *= 0.5, ++hitLevel_)
            {
                const auto fine =
                    std::max(1u, static_cast<unsigned int>(std::ceil((w.second - w.first) * l / (2.0 * c))));
                bool hit[2] = {false, false};
                // The first run of samples inside an obstacle on each side (its first and last sample): where
                // a one-sided contact is. A side is no longer sampled once its run has ended.
                double first[2] = {0.0, 0.0}, last[2] = {0.0, 0.0};
                bool ended[2] = {false, false};
                for (unsigned int k = 0; k <= fine && !(hit[0] && hit[1]); ++k)
                {
                    const double t = w.first + (w.second - w.first) * double(k) / double(fine);
                    for (int side = 0; side < 2; ++side)
                    {
                        if (ended[side])
                            continue;
                        const Vec2 p = shifted(t, side == 0 ? c : -c);
                        if (!inBounds(p) || checkPoint(p))
                        {
                            ended[side] = hit[side];
                            continue;
                        }
                        if (!hit[side])
                            first[side] = t;
                        last[side] = t;
                        hit[side] = true;
                    }
                }
                if (!hit[0] && !hit[1])
                    break; // this window passes
                if (!(hit[0] && hit[1]) || minClearance_ <= 0.0 || 0.5 * c < minClearance_ * (1.0 - 1e-9))
                {
                    hitSide_ = hit[0] == hit[1] ? 0 : hit[0] ? 1 : -1;
                    // One side: the middle of the samples inside the obstacle (where makeStrict may put a
                    // waypoint); both sides: the window's middle (where crossesObstacle looks).
                    const int side = hit[0] ? 0 : 1;
                    hitAt_ = hitSide_ != 0 ? 0.5 * (first[side] + last[side]) : 0.5 * (w.first + w.second);
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

    bool MemeticToolkit::makeStrict(MemeticPath &path, const std::function<bool()> &stop,
                                    std::size_t *refused)
    {
        if (refused != nullptr)
            *refused = 0;
        if (margin_ <= 0.0)
            return true;
        // A path tightened against the validator alone touches obstacles. The margin says on which side of a
        // refused segment it found the obstacle within the clearance (c, or c halved in a passage): the
        // segment's movable ends are shifted away from it along the segment's normal by that clearance per
        // round (halved down to twice the smallest clearance where that point is not valid: a narrow
        // passage). Where the margin cannot tell the side (obstacles on both sides, or validator_clearance
        // 0), the ends are pushed outward (away from the chord of their neighbours) by 2c, 4c, ...; a segment
        // between the start and the goal gets a midpoint first.
        // A segment the margin accepts then gets the fine check (docs/variants.md, "The fine check"); one it
        // refuses gets a waypoint beside its first failing sample.
        const StrictScope strict(*this);
        const double base = clearance_ > 0.0 ? 2.0 * clearance_ : margin_;
        for (unsigned int round = 0; round < 12; ++round)
        {
            bool all = true;
            for (std::size_t i = 1; i < path.size(); ++i)
            {
                if (reportableSegment(path[i - 1], path[i]))
                    continue;
                all = false;
                if (fineRefused(path[i - 1], path[i]) || crossesObstacle(path[i - 1], path[i]))
                {
                    if (mendBeside(path, i))
                        ++i; // the new segment i -> i + 1 is checked in the next round
                    continue;
                }
                if (i == 1 && i + 1 == path.size())
                {
                    // Where the margin found the obstacle (the window's middle), so that the next rounds'
                    // shifts move the segment there by their full length.
                    const auto at =
                        caches_->refusedAt.find(SegmentKey{path[0].x, path[0].y, path[1].x, path[1].y});
                    const double t = at != caches_->refusedAt.end() && at->second > 0.0 && at->second < 1.0
                                         ? at->second
                                         : 0.5;
                    path.insert(path.begin() + 1, path[0] + (path[1] - path[0]) * t);
                    ++i;
                    continue;
                }
                double by = clearance_;
                const int side = refusedSide(path[i - 1], path[i], by);
                const Vec2 d = path[i] - path[i - 1];
                const double l = norm(d);
                if (side != 0 && l > 0.0 && insertAway(path, i, Vec2(d.y / l, -d.x / l) * double(side), by))
                {
                    ++i; // the new segment i -> i + 1 is checked in the next round
                    continue;
                }
                for (const std::size_t j : {i - 1, i})
                {
                    if (j == 0 || j + 1 >= path.size())
                        continue;
                    if (side != 0 && l > 0.0)
                        shiftAway(path, j, Vec2(d.y / l, -d.x / l) * double(side), by);
                    else if (round < 8)
                        pushOut(path, j, base * double(1u << round));
                }
            }
            if (all)
                return true;
            if (stop())
                return false;
        }
        bool all = true;
        for (std::size_t i = 1; i < path.size() && (all || refused != nullptr); ++i)
            if (!reportableSegment(path[i - 1], path[i]))
            {
                all = false;
                if (refused != nullptr && !motionValid(path[i - 1], path[i])) // cached: the margin's verdict
                    ++*refused;
            }
        return all;
    }

    void MemeticToolkit::makeReportablePrefix(MemeticPath &path)
    {
        if (margin_ <= 0.0 || path.size() < 2)
            return;
        makeStrict(path, [] { return false; });
        const StrictScope strict(*this);
        for (std::size_t i = 1; i < path.size(); ++i)
            if (!reportableSegment(path[i - 1], path[i]))
            {
                path.resize(i);
                return;
            }
    }

    bool MemeticToolkit::reportableSegment(const Vec2 &a, const Vec2 &b)
    {
        // The fine check (docs/variants.md, "The fine check"): once per segment the margin accepts, the
        // validity checker every fineStep_ along it. The sideways copies see obstacles a segment touches
        // when their chord exceeds the copies' spacing (discs, corners of 90 degrees or more); an acute tip
        // (a star's) may cross the segment between all of their samples, and near the start and the goal the
        // copies fan in. The fine check sees whatever the segment crosses over more than its step.
        if (!motionValid(a, b))
            return false;
        if (fineStep_ <= 0.0 || !strict_)
            return true;
        const SegmentKey key{a.x, a.y, b.x, b.y};
        const auto it = caches_->verdicts.find(key);
        if (it == caches_->verdicts.end())
            return false; // not reached: motionValid() cached the verdict
        if (it->second == kMarginValid)
        {
            double t = 0.0;
            const bool ok = fineCheck(a, b, t);
            it->second = ok ? kFineValid : kFineInvalid;
            if (!ok)
            {
                caches_->refusedAt[key] = t;
                if (hazards_.size() < (std::size_t(1) << 16))
                    hazards_.push_back(a + (b - a) * t);
            }
        }
        return it->second == kFineValid;
    }

    bool MemeticToolkit::crossesObstacle(const Vec2 &a, const Vec2 &b)
    {
        // The margin found obstacles on both sides of the segment down to the smallest clearance: either a
        // passage narrower than that, or the segment itself runs through an obstacle the validator's samples
        // missed (a loose path across a star's tip: the tip enters on one side and leaves on the other, so
        // both copies are inside it). Look at the segment's own points within 2 s of where the margin
        // refused it, every clearance c; a point inside an obstacle is mended like a fine-check refusal
        // (mendBeside: a waypoint beside it), where pushing the ends outward barely moves the crossing.
        const SegmentKey key{a.x, a.y, b.x, b.y};
        const auto it = caches_->verdicts.find(key);
        if (it == caches_->verdicts.end() || it->second != kMarginInvalid)
            return false;
        const double step = clearance_ > 0.0 ? clearance_ : fineStep_;
        const auto at = caches_->refusedAt.find(key);
        const Vec2 d = b - a;
        const double l = norm(d);
        bool crossed = false;
        if (step > 0.0 && l > 0.0 && at != caches_->refusedAt.end())
        {
            const double from = std::max(0.0, at->second * l - 2.0 * spacing_);
            const double to = std::min(l, at->second * l + 2.0 * spacing_);
            const auto pieces = static_cast<std::size_t>(std::ceil((to - from) / step));
            for (std::size_t k = 0; k <= pieces && !crossed; ++k)
            {
                const double u =
                    (from + (to - from) * double(k) / double(std::max<std::size_t>(pieces, 1))) / l;
                if (u <= 0.0 || u >= 1.0 || checkPoint(a + d * u))
                    continue;
                crossed = true;
                at->second = u;
            }
        }
        if (!crossed)
            it->second = kMarginNarrow; // looked once; the ends are pushed outward as before
        return crossed;
    }

    bool MemeticToolkit::fineRefused(const Vec2 &a, const Vec2 &b) const
    {
        const auto it = caches_->verdicts.find(SegmentKey{a.x, a.y, b.x, b.y});
        return it != caches_->verdicts.end() && it->second == kFineInvalid;
    }

    bool MemeticToolkit::fineCheck(const Vec2 &a, const Vec2 &b, double &t, double from, double to)
    {
        // The samples a + (b - a) k / K, K = ceil(l / step): the step is validator_fine_step x s, a share of
        // the validator's spacing, never the caller's (docs/variants.md).
        const Vec2 d = b - a;
        const double l = norm(d);
        const auto pieces = static_cast<std::size_t>(std::ceil(l / fineStep_));
        if (pieces < 2 || !(l > 0.0) || to < from)
            return true;
        // Only the samples in [from, to] along the segment (the hazards' re-check asks for 2 s of it): the
        // first and last index computed, not every sample scanned.
        const double n = static_cast<double>(pieces);
        const auto k0 = static_cast<std::size_t>(std::max(1.0, std::ceil(std::max(0.0, from) / l * n)));
        const auto k1 = static_cast<std::size_t>(std::min(n - 1.0, std::floor(std::min(l, to) / l * n)));
        for (std::size_t k = k0; k <= k1; ++k)
        {
            const double u = static_cast<double>(k) / n;
            if (u * l < from || u * l > to)
                continue; // rounding at the ends of [from, to]
            if (!checkPoint(a + d * u))
            {
                t = u;
                return false;
            }
        }
        return true;
    }

    bool MemeticToolkit::mendBeside(MemeticPath &path, std::size_t i)
    {
        const Vec2 a = path[i - 1], b = path[i];
        const auto it = caches_->refusedAt.find(SegmentKey{a.x, a.y, b.x, b.y});
        if (it == caches_->refusedAt.end())
            return false;
        const Vec2 d = b - a;
        const double l = norm(d);
        if (l <= 0.0)
            return false;
        const Vec2 p = a + d * it->second, n(-d.y / l, d.x / l);
        const double first = clearance_ > 0.0 ? clearance_ : fineStep_, last = 4.0 * spacing_;
        const StrictScope loose(*this, false); // the new segments face the margin in the next round
        for (double h = first; h <= last * (1.0 + 1e-9); h *= 2.0)
        {
            bool found = false;
            Vec2 best;
            double bestLength = 0.0;
            for (const double side : {1.0, -1.0})
            {
                const Vec2 q = p + n * (side * h);
                double t = 0.0;
                // A cheap choice of the side: the samples within s of the new waypoint only (where the
                // obstacle was met); both new segments get the whole fine check in the next round.
                if (!pointValid(q) || !motionValid(a, q) || !motionValid(q, b) ||
                    !fineCheck(q, a, t, 0.0, spacing_) || !fineCheck(q, b, t, 0.0, spacing_))
                    continue;
                const double len = distance(a, q) + distance(q, b);
                if (!found || len < bestLength)
                {
                    found = true;
                    best = q;
                    bestLength = len;
                }
            }
            if (found)
            {
                path.insert(path.begin() + static_cast<std::ptrdiff_t>(i), best);
                return true;
            }
        }
        return false;
    }

    double MemeticToolkit::smallestShift() const
    {
        // Twice the smallest clearance the margin accepts (docs/variants.md, "validator_min_clearance").
        return 2.0 * (minClearance_ > 0.0 ? std::min(minClearance_, clearance_) : clearance_);
    }

    bool MemeticToolkit::validShift(const Vec2 &base, const Vec2 &dir, double step, const Vec2 &a,
                                    const Vec2 &b, Vec2 &q)
    {
        // In a passage narrower than the shift the shifted point lands in the obstacle across it: halve the
        // shift down to smallestShift().
        const double least = smallestShift();
        const StrictScope loose(*this, false); // the new motions face the margin in the next round
        for (double h = step;; h *= 0.5)
        {
            q = base + dir * h;
            if (pointValid(q) && motionValid(a, q) && motionValid(q, b))
                return true;
            if (0.5 * h < least * (1.0 - 1e-9))
                return false;
        }
    }

    bool MemeticToolkit::insertAway(MemeticPath &path, std::size_t i, const Vec2 &dir, double step)
    {
        // A one-sided contact well inside a segment (farther than s from both ends): a loose path crosses a
        // corner between two of its bends, which shifting the bends would only swing round their own
        // obstacles. A waypoint goes where the margin met the obstacle, shifted away from it by the
        // clearance.
        const Vec2 a = path[i - 1], b = path[i];
        const auto at = caches_->refusedAt.find(SegmentKey{a.x, a.y, b.x, b.y});
        const double l = distance(a, b);
        if (at == caches_->refusedAt.end() || !(spacing_ > 0.0) || at->second * l <= spacing_ ||
            (1.0 - at->second) * l <= spacing_)
            return false;
        Vec2 q;
        if (!validShift(a + (b - a) * at->second, dir, step, a, b, q))
            return false;
        path.insert(path.begin() + static_cast<std::ptrdiff_t>(i), q);
        return true;
    }

    void MemeticToolkit::shiftAway(MemeticPath &path, std::size_t j, const Vec2 &dir, double step)
    {
        Vec2 q;
        if (validShift(path[j], dir, step, path[j - 1], path[j + 1], q))
            path[j] = q;
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
        // In a passage narrower than the push, the pushed point lands in the obstacle across it: halve the
        // push down to smallestShift().
        const double least = smallestShift();
        const StrictScope loose(*this, false); // a pushed waypoint need only be valid; the margin is asked of
                                               // the next round
        for (const double side : {1.0, -1.0})
        {
            for (double h = step;; h *= 0.5)
            {
                const Vec2 q = v + dir * (side * h / l);
                if (pointValid(q) && motionValid(u, q) && motionValid(q, w))
                {
                    path[j] = q;
                    return;
                }
                if (0.5 * h < least * (1.0 - 1e-9))
                    break;
            }
            if (!straight)
                return;
        }
    }
} // namespace mhplan
