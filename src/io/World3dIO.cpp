// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/World3dIO.h"

#include "src/base/World.h"
#include "src/io/InputFile.h"
#include "src/io/YamlReader.h"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace mhplan
{
    namespace
    {
        const char *const kHelp = "docs/worlds3d.md";

        /** "FILE:LINE: field 'F': what", as YamlReader::fail writes it. */
        [[noreturn]] void failAt(const std::string &file, int line, const std::string &field,
                                 const std::string &what)
        {
            throw InputError(file + ":" + std::to_string(line) + ": field '" + field + "': " + what);
        }

        Eigen::Vector3d vec3(const YamlReader &r, const YAML::Node &n, const std::string &field)
        {
            if (!n.IsDefined() || n.IsNull())
                r.fail(n, field, "missing; expected [x, y, z]");
            if (!n.IsSequence() || n.size() != 3)
                r.fail(n, field, "expected a list of three numbers [x, y, z]");
            Eigen::Vector3d v;
            for (std::size_t i = 0; i < 3; ++i)
                v[static_cast<int>(i)] = r.number(n[i], field + "[" + std::to_string(i) + "]");
            return v;
        }

        /** {axis: [x, y, z], angle: radians}: a rotation as the .cfg writes it (docs/worlds3d.md). */
        Eigen::Quaterniond rotation(const YamlReader &r, const YAML::Node &n, const std::string &field)
        {
            if (!n.IsMap())
                r.fail(n, field, "expected {axis: [x, y, z], angle: RADIANS}");
            r.allowKeys(n, field, {"axis", "angle"});
            const Eigen::Vector3d axis = vec3(r, r.require(n, "axis", field + ".axis"), field + ".axis");
            const double angle = r.number(r.require(n, "angle", field + ".angle"), field + ".angle");
            if (!(axis.norm() > 0.0))
                r.fail(n["axis"], field + ".axis", "the rotation axis must not be zero");
            return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
        }

        /** The only key of a one-key mapping {KIND: ...}, one of \e kinds. */
        std::string kindOf(const YamlReader &r, const YAML::Node &n, const std::string &field,
                           const std::set<std::string> &kinds, const std::string &expected)
        {
            if (!n.IsMap() || n.size() != 1)
                r.fail(n, field, "expected one of " + expected);
            r.allowKeys(n, field, kinds);
            return n.begin()->first.Scalar();
        }

        RigidPose pose(const YamlReader &r, const YAML::Node &n, const std::string &field, RigidSpace space)
        {
            RigidPose p;
            if (n.IsSequence())
            {
                p.position = vec3(r, n, field);
                return p;
            }
            if (!n.IsMap())
                r.fail(n, field,
                       space == RigidSpace::R3
                           ? "expected [x, y, z]"
                           : "expected [x, y, z] or {position: [x, y, z], axis: [x, y, z], "
                             "angle: RADIANS}");
            if (space == RigidSpace::R3)
                r.fail(n, field, "an R^3 world has no orientation: give [x, y, z] (or use 'space: se3')");
            r.allowKeys(n, field, {"position", "axis", "angle"});
            p.position = vec3(r, r.require(n, "position", field + ".position"), field + ".position");
            if (n["axis"].IsDefined() || n["angle"].IsDefined())
            {
                if (!n["axis"].IsDefined())
                    r.fail(n, field + ".axis", "missing (an orientation needs axis and angle)");
                if (!n["angle"].IsDefined())
                    r.fail(n, field + ".angle", "missing (an orientation needs axis and angle)");
                const Eigen::Vector3d axis = vec3(r, n["axis"], field + ".axis");
                if (!(axis.norm() > 0.0))
                    r.fail(n["axis"], field + ".axis", "the rotation axis must not be zero");
                p.orientation = Eigen::AngleAxisd(r.number(n["angle"], field + ".angle"), axis.normalized());
            }
            return p;
        }

        std::string resolve(const std::string &file, const std::string &worldFile)
        {
            const fs::path p(file);
            return p.is_absolute() ? file : (fs::path(worldFile).parent_path() / p).string();
        }
    } // namespace

    std::vector<std::pair<std::string, std::string>> World3d::meshFiles() const
    {
        std::vector<std::pair<std::string, std::string>> out;
        for (const auto &o : obstacles)
            if (o.kind == World3dObstacle::Kind::Mesh)
                out.emplace_back(file + ":" + std::to_string(o.line) + ": field '" + o.field + "'", o.file);
        if (robot == "mesh")
            out.emplace_back(file + ":" + std::to_string(robotLine) + ": field 'robot.mesh'", robotFile);
        return out;
    }

    bool isWorld3dFile(const std::string &path)
    {
        const std::string ext = fs::path(path).extension().string();
        if (ext != ".yaml" && ext != ".yml")
            return false;
        std::error_code ec;
        if (!fs::is_regular_file(path, ec))
            return false;
        try
        {
            const YAML::Node root = YAML::Load(readInputFile(path, kMaxYamlBytes, "world file"));
            if (!root.IsMap() || !root["space"].IsScalar())
                return false;
            const std::string s = root["space"].Scalar();
            return s == "r3" || s == "se3";
        }
        catch (const std::exception &)
        {
            return false; // the 2D reader reports what is wrong
        }
    }

    World3d parseWorld3d(const std::string &text, const std::string &fileName)
    {
        const YAML::Node root = loadYamlMapping(text, fileName, "3D world", kHelp);
        const YamlReader r(fileName);
        r.allowKeys(root, "(top level)",
                    {"name", "description", "source", "assumptions", "space", "bounds", "robot", "obstacles",
                     "queries", "motion_validator", "resolution", "threshold"});
        World3d w;
        w.file = fileName;
        w.name = root["name"].IsDefined() ? r.name(root["name"], "name") : fs::path(fileName).stem().string();
        if (root["description"].IsDefined())
            w.description = r.text(root["description"], "description");
        const std::string space = r.text(r.require(root, "space", "space"), "space");
        if (space == "r3")
            w.space = RigidSpace::R3;
        else if (space == "se3")
            w.space = RigidSpace::SE3;
        else
            r.fail(root["space"], "space",
                   "'" + space + "': a 3D world's space is r3 or se3 (docs/worlds3d.md)");

        const YAML::Node bounds = r.require(root, "bounds", "bounds");
        if (!bounds.IsMap())
            r.fail(bounds, "bounds", "expected {min: [x, y, z], max: [x, y, z]}");
        r.allowKeys(bounds, "bounds", {"min", "max"});
        const Eigen::Vector3d lo = vec3(r, r.require(bounds, "min", "bounds.min"), "bounds.min");
        const Eigen::Vector3d hi = vec3(r, r.require(bounds, "max", "bounds.max"), "bounds.max");
        for (int i = 0; i < 3; ++i)
            if (!(hi[i] > lo[i]))
                r.fail(bounds["max"], "bounds.max", "each coordinate must exceed bounds.min's");
        w.bounds = Eigen::AlignedBox3d(lo, hi);

        const YAML::Node robot = r.require(root, "robot", "robot");
        w.robot = kindOf(r, robot, "robot", {"point", "sphere", "mesh"},
                         "{point: {}}, {sphere: RADIUS} or {mesh: FILE}");
        w.robotLine = robot.Mark().line + 1;
        const YAML::Node rv = robot[w.robot];
        if (w.robot == "point")
        {
            if (!rv.IsNull() && !(rv.IsMap() && rv.size() == 0))
                r.fail(rv, "robot.point", "expected {} (a point has no parameters)");
        }
        else if (w.robot == "sphere")
        {
            w.robotRadius = r.number(rv, "robot.sphere");
            if (!(w.robotRadius > 0.0))
                r.fail(rv, "robot.sphere", "the radius must be > 0 (a point robot is {point: {}})");
        }
        else
            w.robotFile = resolve(r.nonEmptyText(rv, "robot.mesh"), fileName);

        const YAML::Node obstacles = r.require(root, "obstacles", "obstacles");
        if (!obstacles.IsSequence() || obstacles.size() == 0)
            r.fail(obstacles, "obstacles",
                   "expected a non-empty list of {box: ...}, {sphere: ...} or {mesh: FILE}");
        for (std::size_t i = 0; i < obstacles.size(); ++i)
        {
            const YAML::Node o = obstacles[i];
            const std::string f = "obstacles[" + std::to_string(i) + "]";
            World3dObstacle ob;
            const std::string kind = kindOf(r, o, f, {"box", "sphere", "mesh"},
                                            "{box: {center, size, rotation}}, {sphere: {center, radius}} or "
                                            "{mesh: FILE}");
            ob.field = f + "." + kind;
            const YAML::Node v = o[kind];
            ob.line = (v.Mark().line >= 0 ? v.Mark().line : o.Mark().line) + 1;
            if (kind == "box")
            {
                ob.kind = World3dObstacle::Kind::Box;
                if (!v.IsMap())
                    r.fail(v, ob.field,
                           "expected {center: [x, y, z], size: [x, y, z], rotation: {axis, angle}}");
                r.allowKeys(v, ob.field, {"center", "size", "rotation"});
                ob.pose.translation() =
                    vec3(r, r.require(v, "center", ob.field + ".center"), ob.field + ".center");
                ob.size = vec3(r, r.require(v, "size", ob.field + ".size"), ob.field + ".size");
                if (!(ob.size.minCoeff() > 0.0))
                    r.fail(v["size"], ob.field + ".size", "every edge length must be > 0");
                if (v["rotation"].IsDefined())
                    ob.pose.linear() = rotation(r, v["rotation"], ob.field + ".rotation").toRotationMatrix();
            }
            else if (kind == "sphere")
            {
                ob.kind = World3dObstacle::Kind::Sphere;
                if (!v.IsMap())
                    r.fail(v, ob.field, "expected {center: [x, y, z], radius: R}");
                r.allowKeys(v, ob.field, {"center", "radius"});
                ob.pose.translation() =
                    vec3(r, r.require(v, "center", ob.field + ".center"), ob.field + ".center");
                ob.radius = r.number(r.require(v, "radius", ob.field + ".radius"), ob.field + ".radius");
                if (!(ob.radius > 0.0))
                    r.fail(v["radius"], ob.field + ".radius", "must be > 0");
            }
            else
            {
                ob.kind = World3dObstacle::Kind::Mesh;
                ob.file = resolve(r.nonEmptyText(v, ob.field), fileName);
            }
            w.obstacles.push_back(std::move(ob));
        }

        const YAML::Node queries = r.require(root, "queries", "queries");
        if (!queries.IsSequence() || queries.size() == 0)
            r.fail(queries, "queries", "expected a non-empty list of {name, start, goal}");
        std::set<std::string> names;
        for (std::size_t i = 0; i < queries.size(); ++i)
        {
            const YAML::Node q = queries[i];
            World3dQuery query;
            query.field = "queries[" + std::to_string(i) + "]";
            if (!q.IsMap())
                r.fail(q, query.field, "expected {name: NAME, start: POSE, goal: POSE}");
            r.allowKeys(q, query.field, {"name", "start", "goal"});
            query.name = r.name(r.require(q, "name", query.field + ".name"), query.field + ".name");
            if (!names.insert(query.name).second)
                r.fail(q["name"], query.field + ".name", "'" + query.name + "' is given twice");
            query.start =
                pose(r, r.require(q, "start", query.field + ".start"), query.field + ".start", w.space);
            query.goal = pose(r, r.require(q, "goal", query.field + ".goal"), query.field + ".goal", w.space);
            query.startLine = q["start"].Mark().line + 1;
            query.goalLine = q["goal"].Mark().line + 1;
            w.queries.push_back(std::move(query));
        }

        if (root["motion_validator"].IsDefined())
        {
            w.motionValidator = r.text(root["motion_validator"], "motion_validator");
            if (w.motionValidator != "certified" && w.motionValidator != "discrete")
                r.fail(root["motion_validator"], "motion_validator", "expected certified or discrete");
        }
        if (root["resolution"].IsDefined())
        {
            w.resolution = r.number(root["resolution"], "resolution");
            if (!(w.resolution > 0.0))
                r.fail(root["resolution"], "resolution", "must be > 0 (metres)");
        }
        if (root["threshold"].IsDefined())
        {
            w.threshold = r.number(root["threshold"], "threshold");
            if (!(w.threshold >= 0.0))
                r.fail(root["threshold"], "threshold", "must be >= 0");
        }
        return w;
    }

    namespace
    {
        std::string num(double v)
        {
            std::ostringstream o;
            o.precision(17);
            o << v;
            return o.str();
        }

        std::string list(const Eigen::Vector3d &v)
        {
            return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
        }

        std::string quoted(const std::string &s)
        {
            std::string out = "\"";
            for (const char c : s)
                out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
            return out + "\"";
        }

        std::string rotationText(const Eigen::Quaterniond &q)
        {
            const Eigen::AngleAxisd a(q.normalized());
            return "{axis: " + list(a.axis()) + ", angle: " + num(a.angle()) + "}";
        }

        std::string poseText(const RigidPose &p, RigidSpace space)
        {
            if (space == RigidSpace::R3)
                return list(p.position);
            const Eigen::AngleAxisd a(p.orientation.normalized());
            return "{position: " + list(p.position) + ", axis: " + list(a.axis()) +
                   ", angle: " + num(a.angle()) + "}";
        }
    } // namespace

    std::string world3dYaml(const World3d &w)
    {
        std::ostringstream o;
        o << "name: " << quoted(w.name) << "\n";
        if (!w.description.empty())
            o << "description: " << quoted(w.description) << "\n";
        o << "space: " << toString(w.space) << "\n"
          << "bounds: {min: " << list(w.bounds.min()) << ", max: " << list(w.bounds.max()) << "}\n";
        if (w.robot == "point")
            o << "robot: {point: {}}\n";
        else if (w.robot == "sphere")
            o << "robot: {sphere: " << num(w.robotRadius) << "}\n";
        else
            o << "robot: {mesh: " << quoted(fs::absolute(w.robotFile).string()) << "}\n";
        o << "obstacles:\n";
        for (const auto &ob : w.obstacles)
        {
            if (ob.kind == World3dObstacle::Kind::Box)
                o << "  - box: {center: " << list(ob.pose.translation()) << ", size: " << list(ob.size)
                  << ", rotation: " << rotationText(Eigen::Quaterniond(ob.pose.linear())) << "}\n";
            else if (ob.kind == World3dObstacle::Kind::Sphere)
                o << "  - sphere: {center: " << list(ob.pose.translation()) << ", radius: " << num(ob.radius)
                  << "}\n";
            else
                o << "  - mesh: " << quoted(fs::absolute(ob.file).string()) << "\n";
        }
        o << "queries:\n";
        for (const auto &q : w.queries)
            o << "  - name: " << quoted(q.name) << "\n    start: " << poseText(q.start, w.space)
              << "\n    goal: " << poseText(q.goal, w.space) << "\n";
        if (w.motionValidator != "certified")
            o << "motion_validator: " << w.motionValidator << "\n";
        if (!std::isnan(w.resolution))
            o << "resolution: " << num(w.resolution) << "\n";
        o << "threshold: " << num(w.threshold) << "\n";
        return o.str();
    }

    CfgProblem world3dProblem(const std::shared_ptr<const World3d> &world, const std::string &query)
    {
        const World3d &w = *world;
        const World3dQuery *q = &w.queries.front();
        if (!query.empty())
        {
            q = nullptr;
            std::string names;
            for (const auto &c : w.queries)
            {
                if (c.name == query)
                    q = &c;
                names += (names.empty() ? "" : ", ") + c.name;
            }
            if (q == nullptr)
                throw InputError(w.file + ": no query '" + query + "'; the world has " + names);
        }
        CfgProblem c;
        c.file = w.file;
        c.name = w.queries.size() == 1 || query.empty() ? w.name : w.name + "_" + q->name;
        c.se3 = true;
        c.world3d = world;
        c.start = q->start;
        c.goal = q->goal;
        c.volume = w.bounds;
        c.threshold = w.threshold;
        c.motionValidator = w.motionValidator;
        c.resolution = w.resolution;
        c.lines["query"] = static_cast<int>(q - w.queries.data());
        return c;
    }

    LoadedCfgProblem loadWorld3dProblem(CfgProblem cfg, const MeshLimits &limits)
    {
        LoadedCfgProblem out;
        out.cfg = std::move(cfg);
        const CfgProblem &c = out.cfg;
        const World3d &w = *c.world3d;
        std::vector<SceneObstacle> scene;
        for (const auto &o : w.obstacles)
        {
            SceneObstacle s;
            s.pose = o.pose;
            if (o.kind == World3dObstacle::Kind::Box)
            {
                s.shape = MeshShape::box(o.size);
                s.drawn = boxTriangles(o.size, o.pose);
            }
            else if (o.kind == World3dObstacle::Kind::Sphere)
            {
                s.shape = MeshShape::sphere(o.radius);
                s.drawn = sphereTriangles(o.radius, o.pose.translation());
            }
            else
            {
                try
                {
                    s.drawn = readMesh(o.file, limits);
                    s.shape = std::make_shared<const MeshShape>(s.drawn);
                }
                catch (const InputError &e)
                {
                    failAt(w.file, o.line, o.field, e.what());
                }
            }
            scene.push_back(std::move(s));
        }
        MeshProblemSpec &s = out.spec;
        if (w.robot == "mesh")
        {
            TriangleMesh robot;
            try
            {
                robot = readMesh(w.robotFile, limits);
            }
            catch (const InputError &e)
            {
                failAt(w.file, w.robotLine, "robot.mesh", e.what());
            }
            s.model = std::make_shared<MeshRigidModel>(std::move(scene), robot, w.space);
        }
        else
            // A point robot is an FCL sphere of radius 0 (docs/worlds3d.md).
            s.model = std::make_shared<MeshRigidModel>(std::move(scene),
                                                       w.robot == "sphere" ? w.robotRadius : 0.0, w.space);
        s.volume = w.bounds;
        applyCfgSettings(c, s);
        // The query's poses: inside the bounds and free, else refused naming the query's line.
        const World3dQuery &q = w.queries.at(static_cast<std::size_t>(c.lines.at("query")));
        for (const auto &[what, pose] :
             {std::pair<const char *, const RigidPose *>{"start", &c.start}, {"goal", &c.goal}})
        {
            const int line = std::string(what) == "start" ? q.startLine : q.goalLine;
            const std::string field = q.field + "." + what;
            if (!w.bounds.contains(pose->position))
                failAt(w.file, line, field, "the position lies outside the bounds");
            if (s.model->collides(rigidPlacement(*pose, w.space)))
                failAt(w.file, line, field, "the robot is in collision there");
        }
        return out;
    }
} // namespace mhplan
