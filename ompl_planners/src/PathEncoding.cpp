#include "PathEncoding.h"

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
        if (samples < 2)
            throw std::invalid_argument("parameter 'spline_samples' must be in [2, 100000]; got " +
                                        std::to_string(samples));
        start_ = start;
        goal_ = goal;
        waypoints_ = waypoints;
        decoding_ = decoding;
        sampleCount_ = samples;
        const std::size_t knots = waypoints + 2;
        knots_.assign(knots, Vec2());
        knots_.front() = start;
        knots_.back() = goal;
        mx_.assign(knots, 0.0);
        my_.assign(knots, 0.0);
        rhs_.assign(knots, 0.0);
        cprime_.assign(knots, 0.0);
        samples_.assign(samples, Vec2());
        path_.assign(decoding == PathDecoding::Spline ? samples : knots, Vec2());
    }

    void WaypointDecoder::splineMoments(bool yCoordinate, std::vector<double> &M)
    {
        const std::size_t n = knots_.size();
        auto y = [&](std::size_t i) { return yCoordinate ? knots_[i].y : knots_[i].x; };
        std::fill(M.begin(), M.end(), 0.0);
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
        for (unsigned int i = 0; i < waypoints_; ++i)
            knots_[i + 1] = Vec2(x[2 * i], x[2 * i + 1]);
        const std::size_t n = knots_.size();
        const double tmax = static_cast<double>(n - 1);
        if (decoding_ == PathDecoding::Polyline)
        {
            for (std::size_t i = 0; i < n; ++i)
                path_[i] = knots_[i];
            for (unsigned int k = 0; k < sampleCount_; ++k)
            {
                const double t = tmax * k / (sampleCount_ - 1);
                std::size_t i = std::min(static_cast<std::size_t>(t), n - 2);
                const double u = t - static_cast<double>(i);
                samples_[k] = knots_[i] + (knots_[i + 1] - knots_[i]) * u;
            }
            samples_.back() = goal_;
            return;
        }
        splineMoments(false, mx_);
        splineMoments(true, my_);
        for (unsigned int k = 0; k < sampleCount_; ++k)
        {
            const double t = tmax * k / (sampleCount_ - 1);
            const std::size_t i = std::min(static_cast<std::size_t>(t), n - 2);
            const double u = t - static_cast<double>(i); // in [0, 1]
            const double v = 1.0 - u;
            const double a3 = v * v * v / 6.0, b3 = u * u * u / 6.0;
            const Vec2 &p0 = knots_[i], &p1 = knots_[i + 1];
            path_[k].x =
                mx_[i] * a3 + mx_[i + 1] * b3 + (p0.x - mx_[i] / 6.0) * v + (p1.x - mx_[i + 1] / 6.0) * u;
            path_[k].y =
                my_[i] * a3 + my_[i + 1] * b3 + (p0.y - my_[i] / 6.0) * v + (p1.y - my_[i + 1] / 6.0) * u;
        }
        path_.front() = start_;
        path_.back() = goal_;
    }
} // namespace mhplan
