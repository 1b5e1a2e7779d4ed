// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/CfgIO.h"

#include "src/base/World.h"
#include "src/io/InputFile.h"
#include "src/io/World3dIO.h"
#include "src/io/YamlReader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace mhplan
{
    namespace
    {
        std::string trim(const std::string &s)
        {
            const auto b = s.find_first_not_of(" \t\r");
            if (b == std::string::npos)
                return "";
            const auto e = s.find_last_not_of(" \t\r");
            return s.substr(b, e - b + 1);
        }

        std::string lower(std::string s)
        {
            std::transform(s.begin(), s.end(), s.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            return s;
        }

        const std::set<std::string> kPoseKeys = {"x", "y", "z", "theta", "axis.x", "axis.y", "axis.z"};

        /** The [problem] keys mhplan reads (besides start.*, goal.*, volume.*). */
        const std::set<std::string> kProblemKeys = {
            "name",    "world",           "robot",      "objective",     "objective.threshold", "threshold",
            "control", "solution_length", "statespace", "turningradius", "motion_validator",    "resolution"};
        const std::set<std::string> kBenchmarkKeys = {"time_limit", "mem_limit",  "run_count",
                                                      "output",     "save_paths", "simplify"};

        std::string joined(const std::set<std::string> &keys)
        {
            std::string out;
            for (const auto &k : keys)
                out += (out.empty() ? "" : ", ") + k;
            return out;
        }

        class Reader
        {
          public:
            Reader(const std::string &file) : file_(file) {}

            [[noreturn]] void fail(int line, const std::string &key, const std::string &msg) const
            {
                throw InputError(file_ + ":" + std::to_string(line) +
                                 (key.empty() ? "" : ": key '" + key + "'") + ": " + msg);
            }

            double number(const CfgValue &v, const std::string &key) const
            {
                const std::string s = trim(v.value);
                char *end = nullptr;
                errno = 0;
                const double d = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
                if (s.empty() || end != s.c_str() + s.size() || errno != 0 || !std::isfinite(d))
                    fail(v.line, key, "expected a finite number, got '" + v.value + "'");
                return d;
            }

          private:
            std::string file_;
        };
    } // namespace

    std::string CfgProblem::where(const std::string &key) const
    {
        const auto it = lines.find(key);
        return file + (it == lines.end() ? "" : ":" + std::to_string(it->second)) + ": key '" + key + "'";
    }

    CfgProblem parseCfg(const std::string &text, const std::string &fileName)
    {
        const Reader r(fileName);
        CfgProblem p;
        p.file = fileName;
        // Every (section, key) with its value and line; planner lines kept in order.
        std::map<std::string, CfgValue> problem, benchmark;
        std::map<std::string, CfgValue> pendingContext; // [planner] problem.KEY before any planner
        std::istringstream in(text);
        std::string raw, section;
        int lineNo = 0;
        while (std::getline(in, raw))
        {
            ++lineNo;
            const std::string line = trim(raw.substr(0, raw.find('#')));
            if (line.empty())
                continue;
            if (line.front() == '[')
            {
                if (line.back() != ']')
                    r.fail(lineNo, "", "a section header must be [NAME], got '" + line + "'");
                section = lower(trim(line.substr(1, line.size() - 2)));
                if (section != "problem" && section != "benchmark" && section != "planner")
                    r.fail(lineNo, "",
                           "unknown section [" + section + "]; accepted: [problem], [benchmark], [planner]");
                continue;
            }
            const auto eq = line.find('=');
            if (eq == std::string::npos || eq == 0)
                r.fail(lineNo, "", "expected KEY = VALUE, got '" + line + "'");
            if (section.empty())
                r.fail(lineNo, "", "a key before any section ([problem], [benchmark] or [planner])");
            const std::string key = trim(line.substr(0, eq));
            const CfgValue value{trim(line.substr(eq + 1)), lineNo};
            const std::string full = section + "." + key;
            if (section == "problem" || section == "benchmark")
            {
                auto &m = section == "problem" ? problem : benchmark;
                if (!m.emplace(key, value).second)
                    r.fail(lineNo, full,
                           "given twice (first on line " + std::to_string(m.at(key).line) + ")");
                p.lines[full] = lineNo;
                continue;
            }
            // [planner]: NAME=, NAME.PARAM=VALUE, NAME.name=DISPLAY, NAME.problem.KEY=VALUE,
            // problem.KEY=VALUE.
            const std::string lkey = lower(key);
            if (lkey.rfind("problem.", 0) == 0)
            {
                if (p.planners.empty())
                    pendingContext[key.substr(8)] = value;
                else
                    p.planners.back().context[key.substr(8)] = value;
                continue;
            }
            const auto dot = key.find('.');
            const std::string planner = lower(key.substr(0, dot));
            const auto lastOf = [&]() -> CfgPlannerInstance *
            {
                for (auto it = p.planners.rbegin(); it != p.planners.rend(); ++it)
                    if (it->name == planner)
                        return &*it;
                return nullptr;
            };
            CfgPlannerInstance *instance = dot == std::string::npos ? nullptr : lastOf();
            if (instance == nullptr)
            {
                p.planners.push_back({planner, lineNo, {}, pendingContext, ""});
                pendingContext.clear();
                instance = &p.planners.back();
                if (dot == std::string::npos && !value.value.empty())
                    p.notes.push_back(fileName + ":" + std::to_string(lineNo) + ": key '" + full +
                                      "': a planner line takes no value; '" + value.value + "' is not used");
            }
            if (dot == std::string::npos)
                continue;
            const std::string param = key.substr(dot + 1);
            if (param.empty())
                r.fail(lineNo, full, "expected PLANNER.PARAMETER");
            if (lower(param).rfind("problem.", 0) == 0)
                instance->context[param.substr(8)] = value;
            else if (param == "name")
                instance->displayName = value.value;
            else
                instance->params[param] = value;
        }

        // [problem]
        std::set<std::string> startKeys, goalKeys;
        for (const auto &[key, value] : problem)
        {
            const std::string full = "problem." + key;
            if (key.rfind("start.", 0) == 0 || key.rfind("goal.", 0) == 0)
            {
                const bool isStart = key[0] == 's';
                const std::string rest = key.substr(isStart ? 6 : 5);
                if (kPoseKeys.count(rest) == 0)
                    r.fail(value.line, full, "unknown pose key; accepted: " + joined(kPoseKeys));
                (isStart ? startKeys : goalKeys).insert(rest);
                continue;
            }
            if (key.rfind("volume.", 0) == 0)
            {
                static const std::set<std::string> vol = {"min.x", "min.y", "min.z",
                                                          "max.x", "max.y", "max.z"};
                if (vol.count(key.substr(7)) == 0)
                    r.fail(value.line, full, "unknown volume key; accepted: volume." + joined(vol));
                continue;
            }
            if (key == "control")
                r.fail(value.line, full,
                       "control-based problems ('" + value.value +
                           "') are not supported: mhplan plans geometric SE(2) and SE(3) rigid-body problems "
                           "only");
            if (kProblemKeys.count(key) == 0)
                p.context[key] = value; // OMPL.app's problem context: checked against OMPL at load
        }
        const auto need = [&](const std::string &key) -> const CfgValue &
        {
            const auto it = problem.find(key);
            if (it == problem.end())
                throw InputError(fileName + ": key 'problem." + key + "' is missing");
            return it->second;
        };
        p.name = problem.count("name") ? problem.at("name").value
                                       : std::filesystem::path(fileName).stem().string();
        const std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
        for (const char *which : {"world", "robot"})
        {
            const CfgValue &v = need(which);
            if (v.value.empty())
                r.fail(v.line, std::string("problem.") + which, "a mesh file name is needed");
            const std::filesystem::path mesh(v.value);
            (std::string(which) == "world" ? p.world : p.robot) =
                (mesh.is_absolute() ? mesh : folder / mesh).lexically_normal().string();
        }
        static const std::set<std::string> se3Keys = {"z", "axis.x", "axis.y", "axis.z"};
        std::size_t se3Count = 0;
        for (const auto &k : se3Keys)
            se3Count += startKeys.count(k) + goalKeys.count(k);
        p.se3 = se3Count > 0;
        if (p.se3 && se3Count != 2 * se3Keys.size())
            for (const char *pose : {"start", "goal"})
                for (const auto &k : se3Keys)
                    if ((std::string(pose) == "start" ? startKeys : goalKeys).count(k) == 0)
                        throw InputError(
                            fileName + ": key 'problem." + pose + "." + k +
                            "' is missing: an SE(3) problem (some z or axis keys are given) needs "
                            "x, y, z, theta and axis.x/y/z for start and goal");
        for (const char *pose : {"start", "goal"})
        {
            const std::string pre = std::string(pose) + ".";
            RigidPose &out = std::string(pose) == "start" ? p.start : p.goal;
            const double theta = r.number(need(pre + "theta"), "problem." + pre + "theta");
            out.position = {r.number(need(pre + "x"), "problem." + pre + "x"),
                            r.number(need(pre + "y"), "problem." + pre + "y"),
                            p.se3 ? r.number(need(pre + "z"), "problem." + pre + "z") : 0.0};
            Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
            if (p.se3)
            {
                axis = {r.number(need(pre + "axis.x"), "problem." + pre + "axis.x"),
                        r.number(need(pre + "axis.y"), "problem." + pre + "axis.y"),
                        r.number(need(pre + "axis.z"), "problem." + pre + "axis.z")};
                if (!(axis.norm() > 0.0))
                    r.fail(need(pre + "axis.x").line, "problem." + pre + "axis",
                           "the rotation axis is zero; give a direction (e.g. axis.z = 1)");
            }
            out.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(theta, axis.normalized()));
        }
        // The volume: all its keys (x, y, and z for SE(3)) or none.
        {
            std::vector<std::string> axes = {"x", "y"};
            if (p.se3)
                axes.push_back("z");
            std::vector<std::string> present, missing;
            for (const char *end : {"min.", "max."})
                for (const auto &a : axes)
                    (problem.count("volume." + std::string(end) + a) ? present : missing)
                        .push_back("problem.volume." + std::string(end) + a);
            if (!p.se3 && (problem.count("volume.min.z") || problem.count("volume.max.z")))
                p.notes.push_back(fileName +
                                  ": volume.min.z and volume.max.z are not used by an SE(2) problem");
            if (!present.empty() && !missing.empty())
                throw InputError(fileName + ": key '" + missing.front() +
                                 "' is missing: give the whole volume or none (then it is inferred from the "
                                 "environment)");
            if (missing.empty())
            {
                Eigen::Vector3d lo(0, 0, 0), hi(0, 0, 0);
                for (std::size_t i = 0; i < axes.size(); ++i)
                {
                    const std::string kmin = "volume.min." + axes[i], kmax = "volume.max." + axes[i];
                    lo[static_cast<int>(i)] = r.number(problem.at(kmin), "problem." + kmin);
                    hi[static_cast<int>(i)] = r.number(problem.at(kmax), "problem." + kmax);
                    if (!(lo[static_cast<int>(i)] < hi[static_cast<int>(i)]))
                        r.fail(problem.at(kmax).line, "problem." + kmax,
                               "must be greater than volume.min." + axes[i]);
                }
                p.volume = Eigen::AlignedBox3d(lo, hi);
            }
        }
        if (problem.count("threshold"))
        {
            p.threshold = r.number(problem.at("threshold"), "problem.threshold");
            if (!(p.threshold >= 0.0))
                r.fail(problem.at("threshold").line, "problem.threshold", "must be >= 0");
        }
        if (problem.count("objective"))
        {
            p.objective = problem.at("objective").value;
            if (p.objective != "length" && p.objective != "max_min_clearance")
                r.fail(problem.at("objective").line, "problem.objective",
                       "objective '" + p.objective +
                           "' is not supported; accepted: length, max_min_clearance");
        }
        for (const char *k : {"objective.threshold", "solution_length"})
            if (problem.count(k))
            {
                if (std::string(k) == "solution_length" && p.objective != "length")
                    r.fail(problem.at(k).line, "problem.solution_length",
                           "applies to the length objective only");
                if (!std::isnan(p.objectiveThreshold))
                    r.fail(problem.at(k).line, std::string("problem.") + k,
                           "objective.threshold and solution_length both set the objective's threshold");
                p.objectiveThreshold = r.number(problem.at(k), std::string("problem.") + k);
            }
        if (problem.count("statespace"))
        {
            // OMPL.app's names of the geometric spaces a rigid body plans in; the cars only in the plane.
            std::string s = lower(problem.at("statespace").value);
            s.erase(
                std::remove_if(s.begin(), s.end(), [](char c) { return c == '_' || c == '-' || c == ' '; }),
                s.end());
            if (!p.se3 && (s == "dubins" || s == "reedsshepp"))
                p.car = s == "dubins" ? "dubins" : "reeds_shepp";
            else if (s != (p.se3 ? "se3" : "se2"))
                r.fail(problem.at("statespace").line, "problem.statespace",
                       "state space '" + problem.at("statespace").value +
                           "' is not supported for this problem; " +
                           "accepted: " + (p.se3 ? "se3" : "se2, dubins, reedsshepp") +
                           " (the poses make it " + (p.se3 ? "SE(3)" : "SE(2)") + ")");
        }
        if (problem.count("turningradius"))
        {
            if (p.car.empty())
                r.fail(problem.at("turningradius").line, "problem.turningradius",
                       "only a car has a turning radius: add statespace = dubins or reedsshepp");
            p.turningRadius = r.number(problem.at("turningradius"), "problem.turningradius");
            if (!(p.turningRadius > 0.0) || !std::isfinite(p.turningRadius))
                r.fail(problem.at("turningradius").line, "problem.turningradius", "must be > 0 (metres)");
        }
        else if (!p.car.empty())
            p.notes.push_back(p.where("problem.statespace") +
                              ": no turningradius: OMPL's default turning radius 1 is used");
        if (problem.count("motion_validator"))
        {
            p.motionValidator = problem.at("motion_validator").value;
            if (p.motionValidator != "certified" && p.motionValidator != "discrete")
                r.fail(problem.at("motion_validator").line, "problem.motion_validator",
                       "expected certified or discrete (OMPL's DiscreteMotionValidator, as OMPL.app)");
        }
        if (problem.count("resolution"))
        {
            p.resolution = r.number(problem.at("resolution"), "problem.resolution");
            if (!(p.resolution > 0.0))
                r.fail(problem.at("resolution").line, "problem.resolution", "must be > 0");
        }

        // [benchmark]
        for (const auto &[key, value] : benchmark)
        {
            const std::string full = "benchmark." + key;
            if (kBenchmarkKeys.count(key) == 0)
                r.fail(value.line, full, "unknown key; accepted: " + joined(kBenchmarkKeys));
            if (key == "time_limit" || key == "mem_limit")
            {
                const double v = r.number(value, full);
                if (!(v > 0.0))
                    r.fail(value.line, full, "must be > 0");
                (key == "time_limit" ? p.timeLimit : p.memLimit) = v;
            }
            else if (key == "run_count")
            {
                const double v = r.number(value, full);
                if (v < 1 || v > 1e6 || v != std::floor(v))
                    r.fail(value.line, full, "expected an integer in [1, 1000000]");
                p.runCount = static_cast<unsigned>(v);
            }
            else if (key == "output")
                p.output = value.value;
            else if (key == "save_paths")
            {
                // OMPL.app reads the start of the value: "all...", "shortest..." or "best...", else none.
                const std::string v = lower(value.value);
                if (v.rfind("all", 0) == 0)
                    p.savePaths = "all";
                else if (v.rfind("shortest", 0) == 0 || v.rfind("best", 0) == 0)
                    p.savePaths = "shortest";
                else if (v.empty() || v == "none" || v == "0" || v == "false")
                    p.savePaths = "";
                else
                    r.fail(value.line, full, "expected all, shortest, best or none");
            }
            else if (key == "simplify")
            {
                const std::string v = lower(value.value);
                if (v == "1" || v == "true" || v == "yes")
                    p.simplify = true;
                else if (v == "0" || v == "false" || v == "no")
                    p.simplify = false;
                else
                    r.fail(value.line, full, "expected 0 or 1");
            }
        }
        if (p.memLimit)
            p.notes.push_back(
                p.where("benchmark.mem_limit") +
                ": recorded; mhplan bounds a run by time and by its own memory cap (docs/omplapp.md)");
        return p;
    }

    RigidSpace CfgProblem::space() const
    {
        if (world3d)
            return world3d->space;
        return se3 ? RigidSpace::SE3 : RigidSpace::SE2;
    }

    std::string CfgProblem::spaceName() const
    {
        return car.empty() ? toString(space()) : car;
    }

    std::string CfgProblem::spaceLabel() const
    {
        const RigidSpace s = space();
        if (s != RigidSpace::SE2)
            return s == RigidSpace::SE3 ? "SE(3)" : "R^3";
        return car == "dubins" ? "Dubins" : car == "reeds_shepp" ? "Reeds-Shepp" : "SE(2)";
    }

    CfgProblem loadCfg(const std::string &path, const std::string &query)
    {
        if (isWorld3dFile(path))
            return world3dProblem(std::make_shared<const World3d>(
                                      parseWorld3d(readInputFile(path, kMaxYamlBytes, "world file"), path)),
                                  query);
        if (!query.empty())
            throw InputError(path + ": a query ('" + query +
                             "') applies to 3D YAML worlds only; a .cfg file has one start and goal");
        // Only a regular file, at most kMaxCfgBytes (a FIFO or /dev/zero is refused, never read).
        return parseCfg(readInputFile(path, kMaxCfgBytes, "problem file"), path);
    }

    LoadedCfgProblem loadCfgProblem(const std::string &path, const MeshLimits &limits)
    {
        return loadCfgProblem(loadCfg(path), limits);
    }

    LoadedCfgProblem loadCfgProblem(CfgProblem cfg, const MeshLimits &limits)
    {
        if (cfg.world3d)
            return loadWorld3dProblem(std::move(cfg), limits);
        LoadedCfgProblem out;
        out.cfg = std::move(cfg);
        const CfgProblem &c = out.cfg;
        TriangleMesh world, robot;
        try
        {
            world = readMesh(c.world, limits);
        }
        catch (const InputError &e)
        {
            throw InputError(c.where("problem.world") + ": " + e.what());
        }
        try
        {
            robot = readMesh(c.robot, limits);
        }
        catch (const InputError &e)
        {
            throw InputError(c.where("problem.robot") + ": " + e.what());
        }
        MeshProblemSpec &s = out.spec;
        s.model = std::make_shared<MeshRigidModel>(world, robot, !c.se3);
        if (c.volume)
            s.volume = *c.volume;
        else
        {
            // OMPL.app: the environment's box, grown to hold the start and goal positions.
            s.volume = world.box();
            s.volume.extend(c.start.position);
            s.volume.extend(c.goal.position);
            if (!c.se3)
            {
                s.volume.min().z() = 0.0;
                s.volume.max().z() = 0.0;
            }
            for (int i = 0; i < (c.se3 ? 3 : 2); ++i)
                if (!(s.volume.max()[i] > s.volume.min()[i]))
                    throw InputError(
                        c.where("problem.world") +
                        ": the environment is flat along an axis; give the volume (volume.min.*, "
                        "volume.max.*)");
        }
        applyCfgSettings(c, s);
        return out;
    }

    void applyCfgSettings(const CfgProblem &c, MeshProblemSpec &s)
    {
        s.start = c.start;
        s.goal = c.goal;
        s.threshold = c.threshold;
        s.objective = c.objective;
        s.objectiveThreshold = c.objectiveThreshold;
        s.motionValidator = c.motionValidator;
        s.resolution = c.resolution;
        s.car = c.car;
        s.turningRadius = c.turningRadius;
        for (const auto &[key, value] : c.context)
            s.context[key] = value.value;
    }
} // namespace mhplan
