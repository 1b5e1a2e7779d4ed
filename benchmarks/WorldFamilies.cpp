// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/WorldFamilies.h"

#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "src/optimum/Optimum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mhplan
{
    namespace
    {

        /** Distance between two simple polygons (0 when they meet or one contains the other). */
        double polygonDistance(const std::vector<Vec2> &a, const std::vector<Vec2> &b)
        {
            if (pointInPolygon(a[0], b) || pointInPolygon(b[0], a))
                return 0.0;
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < a.size(); ++i)
                for (std::size_t j = 0; j < b.size(); ++j)
                    best = std::min(best, segmentSegmentDistance(a[i], a[(i + 1) % a.size()], b[j],
                                                                 b[(j + 1) % b.size()]));
            return best;
        }

        /** A candidate obstacle: a circle or a polygon, with its bounding circle. */
        struct Shape
        {
            Vec2 center;
            double boundRadius{0.0};
            bool circle{true};
            std::vector<Vec2> vertices;
            double area{0.0};
        };

        double shapeDistance(const Shape &a, const Shape &b)
        {
            const double d = distance(a.center, b.center);
            if (a.circle && b.circle)
                return d - a.boundRadius - b.boundRadius;
            if (d - a.boundRadius - b.boundRadius > 0.0)
                return d - a.boundRadius - b.boundRadius; // a lower bound, enough when above the gap
            if (a.circle || b.circle)
            {
                const Shape &c = a.circle ? a : b;
                const Shape &p = a.circle ? b : a;
                return pointPolygonSignedDistance(c.center, p.vertices) - c.boundRadius;
            }
            return polygonDistance(a.vertices, b.vertices);
        }
    } // namespace

    World generateFamilyWorld(const FamilyOptions &o)
    {
        const bool grid = o.kind == "maze" || o.kind == "grid";
        if (!grid && o.kind != "circles" && o.kind != "rectangles" && o.kind != "polygons")
            throw InputError("generate: unknown kind '" + o.kind +
                             "'; accepted: circles, rectangles, polygons, maze, grid");
        if (!(o.robotRadius >= 0.0) || !std::isfinite(o.robotRadius))
            throw InputError("generate: robot_radius must be >= 0");
        if (grid)
        {
            if (o.cells < 5 || o.cells > 8192)
                throw InputError("generate " + o.kind + ": cells must be in [5, 8192] (got " +
                                 std::to_string(o.cells) + ")");
            GeneratorOptions g;
            g.seed = o.seed;
            g.robotRadius = o.robotRadius;
            if (o.kind == "maze")
            {
                g.width = g.height = (o.cells - 1) / 2;
                World w = generateMaze(g);
                w.name = "maze_" + std::to_string(2 * g.width + 1) + "_s" + std::to_string(o.seed);
                return w;
            }
            if (!(o.density >= 0.0 && o.density <= 0.45))
                throw InputError("generate grid: density must be in [0, 0.45] (got " +
                                 std::to_string(o.density) + ")");
            g.width = g.height = o.cells;
            g.density = o.density;
            World w = generateGrid(g);
            w.name = "grid_" + std::to_string(o.cells) + "_s" + std::to_string(o.seed);
            return w;
        }
        if (o.count < 1 || o.count > 100000)
            throw InputError("generate " + o.kind + ": count must be in [1, 100000] (got " +
                             std::to_string(o.count) + ")");
        if (!(o.coverage >= 0.01 && o.coverage <= 0.4))
            throw InputError("generate " + o.kind + ": coverage must be in [0.01, 0.4] (got " +
                             std::to_string(o.coverage) + ")");
        if (!(o.minSize > 0.0) || !(o.maxSize >= o.minSize) || !std::isfinite(o.maxSize))
            throw InputError("generate " + o.kind + ": sizes need 0 < min_size <= max_size");

        // Draw every obstacle first; the square's side makes their exact total area the target share.
        PortableRandom rng(o.seed);
        std::vector<Shape> drawn(o.count);
        double covered = 0.0;
        for (Shape &s : drawn)
        {
            const double size = rng.uniform(o.minSize, o.maxSize);
            s.circle = o.kind == "circles";
            if (o.kind == "circles")
            {
                s.boundRadius = size;
                s.area = kPi * size * size;
            }
            else if (o.kind == "rectangles")
            {
                const double h = rng.uniform(o.minSize, o.maxSize);
                s.boundRadius = 0.5 * std::hypot(size, h);
                s.area = size * h;
                s.vertices = rectangleCorners({0.0, 0.0}, size, h, rng.uniform(0.0, kPi));
            }
            else
            {
                // A star: 2m vertices alternating between an outer radius (size, jittered) and half of it.
                const int m = 5 + static_cast<int>(rng.index(4));
                const double phase = rng.uniform(0.0, 2.0 * kPi);
                for (int j = 0; j < 2 * m; ++j)
                {
                    const double a = phase + kPi * j / m;
                    const double r = (j % 2 == 0) ? size * rng.uniform(0.85, 1.0) : 0.5 * size;
                    s.vertices.push_back({r * std::cos(a), r * std::sin(a)});
                    s.boundRadius = std::max(s.boundRadius, r);
                }
                s.area = 0.5 * std::abs(signedArea2(s.vertices));
            }
            covered += s.area;
        }
        const double side = std::sqrt(covered / o.coverage);
        const double gap = 2.0 * o.robotRadius + o.minSize / 20.0;
        World w;
        w.name = o.kind + "_" + std::to_string(o.count) + "_s" + std::to_string(o.seed);
        w.bounds = {0.0, side, 0.0, side};
        w.robotRadius = o.robotRadius;

        // Largest first (random sequential addition packs far better that way), each at up to 20000 uniform
        // positions. Bounding-circle buckets: a candidate meets only shapes in its own and the next buckets.
        std::stable_sort(drawn.begin(), drawn.end(),
                         [](const Shape &a, const Shape &b) { return a.boundRadius > b.boundRadius; });
        const double maxBound = drawn.front().boundRadius;
        const double bucket = 2.0 * maxBound + gap;
        const int nb = std::max(1, static_cast<int>(std::ceil(side / bucket)));
        std::vector<std::vector<std::size_t>> buckets(static_cast<std::size_t>(nb) * nb);
        std::vector<Shape> shapes;
        const auto bucketOf = [&](double v) { return std::clamp(static_cast<int>(v / bucket), 0, nb - 1); };
        for (Shape &d : drawn)
        {
            const double keep = d.boundRadius + gap;
            bool placed = false;
            for (int attempt = 0; attempt < 20000 && !placed && side > 2.0 * keep; ++attempt)
            {
                Shape s = d;
                s.center = {rng.uniform(keep, side - keep), rng.uniform(keep, side - keep)};
                for (Vec2 &v : s.vertices)
                    v = v + s.center;
                const int bx = bucketOf(s.center.x), by = bucketOf(s.center.y);
                bool ok = true;
                for (int y = std::max(0, by - 1); ok && y <= std::min(nb - 1, by + 1); ++y)
                    for (int x = std::max(0, bx - 1); ok && x <= std::min(nb - 1, bx + 1); ++x)
                        for (std::size_t k : buckets[static_cast<std::size_t>(y) * nb + x])
                            if (shapeDistance(s, shapes[k]) < gap)
                            {
                                ok = false;
                                break;
                            }
                if (!ok)
                    continue;
                buckets[static_cast<std::size_t>(by) * nb + bx].push_back(shapes.size());
                shapes.push_back(std::move(s));
                placed = true;
            }
            if (!placed)
                break;
        }
        if (shapes.size() < o.count)
            throw InputError("generate " + o.kind + ": could only place " + std::to_string(shapes.size()) +
                             " of " + std::to_string(o.count) + " disjoint obstacles at coverage " +
                             std::to_string(o.coverage) + "; lower the coverage or the robot radius");
        for (Shape &s : shapes)
        {
            if (s.circle)
                w.circles.push_back({s.center, s.boundRadius});
            else
                w.polygons.push_back(
                    makePolygon(std::move(s.vertices), o.kind == "rectangles" ? "rectangle" : "polygon"));
        }
        std::ostringstream src;
        src << "mhplan scaling family: kind " << o.kind << ", count " << o.count << ", seed " << o.seed
            << ", sizes " << o.minSize << ".." << o.maxSize << ", target coverage " << o.coverage
            << ", robot radius " << o.robotRadius;
        w.source = src.str();
        std::ostringstream desc;
        desc.precision(4);
        desc << o.count << " disjoint " << o.kind << " (at least " << gap
             << " m apart and from the bounds) covering " << 100.0 * covered / (side * side) << " % of a "
             << side << " m square";
        w.description = desc.str();
        const double inset = std::max(o.robotRadius, 0.02 * side);
        w.queries.push_back({"default", {inset, inset}, {side - inset, side - inset}});
        return w;
    }

    void addRandomQueries(World &w, const QueryOptions &o)
    {
        if (o.count < 1 || o.count > 1000)
            throw InputError("queries: count must be in [1, 1000] (got " + std::to_string(o.count) + ")");
        if (!(o.minSeparation >= 0.0 && o.minSeparation <= 0.9))
            throw InputError("queries: min_separation must be in [0, 0.9] (a share of the diagonal; got " +
                             std::to_string(o.minSeparation) + ")");
        const CollisionModelPtr model = makeCollisionModel(w);
        const Box &b = w.bounds;
        const double diagonal = std::hypot(b.width(), b.height());
        PortableRandom rng(o.seed);
        const auto draw = [&](Vec2 &p)
        {
            for (int k = 0; k < 10000; ++k)
            {
                if (w.isGrid())
                {
                    const OccupancyGrid &g = *w.grid;
                    const int ix = static_cast<int>(rng.index(static_cast<std::size_t>(g.width())));
                    const int iy = static_cast<int>(rng.index(static_cast<std::size_t>(g.height())));
                    if (g.blocked(ix, iy))
                        continue;
                    p = g.cellCenter(ix, iy);
                }
                else
                    p = {rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax)};
                if (model->isValid(p))
                    return true;
            }
            return false;
        };
        std::vector<Query> queries;
        const std::size_t maxDraws = 1000 * o.count;
        for (std::size_t attempt = 0; attempt < maxDraws && queries.size() < o.count; ++attempt)
        {
            Query q;
            q.name = "q" + std::to_string(queries.size());
            if (!draw(q.start) || !draw(q.goal) || distance(q.start, q.goal) < o.minSeparation * diagonal)
                continue;
            bool connected = false;
            if (w.isGrid())
            {
                const OccupancyGrid &g = *w.grid;
                connected = gridCellsConnected(g, g.cellX(q.start.x), g.cellY(q.start.y), g.cellX(q.goal.x),
                                               g.cellY(q.goal.y));
            }
            else
                connected = computeOptimum(w, q).found;
            if (connected)
                queries.push_back(q);
        }
        if (queries.size() < o.count)
            throw InputError("queries: found only " + std::to_string(queries.size()) + " of " +
                             std::to_string(o.count) + " connected queries at least " +
                             std::to_string(o.minSeparation) + " x the diagonal apart in world '" + w.name +
                             "'");
        w.queries = std::move(queries);
    }
} // namespace mhplan
