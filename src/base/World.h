// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the 2D world model shared by every planner, checker and tool. */
#ifndef MHPLAN_WORLD_H
#define MHPLAN_WORLD_H

#include "src/base/Geometry.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Error in user input (a world file, a command line, a campaign): the message names the file,
        line and field where they are known. */
    class InputError : public std::runtime_error
    {
      public:
        using std::runtime_error::runtime_error;
    };

    /** \brief A closed disc obstacle. */
    struct Circle
    {
        Vec2 center;
        double radius{0.0};
    };

    /** \brief A closed simple polygon obstacle (rectangles are stored as polygons too). Vertices are kept
        counter-clockwise. */
    struct Polygon
    {
        std::vector<Vec2> vertices;
        bool convex{false};
        /** \brief What the world file called it: "polygon", "rectangle" (used for drawing and counting). */
        std::string kind{"polygon"};
        Box bbox;
    };

    /** \brief An occupancy grid. Cell (ix, iy) covers [ox + ix*s, ox + (ix+1)*s] x [oy + iy*s, oy + (iy+1)*s]
        with s = cellSize; iy grows upwards (row 0 of a MovingAI or PGM file is the top row, iy = height-1).
        A blocked cell is a closed square obstacle. */
    class OccupancyGrid
    {
      public:
        OccupancyGrid() = default;
        OccupancyGrid(int width, int height, double cellSize, Vec2 origin = {0.0, 0.0});

        int width() const { return width_; }
        int height() const { return height_; }
        double cellSize() const { return cellSize_; }
        const Vec2 &origin() const { return origin_; }

        bool inside(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width_ && iy < height_; }
        /** \brief Cells outside the grid count as blocked. */
        bool blocked(int ix, int iy) const
        {
            return !inside(ix, iy) || cells_[static_cast<std::size_t>(iy) * width_ + ix] != 0;
        }
        void setBlocked(int ix, int iy, bool b)
        {
            cells_[static_cast<std::size_t>(iy) * width_ + ix] = b ? 1 : 0;
        }
        std::size_t blockedCount() const;

        /** \brief Index of the cell containing \e p (may be outside the grid). */
        int cellX(double x) const { return static_cast<int>(std::floor((x - origin_.x) / cellSize_)); }
        int cellY(double y) const { return static_cast<int>(std::floor((y - origin_.y) / cellSize_)); }
        Vec2 cellCenter(int ix, int iy) const
        {
            return {origin_.x + (ix + 0.5) * cellSize_, origin_.y + (iy + 0.5) * cellSize_};
        }
        Box cellBox(int ix, int iy) const
        {
            return {origin_.x + ix * cellSize_, origin_.x + (ix + 1) * cellSize_, origin_.y + iy * cellSize_,
                    origin_.y + (iy + 1) * cellSize_};
        }
        Box bounds() const
        {
            return {origin_.x, origin_.x + width_ * cellSize_, origin_.y, origin_.y + height_ * cellSize_};
        }

        /** \brief Convert a MovingAI (column, row) pair (row 0 = top line of the file) to grid indices. */
        int rowToIy(int row) const { return height_ - 1 - row; }

      private:
        int width_{0};
        int height_{0};
        double cellSize_{1.0};
        Vec2 origin_;
        std::vector<std::uint8_t> cells_;
    };

    /** \brief A named planning query. In an SE(2)-based world (se2, dubins, reeds_shepp) start and goal are
        poses: the position and a heading in radians (default 0); an r2 world has no headings (both 0). */
    struct Query
    {
        std::string name{"default"};
        Vec2 start;
        Vec2 goal;
        double startYaw{0.0};
        double goalYaw{0.0};
    };

    /** \brief The configuration space of a world's robot (docs/spaces.md, "Rigid-body and car worlds"). */
    enum class SpaceType
    {
        R2,        ///< a disc or point robot translating in the plane (RealVectorStateSpace(2))
        SE2,       ///< a rigid body translating and rotating freely (SE2StateSpace)
        Dubins,    ///< a forward-only car with a minimum turning radius (DubinsStateSpace)
        ReedsShepp ///< a car that also reverses, with a minimum turning radius (ReedsSheppStateSpace)
    };

    /** \brief "r2", "se2", "dubins", "reeds_shepp" (the world file's words). */
    std::string toString(SpaceType space);
    /** \brief Parse the world file's word; throws InputError listing the accepted words. */
    SpaceType parseSpaceType(const std::string &word);

    /** \brief A 2D world: bounds, a disc robot, obstacles (geometric or an occupancy grid) and queries.
        Validity (see Collision.h): a robot position is valid when the disc lies inside the bounds and does
        not overlap the interior of any obstacle (touching is allowed; obstacles are closed sets, free space
       is closed). */
    struct World
    {
        std::string name;
        std::string description;
        /** \brief Where the world comes from (paper, generator and seed). */
        std::string source;
        /** \brief Assumptions made where the source is silent (e.g. an assumed start and goal). */
        std::string assumptions;
        /** \brief The file it was loaded from, if any. */
        std::string file;

        Box bounds;
        double robotRadius{0.0};
        /** \brief The robot's outline in its own frame (a simple polygon, counter-clockwise); empty for a
           disc (or point) robot of radius robotRadius. Only in SE(2)-based spaces. */
        std::vector<Vec2> robotPolygon;
        /** \brief The robot's configuration space (r2 by default). */
        SpaceType space{SpaceType::R2};
        /** \brief The cars' minimum turning radius (dubins, reeds_shepp); 0 otherwise. */
        double turningRadius{0.0};
        std::vector<Circle> circles;
        std::vector<Polygon> polygons;
        /** \brief Set for grid worlds; then circles and polygons are empty. */
        std::shared_ptr<const OccupancyGrid> grid;
        std::vector<Query> queries;

        bool isGrid() const { return grid != nullptr; }
        /** \brief True for the SE(2)-based spaces (se2, dubins, reeds_shepp): a pose has a heading. */
        bool isRigid() const { return space != SpaceType::R2; }
        /** \brief The farthest point of the robot from its origin: the farthest polygon vertex, or the disc's
            radius. */
        double robotReach() const;
        /** \brief "grid", "circles", "polygons" or "mixed". */
        std::string type() const;
        std::size_t obstacleCount() const;
        /** \brief The query named \e name; throws InputError listing the available names. */
        const Query &query(const std::string &name) const;
        /** \brief The first query when \e name is empty, else query(name). */
        const Query &queryOrDefault(const std::string &name) const;
    };

    /** \brief Build a Polygon (orientation normalised to counter-clockwise, convexity and bbox computed). */
    Polygon makePolygon(std::vector<Vec2> vertices, const std::string &kind = "polygon");
} // namespace mhplan

#endif
