// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/WorldIO.h"

#include "src/io/InputFile.h"

#include "src/collision/Collision.h"
#include "src/io/GridIO.h"
#include "src/io/QueryList.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidBody.h"
#include "src/io/YamlReader.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    namespace
    {
        std::string directoryOf(const std::string &path)
        {
            const auto slash = path.find_last_of('/');
            return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
        }

        std::string extensionOf(const std::string &path)
        {
            const auto dot = path.find_last_of('.');
            const auto slash = path.find_last_of('/');
            if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
                return "";
            std::string ext = path.substr(dot + 1);
            for (auto &c : ext)
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            return ext;
        }

        Box readBounds(const YamlReader &r, const YAML::Node &n)
        {
            Box b;
            if (n.IsSequence())
            {
                if (n.size() != 4)
                    r.fail(n, "bounds", "expected [xmin, xmax, ymin, ymax]");
                b = {r.number(n[0], "bounds[0]"), r.number(n[1], "bounds[1]"), r.number(n[2], "bounds[2]"),
                     r.number(n[3], "bounds[3]")};
            }
            else
            {
                r.allowKeys(n, "bounds", {"xmin", "xmax", "ymin", "ymax"});
                b = {r.number(r.require(n, "xmin", "bounds"), "bounds.xmin"),
                     r.number(r.require(n, "xmax", "bounds"), "bounds.xmax"),
                     r.number(r.require(n, "ymin", "bounds"), "bounds.ymin"),
                     r.number(r.require(n, "ymax", "bounds"), "bounds.ymax")};
            }
            const std::string problem = boundsProblem(b);
            if (!problem.empty())
                r.fail(n, "bounds", problem);
            return b;
        }

        void readObstacle(const YamlReader &r, const YAML::Node &item, std::size_t index, World &world)
        {
            const std::string base = "obstacles[" + std::to_string(index) + "]";
            if (!item.IsMap() || item.size() != 1)
                r.fail(item, base, "expected one of {circle: ...}, {rectangle: ...}, {polygon: ...}");
            const std::string kind = r.key(item.begin()->first, base);
            const YAML::Node n = item.begin()->second;
            const std::string field = base + "." + kind;
            if (kind == "circle")
            {
                r.allowKeys(n, field, {"center", "radius"});
                Circle c;
                c.center = r.point(r.require(n, "center", field), field + ".center");
                c.radius = r.number(r.require(n, "radius", field), field + ".radius", -kMaxCoordinate,
                                    kMaxCoordinate);
                if (!(c.radius > 0.0))
                    r.fail(n["radius"], field + ".radius", "must be > 0 (got " + n["radius"].Scalar() + ")");
                world.circles.push_back(c);
            }
            else if (kind == "rectangle")
            {
                r.allowKeys(n, field, {"center", "size", "angle", "min", "max"});
                std::vector<Vec2> corners;
                if (n["min"].IsDefined() || n["max"].IsDefined())
                {
                    if (n["center"].IsDefined() || n["size"].IsDefined() || n["angle"].IsDefined())
                        r.fail(n, field, "give either min/max or center/size/angle, not both");
                    const Vec2 lo = r.point(r.require(n, "min", field), field + ".min");
                    const Vec2 hi = r.point(r.require(n, "max", field), field + ".max");
                    if (!(lo.x < hi.x) || !(lo.y < hi.y))
                        r.fail(n, field, "needs min < max in both coordinates");
                    corners = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
                }
                else
                {
                    const Vec2 c = r.point(r.require(n, "center", field), field + ".center");
                    const Vec2 size = r.point(r.require(n, "size", field), field + ".size");
                    if (!(size.x > 0.0) || !(size.y > 0.0))
                        r.fail(n["size"], field + ".size", "width and height must be > 0");
                    const double angle =
                        n["angle"].IsDefined() ? r.number(n["angle"], field + ".angle") : 0.0;
                    corners = rectangleCorners(c, size.x, size.y, angle * kPi / 180.0);
                }
                world.polygons.push_back(makePolygon(std::move(corners), "rectangle"));
            }
            else if (kind == "polygon")
            {
                r.allowKeys(n, field, {"points"});
                const YAML::Node pts = r.require(n, "points", field);
                if (!pts.IsSequence() || pts.size() < 3)
                    r.fail(pts, field + ".points", "expected a list of at least 3 points");
                if (pts.size() > kMaxPolygonVertices)
                    r.fail(pts, field + ".points",
                           std::to_string(pts.size()) + " vertices; a polygon may have at most " +
                               std::to_string(kMaxPolygonVertices) + " (split it into several polygons)");
                std::vector<Vec2> v;
                for (std::size_t i = 0; i < pts.size(); ++i)
                    v.push_back(r.point(pts[i], field + ".points[" + std::to_string(i) + "]"));
                if (!polygonIsSimple(v))
                    r.fail(pts, field + ".points",
                           "the polygon is not simple (self-intersecting, repeated vertex or zero area)");
                world.polygons.push_back(makePolygon(std::move(v), "polygon"));
            }
            else
                r.fail(item, base,
                       "unknown obstacle type '" + kind + "'; accepted: circle, rectangle, polygon");
        }

        std::shared_ptr<const OccupancyGrid> readGrid(const YamlReader &r, const YAML::Node &n)
        {
            r.allowKeys(n, "grid", {"file", "rows", "cell_size", "origin", "threshold", "negate"});
            const double cell = n["cell_size"].IsDefined() ? r.number(n["cell_size"], "grid.cell_size") : 1.0;
            if (!(cell > 0.0))
                r.fail(n["cell_size"], "grid.cell_size", "must be > 0");
            const Vec2 origin =
                n["origin"].IsDefined() ? r.point(n["origin"], "grid.origin") : Vec2{0.0, 0.0};
            const bool hasFile = n["file"].IsDefined();
            const bool hasRows = n["rows"].IsDefined();
            if (hasFile == hasRows)
                r.fail(n, "grid", "give exactly one of 'file' (a .map or .pgm) and 'rows'");
            const bool pgmFile = hasFile && n["file"].IsScalar() && extensionOf(n["file"].Scalar()) == "pgm";
            for (const char *key : {"threshold", "negate"})
                if (n[key].IsDefined() && !pgmFile)
                    r.fail(n[key], std::string("grid.") + key,
                           "applies only to a .pgm grid file (line " +
                               std::to_string(n[key].Mark().line + 1) + "), not to " +
                               (hasRows ? "'rows'" : "a .map file"));
            OccupancyGrid grid;
            if (hasRows)
            {
                const YAML::Node rows = n["rows"];
                if (!rows.IsSequence() || rows.size() == 0)
                    r.fail(rows, "grid.rows", "expected a non-empty list of strings");
                std::ostringstream text;
                const std::string first = r.text(rows[0], "grid.rows[0]");
                text << "type octile\nheight " << rows.size() << "\nwidth " << first.size() << "\nmap\n";
                for (std::size_t i = 0; i < rows.size(); ++i)
                    text << r.text(rows[i], "grid.rows[" + std::to_string(i) + "]") << "\n";
                std::istringstream in(text.str());
                try
                {
                    grid = parseMovingAIMap(in, r.file() + " (grid.rows)", cell);
                }
                catch (const InputError &e)
                {
                    r.fail(rows, "grid.rows", e.what());
                }
            }
            else
            {
                std::string path = r.text(n["file"], "grid.file");
                if (!path.empty() && path[0] != '/')
                    path = directoryOf(r.file()) + "/" + path;
                const std::string ext = extensionOf(path);
                if (ext != "map" && ext != "pgm")
                    r.fail(n["file"], "grid.file", "expected a .map or .pgm file, got '" + path + "'");
                double threshold = 0.5;
                bool negate = false;
                if (ext == "pgm")
                {
                    threshold = n["threshold"].IsDefined() ? r.number(n["threshold"], "grid.threshold") : 0.5;
                    if (!(threshold > 0.0 && threshold < 1.0))
                        r.fail(n["threshold"], "grid.threshold", "must be in (0, 1)");
                    negate = n["negate"].IsDefined() && r.boolean(n["negate"], "grid.negate");
                }
                try
                {
                    if (ext == "map")
                        grid = loadMovingAIMap(path, cell);
                    else
                        grid = loadPgm(path, cell, threshold, negate);
                }
                catch (const InputError &e)
                {
                    // The grid file's own error names its line; add where it was referenced.
                    r.fail(n["file"], "grid.file", e.what());
                }
            }
            if (origin != Vec2{0.0, 0.0})
            {
                OccupancyGrid moved(grid.width(), grid.height(), grid.cellSize(), origin);
                for (int iy = 0; iy < grid.height(); ++iy)
                    for (int ix = 0; ix < grid.width(); ++ix)
                        moved.setBlocked(ix, iy, grid.blocked(ix, iy));
                grid = std::move(moved);
            }
            const std::string problem = boundsProblem(grid.bounds());
            if (!problem.empty())
                r.fail(n, "grid", "the grid's extent (cell_size times the cells, from origin): " + problem);
            return std::make_shared<const OccupancyGrid>(std::move(grid));
        }

        /** A query's start or goal: [x, y], or [x, y, yaw] (radians) in an SE(2)-based world. */
        void readPose(const YamlReader &r, const YAML::Node &n, const std::string &field, const World &world,
                      Vec2 &position, double &yaw)
        {
            if (n.IsSequence() && n.size() == 3)
            {
                if (!world.isRigid())
                    r.fail(
                        n, field,
                        "a heading [x, y, yaw] needs 'space: se2', 'dubins' or 'reeds_shepp'; this world's "
                        "space is r2: give [x, y]");
                position = {r.number(n[0], field + "[0]", -kMaxCoordinate, kMaxCoordinate),
                            r.number(n[1], field + "[1]", -kMaxCoordinate, kMaxCoordinate)};
                yaw = r.number(n[2], field + "[2]", -1e3, 1e3);
                return;
            }
            if (!n.IsSequence() || n.size() != 2)
                r.fail(n, field,
                       world.isRigid() ? "expected a pose [x, y, yaw] (yaw in radians) or [x, y]"
                                       : "expected a point [x, y]");
            position = r.point(n, field);
            yaw = 0.0;
        }

        /** robot: {radius: R} or {polygon: [[x, y], ...]} (SE(2)-based worlds only). */
        void readRobot(const YamlReader &r, const YAML::Node &n, World &world)
        {
            r.allowKeys(n, "robot", {"radius", "polygon"});
            if (n["radius"].IsDefined() && n["polygon"].IsDefined())
                r.fail(n, "robot", "give either 'radius' (a disc) or 'polygon' (a rigid body), not both");
            if (n["polygon"].IsDefined())
            {
                const YAML::Node pts = n["polygon"];
                if (!world.isRigid())
                    r.fail(
                        pts, "robot.polygon",
                        "a polygon robot needs 'space: se2', 'dubins' or 'reeds_shepp' (an r2 world's robot "
                        "is a disc: 'radius')");
                if (!pts.IsSequence() || pts.size() < 3)
                    r.fail(pts, "robot.polygon", "expected a list of at least 3 points [x, y] (robot frame)");
                if (pts.size() > kMaxRobotVertices)
                    r.fail(pts, "robot.polygon",
                           std::to_string(pts.size()) + " vertices; a robot polygon may have at most " +
                               std::to_string(kMaxRobotVertices));
                std::vector<Vec2> v;
                for (std::size_t i = 0; i < pts.size(); ++i)
                {
                    const std::string f = "robot.polygon[" + std::to_string(i) + "]";
                    const Vec2 p = r.point(pts[i], f);
                    if (std::fabs(p.x) > kMaxRobotCoordinate || std::fabs(p.y) > kMaxRobotCoordinate)
                        r.fail(pts[i], f, "robot-frame coordinates must be within +-1e6");
                    v.push_back(p);
                }
                if (!polygonIsSimple(v))
                    r.fail(pts, "robot.polygon",
                           "the polygon is not simple (self-intersecting, repeated vertex or zero area)");
                world.robotPolygon = makePolygon(std::move(v)).vertices; // counter-clockwise
                return;
            }
            world.robotRadius =
                r.number(r.require(n, "radius", "robot"), "robot.radius", -kMaxCoordinate, kMaxCoordinate);
            if (world.robotRadius < 0.0)
                r.fail(n["radius"], "robot.radius", "must be >= 0 (got " + n["radius"].Scalar() + ")");
        }

        void readQueries(const YamlReader &r, const YAML::Node &n, World &world,
                         std::vector<YAML::Node> &nodes)
        {
            if (!n.IsSequence())
                r.fail(n, "queries", "expected a list of {name, start, goal}");
            std::set<std::string> names;
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string field = "queries[" + std::to_string(i) + "]";
                r.allowKeys(n[i], field, {"name", "start", "goal"});
                Query q;
                q.name = n[i]["name"].IsDefined()
                             ? r.name(n[i]["name"], field + ".name")
                             : (i == 0 ? std::string("default") : "q" + std::to_string(i));
                if (!names.insert(q.name).second)
                    r.fail(n[i], field + ".name", "duplicate query name '" + q.name + "'");
                readPose(r, r.require(n[i], "start", field), field + ".start", world, q.start, q.startYaw);
                readPose(r, r.require(n[i], "goal", field), field + ".goal", world, q.goal, q.goalYaw);
                world.queries.push_back(q);
                nodes.push_back(n[i]);
            }
        }
    } // namespace

    std::string boundsProblem(const Box &b)
    {
        const double c[4] = {b.xmin, b.xmax, b.ymin, b.ymax};
        for (double v : c)
            if (!std::isfinite(v) || std::fabs(v) > kMaxCoordinate)
            {
                std::ostringstream msg;
                msg << "coordinates must be finite and within +-" << kMaxCoordinate << " (got " << v << ")";
                return msg.str();
            }
        if (!(b.xmin < b.xmax) || !(b.ymin < b.ymax))
            return "needs xmin < xmax and ymin < ymax";
        if (b.width() < kMinExtent || b.height() < kMinExtent)
        {
            std::ostringstream msg;
            msg << "the extent " << b.width() << " x " << b.height() << " is degenerate (at least "
                << kMinExtent << " in x and y)";
            return msg.str();
        }
        return "";
    }

    namespace
    {
        /** The quick reading of the queries (QueryList.h) cannot stand for yaml-cpp's tree here: read the
            whole file with the tree, which names the problem. */
        struct ReadWithTree
        {
        };

        World readWorld(const YamlReader &r, const YAML::Node &root, const std::set<std::string> &extraKeys,
                        SplitQueries *split);
    } // namespace

    World parseWorldYaml(const std::string &textIn, const std::string &fileName)
    {
        // A world's queries are read from yaml-cpp's parse events, the rest of the file as a tree
        // (QueryList.h): a list of 10^5 queries as a tree takes 470 MB. Whatever that reading does not take,
        // and every problem, is read again with the whole tree, whose errors name file, line and field.
        if (std::optional<SplitQueries> split = splitQueries(textIn))
        {
            try
            {
                const YAML::Node root =
                    loadYamlMapping(split->rest, fileName, "world file", "environments/README.md");
                return readWorld(YamlReader(fileName), root, {}, &*split);
            }
            catch (const ReadWithTree &)
            {
            }
            catch (const InputError &)
            {
            }
        }
        const YAML::Node root = loadYamlMapping(textIn, fileName, "world file", "environments/README.md");
        return readWorldNode(YamlReader(fileName), root);
    }

    World readWorldNode(const YamlReader &r, const YAML::Node &root, const std::set<std::string> &extraKeys)
    {
        return readWorld(r, root, extraKeys, nullptr);
    }

    namespace
    {
        World readWorld(const YamlReader &r, const YAML::Node &root, const std::set<std::string> &extraKeys,
                        SplitQueries *split)
        {
            const std::string &fileName = r.file();
            std::set<std::string> keys{"name",    "description", "source",        "assumptions",
                                       "bounds",  "robot",       "obstacles",     "grid",
                                       "queries", "space",       "turning_radius"};
            keys.insert(extraKeys.begin(), extraKeys.end());
            r.allowKeys(root, "", keys);

            World world;
            world.file = fileName;
            world.name = root["name"].IsDefined() ? r.name(root["name"], "name") : fileName;
            if (root["description"].IsDefined())
                world.description = r.text(root["description"], "description");
            if (root["source"].IsDefined())
                world.source = r.text(root["source"], "source");
            if (root["assumptions"].IsDefined())
                world.assumptions = r.text(root["assumptions"], "assumptions");
            if (root["space"].IsDefined())
            {
                try
                {
                    world.space = parseSpaceType(r.text(root["space"], "space"));
                }
                catch (const InputError &e)
                {
                    r.fail(root["space"], "space", e.what());
                }
            }
            const bool car = world.space == SpaceType::Dubins || world.space == SpaceType::ReedsShepp;
            if (root["turning_radius"].IsDefined())
            {
                if (!car)
                    r.fail(root["turning_radius"], "turning_radius",
                           "applies only to 'space: dubins' or 'reeds_shepp' (this world's space is " +
                               toString(world.space) + ")");
                world.turningRadius =
                    r.number(root["turning_radius"], "turning_radius", -kMaxCoordinate, kMaxCoordinate);
                if (!(world.turningRadius > 0.0))
                    r.fail(root["turning_radius"], "turning_radius",
                           "must be > 0 (got " + root["turning_radius"].Scalar() + ")");
            }
            else if (car)
                r.fail(root["space"], "turning_radius",
                       "'space: " + toString(world.space) + "' needs 'turning_radius: R' (R > 0, metres)");
            if (root["robot"].IsDefined())
                readRobot(r, root["robot"], world);

            if (root["grid"].IsDefined())
            {
                if (root["obstacles"].IsDefined())
                    r.fail(root["obstacles"], "obstacles",
                           "a grid world cannot also list geometric obstacles");
                if (root["bounds"].IsDefined())
                    r.fail(root["bounds"], "bounds",
                           "a grid world's bounds come from its grid; remove 'bounds'");
                world.grid = readGrid(r, root["grid"]);
                world.bounds = world.grid->bounds();
            }
            else
            {
                world.bounds = readBounds(r, r.require(root, "bounds", ""));
                if (root["obstacles"].IsDefined() && !root["obstacles"].IsNull())
                {
                    const YAML::Node obs = root["obstacles"];
                    if (!obs.IsSequence())
                        r.fail(obs, "obstacles", "expected a list");
                    for (std::size_t i = 0; i < obs.size(); ++i)
                        readObstacle(r, obs[i], i, world);
                }
            }
            if (2.0 * world.robotRadius >= std::min(world.bounds.width(), world.bounds.height()))
                r.fail(root["robot"], "robot.radius", "the robot does not fit inside the bounds");

            std::vector<YAML::Node> queryNodes;
            if (root["queries"].IsDefined())
                readQueries(r, root["queries"], world, queryNodes);
            if (split)
            {
                if (split->headings && !world.isRigid())
                    throw ReadWithTree{}; // refused, with the line, by readPose
                world.queries = std::move(split->queries);
            }
            // A query's start or goal that is out of bounds or in collision: refused with its line.
            const auto failQuery = [&](std::size_t i, const char *key, const std::string &what)
            {
                if (split)
                    throw ReadWithTree{};
                r.fail(queryNodes[i][key], "queries[" + std::to_string(i) + "]." + key, what);
            };

            if (world.isRigid())
            {
                // Start and goal poses must be valid for the robot at its heading.
                const RigidBodyModel rigid(world);
                for (std::size_t i = 0; i < world.queries.size(); ++i)
                {
                    const Query &q = world.queries[i];
                    for (const bool start : {true, false})
                    {
                        const char *key = start ? "start" : "goal";
                        const Pose2 p{start ? q.start.x : q.goal.x, start ? q.start.y : q.goal.y,
                                      start ? q.startYaw : q.goalYaw};
                        const auto at = [&]
                        {
                            std::ostringstream out;
                            out << "(" << p.x << ", " << p.y << ", yaw " << p.yaw << ")";
                            return out.str();
                        };
                        if (!rigid.inBounds(p))
                            failQuery(i, key,
                                      at() +
                                          " is out of bounds (the whole robot must lie inside the bounds)");
                        if (!rigid.isValid(p))
                            failQuery(i, key, at() + " is in collision (the robot overlaps an obstacle)");
                    }
                }
                return world;
            }
            // Start and goal must be valid for the world's own collision model.
            const CollisionModelPtr model = makeCollisionModel(world);
            for (std::size_t i = 0; i < world.queries.size(); ++i)
            {
                const Query &q = world.queries[i];
                for (const bool start : {true, false})
                {
                    const char *key = start ? "start" : "goal";
                    const Vec2 p = start ? q.start : q.goal;
                    const auto at = [&]
                    {
                        std::ostringstream out;
                        out << "(" << p.x << ", " << p.y << ")";
                        return out.str();
                    };
                    if (!model->inBounds(p))
                        failQuery(i, key,
                                  at() + " is out of bounds (the robot disc must lie inside the bounds)");
                    if (!model->isValid(p))
                    {
                        std::ostringstream c;
                        c << std::setprecision(6) << model->clearance(p);
                        failQuery(i, key, at() + " is in collision (clearance " + c.str() + ")");
                    }
                }
            }
            return world;
        }
    } // namespace

    namespace
    {
        /** A grid file format, \e extension: \e parse reads the grid; the world is named after the file's
            stem. */
        WorldFormat gridFormat(const char *extension,
                               OccupancyGrid (*parse)(std::istream &, const std::string &))
        {
            const auto read = [parse](const std::string &text, const std::string &path)
            {
                std::string stem =
                    path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
                stem = stem.substr(0, stem.find_last_of('.'));
                std::istringstream in(text);
                World w = gridWorld(stem, std::make_shared<const OccupancyGrid>(parse(in, path)));
                w.file = path;
                return w;
            };
            return {{extension}, kMaxGridFileBytes, read, ""};
        }

        /** The built-in world formats: the registration list. One entry per format (docs/conventions.md). */
        std::vector<WorldFormat> builtInWorldFormats()
        {
            return {
                {{"yaml", "yml"},
                 kMaxYamlBytes,
                 parseWorldYaml,
                 "YAML input files are limited to " + std::to_string(kMaxYamlBytes) +
                     " bytes (4 MiB; large grids belong in .map or .pgm files)"},
                gridFormat("map", [](std::istream &in, const std::string &file)
                           { return parseMovingAIMap(in, file); }),
                gridFormat("pgm",
                           [](std::istream &in, const std::string &file) { return parsePgm(in, file); }),
            };
        }

        std::vector<WorldFormat> &formatRegistry()
        {
            static std::vector<WorldFormat> formats = builtInWorldFormats();
            return formats;
        }

        /** The format of extension \e ext, or null. */
        const WorldFormat *formatOf(const std::string &ext)
        {
            for (const WorldFormat &f : worldFormats())
                if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end())
                    return &f;
            return nullptr;
        }

        /** The accepted extensions ".a, .b, .c", the last joined by \e lastJoint. */
        std::string acceptedExtensions(const std::string &lastJoint)
        {
            std::vector<std::string> all;
            for (const WorldFormat &f : worldFormats())
                for (const std::string &e : f.extensions)
                    all.push_back("." + e);
            std::string out;
            for (std::size_t i = 0; i < all.size(); ++i)
                out += (i == 0 ? "" : i + 1 == all.size() ? lastJoint : ", ") + all[i];
            return out;
        }
    } // namespace

    const std::vector<WorldFormat> &worldFormats()
    {
        return formatRegistry();
    }

    void registerWorldFormat(WorldFormat format)
    {
        if (format.extensions.empty() || !format.parse)
            throw std::invalid_argument(
                "registerWorldFormat: a world format needs an extension and a parser");
        for (const std::string &e : format.extensions)
            if (formatOf(e) != nullptr)
                throw std::invalid_argument("registerWorldFormat: the extension '." + e +
                                            "' is registered already");
        formatRegistry().push_back(std::move(format));
    }

    bool unregisterWorldFormat(const std::string &extension)
    {
        std::vector<WorldFormat> &formats = formatRegistry();
        for (std::size_t i = builtInWorldFormats().size(); i < formats.size(); ++i)
            if (std::find(formats[i].extensions.begin(), formats[i].extensions.end(), extension) !=
                formats[i].extensions.end())
            {
                formats.erase(formats.begin() + static_cast<std::ptrdiff_t>(i));
                return true;
            }
        return false;
    }

    World loadWorld(const std::string &path, std::string *contents)
    {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            throw InputError(path + ": is a directory, not a world file (" + acceptedExtensions(" or ") +
                             ")");
        const std::string ext = extensionOf(path);
        const WorldFormat *format = formatOf(ext);
        if (format == nullptr)
        {
            requireRegularFile(path, "world file");
            throw InputError(path + ": " +
                             (ext.empty() ? std::string("the file name has no extension")
                                          : "unknown world file type '." + ext + "'") +
                             "; accepted: " + acceptedExtensions(", "));
        }
        // Read once, whole (only a regular file, at most its limit): what is parsed is exactly what the
        // caller may fingerprint (contents).
        std::string text;
        try
        {
            text = readInputFile(path, format->maxBytes, "world file");
        }
        catch (const InputError &e)
        {
            if (!format->limitNote.empty() &&
                std::string(e.what()).find("is larger than") != std::string::npos)
                throw InputError(path + ": the world file is larger than " +
                                 std::to_string(format->maxBytes) + " bytes; " + format->limitNote);
            throw;
        }
        if (contents)
            *contents = text;
        return format->parse(text, path);
    }

    namespace
    {
        std::string yamlString(const std::string &s)
        {
            std::string out = "\"";
            for (char c : s)
            {
                if (c == '"' || c == '\\')
                    out += '\\';
                if (c == '\n')
                {
                    out += "\\n";
                    continue;
                }
                out += c;
            }
            return out + "\"";
        }
    } // namespace

    std::string worldToYaml(const World &world)
    {
        std::ostringstream out;
        out << std::setprecision(17);
        out << "name: " << yamlString(world.name) << "\n";
        if (!world.description.empty())
            out << "description: " << yamlString(world.description) << "\n";
        if (!world.source.empty())
            out << "source: " << yamlString(world.source) << "\n";
        if (!world.assumptions.empty())
            out << "assumptions: " << yamlString(world.assumptions) << "\n";
        if (world.isRigid())
        {
            out << "space: " << toString(world.space) << "\n";
            if (world.turningRadius > 0.0)
                out << "turning_radius: " << world.turningRadius << "\n";
        }
        if (world.robotPolygon.empty())
            out << "robot: {radius: " << world.robotRadius << "}\n";
        else
        {
            out << "robot: {polygon: [";
            for (std::size_t i = 0; i < world.robotPolygon.size(); ++i)
                out << (i ? ", " : "") << "[" << world.robotPolygon[i].x << ", " << world.robotPolygon[i].y
                    << "]";
            out << "]}\n";
        }
        if (world.isGrid())
        {
            const OccupancyGrid &g = *world.grid;
            out << "grid:\n  cell_size: " << g.cellSize() << "\n";
            if (g.origin() != Vec2{0.0, 0.0})
                out << "  origin: [" << g.origin().x << ", " << g.origin().y << "]\n";
            out << "  rows:\n";
            for (int row = 0; row < g.height(); ++row)
            {
                out << "    - \"";
                const int iy = g.rowToIy(row);
                for (int ix = 0; ix < g.width(); ++ix)
                    out << (g.blocked(ix, iy) ? '@' : '.');
                out << "\"\n";
            }
        }
        else
        {
            out << "bounds: {xmin: " << world.bounds.xmin << ", xmax: " << world.bounds.xmax
                << ", ymin: " << world.bounds.ymin << ", ymax: " << world.bounds.ymax << "}\n";
            out << "obstacles:\n";
            if (world.circles.empty() && world.polygons.empty())
                out << "  []\n";
            for (const auto &c : world.circles)
                out << "  - circle: {center: [" << c.center.x << ", " << c.center.y
                    << "], radius: " << c.radius << "}\n";
            for (const auto &p : world.polygons)
            {
                out << "  - polygon: {points: [";
                for (std::size_t i = 0; i < p.vertices.size(); ++i)
                    out << (i ? ", " : "") << "[" << p.vertices[i].x << ", " << p.vertices[i].y << "]";
                out << "]}\n";
            }
        }
        if (!world.queries.empty())
        {
            out << "queries:\n";
            for (const auto &q : world.queries)
            {
                out << "  - {name: " << yamlString(q.name) << ", start: [" << q.start.x << ", " << q.start.y;
                if (world.isRigid())
                    out << ", " << q.startYaw;
                out << "], goal: [" << q.goal.x << ", " << q.goal.y;
                if (world.isRigid())
                    out << ", " << q.goalYaw;
                out << "]}\n";
            }
        }
        return out.str();
    }

    void validateWorldQueries(const World &world)
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        for (const auto &q : world.queries)
            validateQuery(world, q, *model);
    }
} // namespace mhplan
