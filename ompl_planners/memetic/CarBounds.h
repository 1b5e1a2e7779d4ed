// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: lower bounds of the Dubins and Reeds-Shepp distances for the memetic planners' nearest-state
   searches off the plane (docs/spaces.md, "First paths: a lazy roadmap on states"). */
#ifndef MHPLAN_OMPL_PLANNERS_MEMETIC_CAR_BOUNDS_H
#define MHPLAN_OMPL_PLANNERS_MEMETIC_CAR_BOUNDS_H

#include "src/collision/CarSpaces.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhplan
{
    /** \brief A car state (x, y, yaw) with the yaw's cosine and sine. */
    struct CarPose
    {
        double x{0.0}, y{0.0}, yaw{0.0}, c{1.0}, s{0.0};
        CarPose() = default;
        /** \brief \e trig false: no cosine and sine (for CarBounds::basic() only). */
        CarPose(double x_, double y_, double yaw_, bool trig = true)
            : x(x_), y(y_), yaw(yaw_), c(trig ? std::cos(yaw_) : 1.0), s(trig ? std::sin(yaw_) : 0.0)
        {
        }
    };

    /** \brief The car bounds of a space: its turning radius (0: not OMPL's Dubins or Reeds-Shepp space, no
        bound) and whether it drives forward only with a directed distance (Dubins, not the symmetric
        variant). States are parametrised (x, y, yaw). */
    struct CarBounds
    {
        double radius{0.0};
        bool forward{false};

        explicit CarBounds(const ompl::base::StateSpace *space)
        {
            if (const auto *d = dynamic_cast<const ompl::base::DubinsStateSpace *>(space))
            {
                radius = detail::DubinsRadius::of(*d);
                forward = !d->hasSymmetricDistance();
            }
            else if (const auto *r = dynamic_cast<const ompl::base::ReedsSheppStateSpace *>(space))
                radius = detail::ReedsSheppRadius::of(*r);
        }

        bool active() const { return radius > 0.0; }

        /** \brief A lower bound of the space's distance between \e a and \e b (either way): any car path of
            curvature at most 1 / r is at least as long as the positions' distance and as r times the heading
            change (the heading turns at most 1 / r per unit length). Shrunk by a relative 1e-9: rounding
           never makes it exceed the distance. */
        double basic(const CarPose &a, const CarPose &b) const
        {
            constexpr double kTwoPi = 6.283185307179586;
            const double dx = b.x - a.x, dy = b.y - a.y;
            double turn = std::abs(a.yaw - b.yaw);
            if (turn >= kTwoPi)
                turn = std::fmod(turn, kTwoPi);
            turn = std::min(turn, kTwoPi - turn);
            return std::max(std::sqrt(dx * dx + dy * dy), radius * turn) * (1.0 - 1e-9);
        }

        /** \brief A lower bound of the space's distance from \e a to \e b, at least basic(). Forward only
            (Dubins): a path from \e a to \e b also reaches b's position from \e a, and, driven backwards, a's
            position from \e b turned by pi: each at least pointBound(). */
        double lower(const CarPose &a, const CarPose &b) const
        {
            const double lb = basic(a, b);
            if (!forward)
                return lb;
            const double dx = b.x - a.x, dy = b.y - a.y;
            // b's position in a's frame; a's position in the frame of b turned by pi (mirrored: the bound is
            // the same for both sides).
            const double depart = pointBound(a.c * dx + a.s * dy, -a.s * dx + a.c * dy);
            const double arrive = pointBound(b.c * dx + b.s * dy, b.s * dx - b.c * dy);
            return std::max(lb, std::max(depart, arrive) * (1.0 - 1e-9));
        }

        /** \brief A lower bound of the shortest forward path of curvature at most 1 / r from the origin
            (heading +x) to the position (px, py), any final heading: outside both turning circles the
            shorter of the two arc-then-line paths (turn left or right until the heading points at the
            position, then straight: the shortest way there, Dubins' result for a free final heading), inside
            one the straight-line distance. */
        double pointBound(double px, double py) const
        {
            constexpr double kTwoPi = 6.283185307179586;
            const double r = radius;
            const double straight = std::sqrt(px * px + py * py);
            double best = std::numeric_limits<double>::infinity();
            for (const double side : {1.0, -1.0})
            {
                // The turning circle's centre is (0, side r); mirrored to a left turn.
                const double vx = px, vy = side * py - r;
                const double d2 = vx * vx + vy * vy;
                if (d2 <= r * r)
                    return straight;
                const double t = std::sqrt(d2 - r * r);
                double phi = std::atan2(vy, vx) + std::atan2(r, t);
                if (phi < 0.0)
                    phi += kTwoPi;
                if (phi >= kTwoPi)
                    phi -= kTwoPi;
                best = std::min(best, r * phi + t);
            }
            return std::max(best, straight);
        }
    };
} // namespace mhplan

#endif
