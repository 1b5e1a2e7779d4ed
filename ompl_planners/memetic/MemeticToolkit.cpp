// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/memetic/MemeticToolkit.h"

#include "ompl_planners/memetic/detail/SegmentCaches.h"
#include "ompl_planners/memetic/PathShortcut.h"

#include "src/collision/Validity.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <queue>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief \e n points at equal arc length and the segment index each lies on. */
        void resampleWithSegments(const MemeticPath &path, unsigned int n, MemeticPath &out,
                                  std::vector<std::size_t> &segments)
        {
            out.clear();
            segments.clear();
            const double total = MemeticToolkit::length(path);
            std::size_t seg = 0;
            double before = 0.0;
            for (unsigned int k = 0; k < n; ++k)
            {
                const double s = n > 1 ? total * double(k) / double(n - 1) : 0.0;
                while (seg + 2 < path.size() && before + distance(path[seg], path[seg + 1]) < s)
                {
                    before += distance(path[seg], path[seg + 1]);
                    ++seg;
                }
                const double l = distance(path[seg], path[seg + 1]);
                const double u = l > 0.0 ? std::min(1.0, std::max(0.0, (s - before) / l)) : 0.0;
                out.push_back(path[seg] + (path[seg + 1] - path[seg]) * u);
                segments.push_back(seg);
            }
            if (n > 1)
            {
                out.front() = path.front();
                out.back() = path.back();
            }
        }

        double turnAngle(const Vec2 &a, const Vec2 &v, const Vec2 &b)
        {
            const Vec2 u = v - a, w = b - v;
            const double nu = norm(u), nw = norm(w);
            if (nu <= 0.0 || nw <= 0.0)
                return 0.0;
            return std::atan2(std::abs(cross(u, w)), dot(u, w));
        }
    } // namespace

    MemeticToolkit::MemeticToolkit(ob::SpaceInformationPtr si, ompl::RNG &rng)
        : si_(std::move(si)), rng_(rng), caches_(std::make_unique<SegmentCaches>())
    {
        a_ = si_->allocState();
        b_ = si_->allocState();
        c_ = si_->allocState();
    }

    MemeticToolkit::~MemeticToolkit()
    {
        si_->freeState(a_);
        si_->freeState(b_);
        si_->freeState(c_);
    }

    void MemeticToolkit::clearCache()
    {
        caches_->verdicts.clear();
        caches_->refusedAt.clear();
        hazards_.clear();
    }

    bool MemeticToolkit::motionValid(const Vec2 &a, const Vec2 &b, double &fraction)
    {
        fraction = 0.0;
        if (!inBounds(a) || !inBounds(b))
            return false;
        ++motionChecks_;
        setStatePosition(a_, a);
        setStatePosition(b_, b);
        std::pair<ob::State *, double> last(c_, 0.0);
        if (si_->getMotionValidator()->checkMotion(a_, b_, last))
        {
            fraction = 1.0;
            return true;
        }
        fraction = last.second;
        return false;
    }

    bool MemeticToolkit::pathValid(const MemeticPath &path)
    {
        for (std::size_t i = 1; i < path.size(); ++i)
            if (!motionValid(path[i - 1], path[i]))
                return false;
        return true;
    }

    bool MemeticToolkit::pointValid(const Vec2 &p)
    {
        if (!inBounds(p))
            return false;
        setStatePosition(a_, p);
        return si_->isValid(a_);
    }

    double MemeticToolkit::length(const MemeticPath &path)
    {
        double l = 0.0;
        for (std::size_t i = 1; i < path.size(); ++i)
            l += distance(path[i - 1], path[i]);
        return l;
    }

    Vec2 MemeticToolkit::pointAt(const MemeticPath &path, double s, std::size_t &segment)
    {
        double before = 0.0;
        for (std::size_t i = 0; i + 1 < path.size(); ++i)
        {
            const double l = distance(path[i], path[i + 1]);
            if (before + l >= s || i + 2 == path.size())
            {
                segment = i;
                const double u = l > 0.0 ? std::min(1.0, std::max(0.0, (s - before) / l)) : 0.0;
                return path[i] + (path[i + 1] - path[i]) * u;
            }
            before += l;
        }
        segment = 0;
        return path.front();
    }

    void MemeticToolkit::resample(const MemeticPath &path, unsigned int n, MemeticPath &out)
    {
        std::vector<std::size_t> segments;
        resampleWithSegments(path, n, out, segments);
    }

    double MemeticToolkit::maxTurnAngle(const MemeticPath &path)
    {
        double m = 0.0;
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
            m = std::max(m, turnAngle(path[i - 1], path[i], path[i + 1]));
        return m;
    }

    MemeticToolkit::WalkResult
    MemeticToolkit::randomWalk(MemeticPath &path, const Vec2 &start, const Vec2 &goal, double h, double noise,
                               unsigned int maxExpansions, const std::function<bool()> &stop,
                               MemeticPath &closest, double &closestDistance, double weight)
    {
        static const int kMoves[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                         {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        struct Entry
        {
            double f, g;
            std::uint32_t node, parent;
            bool operator<(const Entry &o) const
            {
                // std::priority_queue is a max-heap: the smallest f (then the smallest node) on top.
                return f > o.f || (f == o.f && node > o.node);
            }
        };
        constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
        auto key = [](long ix, long iy)
        { return (std::uint64_t(std::uint32_t(ix)) << 32) | std::uint64_t(std::uint32_t(iy)); };
        auto at = [&](long ix, long iy) { return start + Vec2(double(ix) * h, double(iy) * h); };
        nodes_.clear();
        index_.clear();
        std::priority_queue<Entry> open;
        nodes_.push_back({0, 0, none, std::numeric_limits<double>::infinity(), false});
        index_.emplace(key(0, 0), 0u);
        open.push({weight * distance(start, goal), 0.0, 0u, none});
        const double reach = 2.0 * h;
        unsigned int expansions = 0;
        auto chain = [&](std::uint32_t n, MemeticPath &out)
        {
            out.clear();
            for (std::uint32_t k = n; k != none; k = nodes_[k].parent)
                out.push_back(at(nodes_[k].ix, nodes_[k].iy));
            std::reverse(out.begin(), out.end());
            out.front() = start;
        };
        // The node closest to the goal (for approximate solutions), chained once when the walk ends.
        double closestHere = std::numeric_limits<double>::infinity();
        std::uint32_t closestNode = none;
        auto finish = [&](WalkResult r)
        {
            if (closestNode != none && closestHere < closestDistance)
            {
                closestDistance = closestHere;
                chain(closestNode, closest);
            }
            return r;
        };
        while (!open.empty())
        {
            if ((expansions & 63u) == 0 && stop())
                return finish(WalkResult::Stopped);
            if (expansions >= maxExpansions)
                return finish(WalkResult::Budget);
            const Entry e = open.top();
            open.pop();
            Node &n = nodes_[e.node];
            if (n.closed || e.g > n.g)
                continue;
            const Vec2 p = at(n.ix, n.iy);
            if (e.parent != none)
            {
                const Node &q = nodes_[e.parent];
                if (!motionValid(at(q.ix, q.iy), p))
                    continue; // lazily refused edge; the node may still be reached from elsewhere
            }
            ++expansions;
            nodes_[e.node].closed = true;
            nodes_[e.node].parent = e.parent;
            nodes_[e.node].g = e.g;
            const double dGoal = distance(p, goal);
            if (dGoal < closestHere)
            {
                closestHere = dGoal;
                closestNode = e.node;
            }
            if (dGoal <= reach && motionValid(p, goal))
            {
                chain(e.node, path);
                if (path.back() != goal)
                    path.push_back(goal);
                if (path.size() == 1)
                    path.push_back(goal);
                return finish(WalkResult::Found);
            }
            const long ix = nodes_[e.node].ix, iy = nodes_[e.node].iy;
            for (const auto &m : kMoves)
            {
                const long jx = ix + m[0], jy = iy + m[1];
                const Vec2 q = at(jx, jy);
                if (!inBounds(q))
                    continue;
                const double step = (m[0] != 0 && m[1] != 0) ? h * std::sqrt(2.0) : h;
                const double g = e.g + step * (1.0 + noise * 0.5 * (1.0 + fieldAt((p + q) * 0.5)));
                auto it = index_.find(key(jx, jy));
                std::uint32_t id;
                if (it == index_.end())
                {
                    id = static_cast<std::uint32_t>(nodes_.size());
                    nodes_.push_back({jx, jy, none, std::numeric_limits<double>::infinity(), false});
                    index_.emplace(key(jx, jy), id);
                }
                else
                    id = it->second;
                Node &nb = nodes_[id];
                if (nb.closed || g >= nb.g)
                    continue;
                nb.g = g;
                open.push({g + weight * distance(q, goal), g, id, e.node});
            }
        }
        return finish(WalkResult::Exhausted);
    }

    void MemeticToolkit::randomiseField(double diag)
    {
        const double twoPi = 2.0 * 3.14159265358979323846;
        field_.clear();
        for (int m = 0; m < 6; ++m)
        {
            const double lambda = diag / 24.0 * std::pow(8.0, rng_.uniform01());
            const double angle = rng_.uniformReal(0.0, twoPi);
            const double k = twoPi / lambda;
            field_.push_back({k * std::cos(angle), k * std::sin(angle), rng_.uniformReal(0.0, twoPi),
                              rng_.uniformReal(0.5, 1.0)});
        }
    }

    double MemeticToolkit::fieldAt(const Vec2 &p) const
    {
        double s = 0.0, total = 0.0;
        for (const Wave &w : field_)
        {
            s += w.amplitude * std::cos(w.kx * p.x + w.ky * p.y + w.phase);
            total += w.amplitude;
        }
        return total > 0.0 ? s / total : 0.0;
    }

    void MemeticToolkit::shortcut(MemeticPath &path, const std::function<bool()> &stop)
    {
        greedyShortcut(
            path, [this](const auto &a, const auto &b) { return motionValid(a, b); }, stop);
    }

    double MemeticToolkit::bisectMove(const Vec2 &a, const Vec2 &v, const Vec2 &d, const Vec2 &b)
    {
        auto valid = [&](double t)
        {
            const Vec2 q = v + d * t;
            return inBounds(q) && motionValid(a, q) && motionValid(q, b);
        };
        double lo = 0.0, hi = 1.0;
        for (unsigned int k = 0; k < bisections_; ++k)
        {
            const double mid = 0.5 * (lo + hi);
            if (valid(mid))
                lo = mid;
            else
                hi = mid;
        }
        if (lo > 0.0 || !precise_)
            return lo;
        // Nothing at the relative resolution: keep halving down to 1e-9 of the bounds (a long move direction
        // may allow only a tiny step, e.g. a waypoint sliding along a long corridor).
        const double floor = 1e-9 * std::max(bounds_.width(), bounds_.height());
        for (double t = hi * 0.5; norm(d) * t > floor; t *= 0.5)
            if (valid(t))
                return t;
        return 0.0;
    }

    bool MemeticToolkit::pullPass(MemeticPath &path, std::vector<char> &dirty,
                                  const std::function<bool()> &stop)
    {
        bool changed = false;
        const double scale = std::max(bounds_.width(), bounds_.height());
        const double eps = 1e-12 * scale;
        for (std::size_t i = 1; i + 1 < path.size();)
        {
            if (!dirty[i])
            {
                ++i;
                continue;
            }
            if ((i & 15u) == 0 && stop())
                return changed;
            const Vec2 a = path[i - 1], b = path[i + 1];
            Vec2 v = path[i];
            if (motionValid(a, b))
            {
                path.erase(path.begin() + static_cast<std::ptrdiff_t>(i));
                dirty.erase(dirty.begin() + static_cast<std::ptrdiff_t>(i));
                dirty[i - 1] = 1;
                if (i < dirty.size())
                    dirty[i] = 1;
                changed = true;
                continue;
            }
            bool moved = false;
            const Vec2 target = closestPointOnSegment(v, a, b);
            for (const Vec2 &towards : {target, a, b})
            {
                const Vec2 d = towards - v;
                if (norm(d) <= eps)
                    continue;
                const double t = bisectMove(a, v, d, b);
                if (t > 0.0)
                {
                    const Vec2 w = v + d * t;
                    // Never lengthen (guards rounding in the slides).
                    if (distance(a, w) + distance(w, b) < distance(a, v) + distance(v, b))
                    {
                        v = w;
                        moved = true;
                    }
                }
            }
            if (!moved && precise_ && norm(target - v) > eps)
            {
                // Held by a contact inside a segment: split that segment at the contact.
                const Vec2 probe = v + (target - v) * 1e-3;
                for (int side = 0; side < 2 && !moved; ++side)
                {
                    const Vec2 end = side == 0 ? a : b;
                    double f = 0.0;
                    if (motionValid(end, probe, f) || f <= 0.02 || f >= 0.98)
                        continue;
                    const Vec2 c = end + (v - end) * f;
                    if (distance(c, end) <= eps || distance(c, v) <= eps || !motionValid(end, c) ||
                        !motionValid(c, v))
                        continue;
                    const std::size_t at = side == 0 ? i : i + 1;
                    path.insert(path.begin() + static_cast<std::ptrdiff_t>(at), c);
                    dirty.insert(dirty.begin() + static_cast<std::ptrdiff_t>(at), 1);
                    if (side == 0)
                        ++i; // v moved one place on
                    dirty[i] = 1;
                    changed = true;
                    moved = true;
                }
                if (moved)
                {
                    ++i;
                    continue;
                }
            }
            if (moved)
            {
                path[i] = v;
                dirty[i - 1] = 1;
                dirty[i + 1] = 1;
                changed = true;
            }
            else
                dirty[i] = 0;
            ++i;
        }
        return changed;
    }

    bool MemeticToolkit::subdivide(MemeticPath &path, std::vector<char> &dirty, double maxTurn,
                                   unsigned int maxPoints)
    {
        if (path.size() < 3 || path.size() >= maxPoints)
            return false;
        MemeticPath out;
        std::vector<char> outDirty;
        out.reserve(path.size() * 2);
        outDirty.reserve(path.size() * 2);
        out.push_back(path[0]);
        outDirty.push_back(0);
        bool any = false;
        const double scale = std::max(bounds_.width(), bounds_.height());
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
        {
            const Vec2 a = path[i - 1], v = path[i], b = path[i + 1];
            const bool split = out.size() + (path.size() - i) + 2 < maxPoints && turnAngle(a, v, b) > maxTurn;
            const double la = distance(a, v), lb = distance(v, b);
            if (split && std::min(la, lb) > 1e-9 * scale)
            {
                // Points at half the shorter neighbouring segment on both sides (near the obstacle that holds
                // v: on a finely wrapped arc these are the tangent points).
                const double delta = 0.5 * std::min(la, lb);
                const Vec2 pa = v + (a - v) * (delta / la), pb = v + (b - v) * (delta / lb);
                const bool keepA = motionValid(out.back(), pa) && motionValid(pa, v);
                if (keepA && out.back() != pa)
                {
                    out.push_back(pa);
                    outDirty.push_back(1);
                }
                if (out.back() != v)
                {
                    out.push_back(v);
                    outDirty.push_back(1);
                }
                if (motionValid(v, pb) && motionValid(pb, b))
                {
                    out.push_back(pb);
                    outDirty.push_back(1);
                }
                any = true;
            }
            else
            {
                if (out.back() != v)
                {
                    out.push_back(v);
                    outDirty.push_back(dirty[i]);
                }
            }
        }
        if (out.back() == path.back())
            out.pop_back(), outDirty.pop_back();
        out.push_back(path.back());
        outDirty.push_back(0);
        if (any)
        {
            path.swap(out);
            dirty.swap(outDirty);
        }
        return any;
    }

    bool MemeticToolkit::tighten(MemeticPath &path, double maxTurn, double relTol, unsigned int maxPasses,
                                 const std::function<bool()> &stop, unsigned int maxPoints, bool precise,
                                 const std::function<void(const MemeticPath &)> &afterPass)
    {
        precise_ = precise;
        shortcut(path, stop);
        std::vector<char> dirty(path.size(), 1);
        double len = length(path);
        for (unsigned int pass = 0; pass < maxPasses; ++pass)
        {
            if (stop())
                return false;
            const bool split = subdivide(path, dirty, maxTurn, maxPoints);
            const bool changed = pullPass(path, dirty, stop);
            const double now = length(path);
            if (!changed && !split)
                break;
            if (len - now < relTol * len && pass > 0)
                break;
            len = now;
            if (afterPass && pass + 1 < maxPasses)
                afterPass(path);
        }
        return true;
    }

    bool MemeticToolkit::splice(const MemeticPath &a, const MemeticPath &b, double radius, bool twoPoint,
                                MemeticPath &child)
    {
        constexpr unsigned int n = 48;
        std::vector<std::size_t> segA, segB;
        resampleWithSegments(a, n, sa_, segA);
        resampleWithSegments(b, n, sb_, segB);
        std::vector<std::pair<unsigned int, unsigned int>> close;
        const double r2 = radius * radius;
        for (unsigned int i = 1; i + 1 < n; ++i)
            for (unsigned int j = 1; j + 1 < n; ++j)
                if (squaredNorm(sa_[i] - sb_[j]) <= r2)
                    close.emplace_back(i, j);
        if (close.empty())
            return false;
        auto prefixA = [&](unsigned int i, MemeticPath &out)
        {
            out.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(segA[i] + 1));
            if (out.back() != sa_[i])
                out.push_back(sa_[i]);
        };
        for (int attempt = 0; attempt < 6; ++attempt)
        {
            const auto &p1 = close[static_cast<std::size_t>(rng_.uniformInt(0, int(close.size()) - 1))];
            if (!motionValid(sa_[p1.first], sb_[p1.second]))
                continue;
            if (!twoPoint)
            {
                prefixA(p1.first, child);
                child.push_back(sb_[p1.second]);
                child.insert(child.end(), b.begin() + static_cast<std::ptrdiff_t>(segB[p1.second] + 1),
                             b.end());
                return true;
            }
            // Second joint back from b to a, later on both.
            std::vector<std::pair<unsigned int, unsigned int>> later;
            for (const auto &c : close)
                if (c.first > p1.first + 1 && c.second > p1.second + 1)
                    later.push_back(c);
            if (later.empty())
                continue;
            const auto &p2 = later[static_cast<std::size_t>(rng_.uniformInt(0, int(later.size()) - 1))];
            if (!motionValid(sb_[p2.second], sa_[p2.first]))
                continue;
            prefixA(p1.first, child);
            child.push_back(sb_[p1.second]);
            child.insert(child.end(), b.begin() + static_cast<std::ptrdiff_t>(segB[p1.second] + 1),
                         b.begin() + static_cast<std::ptrdiff_t>(segB[p2.second] + 1));
            if (child.back() != sb_[p2.second])
                child.push_back(sb_[p2.second]);
            child.push_back(sa_[p2.first]);
            child.insert(child.end(), a.begin() + static_cast<std::ptrdiff_t>(segA[p2.first] + 1), a.end());
            return true;
        }
        return false;
    }

    bool MemeticToolkit::flip(MemeticPath &path)
    {
        if (path.size() < 3)
            return false;
        for (int attempt = 0; attempt < 4; ++attempt)
        {
            const auto i = static_cast<std::size_t>(rng_.uniformInt(1, int(path.size()) - 2));
            const Vec2 a = path[i - 1], v = path[i], b = path[i + 1];
            if (turnAngle(a, v, b) < 1e-3)
                continue;
            const Vec2 proj = closestPointOnSegment(v, a, b);
            for (const double lambda : {1.0, 1.5, 2.5})
            {
                const Vec2 w = proj + (proj - v) * lambda;
                if (inBounds(w) && pointValid(w) && motionValid(a, w) && motionValid(w, b))
                {
                    path[i] = w;
                    return true;
                }
            }
        }
        return false;
    }

    bool MemeticToolkit::rewalk(MemeticPath &path, double scale, double noise, unsigned int maxExpansions,
                                const std::function<bool()> &stop)
    {
        const double total = length(path);
        if (total <= 0.0 || path.size() < 2)
            return false;
        const double u = rng_.uniform01();
        const double span = total * std::min(1.0, 0.03 + scale * u * u);
        const double s1 = rng_.uniformReal(0.0, total - span), s2 = s1 + span;
        std::size_t seg1 = 0, seg2 = 0;
        const Vec2 p1 = pointAt(path, s1, seg1), p2 = pointAt(path, s2, seg2);
        if (distance(p1, p2) <= 0.0)
            return false;
        randomiseField(3.0 * span);
        MemeticPath piece, closest;
        double closestDistance = std::numeric_limits<double>::infinity();
        if (randomWalk(piece, p1, p2, span / rng_.uniformReal(24.0, 96.0), noise, maxExpansions, stop,
                       closest, closestDistance) != WalkResult::Found)
            return false;
        MemeticPath out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(seg1 + 1));
        if (out.back() != p1)
            out.push_back(p1);
        out.insert(out.end(), piece.begin() + 1, piece.end());
        out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(seg2 + 1), path.end());
        if (out.back() != path.back())
            out.push_back(path.back());
        path.swap(out);
        return true;
    }

    bool MemeticToolkit::detour(MemeticPath &path, double scale)
    {
        const double total = length(path);
        if (total <= 0.0 || path.size() < 2)
            return false;
        for (int attempt = 0; attempt < 4; ++attempt)
        {
            const double u = rng_.uniform01();
            const double span = total * std::min(0.6, 0.01 + scale * u * u);
            const double s1 = rng_.uniformReal(0.0, total - span), s2 = s1 + span;
            std::size_t seg1 = 0, seg2 = 0;
            const Vec2 p1 = pointAt(path, s1, seg1), p2 = pointAt(path, s2, seg2);
            const Vec2 chord = p2 - p1;
            const double lc = norm(chord);
            if (lc <= 0.0)
                continue;
            const Vec2 normal(-chord.y / lc, chord.x / lc);
            const double side = rng_.uniform01() < 0.5 ? -1.0 : 1.0;
            const Vec2 q = (p1 + p2) * 0.5 + chord * rng_.uniformReal(-0.25, 0.25) +
                           normal * (side * span * rng_.uniformReal(0.2, 1.2));
            if (!inBounds(q) || !pointValid(q) || !motionValid(p1, q) || !motionValid(q, p2))
                continue;
            MemeticPath out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(seg1 + 1));
            if (out.back() != p1)
                out.push_back(p1);
            out.push_back(q);
            out.push_back(p2);
            out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(seg2 + 1), path.end());
            if (out.back() != path.back())
                out.push_back(path.back());
            path.swap(out);
            return true;
        }
        return false;
    }
} // namespace mhplan
