// SPDX-License-Identifier: BSD-3-Clause
#include "src/base/World.h"

#include <algorithm>
#include <sstream>

namespace mhplan
{
    OccupancyGrid::OccupancyGrid(int width, int height, double cellSize, Vec2 origin)
        : width_(width), height_(height), cellSize_(cellSize), origin_(origin)
    {
        if (width <= 0 || height <= 0)
            throw InputError("occupancy grid: width and height must be positive (got " +
                             std::to_string(width) + " x " + std::to_string(height) + ")");
        if (!(cellSize > 0.0))
            throw InputError("occupancy grid: cell_size must be > 0 (got " + std::to_string(cellSize) + ")");
        cells_.assign(static_cast<std::size_t>(width) * height, 0);
    }

    std::size_t OccupancyGrid::blockedCount() const
    {
        return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), std::uint8_t{1}));
    }

    std::string toString(SpaceType space)
    {
        switch (space)
        {
        case SpaceType::R2:
            return "r2";
        case SpaceType::SE2:
            return "se2";
        case SpaceType::Dubins:
            return "dubins";
        case SpaceType::ReedsShepp:
            return "reeds_shepp";
        }
        return "r2";
    }

    SpaceType parseSpaceType(const std::string &word)
    {
        for (SpaceType s : {SpaceType::R2, SpaceType::SE2, SpaceType::Dubins, SpaceType::ReedsShepp})
            if (toString(s) == word)
                return s;
        throw InputError("unknown space '" + word + "'; accepted: r2, se2, dubins, reeds_shepp");
    }

    double World::robotReach() const
    {
        if (robotPolygon.empty())
            return robotRadius;
        double r = 0.0;
        for (const Vec2 &v : robotPolygon)
            r = std::max(r, norm(v));
        return r;
    }

    std::string World::type() const
    {
        if (isGrid())
            return "grid";
        if (polygons.empty())
            return "circles";
        if (circles.empty())
            return "polygons";
        return "mixed";
    }

    std::size_t World::obstacleCount() const
    {
        if (isGrid())
            return grid->blockedCount();
        return circles.size() + polygons.size();
    }

    const Query &World::query(const std::string &queryName) const
    {
        for (const auto &q : queries)
            if (q.name == queryName)
                return q;
        std::ostringstream msg;
        msg << "world '" << name << "' has no query named '" << queryName << "'; available:";
        if (queries.empty())
            msg << " (none)";
        for (const auto &q : queries)
            msg << " " << q.name;
        throw InputError(msg.str());
    }

    const Query &World::queryOrDefault(const std::string &queryName) const
    {
        if (!queryName.empty())
            return query(queryName);
        if (queries.empty())
            throw InputError("world '" + name + "' has no queries; give --start X,Y and --goal X,Y");
        return queries.front();
    }

    Polygon makePolygon(std::vector<Vec2> vertices, const std::string &kind)
    {
        Polygon p;
        if (signedArea2(vertices) < 0.0)
            std::reverse(vertices.begin(), vertices.end());
        p.vertices = std::move(vertices);
        p.convex = polygonIsConvex(p.vertices);
        p.kind = kind;
        p.bbox = boundingBox(p.vertices);
        return p;
    }
} // namespace mhplan
