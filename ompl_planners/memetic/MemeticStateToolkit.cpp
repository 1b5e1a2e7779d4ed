// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/memetic/MemeticStateToolkit.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr std::size_t kCacheLimit = 1u << 20;
        /** \brief Draws of a mend of one motion (makeStrict): four at each of 1, 2, 4, ... 32 margins. */
        constexpr int kMendDraws = 24;
    } // namespace

    std::size_t MemeticStateToolkit::KeyHash::operator()(const std::vector<double> &k) const
    {
        std::uint64_t h = 1469598103934665603ull;
        for (double v : k)
        {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
            h ^= h >> 29;
        }
        return static_cast<std::size_t>(h);
    }

    MemeticStateToolkit::MemeticStateToolkit(ob::SpaceInformationPtr si, const StateParametrisation &param,
                                             ompl::RNG &rng)
        : si_(std::move(si)), param_(param), car_(si_->getStateSpace().get()),
          dubins_(si_->getStateSpace().get()), rng_(rng)
    {
        a_ = si_->allocState();
        b_ = si_->allocState();
        c_ = si_->allocState();
    }

    MemeticStateToolkit::~MemeticStateToolkit()
    {
        si_->freeState(a_);
        si_->freeState(b_);
        si_->freeState(c_);
    }

    void MemeticStateToolkit::dedupe(StatePath &path)
    {
        path.erase(std::unique(path.begin(), path.end()), path.end());
    }

    void MemeticStateToolkit::resetCounts()
    {
        motionChecks_ = stateChecks_ = cacheHits_ = roadmapDistances_ = 0;
        cache_.clear();
        strictCache_.clear();
        strictRoutes_ = false;
        roadmapClear();
    }

    void MemeticStateToolkit::fromState(const ob::State *s, StatePoint &p) const
    {
        p.resize(param_.dimension());
        param_.toVector(s, p.data());
    }

    bool MemeticStateToolkit::pointValid(const StatePoint &p)
    {
        ++stateChecks_;
        toState(p, a_);
        return si_->satisfiesBounds(a_) && si_->isValid(a_);
    }

    bool MemeticStateToolkit::motionValid(const StatePoint &a, const StatePoint &b)
    {
        key_.assign(a.begin(), a.end());
        key_.insert(key_.end(), b.begin(), b.end());
        const auto it = cache_.find(key_);
        if (it != cache_.end())
        {
            ++cacheHits_;
            return it->second;
        }
        ++motionChecks_;
        toState(a, a_);
        toState(b, b_);
        const bool ok = si_->satisfiesBounds(b_) && dubins_.checkMotion(*si_, a_, b_);
        if (cache_.size() >= kCacheLimit)
            cache_.clear();
        cache_.emplace(key_, ok);
        return ok;
    }

    bool MemeticStateToolkit::pathValid(const StatePath &path)
    {
        for (std::size_t i = 1; i < path.size(); ++i)
            if (!motionValid(path[i - 1], path[i]))
                return false;
        return true;
    }

    void MemeticStateToolkit::setFineSpacing(double spacing)
    {
        strictSpacing_ = spacing > 0.0 ? spacing : 0.0;
        strictCache_.clear();
    }

    double MemeticStateToolkit::strictFailure(const StatePoint &a, const StatePoint &b)
    {
        key_.assign(a.begin(), a.end());
        key_.insert(key_.end(), b.begin(), b.end());
        const auto it = strictCache_.find(key_);
        if (it != strictCache_.end())
            return it->second;
        toState(a, a_);
        toState(b, b_);
        // The guard asked once for the pair, not at every sample.
        const bool safe = dubins_.safe(a_, b_);
        const auto n =
            static_cast<unsigned long>(std::ceil(dubins_.distance(*si_, a_, b_, safe) / strictSpacing_));
        double failure = -1.0;
        for (unsigned long k = 1; k < n && failure < 0.0; ++k)
        {
            const double t = double(k) / double(n);
            dubins_.interpolate(*si_, a_, b_, t, c_, safe);
            ++stateChecks_;
            if (!si_->isValid(c_))
                failure = t;
        }
        if (strictCache_.size() >= kCacheLimit)
            strictCache_.clear();
        strictCache_.emplace(key_, failure);
        return failure;
    }

    std::size_t MemeticStateToolkit::strictPrefix(const StatePath &path)
    {
        if (!strictNeeded())
            return path.size();
        for (std::size_t i = 1; i < path.size(); ++i)
            if (strictFailure(path[i - 1], path[i]) >= 0.0)
                return i;
        return path.size();
    }

    bool MemeticStateToolkit::makeStrict(StatePath &path, const std::function<bool()> &stop)
    {
        if (!strictNeeded())
            return true;
        StatePath out{path.front()};
        StatePoint p, q;
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            if (stop())
                return false;
            const StatePoint a = out.back();
            const double t = strictFailure(a, path[i]);
            if (t >= 0.0)
            {
                interpolate(a, path[i], t, p);
                bool mended = false;
                for (int k = 0; k < kMendDraws && !mended; ++k)
                {
                    // Every other draw keeps the turn small: the metric weighs a heading against positions
                    // without knowing the robot's reach, and a draw anywhere within d of the heading spins a
                    // big robot round (OMPL.app's Barriers: a 46-unit robot, margins of 4 units, every
                    // heading within 4 rad: no route of its dense roadmap could be mended).
                    const double d = margin_ * double(1 << (k / 4));
                    sampleAround(p, d, k % 2 == 0 ? mendTurn(d) : d, q);
                    mended = pointValid(q) && motionValid(a, q) && motionValid(q, path[i]) &&
                             strictFailure(a, q) < 0.0 && strictFailure(q, path[i]) < 0.0;
                }
                if (!mended)
                    return false;
                out.push_back(q);
            }
            out.push_back(path[i]);
        }
        path.swap(out);
        return true;
    }

    double MemeticStateToolkit::segmentCost(const StatePoint &a, const StatePoint &b)
    {
        toState(a, a_);
        toState(b, b_);
        // A pair OMPL's Dubins code would abort on is never a motion (motionValid), so never a path's.
        if (!dubins_.safe(a_, b_))
            return std::numeric_limits<double>::infinity();
        return opt_ ? opt_->motionCost(a_, b_).value() : si_->distance(a_, b_);
    }

    double MemeticStateToolkit::cost(const StatePath &path)
    {
        if (!opt_)
        {
            double c = 0.0;
            for (std::size_t i = 1; i < path.size(); ++i)
                c += segmentCost(path[i - 1], path[i]);
            return c;
        }
        ob::Cost c = opt_->identityCost();
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            toState(path[i - 1], a_);
            toState(path[i], b_);
            if (!dubins_.safe(a_, b_))
                return std::numeric_limits<double>::infinity();
            c = opt_->combineCosts(c, opt_->motionCost(a_, b_));
        }
        return c.value();
    }

    double MemeticStateToolkit::distance(const StatePoint &a, const StatePoint &b)
    {
        toState(a, a_);
        toState(b, b_);
        return dubins_.distance(*si_, a_, b_);
    }

    void MemeticStateToolkit::interpolate(const StatePoint &a, const StatePoint &b, double t, StatePoint &out)
    {
        toState(a, a_);
        toState(b, b_);
        dubins_.interpolate(*si_, a_, b_, t, c_);
        fromState(c_, out);
    }

    bool MemeticStateToolkit::sampleUniform(StatePoint &out)
    {
        // The parametrisation's uniform draw with the planner's RNG (the space's sampler has a generator of
        // its own, which the planner's seed would not reproduce).
        out.resize(param_.dimension());
        param_.sample(rng_, out.data());
        return true;
    }

    bool MemeticStateToolkit::sampleNear(const StatePoint &near, double d, StatePoint &out)
    {
        sampleAround(near, d, d, out); // every coordinate within d of near's
        return true;
    }

    void MemeticStateToolkit::sampleAround(const StatePoint &near, double d, double turn, StatePoint &out)
    {
        out = near;
        for (unsigned int j = 0; j < out.size(); ++j)
        {
            const double r = param_.isRotation(j) ? turn : d;
            out[j] += rng_.uniformReal(-r, r);
        }
        param_.enforce(out.data());
    }

    double MemeticStateToolkit::mendTurn(double d) const
    {
        double span = 0.0;
        for (unsigned int j = 0; j < param_.dimension(); ++j)
            if (!param_.isRotation(j))
                span = std::max(span, param_.upper(j) - param_.lower(j));
        return span > 0.0 ? std::min(d, boost::math::constants::pi<double>() * d / span) : d;
    }

    double MemeticStateToolkit::extent() const
    {
        return si_->getMaximumExtent();
    }

    void MemeticStateToolkit::resample(const StatePath &path, unsigned int n, StatePath &out,
                                       std::vector<std::size_t> *segments)
    {
        out.clear();
        if (segments != nullptr)
            segments->clear();
        std::vector<double> cum(path.size(), 0.0);
        for (std::size_t i = 1; i < path.size(); ++i)
            cum[i] = cum[i - 1] + distance(path[i - 1], path[i]);
        const double total = cum.back();
        std::size_t seg = 0;
        StatePoint p;
        for (unsigned int k = 0; k < n; ++k)
        {
            const double s = n > 1 ? total * double(k) / double(n - 1) : 0.0;
            while (seg + 2 < path.size() && cum[seg + 1] < s)
                ++seg;
            if (path.size() < 2)
                p = path.front();
            else
            {
                const double l = cum[seg + 1] - cum[seg];
                const double u = l > 0.0 ? std::min(1.0, std::max(0.0, (s - cum[seg]) / l)) : 0.0;
                interpolate(path[seg], path[seg + 1], u, p);
            }
            out.push_back(p);
            if (segments != nullptr)
                segments->push_back(seg);
        }
        if (n > 1 && !path.empty())
        {
            out.front() = path.front();
            out.back() = path.back();
        }
    }

    bool MemeticStateToolkit::splice(const StatePath &a, const StatePath &b, double radius, bool twoPoint,
                                     StatePath &child)
    {
        constexpr unsigned int kSamples = 48;
        StatePath sa, sb;
        std::vector<std::size_t> ga, gb;
        resample(a, kSamples, sa, &ga);
        resample(b, kSamples, sb, &gb);
        // The sample of b nearest to sa[p] among indices [q0, kSamples - 2].
        auto nearest = [&](const StatePoint &x, std::size_t q0, std::size_t &q)
        {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t j = q0; j + 1 < kSamples; ++j)
            {
                const double d = distance(x, sb[j]);
                if (d < best)
                {
                    best = d;
                    q = j;
                }
            }
            return best;
        };
        for (int tries = 0; tries < 4; ++tries)
        {
            const auto p1 = static_cast<std::size_t>(rng_.uniformInt(1, twoPoint ? 30 : int(kSamples) - 2));
            std::size_t q1 = 1;
            if (nearest(sa[p1], 1, q1) > radius || !motionValid(sa[p1], sb[q1]))
                continue;
            child.assign(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(ga[p1] + 1));
            child.push_back(sa[p1]);
            child.push_back(sb[q1]);
            if (!twoPoint)
            {
                child.insert(child.end(), b.begin() + static_cast<std::ptrdiff_t>(gb[q1] + 1), b.end());
                dedupe(child);
                return true;
            }
            const auto p2 = static_cast<std::size_t>(rng_.uniformInt(int(p1) + 4, int(kSamples) - 2));
            std::size_t q2 = q1;
            if (q1 + 2 >= kSamples - 1 || nearest(sa[p2], q1 + 1, q2) > radius ||
                !motionValid(sb[q2], sa[p2]))
                continue;
            child.insert(child.end(), b.begin() + static_cast<std::ptrdiff_t>(gb[q1] + 1),
                         b.begin() + static_cast<std::ptrdiff_t>(gb[q2] + 1));
            child.push_back(sb[q2]);
            child.push_back(sa[p2]);
            child.insert(child.end(), a.begin() + static_cast<std::ptrdiff_t>(ga[p2] + 1), a.end());
            dedupe(child);
            return true;
        }
        return false;
    }

    bool MemeticStateToolkit::pickPiece(const StatePath &path, double scale, StatePoint &p1,
                                        std::size_t &seg1, StatePoint &p2, std::size_t &seg2)
    {
        if (path.size() < 2)
            return false;
        constexpr unsigned int kSamples = 65;
        StatePath s;
        std::vector<std::size_t> g;
        resample(path, kSamples, s, &g);
        const double share = rng_.uniformReal(0.05, std::max(0.06, scale));
        const auto span = std::max<int>(2, static_cast<int>(share * (kSamples - 1)));
        const int i = rng_.uniformInt(0, int(kSamples) - 1 - span);
        p1 = s[std::size_t(i)];
        seg1 = g[std::size_t(i)];
        p2 = s[std::size_t(i + span)];
        seg2 = g[std::size_t(i + span)];
        return true;
    }

    bool MemeticStateToolkit::detour(StatePath &path, double scale)
    {
        StatePoint p1, p2, mid, c;
        std::size_t s1 = 0, s2 = 0;
        for (int tries = 0; tries < 4; ++tries)
        {
            if (!pickPiece(path, scale, p1, s1, p2, s2))
                return false;
            interpolate(p1, p2, 0.5, mid);
            const double d = distance(p1, p2);
            sampleNear(mid, std::max(d, 1e-6 * extent()), c);
            if (!pointValid(c) || !motionValid(p1, c) || !motionValid(c, p2))
                continue;
            StatePath out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(s1 + 1));
            out.push_back(p1);
            out.push_back(c);
            out.push_back(p2);
            out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(s2 + 1), path.end());
            dedupe(out);
            path.swap(out);
            return true;
        }
        return false;
    }

    bool MemeticStateToolkit::reconnect(StatePath &path, double scale, unsigned int maxNodes,
                                        const std::function<bool()> &stop)
    {
        StatePoint p1, p2, mid;
        std::size_t s1 = 0, s2 = 0;
        if (!pickPiece(path, scale, p1, s1, p2, s2))
            return false;
        interpolate(p1, p2, 0.5, mid);
        double span = 0.0;
        for (std::size_t i = s1; i <= s2 && i + 1 < path.size(); ++i)
            span += distance(path[i], path[i + 1]);
        span = std::max(span, 1e-6 * extent());
        StatePath piece;
        const Sampler local = [&](StatePoint &x) { return sampleNear(mid, span, x); };
        if (connect(piece, p1, p2, 0.25 * span, maxNodes, local, stop) != ConnectResult::Found)
            return false;
        StatePath out(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(s1 + 1));
        out.insert(out.end(), piece.begin(), piece.end());
        out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(s2 + 1), path.end());
        dedupe(out);
        path.swap(out);
        return true;
    }
} // namespace mhplan
