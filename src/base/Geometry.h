// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: exact 2D geometry shared by the world model, the collision back ends and the optimum. */
#ifndef MHPLAN_GEOMETRY_H
#define MHPLAN_GEOMETRY_H

#include <algorithm>
#include <cmath>
#include <vector>

namespace mhplan
{
    /** \brief pi, the one definition of it in mhplan. */
    constexpr double kPi = 3.14159265358979323846;

    /** \brief A point or vector in the plane. */
    struct Vec2
    {
        double x{0.0};
        double y{0.0};

        Vec2() = default;
        Vec2(double x_, double y_) : x(x_), y(y_) {}

        Vec2 operator+(const Vec2 &o) const { return {x + o.x, y + o.y}; }
        Vec2 operator-(const Vec2 &o) const { return {x - o.x, y - o.y}; }
        Vec2 operator*(double s) const { return {x * s, y * s}; }
        Vec2 operator/(double s) const { return {x / s, y / s}; }
        bool operator==(const Vec2 &o) const { return x == o.x && y == o.y; }
        bool operator!=(const Vec2 &o) const { return !(*this == o); }
    };

    inline double dot(const Vec2 &a, const Vec2 &b)
    {
        return a.x * b.x + a.y * b.y;
    }
    /** \brief z-component of the 3D cross product (positive when b is counter-clockwise of a). */
    inline double cross(const Vec2 &a, const Vec2 &b)
    {
        return a.x * b.y - a.y * b.x;
    }

    /** \brief The sign of the turn a -> b -> c: 1 left (counter-clockwise), -1 right, 0 collinear (the sign
       of the exact cross product's rounding, as every polygon predicate here uses it). */
    inline int orientation(const Vec2 &a, const Vec2 &b, const Vec2 &c)
    {
        const double v = cross(b - a, c - a);
        return (v > 0.0) - (v < 0.0);
    }

    /** \brief \e p lies in the axis-aligned box of [a, b] (on the segment when also collinear with it). */
    inline bool onSegment(const Vec2 &p, const Vec2 &a, const Vec2 &b)
    {
        return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
               p.y <= std::max(a.y, b.y);
    }
    inline double norm(const Vec2 &a)
    {
        // The square root of the squares where they neither overflow nor underflow (within an ulp or so of
        // std::hypot, which cost a fifth of a memetic planner's time among 1,000 rectangles); std::hypot
        // beyond (and for NaN).
        const double s = a.x * a.x + a.y * a.y;
        return s < 1e300 && s > 1e-300 ? std::sqrt(s) : std::hypot(a.x, a.y);
    }
    inline double squaredNorm(const Vec2 &a)
    {
        return a.x * a.x + a.y * a.y;
    }
    inline double distance(const Vec2 &a, const Vec2 &b)
    {
        return norm(a - b);
    }

    /** \brief Axis-aligned box [xmin, xmax] x [ymin, ymax]. */
    struct Box
    {
        double xmin{0.0}, xmax{0.0}, ymin{0.0}, ymax{0.0};
        bool contains(const Vec2 &p) const
        {
            return p.x >= xmin && p.x <= xmax && p.y >= ymin && p.y <= ymax;
        }
        bool overlaps(const Box &o) const
        {
            return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax;
        }
        double width() const { return xmax - xmin; }
        double height() const { return ymax - ymin; }
        /** \brief The box grown by \e d on every side. */
        Box inflated(double d) const { return {xmin - d, xmax + d, ymin - d, ymax + d}; }
    };

    /** \brief Closest point to \e p on the segment [a, b] (a == b allowed). */
    Vec2 closestPointOnSegment(const Vec2 &p, const Vec2 &a, const Vec2 &b);

    /** \brief Euclidean distance from \e p to the closed segment [a, b]. */
    double pointSegmentDistance(const Vec2 &p, const Vec2 &a, const Vec2 &b);

    /** \brief True when the closed segments [a, b] and [c, d] share a point (touching counts). */
    bool segmentsIntersect(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

    /** \brief True when the open segments cross properly (interiors meet in one point, no touching). */
    bool segmentsCrossProperly(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

    /** \brief Distance between the closed segments [a, b] and [c, d] (0 when they intersect). */
    double segmentSegmentDistance(const Vec2 &a, const Vec2 &b, const Vec2 &c, const Vec2 &d);

    /** \brief Bounding box of a point set (empty set gives an inverted box). */
    Box boundingBox(const std::vector<Vec2> &pts);

    /** \brief Twice the signed area (positive for counter-clockwise vertex order). */
    double signedArea2(const std::vector<Vec2> &poly);

    /** \brief True when the polygon is convex (either orientation, collinear vertices allowed). */
    bool polygonIsConvex(const std::vector<Vec2> &poly);

    /** \brief True when no two non-adjacent edges of the closed polygon meet and no edge has zero length. */
    bool polygonIsSimple(const std::vector<Vec2> &poly);

    /** \brief True when \e p lies inside or on the boundary of the simple polygon (even-odd rule). */
    bool pointInPolygon(const Vec2 &p, const std::vector<Vec2> &poly);

    /** \brief Distance from \e p to the polygon's boundary. */
    double pointPolygonBoundaryDistance(const Vec2 &p, const std::vector<Vec2> &poly);

    /** \brief Signed distance from \e p to the polygon region: positive outside, negative inside. */
    double pointPolygonSignedDistance(const Vec2 &p, const std::vector<Vec2> &poly);

    /** \brief Distance from the segment [a, b] to the closed polygon region (0 if they meet). */
    double segmentPolygonDistance(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly);

    /** \brief True when some point of the segment [a, b] lies strictly inside the simple polygon (running
        along an edge or touching a vertex does not count). With \e depth > 0: when the midpoint of a piece
        of the segment between two boundary crossings (or an end) lies farther than \e depth inside. */
    bool segmentEntersPolygonInterior(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly,
                                      double depth = 0.0);

    /** \brief Minimum over the segment [a, b] of the polygon's signed distance: the segment-polygon distance
        when the segment stays outside, minus the deepest penetration otherwise. Exact for convex polygons;
        for non-convex ones an upper bound within |b - a| / 128 of the minimum (sampling plus golden-section
        refinement). */
    double deepestSegmentPenetration(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly);

    /** \brief Distance from the segment [a, b] to the closed disc (c, r) (0 if they meet). */
    inline double segmentCircleDistance(const Vec2 &a, const Vec2 &b, const Vec2 &c, double r)
    {
        return std::max(0.0, pointSegmentDistance(c, a, b) - r);
    }

    /** \brief Corners of a rectangle of the given centre, size and rotation (radians), counter-clockwise. */
    std::vector<Vec2> rectangleCorners(const Vec2 &center, double width, double height, double angle);
} // namespace mhplan

#endif
