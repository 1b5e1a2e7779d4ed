// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/PathEncoding.h"

#include <algorithm>
#include <stdexcept>

namespace mhplan
{
    PathDecoding parsePathDecoding(const std::string &name)
    {
        if (name == "polyline")
            return PathDecoding::Polyline;
        if (name == "spline")
            return PathDecoding::Spline;
        throw std::invalid_argument("parameter 'decoding' must be one of {polyline, spline}; got '" + name +
                                    "'");
    }

    std::string toString(PathDecoding decoding)
    {
        return decoding == PathDecoding::Spline ? "spline" : "polyline";
    }

    void WaypointDecoder::configure(const Vec2 &start, const Vec2 &goal, unsigned int waypoints,
                                    PathDecoding decoding, unsigned int samples)
    {
        const double s[2] = {start.x, start.y}, g[2] = {goal.x, goal.y};
        configure(s, g, 2, waypoints, decoding, samples);
    }

    void WaypointDecoder::configure(const double *start, const double *goal, unsigned int dim,
                                    unsigned int waypoints, PathDecoding decoding, unsigned int samples)
    {
        if (samples < 2)
            throw std::invalid_argument("parameter 'spline_samples' must be in [2, 100000]; got " +
                                        std::to_string(samples));
        if (dim < 1)
            throw std::invalid_argument(
                "WaypointDecoder: the state space dimension must be at least 1; got 0");
        dim_ = dim;
        start_.assign(start, start + dim);
        goal_.assign(goal, goal + dim);
        waypoints_ = waypoints;
        decoding_ = decoding;
        sampleCount_ = samples;
        const std::size_t knots = waypoints + 2;
        knots_.assign(knots * dim, 0.0);
        std::copy(start_.begin(), start_.end(), knots_.begin());
        std::copy(goal_.begin(), goal_.end(), knots_.end() - dim);
        moments_.assign(knots * dim, 0.0);
        rhs_.assign(knots, 0.0);
        cprime_.assign(knots, 0.0);
        samples_.assign(std::size_t(samples) * dim, 0.0);
        path_.assign((decoding == PathDecoding::Spline ? samples : knots) * std::size_t(dim), 0.0);
    }

    const std::vector<Vec2> &WaypointDecoder::path() const
    {
        if (dim_ != 2)
            throw std::logic_error("WaypointDecoder::path(): planar view of a " + std::to_string(dim_) +
                                   "-dimensional path; use pathView()");
        planarPath_.resize(path_.size() / 2);
        for (std::size_t i = 0; i < planarPath_.size(); ++i)
            planarPath_[i] = Vec2(path_[2 * i], path_[2 * i + 1]);
        return planarPath_;
    }

    const std::vector<Vec2> &WaypointDecoder::samples() const
    {
        if (decoding_ == PathDecoding::Spline)
            return path();
        if (dim_ != 2)
            throw std::logic_error("WaypointDecoder::samples(): planar view of " + std::to_string(dim_) +
                                   "-dimensional samples; use samplesView()");
        planarSamples_.resize(samples_.size() / 2);
        for (std::size_t i = 0; i < planarSamples_.size(); ++i)
            planarSamples_[i] = Vec2(samples_[2 * i], samples_[2 * i + 1]);
        return planarSamples_;
    }

    void WaypointDecoder::splineMoments(unsigned int c, double *M)
    {
        const std::size_t n = waypoints_ + 2;
        auto y = [&](std::size_t i) { return knot(i, c); };
        std::fill(M, M + n, 0.0);
        if (n < 3)
            return; // a straight line
        if (n == 3)
        {
            // Not-a-knot with three points: the parabola through them (constant second derivative).
            const double m = y(0) - 2.0 * y(1) + y(2);
            M[0] = M[1] = M[2] = m;
            return;
        }
        // Unit spacing: M[i-1] + 4 M[i] + M[i+1] = 6 (y[i+1] - 2 y[i] + y[i-1]) for 1 <= i <= n-2, and
        // not-a-knot (continuous third derivative at t = 1 and t = n-2): M0 - 2 M1 + M2 = 0, likewise at the
        // other end. Substituting M0 = 2 M1 - M2 into the first equation gives 6 M1 = rhs1 (same at the end),
        // so M1 and M[n-2] are known and the interior is a tridiagonal system (Thomas algorithm).
        for (std::size_t i = 1; i + 1 < n; ++i)
            rhs_[i] = 6.0 * (y(i + 1) - 2.0 * y(i) + y(i - 1));
        M[1] = rhs_[1] / 6.0;
        M[n - 2] = rhs_[n - 2] / 6.0;
        if (n > 5)
        {
            // Unknowns M[2..n-3]; equation i: M[i-1] + 4 M[i] + M[i+1] = rhs[i].
            const std::size_t lo = 2, hi = n - 3;
            rhs_[lo] -= M[1];
            rhs_[hi] -= M[n - 2];
            cprime_[lo] = 1.0 / 4.0;
            rhs_[lo] /= 4.0;
            for (std::size_t i = lo + 1; i <= hi; ++i)
            {
                const double denom = 4.0 - cprime_[i - 1];
                cprime_[i] = 1.0 / denom;
                rhs_[i] = (rhs_[i] - rhs_[i - 1]) / denom;
            }
            M[hi] = rhs_[hi];
            for (std::size_t i = hi; i-- > lo;)
                M[i] = rhs_[i] - cprime_[i] * M[i + 1];
        }
        else if (n == 5)
            M[2] = (rhs_[2] - M[1] - M[3]) / 4.0;
        M[0] = 2.0 * M[1] - M[2];
        M[n - 1] = 2.0 * M[n - 2] - M[n - 3];
    }

    void WaypointDecoder::decode(const double *x)
    {
        const unsigned int k = dim_;
        std::copy(x, x + std::size_t(waypoints_) * k, knots_.begin() + k);
        const std::size_t n = waypoints_ + 2;
        const double tmax = static_cast<double>(n - 1);
        if (decoding_ == PathDecoding::Polyline)
        {
            std::copy(knots_.begin(), knots_.end(), path_.begin());
            for (unsigned int s = 0; s < sampleCount_; ++s)
            {
                const double t = tmax * s / (sampleCount_ - 1);
                const std::size_t i = std::min(static_cast<std::size_t>(t), n - 2);
                const double u = t - static_cast<double>(i);
                const double *p0 = knots_.data() + i * k, *p1 = p0 + k;
                double *q = samples_.data() + std::size_t(s) * k;
                for (unsigned int c = 0; c < k; ++c)
                    q[c] = p0[c] + (p1[c] - p0[c]) * u;
            }
            std::copy(goal_.begin(), goal_.end(), samples_.end() - k);
            return;
        }
        for (unsigned int c = 0; c < k; ++c)
            splineMoments(c, moments_.data() + std::size_t(c) * n);
        for (unsigned int s = 0; s < sampleCount_; ++s)
        {
            const double t = tmax * s / (sampleCount_ - 1);
            const std::size_t i = std::min(static_cast<std::size_t>(t), n - 2);
            const double u = t - static_cast<double>(i); // in [0, 1]
            const double v = 1.0 - u;
            const double a3 = v * v * v / 6.0, b3 = u * u * u / 6.0;
            double *q = path_.data() + std::size_t(s) * k;
            for (unsigned int c = 0; c < k; ++c)
            {
                const double *M = moments_.data() + std::size_t(c) * n;
                q[c] = M[i] * a3 + M[i + 1] * b3 + (knot(i, c) - M[i] / 6.0) * v +
                       (knot(i + 1, c) - M[i + 1] / 6.0) * u;
            }
        }
        std::copy(start_.begin(), start_.end(), path_.begin());
        std::copy(goal_.begin(), goal_.end(), path_.end() - k);
    }
} // namespace mhplan
