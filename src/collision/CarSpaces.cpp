// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/CarSpaces.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <array>
#include <cmath>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

        double mod2pi(double x)
        {
            double y = std::fmod(x, kTwoPi);
            if (y < 0.0)
                y += kTwoPi;
            return y >= kTwoPi ? 0.0 : y;
        }

        using Type = ob::DubinsStateSpace::DubinsPathSegmentType;

        /** The end pose of following three segments (lengths in turning radii) from (0, 0, alpha). */
        void follow(const Type *type, const std::array<double, 3> &len, double alpha, double &x, double &y,
                    double &theta)
        {
            x = 0.0;
            y = 0.0;
            theta = alpha;
            for (int i = 0; i < 3; ++i)
            {
                const double v = len[i];
                if (type[i] == ob::DubinsStateSpace::DUBINS_LEFT)
                {
                    x += std::sin(theta + v) - std::sin(theta);
                    y += -std::cos(theta + v) + std::cos(theta);
                    theta += v;
                }
                else if (type[i] == ob::DubinsStateSpace::DUBINS_RIGHT)
                {
                    x += -std::sin(theta - v) + std::sin(theta);
                    y += std::cos(theta - v) - std::cos(theta);
                    theta -= v;
                }
                else
                {
                    x += v * std::cos(theta);
                    y += v * std::sin(theta);
                }
            }
        }

        const Type *typeOf(Type a, Type b, Type c)
        {
            for (const auto &t : ob::DubinsStateSpace::dubinsPathType)
                if (t[0] == a && t[1] == b && t[2] == c)
                    return t;
            return ob::DubinsStateSpace::dubinsPathType[0];
        }
    } // namespace

    ob::DubinsStateSpace::DubinsPath SafeDubinsStateSpace::shortestPath(const ob::State *state1,
                                                                        const ob::State *state2) const
    {
        const auto *s1 = state1->as<ob::SE2StateSpace::StateType>();
        const auto *s2 = state2->as<ob::SE2StateSpace::StateType>();
        const double dx = s2->getX() - s1->getX();
        const double dy = s2->getY() - s1->getY();
        const double d = std::hypot(dx, dy) / rho_;
        const double th = d > 0.0 ? std::atan2(dy, dx) : 0.0;
        const double a = mod2pi(s1->getYaw() - th);
        const double b = mod2pi(s2->getYaw() - th);
        const double sa = std::sin(a), sb = std::sin(b), ca = std::cos(a), cb = std::cos(b);
        const double cab = std::cos(a - b);
        const Type L = DUBINS_LEFT, S = DUBINS_STRAIGHT, R = DUBINS_RIGHT;

        struct Candidate
        {
            const Type *type;
            std::array<double, 3> len;
        };
        std::array<Candidate, 8> c{};
        std::size_t n = 0;
        // A single arc: where LSL or RSR degenerate (p = 0, their angle from atan2(0, 0) is arbitrary and may
        // add a full circle).
        c[n++] = {typeOf(L, S, L), {mod2pi(b - a), 0.0, 0.0}};
        c[n++] = {typeOf(R, S, R), {mod2pi(a - b), 0.0, 0.0}};
        // Shkel & Lumelsky's closed forms, in the frame where the goal lies at (d, 0).
        double p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sa - sb); // LSL
        if (p2 >= 0.0)
        {
            const double tmp = std::atan2(cb - ca, d + sa - sb);
            c[n++] = {typeOf(L, S, L), {mod2pi(tmp - a), std::sqrt(p2), mod2pi(b - tmp)}};
        }
        p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sb - sa); // RSR
        if (p2 >= 0.0)
        {
            const double tmp = std::atan2(ca - cb, d - sa + sb);
            c[n++] = {typeOf(R, S, R), {mod2pi(a - tmp), std::sqrt(p2), mod2pi(tmp - b)}};
        }
        p2 = -2.0 + d * d + 2.0 * cab + 2.0 * d * (sa + sb); // LSR
        if (p2 >= 0.0)
        {
            const double p = std::sqrt(p2);
            const double tmp = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p);
            c[n++] = {typeOf(L, S, R), {mod2pi(tmp - a), p, mod2pi(tmp - b)}};
        }
        p2 = -2.0 + d * d + 2.0 * cab - 2.0 * d * (sa + sb); // RSL
        if (p2 >= 0.0)
        {
            const double p = std::sqrt(p2);
            const double tmp = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p);
            c[n++] = {typeOf(R, S, L), {mod2pi(a - tmp), p, mod2pi(b - tmp)}};
        }
        double k = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sa - sb)) / 8.0; // RLR
        if (std::fabs(k) <= 1.0)
        {
            const double p = mod2pi(kTwoPi - std::acos(k));
            const double t = mod2pi(a - std::atan2(ca - cb, d - sa + sb) + 0.5 * p);
            c[n++] = {typeOf(R, L, R), {t, p, mod2pi(a - b - t + p)}};
        }
        k = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sb - sa)) / 8.0; // LRL
        if (std::fabs(k) <= 1.0)
        {
            const double p = mod2pi(kTwoPi - std::acos(k));
            const double t = mod2pi(-a - std::atan2(ca - cb, d + sa - sb) + 0.5 * p);
            c[n++] = {typeOf(L, R, L), {t, p, mod2pi(b - a - t + p)}};
        }

        // Keep the shortest word that arrives; failing that (never seen), the one that comes closest.
        const Candidate *best = nullptr;
        const Candidate *closest = nullptr;
        double bestLength = std::numeric_limits<double>::infinity();
        double closestError = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i)
        {
            double x, y, theta;
            follow(c[i].type, c[i].len, a, x, y, theta);
            const double headingError = std::fabs(std::remainder(theta - b, kTwoPi));
            const double error = std::hypot(x - d, y) + headingError;
            const double length = c[i].len[0] + c[i].len[1] + c[i].len[2];
            if (error < closestError)
            {
                closestError = error;
                closest = &c[i];
            }
            if (error <= 1e-6 && length < bestLength)
            {
                bestLength = length;
                best = &c[i];
            }
        }
        if (best == nullptr)
            best = closest;
        if (best == nullptr) // unreachable: LSL or RSR always exists
            return DubinsPath(dubinsPathType[0], 0.0, d, 0.0);
        return DubinsPath(best->type, best->len[0], best->len[1], best->len[2]);
    }

    double SafeDubinsStateSpace::distance(const ob::State *state1, const ob::State *state2) const
    {
        return rho_ * shortestPath(state1, state2).length();
    }

    void SafeDubinsStateSpace::interpolate(const ob::State *from, const ob::State *to, double t,
                                           ob::State *state) const
    {
        bool firstTime = true;
        DubinsPath path;
        interpolate(from, to, t, firstTime, path, state);
    }

    void SafeDubinsStateSpace::interpolate(const ob::State *from, const ob::State *to, double t,
                                           bool &firstTime, DubinsPath &path, ob::State *state) const
    {
        if (firstTime)
        {
            if (t >= 1.0)
            {
                if (to != state)
                    copyState(state, to);
                return;
            }
            if (t <= 0.0)
            {
                if (from != state)
                    copyState(state, from);
                return;
            }
            path = shortestPath(from, to);
            firstTime = false;
        }
        ob::DubinsStateSpace::interpolate(from, path, t, state);
    }
} // namespace mhplan
