// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/RigidBody.h"

#include "src/collision/detail/FclShapes.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <limits>

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();

        /** The robot placed for one query: shares the robot piece's geometry without touching it (FCL's
            constructors recompute the geometry's local AABB, which would race between threads) and carries
            the exact planar bounding box of the placed piece. Lives on the caller's stack. */
        class PlacedPiece : public fcl::CollisionObjectd
        {
          public:
            PlacedPiece(const std::shared_ptr<fcl::CollisionGeometryd> &geometry, const Pose2 &p,
                        const Box &box)
                : fcl::CollisionObjectd(std::shared_ptr<fcl::CollisionGeometryd>())
            {
                cgeom = geometry;
                cgeom_const = geometry;
                user_data = nullptr;
                fcl::Transform3d tf = fcl::Transform3d::Identity();
                tf.linear() = fcl::AngleAxisd(p.yaw, fcl::Vector3d::UnitZ()).toRotationMatrix();
                tf.translation() = fcl::Vector3d(p.x, p.y, 0.0);
                t = tf;
                aabb.min_ = fcl::Vector3d(box.xmin, box.ymin, -0.5 * detail::kPrismHeight);
                aabb.max_ = fcl::Vector3d(box.xmax, box.ymax, 0.5 * detail::kPrismHeight);
            }
        };

        /** The pair a manager hands to a callback, query (the robot piece, without user data) first: FCL
           0.7's libccd solver gave a wrong distance for (box, convex) where (convex, box) was right, so every
            narrow-phase call has one order, uses FCL's own GJK solver (GST_INDEP) and no Box shapes. */
        std::pair<fcl::CollisionObjectd *, fcl::CollisionObjectd *> queryFirst(fcl::CollisionObjectd *o1,
                                                                               fcl::CollisionObjectd *o2)
        {
            return o1->getUserData() == nullptr ? std::make_pair(o1, o2) : std::make_pair(o2, o1);
        }

        struct DistanceData
        {
            DistanceData()
            {
                request.gjk_solver_type = fcl::GST_INDEP;
                request.distance_tolerance = 1e-9;
            }
            double best{kInf};
            fcl::DistanceRequestd request;
        };

        bool distanceCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *cdata, double &dist)
        {
            auto &d = *static_cast<DistanceData *>(cdata);
            fcl::DistanceResultd result;
            const auto pair = queryFirst(o1, o2);
            fcl::distance(pair.first, pair.second, d.request, result);
            d.best = std::min(d.best, result.min_distance);
            dist = std::max(d.best, 0.0);
            return d.best <= 0.0; // in contact: nothing can be closer
        }

        struct CollideData
        {
            CollideData() { request.gjk_solver_type = fcl::GST_INDEP; }
            bool hit{false};
            fcl::CollisionRequestd request;
        };

        bool collideCallback(fcl::CollisionObjectd *o1, fcl::CollisionObjectd *o2, void *cdata)
        {
            auto &d = *static_cast<CollideData *>(cdata);
            fcl::CollisionResultd result;
            const auto pair = queryFirst(o1, o2);
            fcl::collide(pair.first, pair.second, d.request, result);
            d.hit = d.hit || result.isCollision();
            return d.hit;
        }

        std::vector<Vec2> square(const Box &b)
        {
            return {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
        }
    } // namespace

    struct RigidBodyModel::Impl
    {
        std::vector<std::shared_ptr<fcl::CollisionGeometryd>> geometries;
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
        fcl::DynamicAABBTreeCollisionManagerd manager;
        /** Robot pieces in the robot frame: geometry and the vertices (for the placed bounding box). */
        std::vector<std::shared_ptr<fcl::CollisionGeometryd>> robot;
        std::vector<std::vector<Vec2>> robotVertices;
        double margin{0.0};

        Box placedBox(std::size_t piece, const Pose2 &p, double radius) const
        {
            if (robotVertices[piece].empty())
                return Box{p.x, p.x, p.y, p.y}.inflated(radius + margin);
            Box b{kInf, -kInf, kInf, -kInf};
            for (const Vec2 &v : robotVertices[piece])
            {
                const Vec2 q = placePoint(p, v);
                b.xmin = std::min(b.xmin, q.x);
                b.xmax = std::max(b.xmax, q.x);
                b.ymin = std::min(b.ymin, q.y);
                b.ymax = std::max(b.ymax, q.y);
            }
            return b.inflated(margin);
        }
    };

    RigidBodyModel::RigidBodyModel(const World &world)
        : impl_(std::make_unique<Impl>()), polygon_(world.robotPolygon), radius_(world.robotRadius),
          reach_(world.robotReach()), bounds_(world.bounds)
    {
        Impl &m = *impl_;
        double scale = std::max({std::abs(bounds_.xmin), std::abs(bounds_.xmax), std::abs(bounds_.ymin),
                                 std::abs(bounds_.ymax), reach_});
        m.margin = 1e-5 * (1.0 + scale);

        auto add = [&](const std::shared_ptr<fcl::CollisionGeometryd> &g, const Vec2 &at)
        {
            fcl::Transform3d tf = fcl::Transform3d::Identity();
            tf.translation() = fcl::Vector3d(at.x, at.y, 0.0);
            m.geometries.push_back(g);
            m.objects.push_back(std::make_unique<fcl::CollisionObjectd>(g, tf));
            m.objects.back()->setUserData(&m); // obstacles carry user data, the robot's pieces none
        };
        for (const Circle &c : world.circles)
            add(std::make_shared<fcl::Cylinderd>(c.radius, detail::kPrismHeight), c.center);
        for (const Polygon &poly : world.polygons)
            for (const auto &piece : detail::convexPieces(poly))
                add(detail::makePrism(piece), {0.0, 0.0});
        if (world.isGrid())
        {
            const OccupancyGrid &g = *world.grid;
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width();)
                {
                    if (!g.blocked(ix, iy))
                    {
                        ++ix;
                        continue;
                    }
                    int end = ix;
                    while (end < g.width() && g.blocked(end, iy))
                        ++end;
                    const Box first = g.cellBox(ix, iy);
                    const Box last = g.cellBox(end - 1, iy);
                    const Box run{first.xmin, last.xmax, first.ymin, first.ymax};
                    add(detail::makePrism(square(run)), {0.0, 0.0});
                    ix = end;
                }
        }
        std::vector<fcl::CollisionObjectd *> raw;
        for (auto &o : m.objects)
            raw.push_back(o.get());
        m.manager.registerObjects(raw);
        m.manager.setup();

        if (polygon_.empty())
        {
            m.robot.push_back(
                std::make_shared<fcl::Cylinderd>(std::max(radius_, 1e-9), detail::kPrismHeight));
            m.robotVertices.emplace_back();
        }
        else
            for (const auto &piece : detail::convexPieces(makePolygon(polygon_)))
            {
                m.robot.push_back(detail::makePrism(piece));
                m.robotVertices.push_back(piece);
            }
        for (auto &g : m.robot)
            g->computeLocalAABB();
    }

    RigidBodyModel::~RigidBodyModel() = default;

    double RigidBodyModel::margin() const
    {
        return impl_->margin;
    }

    double RigidBodyModel::boundsDistance(const Pose2 &p) const
    {
        if (polygon_.empty())
            return std::min(
                       {p.x - bounds_.xmin, bounds_.xmax - p.x, p.y - bounds_.ymin, bounds_.ymax - p.y}) -
                   radius_;
        double d = kInf;
        for (const Vec2 &v : polygon_)
        {
            const Vec2 q = placePoint(p, v);
            d = std::min({d, q.x - bounds_.xmin, bounds_.xmax - q.x, q.y - bounds_.ymin, bounds_.ymax - q.y});
        }
        return d;
    }

    bool RigidBodyModel::inBounds(const Pose2 &p) const
    {
        return boundsDistance(p) >= 0.0;
    }

    bool RigidBodyModel::isValid(const Pose2 &p) const
    {
        if (!inBounds(p))
            return false;
        if (impl_->objects.empty())
            return true;
        CollideData data;
        for (std::size_t i = 0; i < impl_->robot.size() && !data.hit; ++i)
        {
            PlacedPiece piece(impl_->robot[i], p, impl_->placedBox(i, p, radius_));
            impl_->manager.collide(&piece, &data, collideCallback);
        }
        return !data.hit;
    }

    double RigidBodyModel::clearance(const Pose2 &p) const
    {
        if (impl_->objects.empty())
            return kInf;
        DistanceData data;
        for (std::size_t i = 0; i < impl_->robot.size() && data.best > 0.0; ++i)
        {
            PlacedPiece piece(impl_->robot[i], p, impl_->placedBox(i, p, radius_));
            impl_->manager.distance(&piece, &data, distanceCallback);
        }
        if (data.best <= 0.0)
            return -1.0;
        // (A point robot's cylinder of radius 1e-9 makes this slightly smaller still: conservative.)
        return data.best - impl_->margin;
    }

    double RigidBodyModel::freeDistance(const Pose2 &p) const
    {
        const double b = boundsDistance(p);
        if (b < 0.0)
            return b;
        return std::min(b, clearance(p));
    }

    std::vector<Vec2> placedRobot(const World &world, const Pose2 &p)
    {
        std::vector<Vec2> out;
        out.reserve(world.robotPolygon.size());
        for (const Vec2 &v : world.robotPolygon)
            out.push_back(placePoint(p, v));
        return out;
    }

    namespace
    {
        /** True when the interiors of two simple polygons overlap (touching is not overlap). */
        bool polygonsOverlap(const std::vector<Vec2> &a, const std::vector<Vec2> &b)
        {
            const std::size_t na = a.size();
            const std::size_t nb = b.size();
            for (std::size_t i = 0; i < na; ++i)
                for (std::size_t j = 0; j < nb; ++j)
                    if (segmentsCrossProperly(a[i], a[(i + 1) % na], b[j], b[(j + 1) % nb]))
                        return true;
            // No proper crossing: one may still lie inside the other, or meet it along a diagonal through
            // vertices; a vertex or an edge midpoint strictly inside the other tells.
            for (std::size_t i = 0; i < na; ++i)
                if (pointPolygonSignedDistance(a[i], b) < 0.0 ||
                    pointPolygonSignedDistance((a[i] + a[(i + 1) % na]) * 0.5, b) < 0.0)
                    return true;
            for (std::size_t j = 0; j < nb; ++j)
                if (pointPolygonSignedDistance(b[j], a) < 0.0 ||
                    pointPolygonSignedDistance((b[j] + b[(j + 1) % nb]) * 0.5, a) < 0.0)
                    return true;
            return false;
        }

        double polygonsDistance(const std::vector<Vec2> &a, const std::vector<Vec2> &b)
        {
            if (polygonsOverlap(a, b))
                return 0.0;
            double d = kInf;
            for (std::size_t i = 0; i < a.size(); ++i)
                for (std::size_t j = 0; j < b.size(); ++j)
                    d = std::min(
                        d, segmentSegmentDistance(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]));
            return d;
        }

        /** Distance (0 on overlap) of the robot at \e p to every obstacle, calling \e visit(d) per obstacle
            near the robot (within \e reach of its bounding box); stops when \e visit returns true. */
        template <typename Visit>
        void forEachObstacleDistance(const World &world, const Pose2 &p, double reach, Visit visit)
        {
            const std::vector<Vec2> robot = placedRobot(world, p);
            const bool disc = robot.empty();
            const Box rb = (disc ? Box{p.x, p.x, p.y, p.y}.inflated(world.robotRadius) : boundingBox(robot))
                               .inflated(reach);
            auto polygonDistance = [&](const std::vector<Vec2> &poly)
            {
                if (disc)
                    return std::max(0.0, pointPolygonSignedDistance({p.x, p.y}, poly) - world.robotRadius);
                return polygonsDistance(robot, poly);
            };
            for (const Circle &c : world.circles)
            {
                const double d = disc ? distance({p.x, p.y}, c.center) - c.radius - world.robotRadius
                                      : pointPolygonSignedDistance(c.center, robot) - c.radius;
                if (visit(std::max(0.0, d), d < 0.0))
                    return;
            }
            for (const Polygon &poly : world.polygons)
            {
                if (!rb.overlaps(poly.bbox))
                    continue;
                const double d = polygonDistance(poly.vertices);
                if (visit(d, disc ? pointPolygonSignedDistance({p.x, p.y}, poly.vertices) < world.robotRadius
                                  : polygonsOverlap(robot, poly.vertices)))
                    return;
            }
            if (world.isGrid())
            {
                const OccupancyGrid &g = *world.grid;
                const int x0 = std::max(0, g.cellX(rb.xmin));
                const int x1 = std::min(g.width() - 1, g.cellX(rb.xmax));
                const int y0 = std::max(0, g.cellY(rb.ymin));
                const int y1 = std::min(g.height() - 1, g.cellY(rb.ymax));
                for (int iy = y0; iy <= y1; ++iy)
                    for (int ix = x0; ix <= x1; ++ix)
                    {
                        if (!g.blocked(ix, iy))
                            continue;
                        const std::vector<Vec2> cell = square(g.cellBox(ix, iy));
                        const double d = polygonDistance(cell);
                        if (visit(d, disc ? pointPolygonSignedDistance({p.x, p.y}, cell) < world.robotRadius
                                          : polygonsOverlap(robot, cell)))
                            return;
                    }
            }
        }
    } // namespace

    bool independentPoseFree(const World &world, const Pose2 &p)
    {
        const std::vector<Vec2> robot = placedRobot(world, p);
        if (robot.empty())
        {
            const Box inner = world.bounds.inflated(-world.robotRadius);
            if (!inner.contains({p.x, p.y}))
                return false;
        }
        else
            for (const Vec2 &v : robot)
                if (!world.bounds.contains(v))
                    return false;
        bool hit = false;
        forEachObstacleDistance(world, p, 0.0,
                                [&](double, bool overlap)
                                {
                                    hit = overlap;
                                    return hit;
                                });
        return !hit;
    }

    double independentPoseDistance(const World &world, const Pose2 &p)
    {
        double best = kInf;
        // Grid cells farther than the world's size cannot be the nearest obstacle of a robot in the bounds.
        const double reach = std::hypot(world.bounds.width(), world.bounds.height());
        forEachObstacleDistance(world, p, reach,
                                [&](double d, bool)
                                {
                                    best = std::min(best, d);
                                    return best <= 0.0;
                                });
        return best;
    }
} // namespace mhplan
