// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the exact optimum of geometric worlds, the reduced visibility (tangent) graph over inflated discs
   and polygon corners (computeOptimum in Optimum.h describes the method). */
#include "src/optimum/detail/ArcGeometry.h"
#include "src/optimum/detail/BucketIndex.h"
#include "src/optimum/detail/OptimumInternal.h"
#include "src/optimum/detail/PathGraph.h"
#include "src/optimum/detail/PolygonEdgeIndex.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        namespace
        {
            struct Disc
            {
                Vec2 c;
                double rho{0.0};
                int circle{-1};  ///< index of the circle obstacle, or -1
                int polygon{-1}; ///< index of the polygon whose convex vertex this is, or -1
                Vec2 prev, next; ///< the vertex's neighbours (polygon vertices)
                int pointNode{-1};
                int pointValid{-1}; ///< cached validity of a radius-0 disc's centre (-1 unknown)
                std::vector<std::pair<double, int>> nodes; ///< (angle, node) for discs of radius > 0
            };

            class TangentGraphBuilder
            {
              public:
                /** \e keepVertex, when given, selects the polygon vertices that get a disc (grids: the convex
                    corners of the blocked region, not every corner of every cell). */
                TangentGraphBuilder(const World &w, const Query &q, const OptimumOptions &opt,
                                    std::function<bool(const Vec2 &)> keepVertex = {})
                    : world_(w), query_(q), opt_(opt), keepVertex_(std::move(keepVertex)), r_(w.robotRadius),
                      inner_(w.bounds.inflated(-w.robotRadius)),
                      scale_(std::max(w.bounds.width(), w.bounds.height())), tol_(1e-9 * scale_),
                      index_(inner_.inflated(tol_), w.circles.size() + w.polygons.size())
                {
                    const int nc = static_cast<int>(w.circles.size());
                    for (int i = 0; i < nc; ++i)
                    {
                        const Circle &c = w.circles[i];
                        const double rho = c.radius + r_;
                        index_.insert(
                            i, Box{c.center.x - rho, c.center.x + rho, c.center.y - rho, c.center.y + rho}
                                   .inflated(tol_));
                    }
                    for (std::size_t k = 0; k < w.polygons.size(); ++k)
                        index_.insert(nc + static_cast<int>(k), w.polygons[k].bbox.inflated(r_ + tol_));
                    // Large polygons get an edge index (docs/conventions.md, "Polygon simplicity"). Its
                    // margin exceeds every threshold the checks use (r + tol) by the rounding of the crossing
                    // points they compute (near-tangent circle-edge intersections err by ~1e-8 of the
                    // coordinates).
                    edgeIndex_.resize(w.polygons.size());
                    for (std::size_t k = 0; opt_.polygonEdgeIndex && k < w.polygons.size(); ++k)
                    {
                        const Polygon &poly = w.polygons[k];
                        if (poly.vertices.size() <= kEdgeIndexMinVertices)
                            continue;
                        const double diag = std::hypot(poly.bbox.width(), poly.bbox.height());
                        edgeIndex_[k] = std::make_unique<PolygonEdgeIndex>(
                            poly.vertices, r_ + 2.0 * tol_ + 1e-6 * (scale_ + diag));
                    }
                }

                /** Builds the graph over the discs that meet the ellipse {x : |x - s| + |x - g| <= U} and the
                    tangent segments that can lie on a path of length <= U; a shortest path of length <= U in
                    that graph is the optimum (every shorter path stays inside the ellipse). U grows from 1.05
                    times the straight-line distance to infinity until that holds. */
                OptimumResult run()
                {
                    OptimumResult res;
                    res.method = "tangent-graph";
                    collectDiscs();
                    const double straight = distance(query_.start, query_.goal);
                    for (double slack : {1.05, 1.4, kInf})
                    {
                        bound_ = slack * straight + tol_;
                        if (!(straight > 100.0 * tol_) || !(bound_ < kInf))
                            bound_ = kInf;
                        g_ = Graph();
                        for (auto &d : discs_)
                        {
                            d.pointNode = -1;
                            d.nodes.clear();
                        }
                        const int s = static_cast<int>(discs_.size()) - 2;
                        const int t = s + 1;
                        discs_[s].pointNode = g_.addNode(query_.start);
                        discs_[t].pointNode = g_.addNode(query_.goal);
                        discs_[s].pointValid = discs_[t].pointValid = 1;
                        std::vector<int> active;
                        for (std::size_t i = 0; i < discs_.size(); ++i)
                        {
                            const Disc &d = discs_[i];
                            if (distance(d.c, query_.start) + distance(d.c, query_.goal) - 2.0 * d.rho <=
                                bound_)
                                active.push_back(static_cast<int>(i));
                        }
                        for (std::size_t i = 0; i < active.size(); ++i)
                            for (std::size_t j = i + 1; j < active.size(); ++j)
                                connect(active[i], active[j]);
                        for (int i : active)
                            addArcs(discs_[i]);
                        res = OptimumResult();
                        res.method = "tangent-graph";
                        finish(res, g_, discs_[s].pointNode, discs_[t].pointNode, query_, scale_, inner_,
                               opt_);
                        if (res.found && res.length <= bound_)
                            break;
                        if (bound_ == kInf)
                            break;
                    }
                    return res;
                }

              private:
                const World &world_;
                const Query &query_;
                const OptimumOptions &opt_;
                std::function<bool(const Vec2 &)> keepVertex_;
                double r_;
                Box inner_;
                double scale_;
                double tol_;
                BucketIndex index_;
                /** Polygons of more than this many vertices get an edge index. */
                static constexpr std::size_t kEdgeIndexMinVertices = 32;
                /** Per polygon: its edge index, or null (small polygon, or OptimumOptions::polygonEdgeIndex
                    off). */
                std::vector<std::unique_ptr<PolygonEdgeIndex>> edgeIndex_;
                std::vector<Disc> discs_;
                Graph g_;
                /** Paths longer than this are not looked for (see run()). */
                double bound_{kInf};

                void collectDiscs()
                {
                    for (std::size_t i = 0; i < world_.circles.size(); ++i)
                    {
                        Disc d;
                        d.c = world_.circles[i].center;
                        d.rho = world_.circles[i].radius + r_;
                        d.circle = static_cast<int>(i);
                        discs_.push_back(d);
                    }
                    for (std::size_t k = 0; k < world_.polygons.size(); ++k)
                    {
                        const auto &v = world_.polygons[k].vertices;
                        const std::size_t m = v.size();
                        for (std::size_t i = 0; i < m; ++i)
                        {
                            const Vec2 &prev = v[(i + m - 1) % m];
                            const Vec2 &next = v[(i + 1) % m];
                            // Counter-clockwise vertices: convex where the boundary turns left.
                            if (cross(v[i] - prev, next - v[i]) <= 0.0 || (keepVertex_ && !keepVertex_(v[i])))
                                continue;
                            Disc d;
                            d.c = v[i];
                            d.rho = r_;
                            d.polygon = static_cast<int>(k);
                            d.prev = prev;
                            d.next = next;
                            discs_.push_back(d);
                        }
                    }
                    Disc s, t;
                    s.c = query_.start;
                    t.c = query_.goal;
                    discs_.push_back(s);
                    discs_.push_back(t);
                }

                bool obstacleContainsPoint(int id, const Vec2 &p) const
                {
                    const int nc = static_cast<int>(world_.circles.size());
                    if (id < nc)
                    {
                        const Circle &c = world_.circles[id];
                        const double rho = c.radius + r_ - tol_;
                        return rho > 0.0 && squaredNorm(p - c.center) < rho * rho;
                    }
                    const Polygon &poly = world_.polygons[id - nc];
                    const Box bb = poly.bbox.inflated(r_);
                    if (!bb.contains(p))
                        return false;
                    if (const PolygonEdgeIndex *edges = edgeIndex_[id - nc].get())
                        return edges->signedDistanceBelow(p, r_ - tol_);
                    return pointPolygonSignedDistance(p, poly.vertices) < r_ - tol_;
                }

                bool pointFree(const Vec2 &p) const
                {
                    if (p.x < inner_.xmin - tol_ || p.x > inner_.xmax + tol_ || p.y < inner_.ymin - tol_ ||
                        p.y > inner_.ymax + tol_)
                        return false;
                    return !index_.anyInBox(Box{p.x, p.x, p.y, p.y},
                                            [&](int id) { return obstacleContainsPoint(id, p); });
                }

                bool segmentFree(const Vec2 &a, const Vec2 &b) const
                {
                    const int nc = static_cast<int>(world_.circles.size());
                    const Box sb = boundingBox({a, b});
                    return !index_.anyOnSegment(
                        a, b,
                        [&](int id)
                        {
                            if (id < nc)
                            {
                                const Circle &c = world_.circles[id];
                                return pointSegmentDistance(c.center, a, b) < c.radius + r_ - tol_;
                            }
                            const Polygon &poly = world_.polygons[id - nc];
                            if (!sb.overlaps(poly.bbox.inflated(r_)))
                                return false;
                            if (const PolygonEdgeIndex *edges = edgeIndex_[id - nc].get())
                                return r_ > 0.0 ? edges->segmentDistanceBelow(a, b, r_ - tol_)
                                                : segmentDeepInside(a, b, *edges, tol_);
                            if (r_ > 0.0)
                                return segmentPolygonDistance(a, b, poly.vertices) < r_ - tol_;
                            return segmentDeepInside(a, b, poly.vertices, tol_);
                        });
                }

                bool arcFree(const Arc &arc, int ownCircle) const
                {
                    // The admissible box: end points and the axis-extreme points of the arc.
                    const Box bb = arcBoundingBox(arc);
                    if (bb.xmin < inner_.xmin - tol_ || bb.xmax > inner_.xmax + tol_ ||
                        bb.ymin < inner_.ymin - tol_ || bb.ymax > inner_.ymax + tol_)
                        return false;
                    const int nc = static_cast<int>(world_.circles.size());
                    return !index_.anyInBox(
                        bb.inflated(tol_),
                        [&](int id)
                        {
                            if (id < nc)
                            {
                                if (id == ownCircle)
                                    return false;
                                const Circle &c = world_.circles[id];
                                return pointArcDistance(c.center, arc) < c.radius + r_ - tol_;
                            }
                            const Polygon &poly = world_.polygons[id - nc];
                            if (!bb.overlaps(poly.bbox.inflated(r_)))
                                return false;
                            if (const PolygonEdgeIndex *edges = edgeIndex_[id - nc].get())
                            {
                                if (!(r_ > 0.0))
                                    return arcDeepInside(arc, *edges, tol_);
                                const auto &v = poly.vertices;
                                // Edges closer than r to the arc have an arc point in their inflated box.
                                if (edges->anyEdgeInBox(bb.inflated(tol_),
                                                        [&](int e)
                                                        {
                                                            const auto i = static_cast<std::size_t>(e);
                                                            return arcSegmentDistance(arc, v[i],
                                                                                      v[(i + 1) % v.size()]) <
                                                                   r_ - tol_;
                                                        }))
                                    return true;
                                return edges->signedDistanceBelow(arc.at(0.5), r_ - tol_);
                            }
                            if (r_ > 0.0)
                            {
                                const auto &v = poly.vertices;
                                for (std::size_t i = 0; i < v.size(); ++i)
                                    if (arcSegmentDistance(arc, v[i], v[(i + 1) % v.size()]) < r_ - tol_)
                                        return true;
                                return pointPolygonSignedDistance(arc.at(0.5), v) < r_ - tol_;
                            }
                            return arcDeepInside(arc, poly.vertices, tol_);
                        });
                }

                /** Is the line through the radius-0 polygon vertex d in direction dir tangent to the polygon
                    there (both neighbours on one closed side)? Non-tangent lines never carry a shortest path.
                 */
                static bool taut(const Disc &d, const Vec2 &dir)
                {
                    if (d.polygon < 0 || d.rho > 0.0)
                        return true;
                    const Vec2 a = d.prev - d.c;
                    const Vec2 b = d.next - d.c;
                    const double ca = cross(dir, a);
                    const double cb = cross(dir, b);
                    const double eps = 1e-12 * norm(dir) * std::max(norm(a), norm(b));
                    return !((ca > eps && cb < -eps) || (ca < -eps && cb > eps));
                }

                int nodeOn(Disc &d, const Vec2 &p)
                {
                    if (d.rho == 0.0)
                    {
                        if (d.pointNode < 0)
                            d.pointNode = g_.addNode(d.c);
                        return d.pointNode;
                    }
                    const int id = g_.addNode(p, d.c, d.rho);
                    d.nodes.emplace_back(std::atan2(p.y - d.c.y, p.x - d.c.x), id);
                    return id;
                }

                bool endFree(Disc &d, const Vec2 &p)
                {
                    if (d.rho > 0.0)
                        return pointFree(p);
                    if (d.pointValid < 0)
                        d.pointValid = pointFree(d.c) ? 1 : 0;
                    return d.pointValid == 1;
                }

                void connect(int i, int j)
                {
                    Disc &a = discs_[i];
                    Disc &b = discs_[j];
                    const Vec2 D = b.c - a.c;
                    const double dist = norm(D);
                    if (dist <= 1e-15 * scale_)
                    {
                        if (a.rho == 0.0 && b.rho == 0.0 && endFree(a, a.c) && endFree(b, b.c))
                            g_.addEdge(nodeOn(a, a.c), nodeOn(b, b.c), 0.0);
                        return;
                    }
                    const Vec2 u = D / dist;
                    const Vec2 up{-u.y, u.x};
                    double signs[2] = {1.0, -1.0};
                    const int cases = (a.rho == 0.0 || b.rho == 0.0) ? 1 : 2;
                    for (int cs = 0; cs < cases; ++cs)
                    {
                        const double rho1 = a.rho;
                        const double rho2 = signs[cs] * b.rho;
                        double k = (rho2 - rho1) / dist;
                        if (std::fabs(k) > 1.0 + 1e-12)
                            continue;
                        k = std::clamp(k, -1.0, 1.0);
                        const double h = std::sqrt(std::max(0.0, 1.0 - k * k));
                        const int branches = (h == 0.0 || (a.rho == 0.0 && b.rho == 0.0)) ? 1 : 2;
                        for (int br = 0; br < branches; ++br)
                        {
                            const Vec2 nrm = u * k + up * (br == 0 ? h : -h);
                            const Vec2 t1 = a.c - nrm * rho1;
                            const Vec2 t2 = b.c - nrm * rho2;
                            const Vec2 dir = t2 - t1;
                            if (!taut(a, dir) || !taut(b, dir))
                                continue;
                            // Either direction: the segment lies on no path of length <= bound_ otherwise.
                            const double via =
                                std::min(distance(query_.start, t1) + distance(t2, query_.goal),
                                         distance(query_.start, t2) + distance(t1, query_.goal));
                            if (via + distance(t1, t2) > bound_)
                                continue;
                            if (!endFree(a, t1) || !endFree(b, t2))
                                continue;
                            if (!segmentFree(t1, t2))
                                continue;
                            const int n1 = nodeOn(a, t1);
                            const int n2 = nodeOn(b, t2);
                            g_.addEdge(n1, n2, distance(t1, t2));
                        }
                    }
                }

                void addArcs(Disc &d)
                {
                    if (d.rho == 0.0 || d.nodes.size() < 2)
                        return;
                    std::sort(d.nodes.begin(), d.nodes.end());
                    const std::size_t m = d.nodes.size();
                    for (std::size_t k = 0; k < m; ++k)
                    {
                        const auto &p = d.nodes[k];
                        const auto &q = d.nodes[(k + 1) % m];
                        Arc arc;
                        arc.c = d.c;
                        arc.rho = d.rho;
                        arc.th0 = p.first;
                        arc.sweep = ccwDelta(p.first, q.first);
                        if (m == 2 && k == 1 && arc.sweep == 0.0)
                            arc.sweep = kTwoPi;
                        if (arc.sweep == 0.0)
                        {
                            g_.addEdge(p.second, q.second, 0.0);
                            continue;
                        }
                        if (arcFree(arc, d.circle))
                            g_.addArc(p.second, q.second, arc);
                    }
                }
            };
        } // namespace

        OptimumResult tangentGraphOptimum(const World &world, const Query &query,
                                          const OptimumOptions &options,
                                          std::function<bool(const Vec2 &)> keepVertex)
        {
            TangentGraphBuilder builder(world, query, options, std::move(keepVertex));
            return builder.run();
        }
    } // namespace optimum_detail
} // namespace mhplan
