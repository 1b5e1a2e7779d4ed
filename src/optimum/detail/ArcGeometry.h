// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: angles, arcs and the exact distances between arcs, segments and polygons used by the tangent graph
   (src/optimum/TangentGraph.cpp). Not part of the installed API. */
#ifndef MHPLAN_OPTIMUM_DETAIL_ARC_GEOMETRY_H
#define MHPLAN_OPTIMUM_DETAIL_ARC_GEOMETRY_H

#include "src/base/Geometry.h"
#include "src/optimum/detail/OptimumInternal.h"
#include "src/optimum/detail/PolygonEdgeIndex.h"

#include <cmath>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        /** Angle in [0, 2 pi). */
        inline double normAngle(double a)
        {
            a = std::fmod(a, kTwoPi);
            if (a < 0.0)
                a += kTwoPi;
            if (a >= kTwoPi)
                a -= kTwoPi;
            return a;
        }

        /** Counter-clockwise angle from \e from to \e to, in [0, 2 pi). */
        inline double ccwDelta(double from, double to)
        {
            return normAngle(to - from);
        }

        inline Vec2 polar(const Vec2 &c, double rho, double angle)
        {
            return {c.x + rho * std::cos(angle), c.y + rho * std::sin(angle)};
        }

        /** An arc of the circle (c, rho), counter-clockwise from angle th0 over sweep in [0, 2 pi). */
        struct Arc
        {
            Vec2 c;
            double rho{0.0};
            double th0{0.0};
            double sweep{0.0};
            bool contains(double angle) const { return ccwDelta(th0, angle) <= sweep; }
            Vec2 at(double t) const { return polar(c, rho, th0 + t * sweep); }
        };

        /** Distance from a point to an arc. */
        double pointArcDistance(const Vec2 &p, const Arc &arc);

        /** Exact distance between an arc and a segment. */
        double arcSegmentDistance(const Arc &arc, const Vec2 &a, const Vec2 &b);

        /** True when some part of the segment lies inside the polygon deeper than tol. */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly, double tol);

        /** The same as segmentDeepInside(a, b, index.polygon(), tol), visiting only the edges near the
            segment; tol below the index's margin. */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const PolygonEdgeIndex &index, double tol);

        /** True when some part of the arc lies inside the polygon deeper than tol. */
        bool arcDeepInside(const Arc &arc, const std::vector<Vec2> &poly, double tol);

        /** The same as arcDeepInside(arc, index.polygon(), tol), visiting only the edges near the arc; tol
            below the index's margin. */
        bool arcDeepInside(const Arc &arc, const PolygonEdgeIndex &index, double tol);

        /** The arc's bounding box: its end points and the axis-extreme points it passes. */
        Box arcBoundingBox(const Arc &arc);
    } // namespace optimum_detail
} // namespace mhplan

#endif
