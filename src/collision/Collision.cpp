// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/collision/Collision.h"
#include "mhplan/collision/ContactRule.h"

#include "mhplan/collision/FclCollision.h"
#include "mhplan/collision/GridCollision.h"
#include "mhplan/collision/SpatialHash.h"

#include <algorithm>
#include <limits>

namespace mhplan
{
    CollisionModel::CollisionModel(const World &world)
        : bounds_(world.bounds), inner_(world.bounds.inflated(-world.robotRadius)),
          radius_(world.robotRadius), tol_(contact::tolerance(world.bounds))
    {
    }

    bool CollisionModel::isValid(const Vec2 &p) const
    {
        return inBounds(p) && clearance(p) >= -tol_;
    }

    AnalyticCollisionModel::AnalyticCollisionModel(const World &world)
        : CollisionModel(world), circles_(world.circles), polygons_(world.polygons)
    {
        if (world.isGrid())
            throw InputError("the analytic collision model handles geometric worlds only; '" + world.name +
                             "' is a grid world (use the grid back end)");
    }

    double AnalyticCollisionModel::clearance(const Vec2 &p) const
    {
        double best = std::numeric_limits<double>::infinity();
        for (const auto &c : circles_)
            best = std::min(best, distance(p, c.center) - c.radius);
        for (const auto &poly : polygons_)
            best = std::min(best, pointPolygonSignedDistance(p, poly.vertices));
        return best - radius_;
    }

    bool AnalyticCollisionModel::isValid(const Vec2 &p) const
    {
        if (!inBounds(p))
            return false;
        for (const auto &c : circles_)
            if (contact::pointHitsCircle(p, c.center, c.radius + radius_, tol_))
                return false;
        for (const auto &poly : polygons_)
            if (contact::pointHitsPolygon(p, poly, radius_, tol_))
                return false;
        return true;
    }

    bool AnalyticCollisionModel::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        if (!segmentInBounds(a, b))
            return false;
        // Built by hand: boundingBox() takes a vector, and this is the hot path (no heap allocation).
        const Box sb =
            Box{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)}.inflated(
                radius_);
        for (const auto &c : circles_)
            if (contact::segmentHitsCircle(a, b, c.center, c.radius + radius_, tol_))
                return false;
        for (const auto &poly : polygons_)
            if (sb.overlaps(poly.bbox) && contact::segmentHitsPolygon(a, b, poly, radius_, tol_))
                return false;
        return true;
    }

    double AnalyticCollisionModel::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        double best = std::numeric_limits<double>::infinity();
        for (const auto &c : circles_)
            best = std::min(best, pointSegmentDistance(c.center, a, b) - c.radius);
        for (const auto &poly : polygons_)
            best = std::min(best, deepestSegmentPenetration(a, b, poly.vertices));
        return best - radius_;
    }

    CollisionBackend parseCollisionBackend(const std::string &name)
    {
        if (name == "auto")
            return CollisionBackend::Auto;
        if (name == "analytic")
            return CollisionBackend::Analytic;
        if (name == "fcl")
            return CollisionBackend::FCL;
        if (name == "grid")
            return CollisionBackend::Grid;
        if (name == "hash")
            return CollisionBackend::Hash;
        throw InputError("unknown collision back end '" + name +
                         "'; accepted: auto, analytic, fcl, grid, hash");
    }

    std::string toString(CollisionBackend backend)
    {
        switch (backend)
        {
        case CollisionBackend::Auto:
            return "auto";
        case CollisionBackend::Analytic:
            return "analytic";
        case CollisionBackend::FCL:
            return "fcl";
        case CollisionBackend::Grid:
            return "grid";
        case CollisionBackend::Hash:
            return "hash";
        }
        return "auto";
    }

    CollisionModelPtr makeCollisionModel(const World &world, CollisionBackend backend)
    {
        if (backend == CollisionBackend::Auto)
        {
            if (world.isGrid())
                backend = CollisionBackend::Grid;
            else
                backend = world.obstacleCount() <= kAutoAnalyticMaxObstacles ? CollisionBackend::Analytic
                                                                             : CollisionBackend::Hash;
        }
        switch (backend)
        {
        case CollisionBackend::Analytic:
            return std::make_shared<AnalyticCollisionModel>(world);
        case CollisionBackend::FCL:
            return std::make_shared<FclCollisionModel>(world);
        case CollisionBackend::Grid:
            return std::make_shared<GridCollisionModel>(world);
        case CollisionBackend::Hash:
            return std::make_shared<SpatialHashCollisionModel>(world);
        case CollisionBackend::Auto:
            break;
        }
        throw InputError("no collision back end for world '" + world.name + "'");
    }
} // namespace mhplan
