// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/Generators.h"

#include "src/io/GridIO.h"
#include "src/io/WorldIO.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <sstream>

namespace mhplan
{
    namespace
    {
        void checkCommon(const GeneratorOptions &o, bool geometric)
        {
            const std::string bounds = boundsProblem(o.bounds);
            if (!bounds.empty())
                throw InputError("generate: --bounds: " + bounds);
            if (!(o.robotRadius >= 0.0) || !std::isfinite(o.robotRadius))
                throw InputError("generate: --radius must be finite and >= 0 (got " +
                                 std::to_string(o.robotRadius) + ")");
            if (geometric && 2.0 * o.robotRadius >= std::min(o.bounds.width(), o.bounds.height()))
                throw InputError("generate: --radius " + std::to_string(o.robotRadius) +
                                 ": the robot does not fit inside the bounds");
            if (geometric && (!(o.minSize > 0.0) || o.maxSize < o.minSize))
                throw InputError("generate: sizes need 0 < --min-size <= --max-size (got " +
                                 std::to_string(o.minSize) + ", " + std::to_string(o.maxSize) + ")");
            if (!geometric && (o.width < 2 || o.height < 2 || o.width > 100000 || o.height > 100000))
                throw InputError("generate: --width and --height must be in [2, 100000]");
            if (!geometric && static_cast<long long>(o.width) * o.height > kMaxGridCells)
                throw InputError("generate: grid too large: " + std::to_string(o.width) + " x " +
                                 std::to_string(o.height) + " cells (at most " +
                                 std::to_string(kMaxGridCells) + " cells)");
            if (!geometric && (!(o.cellSize > 0.0) || !std::isfinite(o.cellSize)))
                throw InputError("generate: --cell-size must be finite and > 0");
        }

        Query cornerQuery(const GeneratorOptions &o)
        {
            const double ix = std::max(o.robotRadius, 0.02 * o.bounds.width());
            const double iy = std::max(o.robotRadius, 0.02 * o.bounds.height());
            return {"default",
                    {o.bounds.xmin + ix, o.bounds.ymin + iy},
                    {o.bounds.xmax - ix, o.bounds.ymax - iy}};
        }

        std::string describe(const char *kind, const GeneratorOptions &o)
        {
            std::ostringstream s;
            s << "mhplan generate " << kind << " --seed " << o.seed;
            return s.str();
        }

        template <typename Accept>
        void placeWithRetries(std::size_t count, std::size_t &placed, Accept accept, const char *what)
        {
            const std::size_t maxAttempts = 1000 * count + 1000;
            std::size_t attempts = 0;
            while (placed < count)
            {
                if (++attempts > maxAttempts)
                    throw InputError(
                        std::string("generate ") + what + ": could only place " + std::to_string(placed) +
                        " of " + std::to_string(count) +
                        " obstacles without covering the start or goal; use fewer or smaller ones");
                if (accept())
                    ++placed;
            }
        }
    } // namespace

    World generateCircles(const GeneratorOptions &o)
    {
        checkCommon(o, true);
        PortableRandom rng(o.seed);
        World w;
        w.name = "circles_" + std::to_string(o.count) + "_seed" + std::to_string(o.seed);
        w.source = describe("circles", o);
        w.bounds = o.bounds;
        w.robotRadius = o.robotRadius;
        const Query q = cornerQuery(o);
        std::size_t placed = 0;
        placeWithRetries(
            o.count, placed,
            [&]
            {
                Circle c;
                c.radius = rng.uniform(o.minSize, o.maxSize);
                c.center = {rng.uniform(o.bounds.xmin, o.bounds.xmax),
                            rng.uniform(o.bounds.ymin, o.bounds.ymax)};
                const double keep = c.radius + o.robotRadius;
                if (distance(c.center, q.start) <= keep || distance(c.center, q.goal) <= keep)
                    return false;
                w.circles.push_back(c);
                return true;
            },
            "circles");
        w.queries.push_back(q);
        return w;
    }

    World generateRectangles(const GeneratorOptions &o)
    {
        checkCommon(o, true);
        PortableRandom rng(o.seed);
        World w;
        w.name = "rectangles_" + std::to_string(o.count) + "_seed" + std::to_string(o.seed);
        w.source = describe("rectangles", o);
        w.bounds = o.bounds;
        w.robotRadius = o.robotRadius;
        const Query q = cornerQuery(o);
        std::size_t placed = 0;
        placeWithRetries(
            o.count, placed,
            [&]
            {
                const Vec2 c{rng.uniform(o.bounds.xmin, o.bounds.xmax),
                             rng.uniform(o.bounds.ymin, o.bounds.ymax)};
                const double width = rng.uniform(o.minSize, o.maxSize);
                const double height = rng.uniform(o.minSize, o.maxSize);
                const double angle = rng.uniform(0.0, kPi);
                Polygon p = makePolygon(rectangleCorners(c, width, height, angle), "rectangle");
                if (pointPolygonSignedDistance(q.start, p.vertices) <= o.robotRadius ||
                    pointPolygonSignedDistance(q.goal, p.vertices) <= o.robotRadius)
                    return false;
                w.polygons.push_back(std::move(p));
                return true;
            },
            "rectangles");
        w.queries.push_back(q);
        return w;
    }

    World generateMaze(const GeneratorOptions &o)
    {
        checkCommon(o, false);
        if ((2LL * o.width + 1) * (2LL * o.height + 1) > kMaxGridCells)
            throw InputError("generate maze: a " + std::to_string(o.width) + " x " +
                             std::to_string(o.height) + " maze needs more than the " +
                             std::to_string(kMaxGridCells) + " grid cells allowed");
        PortableRandom rng(o.seed);
        const int mw = o.width;
        const int mh = o.height;
        auto grid = std::make_shared<OccupancyGrid>(2 * mw + 1, 2 * mh + 1, o.cellSize,
                                                    Vec2{o.bounds.xmin, o.bounds.ymin});
        for (int iy = 0; iy < grid->height(); ++iy)
            for (int ix = 0; ix < grid->width(); ++ix)
                grid->setBlocked(ix, iy, true);
        // Randomised depth-first search over maze cells (mx, my) -> grid cell (2mx+1, 2my+1).
        std::vector<char> visited(static_cast<std::size_t>(mw) * mh, 0);
        std::vector<std::pair<int, int>> stack{{0, 0}};
        visited[0] = 1;
        grid->setBlocked(1, 1, false);
        const int dx[4] = {1, -1, 0, 0};
        const int dy[4] = {0, 0, 1, -1};
        while (!stack.empty())
        {
            const auto [cx, cy] = stack.back();
            int options[4];
            int n = 0;
            for (int d = 0; d < 4; ++d)
            {
                const int nx = cx + dx[d];
                const int ny = cy + dy[d];
                if (nx >= 0 && ny >= 0 && nx < mw && ny < mh &&
                    !visited[static_cast<std::size_t>(ny) * mw + nx])
                    options[n++] = d;
            }
            if (n == 0)
            {
                stack.pop_back();
                continue;
            }
            const int d = options[rng.index(static_cast<std::size_t>(n))];
            const int nx = cx + dx[d];
            const int ny = cy + dy[d];
            visited[static_cast<std::size_t>(ny) * mw + nx] = 1;
            grid->setBlocked(2 * cx + 1 + dx[d], 2 * cy + 1 + dy[d], false);
            grid->setBlocked(2 * nx + 1, 2 * ny + 1, false);
            stack.emplace_back(nx, ny);
        }
        World w;
        w.name = "maze_" + std::to_string(mw) + "x" + std::to_string(mh) + "_seed" + std::to_string(o.seed);
        w.source = describe("maze", o);
        w.robotRadius = o.robotRadius;
        w.bounds = grid->bounds();
        w.queries.push_back({"default", grid->cellCenter(1, 1), grid->cellCenter(2 * mw - 1, 2 * mh - 1)});
        w.grid = std::move(grid);
        return w;
    }

    bool gridCellsConnected(const OccupancyGrid &g, int sx, int sy, int gx, int gy)
    {
        if (g.blocked(sx, sy) || g.blocked(gx, gy))
            return false;
        std::vector<char> seen(static_cast<std::size_t>(g.width()) * g.height(), 0);
        std::deque<std::pair<int, int>> open{{sx, sy}};
        seen[static_cast<std::size_t>(sy) * g.width() + sx] = 1;
        while (!open.empty())
        {
            const auto [x, y] = open.front();
            open.pop_front();
            if (x == gx && y == gy)
                return true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                {
                    if (dx == 0 && dy == 0)
                        continue;
                    const int nx = x + dx;
                    const int ny = y + dy;
                    if (g.blocked(nx, ny))
                        continue;
                    if (dx != 0 && dy != 0 && (g.blocked(x + dx, y) || g.blocked(x, y + dy)))
                        continue;
                    char &s = seen[static_cast<std::size_t>(ny) * g.width() + nx];
                    if (!s)
                    {
                        s = 1;
                        open.emplace_back(nx, ny);
                    }
                }
        }
        return false;
    }

    World generateGrid(const GeneratorOptions &o)
    {
        checkCommon(o, false);
        if (!(o.density >= 0.0 && o.density < 1.0))
            throw InputError("generate grid: --density must be in [0, 1) (got " + std::to_string(o.density) +
                             ")");
        for (std::uint64_t attempt = 0; attempt < 1000; ++attempt)
        {
            PortableRandom rng(o.seed + attempt * 0x9E3779B97F4A7C15ULL);
            auto grid = std::make_shared<OccupancyGrid>(o.width, o.height, o.cellSize,
                                                        Vec2{o.bounds.xmin, o.bounds.ymin});
            for (int iy = 0; iy < o.height; ++iy)
                for (int ix = 0; ix < o.width; ++ix)
                    grid->setBlocked(ix, iy, rng.uniform01() < o.density);
            grid->setBlocked(0, 0, false);
            grid->setBlocked(o.width - 1, o.height - 1, false);
            if (!gridCellsConnected(*grid, 0, 0, o.width - 1, o.height - 1))
                continue;
            World w;
            w.name = "grid_" + std::to_string(o.width) + "x" + std::to_string(o.height) + "_seed" +
                     std::to_string(o.seed);
            std::ostringstream src;
            src << describe("grid", o) << " --density " << o.density;
            if (attempt > 0)
                src << " (connected on attempt " << attempt + 1 << ")";
            w.source = src.str();
            w.robotRadius = o.robotRadius;
            w.bounds = grid->bounds();
            w.queries.push_back(
                {"default", grid->cellCenter(0, 0), grid->cellCenter(o.width - 1, o.height - 1)});
            w.grid = std::move(grid);
            return w;
        }
        throw InputError("generate grid: no connected map in 1000 attempts at density " +
                         std::to_string(o.density));
    }
} // namespace mhplan
