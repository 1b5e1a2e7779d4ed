// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/CarSpaces.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <algorithm>
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
        const double forward = shortestPath(state1, state2).length();
        return rho_ * (isSymmetric_ ? std::min(forward, shortestPath(state2, state1).length()) : forward);
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
            if (isSymmetric_)
            {
                // OMPL's rule: the path from \e to back, followed backwards, unless the forward one is
                // shorter (ties go backwards, as in OMPL).
                DubinsPath back = shortestPath(to, from);
                if (!(path.length() < back.length()))
                {
                    back.reverse_ = true;
                    path = back;
                }
            }
            firstTime = false;
        }
        ob::DubinsStateSpace::interpolate(from, path, t, state);
    }

    namespace
    {
        /** OMPL 1.5.2's wrap of the start's and goal's angles into [0, 2 pi): a value in (-1e-7, 0), or
           within 5e-7 below a whole turn, is 0 (docs/spaces.md, "OMPL's Dubins assertions"). */
        double omplWrap(double x)
        {
            if (x < 0.0 && x > -1e-7)
                return 0.0;
            const double y = x - kTwoPi * std::floor(x / kTwoPi);
            return kTwoPi - y < 5e-7 ? 0.0 : y;
        }

        /** How far below a whole turn (a multiple of 2 pi) the turn angle \e x lies where OMPL 1.5.2 rounds
           it to 0 (within 5e-7 below, or in (-1e-7, 0); the window widened by 1 % for rounding); else 0. */
        double roundedAway(double x)
        {
            const double y = x - kTwoPi * std::floor(x / kTwoPi);
            const double gap = kTwoPi - y;
            return gap > 0.0 && gap < 5.05e-7 ? gap : 0.0;
        }

        /** Whether the angle with sine \e sx and cosine \e cx lies between 1e-10 and 1e-6 below a whole turn.
         */
        bool justBelowTurn(double sx, double cx)
        {
            return cx > 0.0 && sx < -1e-10 && sx > -1e-6;
        }
    } // namespace

    bool omplDubinsMayFail(const ob::State *state1, const ob::State *state2, double rho)
    {
        const auto *s1 = state1->as<ob::SE2StateSpace::StateType>();
        const auto *s2 = state2->as<ob::SE2StateSpace::StateType>();
        const double dx = s2->getX() - s1->getX();
        const double dy = s2->getY() - s1->getY();
        // d, the angle of the line and the start's and goal's angles to it, as OMPL computes them.
        const double d = std::sqrt(dx * dx + dy * dy) / rho;
        const double th = std::atan2(dy, dx);
        const double a = omplWrap(s1->getYaw() - th);
        const double b = omplWrap(s2->getYaw() - th);
        if (!std::isfinite(d) || !std::isfinite(a) || !std::isfinite(b))
            return true; // not a pose OMPL can measure at all
        if (d < 1e-6 && std::fabs(a - b) < 1e-6)
            return false; // OMPL returns the empty word without computing any
        const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
        const double cab = ca * cb + sa * sb;
        // The six words OMPL computes, by Shkel and Lumelsky's closed forms: whether each exists (tmp), the
        // vector whose angle theta gives its tangent (less atan2(psi, p) for the two words that change sides,
        // plus p / 2 for the three-arc words, whose middle arc is p = 2 pi - acos(tmp)), and the directions
        // of its first and last turns.
        struct Word
        {
            bool arcs, leftFirst, leftLast;
            double tmp, vx, vy, psi;
        };
        const double lslX = d + sa - sb, lslY = cb - ca, rsrX = d - sa + sb, rsrY = ca - cb;
        const Word words[6] = {
            {false, true, true, 2.0 + d * d - 2.0 * (cab - d * (sa - sb)), lslX, lslY, 0.0},            // LSL
            {false, false, false, 2.0 + d * d - 2.0 * (cab - d * (sb - sa)), rsrX, rsrY, 0.0},          // RSR
            {false, false, true, d * d - 2.0 + 2.0 * (cab - d * (sa + sb)), d - sa - sb, ca + cb, 2.0}, // RSL
            {false, true, false, d * d - 2.0 + 2.0 * (cab + d * (sa + sb)), d + sa + sb, -ca - cb,
             -2.0},                                                                                     // LSR
            {true, false, false, 0.125 * (6.0 - d * d + 2.0 * (cab + d * (sa - sb))), rsrX, rsrY, 0.0}, // RLR
            {true, true, true, 0.125 * (6.0 - d * d + 2.0 * (cab - d * (sa - sb))), lslX, lslY, 0.0}};  // LRL
        // Where OMPL rounds a word's first turn t up to a whole turn by g, the rest of the word turns about
        // the first turning circle's centre by g; OMPL asserts that the centre of the last circle (a turning
        // radius from the goal) still lies where it should to 2e-6 in each coordinate, and it has moved by g
        // times its distance from the first centre, at most r + 1 for r the first centre's distance from the
        // goal: flagged from 1.8e-6. Rounding t and the last turn q together also turns the end's heading by
        // their sum (OMPL's tolerance about 1e-6).
        for (const Word &w : words)
        {
            if (w.arcs ? !(std::fabs(w.tmp) <= 1.0) : !(w.tmp >= -1e-7))
                continue; // OMPL does not compute this word
            // The straight part's length where the quick test needs it (the words that change sides).
            const double ps = w.arcs || w.psi == 0.0 ? 0.0 : std::sqrt(std::max(w.tmp, 0.0));
            // The quick test first: the first turn's cosine and sine from the vector by products and square
            // roots; only a turn between 1e-10 and 1e-6 below a whole turn, or a degenerate word (its vector
            // near zero, its middle arc near a whole or half turn), needs the exact angle (atan2, acos). Far
            // goals (d >= 1e3, where 1e-10 times the lever may matter) always take the exact test.
            const double n = std::sqrt(w.vx * w.vx + w.vy * w.vy);
            if (d < 1e3 && n >= 1e-7 && !(w.arcs && std::fabs(w.tmp) > 1.0 - 1e-9))
            {
                const double np = w.psi != 0.0 ? std::sqrt(ps * ps + 4.0) : 1.0;
                const double cp = w.psi != 0.0 ? ps / np : 1.0, sp = w.psi / np;
                const double ct = (w.vx * cp + w.vy * sp) / n, st = (w.vy * cp - w.vx * sp) / n;
                // t = theta - a (left first) or a - theta, plus h = p / 2 = pi - acos(tmp) / 2 for three
                // arcs.
                const double sy = w.leftFirst ? st * ca - ct * sa : sa * ct - ca * st;
                const double cy = ct * ca + st * sa;
                const double ch = w.arcs ? -std::sqrt(0.5 * (1.0 + w.tmp)) : 1.0;
                const double sh = w.arcs ? std::sqrt(0.5 * (1.0 - w.tmp)) : 0.0;
                const double sx = sy * ch + cy * sh, cx = cy * ch - sy * sh;
                if (!justBelowTurn(sx, cx))
                    continue;
            }
            const double p = w.arcs ? kTwoPi - std::acos(w.tmp) : std::sqrt(std::max(w.tmp, 0.0));
            const double theta = std::atan2(w.vy, w.vx) - (w.psi != 0.0 ? std::atan2(w.psi, p) : 0.0);
            const double t = (w.leftFirst ? theta - a : a - theta) + (w.arcs ? 0.5 * p : 0.0);
            const double q = w.arcs ? (w.leftFirst ? b - a : a - b) - omplWrap(t) + p
                                    : (w.leftLast ? b - theta : theta - b);
            const double gt = roundedAway(t), gq = roundedAway(q);
            const double r = w.leftFirst ? std::hypot(d + sa, -ca) : std::hypot(d - sa, ca);
            if (gt * (r + 1.0) > 1.8e-6 || gt + gq > 0.9e-6)
                return true;
        }
        return false;
    }
} // namespace mhplan
