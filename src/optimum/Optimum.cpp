// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/optimum/Optimum.h"

#include "mhplan/collision/Collision.h"
#include "mhplan/collision/GridCollision.h"
#include "mhplan/collision/Problem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();

        /** A* from \e s to \e goal over nodes 0..n-1: \e expand(u, relax) calls relax(v, w) for every edge
            u -> v of weight w; \e h is an admissible heuristic. Returns the node sequence from s to goal
           (empty when unreachable) and sets \e length (infinity then). */
        template <class Heuristic, class Expand>
        std::vector<int> aStar(std::size_t n, int s, int goal, Heuristic h, Expand expand, double &length)
        {
            std::vector<double> dist(n, kInf);
            std::vector<int> parent(n, -1);
            std::vector<char> closed(n, 0);
            using Item = std::pair<double, int>;
            std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
            dist[s] = 0.0;
            open.emplace(h(s), s);
            while (!open.empty())
            {
                const int u = open.top().second;
                open.pop();
                if (closed[u])
                    continue;
                closed[u] = 1;
                if (u == goal)
                    break;
                expand(u,
                       [&](int v, double w)
                       {
                           const double nd = dist[u] + w;
                           if (nd < dist[v])
                           {
                               dist[v] = nd;
                               parent[v] = u;
                               open.emplace(nd + h(v), v);
                           }
                       });
            }
            length = dist[goal];
            std::vector<int> out;
            if (!(length < kInf))
                return out;
            for (int v = goal; v != -1; v = parent[v])
                out.push_back(v);
            std::reverse(out.begin(), out.end());
            return out;
        }
        constexpr double kTwoPi = 2.0 * kPi;
        /** Largest number of convex corners for the disc-robot grid optimum (the tangent graph checks all
            pairs of corner discs). */
        constexpr std::size_t kMaxGridDiscCorners = 4000;

        /** Angle in [0, 2 pi). */
        double normAngle(double a)
        {
            a = std::fmod(a, kTwoPi);
            if (a < 0.0)
                a += kTwoPi;
            if (a >= kTwoPi)
                a -= kTwoPi;
            return a;
        }

        /** Counter-clockwise angle from \e from to \e to, in [0, 2 pi). */
        double ccwDelta(double from, double to)
        {
            return normAngle(to - from);
        }

        Vec2 polar(const Vec2 &c, double rho, double angle)
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

        double pointArcDistance(const Vec2 &p, const Arc &arc)
        {
            const Vec2 v = p - arc.c;
            const double d = norm(v);
            if (d == 0.0)
                return arc.rho;
            if (arc.contains(std::atan2(v.y, v.x)))
                return std::fabs(d - arc.rho);
            return std::min(distance(p, arc.at(0.0)), distance(p, arc.at(1.0)));
        }

        /** Exact distance between an arc and a segment: end points against the other piece, the arc points
            whose normal is perpendicular to the segment, and intersections. */
        double arcSegmentDistance(const Arc &arc, const Vec2 &a, const Vec2 &b)
        {
            double best = std::min(pointArcDistance(a, arc), pointArcDistance(b, arc));
            best = std::min(best, pointSegmentDistance(arc.at(0.0), a, b));
            best = std::min(best, pointSegmentDistance(arc.at(1.0), a, b));
            const Vec2 d = b - a;
            const double len2 = squaredNorm(d);
            if (len2 == 0.0)
                return best;
            const double base = std::atan2(d.y, d.x) + 0.5 * kPi;
            for (double ang : {base, base + kPi})
                if (arc.contains(ang))
                    best = std::min(best, pointSegmentDistance(polar(arc.c, arc.rho, ang), a, b));
            // Intersections of the segment with the circle.
            const Vec2 f = a - arc.c;
            const double bq = dot(f, d);
            const double cq = squaredNorm(f) - arc.rho * arc.rho;
            const double disc = bq * bq - len2 * cq;
            if (disc >= 0.0)
            {
                const double sq = std::sqrt(disc);
                for (double t : {(-bq - sq) / len2, (-bq + sq) / len2})
                    if (t >= 0.0 && t <= 1.0)
                    {
                        const Vec2 x = a + d * t - arc.c;
                        if (arc.contains(std::atan2(x.y, x.x)))
                            return 0.0;
                    }
            }
            return best;
        }

        /** True when some part of the segment lies inside the polygon deeper than tol (crossing parameters
            split the segment into pieces that are either inside or outside; each piece is probed at three
            points). */
        bool segmentDeepInside(const Vec2 &a, const Vec2 &b, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const Vec2 d = b - a;
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &p = poly[i];
                const Vec2 e = poly[(i + 1) % n] - p;
                const double den = cross(d, e);
                if (den == 0.0)
                    continue;
                const Vec2 w = p - a;
                const double t = cross(w, e) / den;
                const double s = cross(w, d) / den;
                if (t > 0.0 && t < 1.0 && s >= -1e-12 && s <= 1.0 + 1e-12)
                    ts.push_back(t);
            }
            std::sort(ts.begin(), ts.end());
            for (std::size_t i = 0; i + 1 < ts.size(); ++i)
            {
                const double t0 = ts[i];
                const double t1 = ts[i + 1];
                if (t1 <= t0)
                    continue;
                for (double q : {0.25, 0.5, 0.75})
                    if (pointPolygonSignedDistance(a + d * (t0 + q * (t1 - t0)), poly) < -tol)
                        return true;
            }
            return false;
        }

        /** True when some part of the arc lies inside the polygon deeper than tol (the arc is split at its
            intersections with the polygon's edges; each piece is probed at three points). */
        bool arcDeepInside(const Arc &arc, const std::vector<Vec2> &poly, double tol)
        {
            std::vector<double> ts{0.0, 1.0};
            const std::size_t n = poly.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const Vec2 &a = poly[i];
                const Vec2 d = poly[(i + 1) % n] - a;
                const double len2 = squaredNorm(d);
                const Vec2 f = a - arc.c;
                const double bq = dot(f, d);
                const double cq = squaredNorm(f) - arc.rho * arc.rho;
                const double disc = bq * bq - len2 * cq;
                if (len2 == 0.0 || disc < 0.0)
                    continue;
                const double sq = std::sqrt(disc);
                for (double t : {(-bq - sq) / len2, (-bq + sq) / len2})
                    if (t >= -1e-12 && t <= 1.0 + 1e-12)
                    {
                        const Vec2 x = a + d * t - arc.c;
                        const double u = ccwDelta(arc.th0, std::atan2(x.y, x.x));
                        if (arc.sweep > 0.0 && u < arc.sweep)
                            ts.push_back(u / arc.sweep);
                    }
            }
            std::sort(ts.begin(), ts.end());
            for (std::size_t i = 0; i + 1 < ts.size(); ++i)
            {
                const double t0 = ts[i];
                const double t1 = ts[i + 1];
                if (t1 <= t0)
                    continue;
                for (double q : {0.25, 0.5, 0.75})
                    if (pointPolygonSignedDistance(arc.at(t0 + q * (t1 - t0)), poly) < -tol)
                        return true;
            }
            return false;
        }

        /** Uniform bucket grid over a region: each bucket lists the obstacles whose (inflated) bounding box
            meets it. Queries visit only the buckets a segment or box crosses. Not thread-safe (stamps). */
        class BucketIndex
        {
          public:
            BucketIndex(const Box &region, std::size_t obstacles)
            {
                const double side = std::max(region.width(), region.height());
                const int per = std::clamp(
                    static_cast<int>(std::ceil(std::sqrt(static_cast<double>(obstacles)))), 1, 512);
                cell_ = std::max(side / per, 1e-12);
                x0_ = region.xmin;
                y0_ = region.ymin;
                nx_ = std::max(1, static_cast<int>(std::ceil(region.width() / cell_)));
                ny_ = std::max(1, static_cast<int>(std::ceil(region.height() / cell_)));
                buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
                stamp_.assign(obstacles, 0);
            }

            void insert(int id, const Box &bb)
            {
                const int ix0 = colOf(bb.xmin);
                const int ix1 = colOf(bb.xmax);
                const int iy0 = rowOf(bb.ymin);
                const int iy1 = rowOf(bb.ymax);
                if (bb.xmax < x0_ || bb.ymax < y0_ || bb.xmin > x0_ + nx_ * cell_ ||
                    bb.ymin > y0_ + ny_ * cell_)
                    return;
                for (int iy = iy0; iy <= iy1; ++iy)
                    for (int ix = ix0; ix <= ix1; ++ix)
                        buckets_[static_cast<std::size_t>(iy) * nx_ + ix].push_back(id);
            }

            /** Calls f(id) for each obstacle in the buckets the segment crosses (each once); stops and
                returns true as soon as f returns true. */
            template <typename F> bool anyOnSegment(const Vec2 &a, const Vec2 &b, F &&f) const
            {
                next();
                const double eps = 1e-9 * cell_;
                const int ca = colOf(a.x);
                const int cb = colOf(b.x);
                const int step = ca <= cb ? 1 : -1;
                const double dx = b.x - a.x;
                for (int c = ca;; c += step)
                {
                    double ylo, yhi;
                    if (ca == cb || dx == 0.0)
                    {
                        ylo = std::min(a.y, b.y);
                        yhi = std::max(a.y, b.y);
                    }
                    else
                    {
                        const double xl = std::max(std::min(a.x, b.x), x0_ + c * cell_);
                        const double xr = std::min(std::max(a.x, b.x), x0_ + (c + 1) * cell_);
                        const double yl = a.y + (b.y - a.y) * ((xl - a.x) / dx);
                        const double yr = a.y + (b.y - a.y) * ((xr - a.x) / dx);
                        ylo = std::min(yl, yr);
                        yhi = std::max(yl, yr);
                    }
                    const int r0 = rowOf(ylo - eps);
                    const int r1 = rowOf(yhi + eps);
                    for (int r = r0; r <= r1; ++r)
                        if (visit(c, r, f))
                            return true;
                    if (c == cb)
                        break;
                }
                return false;
            }

            template <typename F> bool anyInBox(const Box &bb, F &&f) const
            {
                next();
                for (int r = rowOf(bb.ymin), r1 = rowOf(bb.ymax); r <= r1; ++r)
                    for (int c = colOf(bb.xmin), c1 = colOf(bb.xmax); c <= c1; ++c)
                        if (visit(c, r, f))
                            return true;
                return false;
            }

          private:
            double x0_{0.0}, y0_{0.0}, cell_{1.0};
            int nx_{1}, ny_{1};
            std::vector<std::vector<int>> buckets_;
            mutable std::vector<std::uint32_t> stamp_;
            mutable std::uint32_t current_{0};

            int colOf(double x) const
            {
                return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
            }
            int rowOf(double y) const
            {
                return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
            }
            void next() const
            {
                if (++current_ == 0)
                {
                    std::fill(stamp_.begin(), stamp_.end(), 0);
                    current_ = 1;
                }
            }
            template <typename F> bool visit(int c, int r, F &f) const
            {
                for (int id : buckets_[static_cast<std::size_t>(r) * nx_ + c])
                {
                    if (stamp_[id] == current_)
                        continue;
                    stamp_[id] = current_;
                    if (f(id))
                        return true;
                }
                return false;
            }
        };

        /** An undirected weighted graph with positions; arc edges remember their arc. */
        struct Graph
        {
            struct Edge
            {
                int to;
                double w;
                int arc; ///< index into arcs (oriented from the lower node id), or -1 for a segment
            };
            std::vector<Vec2> pos;
            /** Per node: the disc it lies on (centre, radius; radius 0 for points). */
            std::vector<std::pair<Vec2, double>> support;
            std::vector<std::vector<Edge>> adj;
            std::vector<Arc> arcs;
            std::vector<std::pair<int, int>> arcEnds;
            std::size_t edgeCount{0};

            int addNode(const Vec2 &p, const Vec2 &c = {}, double rho = 0.0)
            {
                pos.push_back(p);
                support.emplace_back(c, rho);
                adj.emplace_back();
                return static_cast<int>(pos.size()) - 1;
            }
            void addEdge(int a, int b, double w, int arc = -1)
            {
                adj[a].push_back({b, w, arc});
                adj[b].push_back({a, w, arc});
                ++edgeCount;
            }
            int addArc(int a, int b, const Arc &arc)
            {
                arcs.push_back(arc);
                arcEnds.emplace_back(a, b);
                const int id = static_cast<int>(arcs.size()) - 1;
                addEdge(a, b, arc.rho * arc.sweep, id);
                return id;
            }

            /** A* with the Euclidean heuristic to \e goal (admissible for every edge). Returns the node
                sequence (empty when unreachable) and sets length. */
            std::vector<int> shortestPath(int s, int g, double &length) const
            {
                return aStar(
                    pos.size(), s, g, [&](int v) { return distance(pos[v], pos[g]); },
                    [&](int u, auto &&relax)
                    {
                        for (const Edge &e : adj[u])
                            relax(e.to, e.w);
                    },
                    length);
            }

            /** The pieces along a node sequence: segments, arcs, and zero-sweep arcs at nodes on discs
                where the path only touches (so that the polyline is pushed off them too). */
            std::vector<OptimumPiece> pieces(const std::vector<int> &nodes) const
            {
                std::vector<OptimumPiece> out;
                for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
                {
                    const int u = nodes[i];
                    const int v = nodes[i + 1];
                    const Edge *best = nullptr;
                    for (const Edge &e : adj[u])
                        if (e.to == v && (best == nullptr || e.w < best->w))
                            best = &e;
                    OptimumPiece p;
                    p.from = pos[u];
                    p.to = pos[v];
                    p.length = best->w;
                    if (best->arc >= 0)
                    {
                        const Arc &a = arcs[best->arc];
                        p.arc = true;
                        p.center = a.c;
                        p.radius = a.rho;
                        p.sweep = arcEnds[best->arc].first == u ? a.sweep : -a.sweep;
                        out.push_back(p);
                        continue;
                    }
                    if (i > 0 && support[u].second > 0.0 && (out.empty() || !out.back().arc))
                    {
                        OptimumPiece touch;
                        touch.arc = true;
                        touch.from = touch.to = pos[u];
                        touch.center = support[u].first;
                        touch.radius = support[u].second;
                        out.push_back(touch);
                    }
                    if (p.length > 0.0)
                        out.push_back(p);
                }
                return out;
            }
        };

        double secondsSince(std::chrono::steady_clock::time_point t0)
        {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }

        void finish(OptimumResult &res, const Graph &g, int s, int t, const Query &query, double scale,
                    const Box &inner, const OptimumOptions &opt)
        {
            double length = kInf;
            const std::vector<int> nodes = g.shortestPath(s, t, length);
            res.graphNodes = g.pos.size();
            res.graphEdges = g.edgeCount;
            if (nodes.empty())
                return;
            res.found = true;
            res.pieces = g.pieces(nodes);
            res.length = 0.0;
            for (const auto &p : res.pieces)
                res.length += p.length;
            if (res.pieces.empty())
                res.path = {query.start, query.goal};
            else
                res.path = piecesToPolyline(res.pieces, opt.arcDeviation * scale, 1e-10 * scale);
            // Points pushed off an arc that touches the bounds return onto them.
            for (Vec2 &p : res.path)
                p = {std::clamp(p.x, inner.xmin, inner.xmax), std::clamp(p.y, inner.ymin, inner.ymax)};
            res.path.front() = query.start;
            res.path.back() = query.goal;
        }

        // ------------------------------------------------------------------------------------------------
        // Geometric worlds: the tangent graph.

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
                        i,
                        Box{c.center.x - rho, c.center.x + rho, c.center.y - rho, c.center.y + rho}.inflated(
                            tol_));
                }
                for (std::size_t k = 0; k < w.polygons.size(); ++k)
                    index_.insert(nc + static_cast<int>(k), w.polygons[k].bbox.inflated(r_ + tol_));
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
                        if (distance(d.c, query_.start) + distance(d.c, query_.goal) - 2.0 * d.rho <= bound_)
                            active.push_back(static_cast<int>(i));
                    }
                    for (std::size_t i = 0; i < active.size(); ++i)
                        for (std::size_t j = i + 1; j < active.size(); ++j)
                            connect(active[i], active[j]);
                    for (int i : active)
                        addArcs(discs_[i]);
                    res = OptimumResult();
                    res.method = "tangent-graph";
                    finish(res, g_, discs_[s].pointNode, discs_[t].pointNode, query_, scale_, inner_, opt_);
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
                        if (r_ > 0.0)
                            return segmentPolygonDistance(a, b, poly.vertices) < r_ - tol_;
                        return segmentDeepInside(a, b, poly.vertices, tol_);
                    });
            }

            bool arcFree(const Arc &arc, int ownCircle) const
            {
                // The admissible box: end points and the axis-extreme points of the arc.
                Box bb = boundingBox({arc.at(0.0), arc.at(1.0)});
                for (int k = 0; k < 4; ++k)
                    if (arc.contains(k * 0.5 * kPi))
                    {
                        const Vec2 p = polar(arc.c, arc.rho, k * 0.5 * kPi);
                        bb = boundingBox({{bb.xmin, bb.ymin}, {bb.xmax, bb.ymax}, p});
                    }
                if (bb.xmin < inner_.xmin - tol_ || bb.xmax > inner_.xmax + tol_ ||
                    bb.ymin < inner_.ymin - tol_ || bb.ymax > inner_.ymax + tol_)
                    return false;
                const int nc = static_cast<int>(world_.circles.size());
                return !index_.anyInBox(bb.inflated(tol_),
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
                                            if (r_ > 0.0)
                                            {
                                                const auto &v = poly.vertices;
                                                for (std::size_t i = 0; i < v.size(); ++i)
                                                    if (arcSegmentDistance(arc, v[i], v[(i + 1) % v.size()]) <
                                                        r_ - tol_)
                                                        return true;
                                                return pointPolygonSignedDistance(arc.at(0.5), v) < r_ - tol_;
                                            }
                                            return arcDeepInside(arc, poly.vertices, tol_);
                                        });
            }

            /** Is the line through the radius-0 polygon vertex d in direction dir tangent to the polygon
                there (both neighbours on one closed side)? Non-tangent lines never carry a shortest path. */
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
                        const double via = std::min(distance(query_.start, t1) + distance(t2, query_.goal),
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

        // ------------------------------------------------------------------------------------------------
        // Grid worlds.

        void requireGrid(const World &world, const char *what)
        {
            if (!world.isGrid())
                throw InputError(std::string(what) + ": world '" + world.name + "' is not a grid world");
        }

        /** Any-angle optimum on a grid for a point robot: visibility graph of the convex corners. */
        class GridAnyAngle
        {
          public:
            GridAnyAngle(const World &w, const Query &q, const GridCollisionModel &model)
                : world_(w), query_(q), model_(model), grid_(*w.grid), W_(grid_.width()), H_(grid_.height()),
                  s_(grid_.cellSize()), o_(grid_.origin())
            {
            }

            OptimumResult run(const OptimumOptions &opt)
            {
                OptimumResult res;
                res.method = "grid-any-angle";
                // Corner nodes: lattice points with exactly one blocked cell among their four.
                nodeAt_.assign(static_cast<std::size_t>(W_ + 1) * (H_ + 1), -1);
                for (int vy = 0; vy <= H_; ++vy)
                    for (int vx = 0; vx <= W_; ++vx)
                    {
                        int count = 0;
                        int qx = 0, qy = 0;
                        for (int dy = -1; dy <= 0; ++dy)
                            for (int dx = -1; dx <= 0; ++dx)
                                if (grid_.blocked(vx + dx, vy + dy))
                                {
                                    ++count;
                                    qx = dx == 0 ? 1 : -1;
                                    qy = dy == 0 ? 1 : -1;
                                }
                        if (count != 1)
                            continue;
                        nodeAt_[vertexIndex(vx, vy)] = g_.addNode(worldPoint(vx, vy));
                        quadrant_.emplace_back(qx, qy);
                        lattice_.emplace_back(vx, vy);
                    }
                const int corners = static_cast<int>(g_.pos.size());
                seen_.assign(corners, -1);
                const int s = g_.addNode(query_.start);
                const int t = g_.addNode(query_.goal);
                // First try a tight ellipse (2% above the straight line), then the octile bound, which is
                // always enough; a path no longer than the bound in use is the optimum.
                const double ceiling = upperBound();
                std::vector<double> bounds;
                const double tight = 1.02 * distance(query_.start, query_.goal) + 1e-9 * s_;
                if (tight < ceiling)
                    bounds.push_back(tight);
                bounds.push_back(ceiling);
                for (double bound : bounds)
                {
                    bound_ = bound;
                    for (auto &adj : g_.adj)
                        adj.clear();
                    g_.edgeCount = 0;
                    seen_.assign(corners, -1);
                    for (int u = 0; u < corners; ++u)
                        if (distance(g_.pos[u], query_.start) + distance(g_.pos[u], query_.goal) <= bound_)
                            scanFrom(u, Vec2{static_cast<double>(lattice_[u].first),
                                             static_cast<double>(lattice_[u].second)});
                    scanFrom(s, cellUnits(query_.start));
                    scanFrom(t, cellUnits(query_.goal));
                    if (model_.segmentValid(query_.start, query_.goal))
                        g_.addEdge(s, t, distance(query_.start, query_.goal));
                    res = OptimumResult();
                    res.method = "grid-any-angle";
                    finish(res, g_, s, t, query_, std::max(world_.bounds.width(), world_.bounds.height()),
                           world_.bounds, opt);
                    if (res.found && res.length <= bound_)
                        break;
                }
                res.lengthCells = res.length / s_;
                return res;
            }

          private:
            const World &world_;
            const Query &query_;
            const GridCollisionModel &model_;
            const OccupancyGrid &grid_;
            int W_, H_;
            double s_;
            Vec2 o_;
            Graph g_;
            std::vector<int> nodeAt_;
            std::vector<std::pair<int, int>> quadrant_, lattice_;
            std::vector<int> seen_;
            /** Upper bound on the optimum (see upperBound()); longer paths are not looked for. */
            double bound_{kInf};

            /** The 8-connected optimum's path, joined to the exact start and goal, is a valid any-angle path:
                its length bounds the optimum, and a shorter path never leaves the ellipse
                {x : |x - start| + |x - goal| <= bound}. Infinity when the octile search finds no path. */
            double upperBound() const
            {
                const OptimumResult oct = computeGridOctileOptimum(world_, query_);
                if (!oct.found)
                    return kInf;
                return oct.length + distance(query_.start, oct.path.front()) +
                       distance(oct.path.back(), query_.goal) + 1e-9 * std::max(1.0, oct.length);
            }

            std::size_t vertexIndex(int vx, int vy) const
            {
                return static_cast<std::size_t>(vy) * (W_ + 1) + vx;
            }
            Vec2 worldPoint(int vx, int vy) const { return {o_.x + vx * s_, o_.y + vy * s_}; }
            Vec2 cellUnits(const Vec2 &p) const { return {(p.x - o_.x) / s_, (p.y - o_.y) / s_}; }

            bool tautAt(int node, double dx, double dy) const
            {
                const auto &q = quadrant_[node];
                return dx * dy * q.first * q.second <= 0.0;
            }

            /** Called for every corner vertex the sweep from node u (at p, cell units) finds possibly
                visible: checks the pruning rules, then the segment exactly, then adds the edge. */
            void candidate(int u, const Vec2 &p, int vx, int vy)
            {
                if (vx < 0 || vy < 0 || vx > W_ || vy > H_)
                    return;
                const int v = nodeAt_[vertexIndex(vx, vy)];
                if (v < 0 || v == u || seen_[v] == u)
                    return;
                seen_[v] = u;
                const bool uIsCorner = u < static_cast<int>(seen_.size());
                if (uIsCorner && v < u)
                    return; // the pair is handled from v's sweep
                const double dx = vx - p.x;
                const double dy = vy - p.y;
                if (!tautAt(v, dx, dy) || (uIsCorner && !tautAt(u, dx, dy)))
                    return;
                const Vec2 &a = g_.pos[u];
                const Vec2 &b = g_.pos[v];
                const double via = std::min(distance(query_.start, a) + distance(b, query_.goal),
                                            distance(query_.start, b) + distance(a, query_.goal));
                if (via + distance(a, b) > bound_)
                    return; // on no path shorter than the octile one
                if (!model_.segmentValid(a, b))
                    return;
                g_.addEdge(u, v, distance(g_.pos[u], g_.pos[v]));
            }

            /** Octant sweep (shadow casting) from p in cell units: the set of visible directions in each
                octant is kept as closed slope intervals; every blocked cell of the columns swept removes the
                open interval of slopes of rays through its interior (shrunk by 1e-10, so the candidate set is
               a superset of the visible corners; candidate() confirms each exactly). */
            void scanFrom(int u, const Vec2 &p)
            {
                // A lattice origin gives exact slopes (quotients of small integers, correctly rounded, so
                // equal rationals give equal doubles); any other origin gets blocked intervals shrunk by eps.
                const bool lattice = p.x == std::floor(p.x) && p.y == std::floor(p.y);
                const double eps = lattice ? 0.0 : 1e-10;
                for (int oct = 0; oct < 8; ++oct)
                {
                    const int sx = (oct & 1) ? -1 : 1;
                    const int sy = (oct & 2) ? -1 : 1;
                    const bool swap = (oct & 4) != 0;
                    const double P = swap ? p.y : p.x;
                    const double Q = swap ? p.x : p.y;
                    const int sp = swap ? sy : sx;
                    const int sq = swap ? sx : sy;
                    const double fu = sp > 0 ? std::floor(P) + 1.0 - P : P - (std::ceil(P) - 1.0);
                    const double fv = sq > 0 ? std::floor(Q) + 1.0 - Q : Q - (std::ceil(Q) - 1.0);
                    const bool onLine = fv == 1.0; // the octant's lower ray runs along a grid line
                    auto cellBlocked = [&](double uMid, double vMid)
                    {
                        const int a = static_cast<int>(std::floor(P + sp * uMid));
                        const int b = static_cast<int>(std::floor(Q + sq * vMid));
                        return swap ? grid_.blocked(b, a) : grid_.blocked(a, b);
                    };
                    std::vector<std::pair<double, double>> vis{{0.0, 1.0}}, nextVis, scratch;
                    const int maxK = W_ + H_ + 4;
                    for (int k = 0; k <= maxK && !vis.empty(); ++k)
                    {
                        const double uL = fu + k - 1.0;
                        const double uR = fu + k;
                        if (uL > 0.0)
                        {
                            const int line = static_cast<int>(std::lround(P + sp * uL));
                            for (const auto &iv : vis)
                            {
                                const int j0 = static_cast<int>(std::ceil(iv.first * uL - (fv - 1.0) - 1e-9));
                                const int j1 =
                                    static_cast<int>(std::floor(iv.second * uL - (fv - 1.0) + 1e-9));
                                for (int j = j0; j <= j1; ++j)
                                {
                                    const int other = static_cast<int>(std::lround(Q + sq * (fv - 1.0 + j)));
                                    if (swap)
                                        candidate(u, p, other, line);
                                    else
                                        candidate(u, p, line, other);
                                }
                            }
                        }
                        nextVis = vis;
                        auto subtract = [&](double a, double b)
                        {
                            std::vector<std::pair<double, double>> &out = scratch;
                            out.clear();
                            for (const auto &iv : nextVis)
                            {
                                if (b <= iv.first || a >= iv.second)
                                {
                                    out.push_back(iv);
                                    continue;
                                }
                                if (a >= iv.first)
                                    out.emplace_back(iv.first, a);
                                if (b <= iv.second)
                                    out.emplace_back(b, iv.second);
                            }
                            nextVis.swap(out);
                        };
                        const double uMid = 0.5 * (uL + uR);
                        for (const auto &iv : vis)
                        {
                            const double vmin = iv.first * std::max(uL, 0.0);
                            const double vmax = iv.second * uR;
                            const int j0 = static_cast<int>(std::floor(vmin - fv + 1.0)) - 1;
                            const int j1 = static_cast<int>(std::floor(vmax - fv + 1.0)) + 1;
                            for (int j = j0; j <= j1; ++j)
                            {
                                const double va = fv - 1.0 + j;
                                const double vb = va + 1.0;
                                if (vb <= 0.0 || !cellBlocked(uMid, va + 0.5))
                                    continue;
                                const double lo = va >= 0.0 ? va / uR + eps : -kInf;
                                const double hi = uL > 0.0 ? vb / uL - eps : kInf;
                                if (lo < hi)
                                    subtract(lo, hi);
                            }
                        }
                        // The lower ray along a grid line is blocked where the cells on both sides are.
                        if (onLine && cellBlocked(uMid, 0.5) && cellBlocked(uMid, -0.5))
                            subtract(-kInf, 2.0 * eps + 1e-12);
                        vis.swap(nextVis);
                    }
                }
            }
        };
        /** Convex corners of the blocked region: lattice points with exactly one blocked cell of four. */
        bool convexCorner(const OccupancyGrid &g, int vx, int vy)
        {
            int count = 0;
            for (int dy = -1; dy <= 0; ++dy)
                for (int dx = -1; dx <= 0; ++dx)
                    count += g.blocked(vx + dx, vy + dy) ? 1 : 0;
            return count == 1;
        }

        /** A disc robot on a grid: the tangent graph over the blocked cells on the region's boundary as
            squares, with discs at the region's convex corners only. */
        OptimumResult gridDiscRobot(const World &world, const Query &query, const OptimumOptions &options)
        {
            const OccupancyGrid &g = *world.grid;
            std::size_t corners = 0;
            for (int vy = 0; vy <= g.height(); ++vy)
                for (int vx = 0; vx <= g.width(); ++vx)
                    corners += convexCorner(g, vx, vy) ? 1 : 0;
            if (corners > kMaxGridDiscCorners)
                throw InputError("optimum: grid world '" + world.name + "' with robot radius " +
                                 std::to_string(world.robotRadius) + " has " + std::to_string(corners) +
                                 " convex corners; the disc-robot grid optimum supports at most " +
                                 std::to_string(kMaxGridDiscCorners) + " (a point robot has no such limit)");
            World squares;
            squares.name = world.name;
            squares.bounds = world.bounds;
            squares.robotRadius = world.robotRadius;
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                {
                    if (!g.blocked(ix, iy))
                        continue;
                    bool boundary = false;
                    for (int dy = -1; dy <= 1 && !boundary; ++dy)
                        for (int dx = -1; dx <= 1 && !boundary; ++dx)
                            boundary = g.inside(ix + dx, iy + dy) && !g.blocked(ix + dx, iy + dy);
                    if (!boundary)
                        continue;
                    const Box b = g.cellBox(ix, iy);
                    squares.polygons.push_back(makePolygon(
                        {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}}, "cell"));
                }
            auto keep = [&g](const Vec2 &v)
            {
                const int vx = static_cast<int>(std::lround((v.x - g.origin().x) / g.cellSize()));
                const int vy = static_cast<int>(std::lround((v.y - g.origin().y) / g.cellSize()));
                return convexCorner(g, vx, vy);
            };
            TangentGraphBuilder builder(squares, query, options, keep);
            OptimumResult res = builder.run();
            res.method = "grid-tangent-graph";
            res.lengthCells = res.found ? res.length / g.cellSize() : 0.0;
            return res;
        }
    } // namespace

    std::vector<Vec2> piecesToPolyline(const std::vector<OptimumPiece> &pieces, double maxDeviation,
                                       double push)
    {
        std::vector<Vec2> out;
        if (pieces.empty())
            return out;
        auto pushed = [&](const OptimumPiece &p, const Vec2 &x)
        {
            const Vec2 v = x - p.center;
            const double d = norm(v);
            return d > 0.0 ? p.center + v * ((p.radius + push) / d) : x;
        };
        out.push_back(pieces.front().from);
        for (const auto &p : pieces)
        {
            if (!p.arc || p.radius <= 0.0)
            {
                out.push_back(p.to);
                continue;
            }
            const Vec2 a = pushed(p, p.from);
            if (distance(out.back(), p.from) <= 1e-9 * (1.0 + p.radius))
                out.back() = a;
            else
                out.push_back(a);
            if (p.sweep != 0.0)
            {
                const double ratio = (p.radius + push) / (p.radius + std::max(maxDeviation, 2.0 * push));
                const double hmax = std::max(2.0 * std::acos(std::min(1.0, ratio)), 1e-6);
                const double th0 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x);
                const double th1 = th0 + p.sweep;
                // Split at the axis directions, where the arc reaches its extreme coordinates: there the
                // polyline has a vertex on the (pushed) circle, so an arc that touches the bounds keeps its
                // polyline inside them once clamped.
                std::vector<double> cuts{th0};
                const double quarter = 0.5 * kPi;
                const double margin = 1e-9;
                if (p.sweep > 0.0)
                    for (double a = (std::floor(th0 / quarter) + 1.0) * quarter; a < th1 - margin;
                         a += quarter)
                    {
                        if (a > th0 + margin)
                            cuts.push_back(a);
                    }
                else
                    for (double a = (std::ceil(th0 / quarter) - 1.0) * quarter; a > th1 + margin;
                         a -= quarter)
                    {
                        if (a < th0 - margin)
                            cuts.push_back(a);
                    }
                cuts.push_back(th1);
                for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
                {
                    const double span = cuts[c + 1] - cuts[c];
                    const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(span) / hmax)));
                    const double h = span / n;
                    const double R = (p.radius + push) / std::cos(0.5 * h);
                    for (int k = 1; k <= n; ++k)
                        out.push_back(polar(p.center, R, cuts[c] + (k - 0.5) * h));
                    out.push_back(c + 2 < cuts.size() ? polar(p.center, p.radius + push, cuts[c + 1])
                                                      : pushed(p, p.to));
                }
            }
        }
        return out;
    }

    double optimalityGap(double pathLength, const OptimumResult &optimum)
    {
        if (!optimum.found)
            return std::numeric_limits<double>::quiet_NaN();
        if (optimum.length == 0.0)
            return 0.0;
        return (pathLength - optimum.length) / optimum.length;
    }

    OptimumResult computeOptimum(const World &world, const Query &query, const OptimumOptions &options)
    {
        if (!(options.arcDeviation > 0.0 && options.arcDeviation <= 0.1))
        {
            std::ostringstream m;
            m << "computeOptimum: options.arcDeviation must be in (0, 0.1], got " << options.arcDeviation;
            throw std::invalid_argument(m.str());
        }
        const auto t0 = std::chrono::steady_clock::now();
        if (world.isGrid())
        {
            GridCollisionModel model(world);
            validateQuery(world, query, model);
            if (world.robotRadius > 0.0)
            {
                OptimumResult res = gridDiscRobot(world, query, options);
                res.seconds = secondsSince(t0);
                return res;
            }
            GridAnyAngle solver(world, query, model);
            OptimumResult res = solver.run(options);
            res.seconds = secondsSince(t0);
            return res;
        }
        {
            AnalyticCollisionModel model(world);
            validateQuery(world, query, model);
        }
        TangentGraphBuilder builder(world, query, options);
        OptimumResult res = builder.run();
        res.seconds = secondsSince(t0);
        return res;
    }

    OptimumResult computeGridOctileOptimum(const World &world, const Query &query)
    {
        requireGrid(world, "grid octile optimum");
        const auto t0 = std::chrono::steady_clock::now();
        const OccupancyGrid &g = *world.grid;
        const int W = g.width();
        const int H = g.height();
        auto cellFor = [&](const Vec2 &p, const char *field)
        {
            const int ix = g.cellX(p.x);
            const int iy = g.cellY(p.y);
            int best = -1;
            double bestD = kInf;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                {
                    const int cx = ix + dx;
                    const int cy = iy + dy;
                    if (g.blocked(cx, cy))
                        continue;
                    const Box b = g.cellBox(cx, cy);
                    if (!b.contains(p))
                        continue;
                    const double d = distance(p, g.cellCenter(cx, cy));
                    if (d < bestD)
                    {
                        bestD = d;
                        best = cy * W + cx;
                    }
                }
            if (best < 0)
            {
                std::ostringstream m;
                m << (world.file.empty() ? world.name : world.file) << ": query '" << query.name
                  << "' field '" << field << "' (" << p.x << ", " << p.y
                  << ") is not in a free cell of the grid";
                throw InputError(m.str());
            }
            return best;
        };
        const int s = cellFor(query.start, "start");
        const int t = cellFor(query.goal, "goal");
        const double sqrt2 = std::sqrt(2.0);
        const int tx = t % W;
        const int ty = t / W;
        auto h = [&](int c)
        {
            const int dx = std::abs(c % W - tx);
            const int dy = std::abs(c / W - ty);
            return (sqrt2 - 1.0) * std::min(dx, dy) + std::max(dx, dy);
        };
        double lengthCells = kInf;
        const std::vector<int> cells = aStar(
            static_cast<std::size_t>(W) * H, s, t, h,
            [&](int c, auto &&relax)
            {
                const int cx = c % W;
                const int cy = c / W;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                    {
                        if ((dx == 0 && dy == 0) || g.blocked(cx + dx, cy + dy))
                            continue;
                        if (dx != 0 && dy != 0 && (g.blocked(cx + dx, cy) || g.blocked(cx, cy + dy)))
                            continue;
                        relax((cy + dy) * W + cx + dx, (dx != 0 && dy != 0) ? sqrt2 : 1.0);
                    }
            },
            lengthCells);
        std::size_t edges = 0;
        // Graph size: free cells and their MovingAI moves (each undirected move counted once).
        std::size_t nodes = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
            {
                if (g.blocked(x, y))
                    continue;
                ++nodes;
                const int fwd[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
                for (const auto &d : fwd)
                {
                    if (g.blocked(x + d[0], y + d[1]))
                        continue;
                    if (d[0] != 0 && d[1] != 0 && (g.blocked(x + d[0], y) || g.blocked(x, y + d[1])))
                        continue;
                    ++edges;
                }
            }
        OptimumResult res;
        res.method = "grid-octile";
        res.graphNodes = nodes;
        res.graphEdges = edges;
        if (!cells.empty())
        {
            res.found = true;
            res.lengthCells = lengthCells;
            res.length = lengthCells * g.cellSize();
            for (int c : cells)
                res.path.push_back(g.cellCenter(c % W, c / W));
            for (std::size_t i = 0; i + 1 < res.path.size(); ++i)
            {
                OptimumPiece p;
                p.from = res.path[i];
                p.to = res.path[i + 1];
                p.length = distance(p.from, p.to);
                res.pieces.push_back(p);
            }
        }
        res.seconds = secondsSince(t0);
        return res;
    }
} // namespace mhplan
