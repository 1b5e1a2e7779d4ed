// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the one contact rule of the exact collision models (docs/contact.md): obstacles and free space are
   closed; a position is valid when its penetration into the obstacles (grown by the robot radius) is at most
   the model's contact tolerance e, a segment when it penetrates by at most e / 2 everywhere. The segment rule
   is the stricter by e / 2, so every point computed along an accepted segment (rounding included) passes the
   point rule, which the independent dense check of every path applies (Metrics.h, denseCollisionFree). */
#ifndef MHPLAN_CONTACT_RULE_H
#define MHPLAN_CONTACT_RULE_H

#include "mhplan/base/Geometry.h"
#include "mhplan/base/World.h"

namespace mhplan::contact
{
    /** \brief The contact tolerance relative to the world's larger side (docs/contact.md). */
    constexpr double kRelativeTolerance = 1e-9;

    /** \brief A world's contact tolerance e: kRelativeTolerance x the larger side of its bounds. */
    inline double tolerance(const Box &bounds)
    {
        return kRelativeTolerance * std::max(bounds.width(), bounds.height());
    }

    /** \brief The robot disc (\e radius) at \e p collides with the circle of \e reach = circle radius +
        robot radius: it penetrates by more than \e tol. */
    inline bool pointHitsCircle(const Vec2 &p, const Vec2 &centre, double reach, double tol)
    {
        const double in = reach - tol;
        return in > 0.0 && squaredNorm(p - centre) < in * in;
    }

    /** \brief The disc swept along [a, b] penetrates the circle of \e reach by more than tol / 2. */
    inline bool segmentHitsCircle(const Vec2 &a, const Vec2 &b, const Vec2 &centre, double reach, double tol)
    {
        return pointSegmentDistance(centre, a, b) < reach - 0.5 * tol;
    }

    /** \brief The robot disc at \e p penetrates the polygon by more than \e tol. */
    inline bool pointHitsPolygon(const Vec2 &p, const Polygon &poly, double radius, double tol)
    {
        if (p.x < poly.bbox.xmin - radius || p.x > poly.bbox.xmax + radius || p.y < poly.bbox.ymin - radius ||
            p.y > poly.bbox.ymax + radius)
            return false;
        return pointPolygonSignedDistance(p, poly.vertices) < radius - tol;
    }

    /** \brief The disc swept along [a, b] penetrates the polygon by more than tol / 2. A disc robot (radius
        above tol / 2): the segment-polygon distance decides. A point robot meeting the polygon: a piece of
        the segment between two boundary crossings enters when its midpoint lies deeper than tol / 4 - radius
        (inside a convex polygon the depth along a piece is concave, so an accepted piece stays within
        tol / 2; docs/contact.md states the non-convex case). */
    inline bool segmentHitsPolygon(const Vec2 &a, const Vec2 &b, const Polygon &poly, double radius,
                                   double tol)
    {
        const double d = segmentPolygonDistance(a, b, poly.vertices);
        if (d < radius - 0.5 * tol)
            return true;
        if (d > 0.0)
            return false;
        return segmentEntersPolygonInterior(a, b, poly.vertices, 0.25 * tol - radius);
    }
} // namespace mhplan::contact

#endif
