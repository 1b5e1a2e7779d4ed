// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/collision/FclCollision.h"
#include "mhplan/collision/ContactRule.h"

#include "mhplan/collision/detail/FclShapes.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <array>
#include <limits>

namespace mhplan
{
    namespace
    {
        /** True when q lies in the closed triangle (a, b, c) given counter-clockwise. */
        bool inClosedTriangle(const Vec2 &q, const Vec2 &a, const Vec2 &b, const Vec2 &c)
        {
            return cross(b - a, q - a) >= 0.0 && cross(c - b, q - b) >= 0.0 && cross(a - c, q - c) >= 0.0;
        }

    } // namespace

    namespace detail
    {
        // The pieces only steer this model's broadphase (its narrow phase tests the whole polygon).
        std::vector<std::vector<Vec2>> convexPieces(const Polygon &poly)
        {
            if (poly.convex)
                return {poly.vertices};
            const std::vector<Vec2> &v = poly.vertices; // counter-clockwise (makePolygon)
            std::vector<std::size_t> idx(v.size());
            for (std::size_t i = 0; i < idx.size(); ++i)
                idx[i] = i;
            std::vector<std::vector<Vec2>> pieces;
            while (idx.size() > 3)
            {
                const std::size_t m = idx.size();
                bool clipped = false;
                for (std::size_t i = 0; i < m && !clipped; ++i)
                {
                    const Vec2 &a = v[idx[(i + m - 1) % m]];
                    const Vec2 &b = v[idx[i]];
                    const Vec2 &c = v[idx[(i + 1) % m]];
                    const double turn = cross(b - a, c - b);
                    if (turn < 0.0)
                        continue; // reflex vertex
                    bool ear = true;
                    if (turn > 0.0)
                    {
                        for (std::size_t j = 0; j < m && ear; ++j)
                        {
                            const Vec2 &q = v[idx[j]];
                            if (q == a || q == b || q == c)
                                continue;
                            ear = !inClosedTriangle(q, a, b, c);
                        }
                        if (ear)
                            pieces.push_back({a, b, c});
                    }
                    // A collinear vertex (turn == 0) is dropped without a triangle: it spans no area.
                    if (ear)
                    {
                        idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
                        clipped = true;
                    }
                }
                if (!clipped)
                {
                    std::vector<Vec2> rest;
                    for (std::size_t i : idx)
                        rest.push_back(v[i]);
                    const Box bb = boundingBox(rest);
                    pieces.push_back(
                        {{bb.xmin, bb.ymin}, {bb.xmax, bb.ymin}, {bb.xmax, bb.ymax}, {bb.xmin, bb.ymax}});
                    return pieces;
                }
            }
            if (idx.size() == 3 && cross(v[idx[1]] - v[idx[0]], v[idx[2]] - v[idx[1]]) != 0.0)
                pieces.push_back({v[idx[0]], v[idx[1]], v[idx[2]]});
            return pieces;
        }

        std::shared_ptr<fcl::CollisionGeometryd> makePrism(const std::vector<Vec2> &pts)
        {
            const int k = static_cast<int>(pts.size());
            auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
            vertices->reserve(2 * pts.size());
            for (const auto &p : pts)
                vertices->emplace_back(p.x, p.y, -0.5 * kPrismHeight);
            for (const auto &p : pts)
                vertices->emplace_back(p.x, p.y, 0.5 * kPrismHeight);
            auto faces = std::make_shared<std::vector<int>>();
            faces->push_back(k); // bottom cap, seen from below
            for (int i = k - 1; i >= 0; --i)
                faces->push_back(i);
            faces->push_back(k); // top cap
            for (int i = 0; i < k; ++i)
                faces->push_back(k + i);
            for (int i = 0; i < k; ++i) // sides
            {
                const int j = (i + 1) % k;
                faces->insert(faces->end(), {4, i, j, k + j, k + i});
            }
            return std::make_shared<fcl::Convexd>(vertices, k + 2, faces);
        }

    } // namespace detail

    namespace
    {
        using detail::convexPieces;
        using detail::kPrismHeight;
        using detail::makePrism;
        /** The robot's query object: shares the robot geometry without touching it (FCL's constructors
            recompute the geometry's local AABB, which would race between threads) and carries an AABB set
            per query. Lives on the caller's stack, so concurrent queries share nothing mutable. */
        class QueryObject : public fcl::CollisionObjectd
        {
          public:
            QueryObject(const std::shared_ptr<fcl::CollisionGeometryd> &geometry, const Box &box, double eps)
                : fcl::CollisionObjectd(std::shared_ptr<fcl::CollisionGeometryd>())
            {
                cgeom = geometry;
                cgeom_const = geometry;
                user_data = nullptr;
                aabb.min_ = fcl::Vector3d(box.xmin - eps, box.ymin - eps, 0.0);
                aabb.max_ = fcl::Vector3d(box.xmax + eps, box.ymax + eps, 0.0);
            }
        };

        /** Remembers the last few polygons a query evaluated, so that the pieces of one polygon do not repeat
            its (whole-polygon) exact test. A miss only costs a repeated, identical evaluation. */
        class RecentPolygons
        {
          public:
            /** True when \e id was seen; otherwise records it. */
            bool seen(std::size_t id)
            {
                for (std::size_t i = 0; i < count_; ++i)
                    if (ids_[i] == id)
                        return true;
                ids_[next_] = id;
                next_ = (next_ + 1) % ids_.size();
                count_ = std::min(count_ + 1, ids_.size());
                return false;
            }

          private:
            std::array<std::size_t, 8> ids_{};
            std::size_t count_{0};
            std::size_t next_{0};
        };
    } // namespace

    namespace
    {
        /** Everything a query reads: the obstacles, FCL's objects and broadphase manager. */
        struct FclScene
        {
            std::vector<Circle> circles;
            std::vector<Polygon> polygons;
            /** Obstacle id of every FCL object (circles, then polygons); each object's user data points here.
             */
            std::vector<std::size_t> ids;
            std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
            fcl::DynamicAABBTreeCollisionManagerd manager;
            /** The robot disc (a cylinder; a tiny one for a point robot). */
            std::shared_ptr<fcl::CollisionGeometryd> robot;
            /** Non-owning alias of \e robot: copying it touches no reference count. */
            std::shared_ptr<fcl::CollisionGeometryd> robotAlias;
            /** Margin that absorbs rounding in FCL's AABBs (relative to the world's coordinates). */
            double eps{0.0};

            /** The obstacle id of the pair (obstacle, query) a manager hands to a callback. The order of the
               two differs between FCL's managers (SaP passes the query first): the query has no user data. */
            std::size_t obstacleOf(const fcl::CollisionObjectd *o1, const fcl::CollisionObjectd *o2) const
            {
                const void *data = o1->getUserData() != nullptr ? o1->getUserData() : o2->getUserData();
                return *static_cast<const std::size_t *>(data);
            }
            bool isCircle(std::size_t id) const { return id < circles.size(); }
            const Polygon &polygon(std::size_t id) const { return polygons[id - circles.size()]; }
        };

        using Impl = FclScene;

        /** Bounding box of the segment [a, b]. */
        Box segmentBox(const Vec2 &a, const Vec2 &b)
        {
            return {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
        }

        struct PointCollisionData
        {
            PointCollisionData(const Impl *i, const Vec2 &q, double r, double t)
                : impl(i), p(q), radius(r), tol(t)
            {
            }
            const Impl *impl;
            Vec2 p;
            double radius;
            double tol;
            bool hit{false};
            RecentPolygons recent;
        };

        /** Exactly the per-obstacle test of AnalyticCollisionModel::isValid. */
        bool pointCollisionCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *cdata)
        {
            auto &d = *static_cast<PointCollisionData *>(cdata);
            const std::size_t id = d.impl->obstacleOf(o1, o2);
            if (d.impl->isCircle(id))
            {
                const Circle &c = d.impl->circles[id];
                d.hit = contact::pointHitsCircle(d.p, c.center, c.radius + d.radius, d.tol);
            }
            else if (!d.recent.seen(id))
                d.hit = contact::pointHitsPolygon(d.p, d.impl->polygon(id), d.radius, d.tol);
            return d.hit;
        }

        struct SegmentCollisionData
        {
            SegmentCollisionData(const Impl *i, const Vec2 &s, const Vec2 &e, double r, double t,
                                 const Box &box)
                : impl(i), a(s), b(e), radius(r), tol(t), sb(box)
            {
            }
            const Impl *impl;
            Vec2 a, b;
            double radius;
            double tol;
            Box sb;
            bool hit{false};
            RecentPolygons recent;
        };

        /** Exactly the per-obstacle test of AnalyticCollisionModel::segmentValid. */
        bool segmentCollisionCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *cdata)
        {
            auto &d = *static_cast<SegmentCollisionData *>(cdata);
            const std::size_t id = d.impl->obstacleOf(o1, o2);
            if (d.impl->isCircle(id))
            {
                const Circle &c = d.impl->circles[id];
                d.hit = contact::segmentHitsCircle(d.a, d.b, c.center, c.radius + d.radius, d.tol);
            }
            else if (!d.recent.seen(id))
            {
                const Polygon &poly = d.impl->polygon(id);
                d.hit =
                    d.sb.overlaps(poly.bbox) && contact::segmentHitsPolygon(d.a, d.b, poly, d.radius, d.tol);
            }
            return d.hit;
        }

        struct DistanceData
        {
            DistanceData(const Impl *i, const Vec2 &s, const Vec2 &e, bool seg)
                : impl(i), a(s), b(e), segment(seg)
            {
            }
            const Impl *impl;
            Vec2 a, b; // a == b for a point query
            bool segment;
            double best{std::numeric_limits<double>::infinity()};
            RecentPolygons recent;
        };

        /** The signed distance of one obstacle (as AnalyticCollisionModel::clearance and segmentClearance
            compute it, robot radius excluded); then tells the manager which subtrees it may prune: any whose
            AABB lies farther than the best distance so far (never less than zero, so that every obstacle
            containing the query stays eligible, plus a rounding margin). */
        bool distanceCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *cdata, double &dist)
        {
            auto &d = *static_cast<DistanceData *>(cdata);
            const std::size_t id = d.impl->obstacleOf(o1, o2);
            double v = std::numeric_limits<double>::infinity();
            if (d.impl->isCircle(id))
            {
                const Circle &c = d.impl->circles[id];
                v = (d.segment ? pointSegmentDistance(c.center, d.a, d.b) : distance(d.a, c.center)) -
                    c.radius;
            }
            else if (!d.recent.seen(id))
            {
                const std::vector<Vec2> &poly = d.impl->polygon(id).vertices;
                if (!d.segment)
                    v = pointPolygonSignedDistance(d.a, poly);
                else
                {
                    v = segmentPolygonDistance(d.a, d.b, poly);
                    if (v == 0.0)
                    {
                        v = std::min({0.0, pointPolygonSignedDistance(d.a, poly),
                                      pointPolygonSignedDistance(d.b, poly)});
                        v = std::min(v, deepestSegmentPenetration(d.a, d.b, poly));
                    }
                }
            }
            d.best = std::min(d.best, v);
            dist = std::max(d.best, 0.0) + d.impl->eps;
            return false;
        }
    } // namespace

    struct FclCollisionModel::Impl : FclScene
    {
    };

    FclCollisionModel::FclCollisionModel(const World &world)
        : CollisionModel(world), impl_(std::make_unique<Impl>())
    {
        if (world.isGrid())
            throw InputError("the FCL collision model handles geometric worlds only; '" + world.name +
                             "' is a grid world (use the grid back end)");
        Impl &m = *impl_;
        m.circles = world.circles;
        m.polygons = world.polygons;

        double scale = std::max({std::abs(bounds_.xmin), std::abs(bounds_.xmax), std::abs(bounds_.ymin),
                                 std::abs(bounds_.ymax), radius_});
        for (const auto &c : m.circles)
            scale = std::max({scale, std::abs(c.center.x) + c.radius, std::abs(c.center.y) + c.radius});
        for (const auto &poly : m.polygons)
            scale = std::max({scale, std::abs(poly.bbox.xmin), std::abs(poly.bbox.xmax),
                              std::abs(poly.bbox.ymin), std::abs(poly.bbox.ymax)});
        m.eps = 1e-12 * (1.0 + scale);

        // One FCL object per circle and per convex piece of each polygon.
        std::vector<std::pair<std::size_t, std::shared_ptr<fcl::CollisionGeometryd>>> parts;
        for (std::size_t i = 0; i < m.circles.size(); ++i)
        {
            const Circle &c = m.circles[i];
            if (!(c.radius >= 0.0))
                throw std::invalid_argument("FclCollisionModel: circle radius must be >= 0, got " +
                                            std::to_string(c.radius));
            parts.emplace_back(i, std::make_shared<fcl::Cylinderd>(c.radius, kPrismHeight));
        }
        for (std::size_t i = 0; i < m.polygons.size(); ++i)
            for (const auto &piece : convexPieces(m.polygons[i]))
                parts.emplace_back(m.circles.size() + i, makePrism(piece));

        m.ids.resize(parts.size());
        std::vector<fcl::CollisionObjectd *> raw;
        raw.reserve(parts.size());
        for (std::size_t k = 0; k < parts.size(); ++k)
        {
            m.ids[k] = parts[k].first;
            fcl::Transform3d tf = fcl::Transform3d::Identity();
            if (m.isCircle(parts[k].first))
            {
                const Vec2 &c = m.circles[parts[k].first].center;
                tf.translation() = fcl::Vector3d(c.x, c.y, 0.0);
            }
            m.objects.push_back(std::make_unique<fcl::CollisionObjectd>(parts[k].second, tf));
            m.objects.back()->setUserData(&m.ids[k]);
            raw.push_back(m.objects.back().get());
        }
        m.manager.registerObjects(raw);
        m.manager.setup();

        m.robot = std::make_shared<fcl::Cylinderd>(std::max(radius_, 1e-9), kPrismHeight);
        m.robot->computeLocalAABB();
        m.robotAlias = std::shared_ptr<fcl::CollisionGeometryd>(std::shared_ptr<void>(), m.robot.get());
    }

    FclCollisionModel::~FclCollisionModel() = default;

    double FclCollisionModel::clearance(const Vec2 &p) const
    {
        QueryObject query(impl_->robotAlias, Box{p.x, p.x, p.y, p.y}, 0.0);
        DistanceData data(impl_.get(), p, p, false);
        impl_->manager.distance(&query, &data, distanceCallback);
        return data.best - radius_;
    }

    bool FclCollisionModel::isValid(const Vec2 &p) const
    {
        if (!inBounds(p))
            return false;
        QueryObject query(impl_->robotAlias, Box{p.x, p.x, p.y, p.y}.inflated(radius_), impl_->eps);
        PointCollisionData data(impl_.get(), p, radius_, tol_);
        impl_->manager.collide(&query, &data, pointCollisionCallback);
        return !data.hit;
    }

    bool FclCollisionModel::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        if (!segmentInBounds(a, b))
            return false;
        const Box sb = segmentBox(a, b).inflated(radius_);
        QueryObject query(impl_->robotAlias, sb, impl_->eps);
        SegmentCollisionData data(impl_.get(), a, b, radius_, tol_, sb);
        impl_->manager.collide(&query, &data, segmentCollisionCallback);
        return !data.hit;
    }

    double FclCollisionModel::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        QueryObject query(impl_->robotAlias, segmentBox(a, b), 0.0);
        DistanceData data(impl_.get(), a, b, true);
        impl_->manager.distance(&query, &data, distanceCallback);
        return data.best - radius_;
    }
} // namespace mhplan
