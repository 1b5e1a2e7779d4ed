// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: a bucket grid over the edges of one large polygon, so that the tangent graph's segment, arc and
   point checks (src/optimum/TangentGraph.cpp) visit only the edges near the query instead of all of them.
   Every predicate returns exactly what the plain per-edge function named in its comment returns: it
   evaluates the same per-edge expressions, in the same operand order, on a subset of the edges that
   contains every edge able to change the answer. Not part of the installed API. */
#ifndef MHPLAN_OPTIMUM_DETAIL_POLYGON_EDGE_INDEX_H
#define MHPLAN_OPTIMUM_DETAIL_POLYGON_EDGE_INDEX_H

#include "src/base/Geometry.h"
#include "src/optimum/detail/BucketIndex.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        /** Edge i of a polygon runs from vertex i to vertex i + 1 (mod n). Each bucket of a uniform grid over
            the polygon's bounding box inflated by \e margin lists the edges whose bounding box inflated by
            \e margin meets it. Not thread-safe (BucketIndex stamps). */
        class PolygonEdgeIndex
        {
          public:
            /** \e margin must exceed, by a few rounding errors, every distance threshold passed to the
                predicates below (the tangent graph passes the robot radius plus twice its tolerance). */
            PolygonEdgeIndex(const std::vector<Vec2> &poly, double margin)
                : poly_(&poly), margin_(margin), bbox_(boundingBox(poly)),
                  grid_(bbox_.inflated(margin), poly.size())
            {
                const std::size_t n = poly.size();
                for (std::size_t i = 0; i < n; ++i)
                    grid_.insert(static_cast<int>(i),
                                 boundingBox({poly[i], poly[(i + 1) % n]}).inflated(margin));
            }

            /** Calls f(i) for (at least) every edge i whose inflated bounding box meets the segment [a, b],
                each once; stops and returns true as soon as f returns true. */
            template <typename F> bool anyEdgeOnSegment(const Vec2 &a, const Vec2 &b, F &&f) const
            {
                return grid_.anyOnSegment(a, b, std::forward<F>(f));
            }

            /** Calls f(i) for (at least) every edge i whose inflated bounding box meets \e bb. */
            template <typename F> bool anyEdgeInBox(const Box &bb, F &&f) const
            {
                return grid_.anyInBox(bb, std::forward<F>(f));
            }

            /** Same as pointInPolygon(p, poly) (Geometry.h): true on the boundary or inside (crossing parity
                of a ray to +x). Visits only the edges listed in p's row of buckets from p's column to the
                right: every edge whose y-range holds p.y and whose x-range reaches p.x is there. */
            bool contains(const Vec2 &p) const
            {
                const std::vector<Vec2> &v = *poly_;
                const std::size_t n = v.size();
                // No edge spans p.y: no crossing and not on an edge.
                if (p.y < bbox_.ymin || p.y > bbox_.ymax)
                    return false;
                bool onEdge = false;
                bool inside = false;
                grid_.anyInBox(Box{p.x, std::max(p.x, bbox_.xmax + margin_), p.y, p.y},
                               [&](int e)
                               {
                                   // pointInPolygon's pair (i, j = i - 1) is (e + 1, e).
                                   const Vec2 &a = v[(static_cast<std::size_t>(e) + 1) % n];
                                   const Vec2 &b = v[static_cast<std::size_t>(e)];
                                   if (orientation(a, b, p) == 0 && onSegment(p, a, b))
                                   {
                                       onEdge = true;
                                       return true;
                                   }
                                   if ((a.y > p.y) != (b.y > p.y))
                                   {
                                       const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                                       if (p.x < xCross)
                                           inside = !inside;
                                   }
                                   return false;
                               });
                return onEdge || inside;
            }

            /** Same as pointPolygonSignedDistance(p, poly) < c (Geometry.h), for |c| < margin. */
            bool signedDistanceBelow(const Vec2 &p, double c) const
            {
                const std::vector<Vec2> &v = *poly_;
                const std::size_t n = v.size();
                const Box at{p.x, p.x, p.y, p.y};
                // An edge through p: signed distance 0.
                if (grid_.anyInBox(at,
                                   [&](int e)
                                   {
                                       const Vec2 &a = v[static_cast<std::size_t>(e)];
                                       const Vec2 &b = v[(static_cast<std::size_t>(e) + 1) % n];
                                       return orientation(a, b, p) == 0 && onSegment(p, a, b);
                                   }))
                    return 0.0 < c;
                // Some edge closer than |c| to p (only those can be, and they are all in p's bucket).
                auto closer = [&](double limit, bool strict)
                {
                    return grid_.anyInBox(at,
                                          [&](int e)
                                          {
                                              const double d = pointSegmentDistance(
                                                  p, v[static_cast<std::size_t>(e)],
                                                  v[(static_cast<std::size_t>(e) + 1) % n]);
                                              return strict ? d < limit : d <= limit;
                                          });
                };
                if (contains(p))
                    // -d < c: always for c > 0 (d >= 0), else when every edge is farther than -c.
                    return c > 0.0 || !closer(-c, false);
                // d < c.
                return c > 0.0 && closer(c, true);
            }

            /** Same as segmentPolygonDistance(a, b, poly) < c (Geometry.h), for c < margin. */
            bool segmentDistanceBelow(const Vec2 &a, const Vec2 &b, double c) const
            {
                if (!(c > 0.0))
                    return false;
                const std::vector<Vec2> &v = *poly_;
                const std::size_t n = v.size();
                if (anyEdgeOnSegment(a, b,
                                     [&](int e)
                                     {
                                         return segmentSegmentDistance(
                                                    a, b, v[static_cast<std::size_t>(e)],
                                                    v[(static_cast<std::size_t>(e) + 1) % n]) < c;
                                     }))
                    return true;
                return contains(a) || contains(b);
            }

            /** The polygon's vertices. */
            const std::vector<Vec2> &polygon() const { return *poly_; }

          private:
            const std::vector<Vec2> *poly_;
            double margin_;
            Box bbox_;
            BucketIndex grid_;
        };
    } // namespace optimum_detail
} // namespace mhplan

#endif
