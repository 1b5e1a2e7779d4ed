// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/CfgWorlds.h"
#include "benchmarks/ExperimentRuns.h"

#include "src/collision/MeshRigidBody.h"
#include "src/io/InputFile.h"
#include "src/io/World3dIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <filesystem>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace fs = std::filesystem;

namespace mhplan::bench::detail
{
    void readCfgWorld(const YamlReader &r, const YAML::Node &entry, const std::string &field, WorldSpec &w)
    {
        r.allowKeys(entry, field, {"cfg"});
        w.cfg = r.nonEmptyText(entry["cfg"], field + ".cfg");
        w.line = entry.Mark().line + 1;
    }

    CfgInputs readCfgInputs(const std::string &cfgFile)
    {
        CfgInputs in;
        const bool world3d = isWorld3dFile(cfgFile);
        const std::string text = readInputFile(cfgFile, world3d ? kMaxYamlBytes : kMaxCfgBytes,
                                               world3d ? "world file" : "problem file");
        Fingerprint f;
        // The meshes it names, each with the place that names it: (where, file).
        std::vector<std::pair<std::string, std::string>> meshes;
        if (world3d)
        {
            // A 3D YAML world (docs/worlds3d.md): its first query, and every mesh it names.
            const auto w = std::make_shared<const World3d>(parseWorld3d(text, cfgFile));
            in.cfg = world3dProblem(w, "");
            f.add("world3d yaml v1\n");
            meshes = w->meshFiles();
        }
        else
        {
            in.cfg = parseCfg(text, cfgFile);
            f.add("omplapp cfg v1\n");
            meshes = {{in.cfg.where("problem.world"), in.cfg.world},
                      {in.cfg.where("problem.robot"), in.cfg.robot}};
        }
        f.add(text);
        // The meshes' bytes as they are on disk (at most MeshLimits' file size, as readMesh reads them).
        const MeshLimits limits;
        for (std::size_t i = 0; i < meshes.size(); ++i)
        {
            const auto &[where, file] = meshes[i];
            std::string bytes;
            try
            {
                bytes = readInputFile(file, limits.maxFileBytes, "mesh file");
            }
            catch (const InputError &e)
            {
                throw InputError(where + ": " + e.what());
            }
            const std::string key = world3d ? "mesh" + std::to_string(i) : (i == 0 ? "world" : "robot");
            f.add("\nmesh " + key + " " + std::to_string(bytes.size()) + "\n");
            f.add(bytes);
        }
        in.hash = f.hex();
        return in;
    }

    std::vector<std::size_t> inapplicablePlanners(const Campaign &campaign, unsigned space, std::size_t world,
                                                  const std::string &worldName)
    {
        std::vector<std::size_t> skipped;
        for (std::size_t pi = 0; pi < campaign.planners.size(); ++pi)
        {
            const PlannerSpec &p = campaign.planners[pi];
            const auto refusal = p.refusals.find(space);
            if (refusal == p.refusals.end())
                continue;
            if (!campaign.skipInapplicable)
                throw InputError(campaign.file + ":" + std::to_string(p.line) + ": planners[" +
                                 std::to_string(pi) + "] (" + p.displayName + ") on worlds[" +
                                 std::to_string(world) + "] '" + worldName + "': " + refusal->second +
                                 "; remove the pair, or add 'skip_inapplicable: true' to the campaign to "
                                 "skip such pairs (benchmarks/README.md)");
            skipped.push_back(pi);
        }
        return skipped;
    }

    void appendCfgExperiment(const Campaign &campaign, const WorldSpec &spec, std::size_t index,
                             const std::function<std::string(const std::string &)> &locate,
                             const std::string &common, std::set<std::string> &names,
                             std::vector<Experiment> &out)
    {
        const std::string where =
            campaign.file + ":" + std::to_string(spec.line) + ": worlds[" + std::to_string(index) + "].cfg: ";
        std::string file;
        CfgInputs inputs;
        try
        {
            file = locate(spec.cfg);
            inputs = readCfgInputs(file);
            const LoadedCfgProblem problem = loadCfgProblem(inputs.cfg);
            makeMeshSetup(problem.spec); // the start and goal inside the volume and free
        }
        catch (const InputError &e)
        {
            throw InputError(where + e.what());
        }
        const CfgProblem &cfg = inputs.cfg;
        for (char c : cfg.name)
            if (std::isspace(static_cast<unsigned char>(c)) || c == ';' || c == ',' || c == '"' || c == '\'')
                throw InputError(where + cfg.where("problem.name") + ": '" + cfg.name +
                                 "' cannot name an experiment: no blanks, ';', ',' or quotes (rename it)");
        Experiment e;
        e.index = out.size();
        e.cfg = true;
        e.name = cfg.name;
        e.worldFile = file;
        e.worldName = cfg.name;
        e.query = "cfg";
        e.runs = campaign.runs;
        const unsigned space = cfg.space() == RigidSpace::R3 ? cap::Rk
                               : cfg.se3                     ? cap::SE3
                               : cfg.car == "dubins"         ? cap::Dubins
                               : cfg.car == "reeds_shepp"    ? cap::ReedsShepp
                                                             : cap::SE2;
        e.skipped = inapplicablePlanners(campaign, space, index, cfg.name);
        if (!names.insert(e.name).second)
            throw InputError(where + "experiment '" + e.name +
                             "' appears twice (two problems of that name, or the file listed twice)");
        e.seed = deriveSeed(campaign.seed, e.name, 0);
        Fingerprint all;
        all.add(common);
        all.add("cfg " + inputs.hash + "\n");
        e.configHash = all.hex();
        e.inputHash = inputs.hash;
        out.push_back(std::move(e));
    }

    void prepareCfgExperiment(ExperimentSetup &xs)
    {
        const Experiment &e = *xs.experiment;
        // The .cfg and its meshes read and fingerprinted here; the meshes are then read by assimp from the
        // same files (a file replaced between the two reads is the one gap, as for any input file).
        CfgInputs inputs = readCfgInputs(e.worldFile);
        if (!e.inputHash.empty() && inputs.hash != e.inputHash)
            throw std::runtime_error(
                "'" + e.worldFile +
                "' or one of its meshes changed after the campaign "
                "started (fingerprint " +
                inputs.hash + ", expected " + e.inputHash +
                "); not run, so that no log mixes two versions of it: re-run the campaign");
        xs.mesh = std::make_shared<const LoadedCfgProblem>(loadCfgProblem(std::move(inputs.cfg)));
        xs.metricStep = 1e-3 * xs.mesh->spec.volume.diagonal().head(xs.mesh->cfg.se3 ? 3 : 2).norm();
        xs.optimumSeconds = 0.0;
    }

    std::string cfgRunProperties(const ExperimentSetup &xs, const ob::SpaceInformation &si,
                                 const og::PathGeometric &path, ompl::tools::Benchmark::RunProperties &run)
    {
        long contact = -1;
        const std::size_t poses = denseMeshPathCheck(*xs.mesh->spec.model, si, path, xs.metricStep, contact);
        run["path length REAL"] = num(path.length());
        run["collision free BOOLEAN"] = contact < 0 ? "1" : "0";
        run["dense check poses INTEGER"] = std::to_string(poses);
        double clearance = std::numeric_limits<double>::infinity(); // at the waypoints
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
            clearance = std::min(
                clearance, xs.mesh->spec.model->clearance(xs.mesh->spec.model->placement(path.getState(i))));
        run["waypoint clearance REAL"] = num(clearance);
        // A car's path is stored as driven: its curve sampled every eighth of the turning radius.
        og::PathGeometric driven(path);
        if (!xs.mesh->cfg.car.empty())
            driven.interpolate(static_cast<unsigned>(
                std::min(1e5, std::ceil(8.0 * path.length() / xs.mesh->cfg.turningRadius) + 1.0)));
        std::string out;
        for (std::size_t i = 0; i < driven.getStateCount(); ++i)
        {
            const ob::State *s = driven.getState(i);
            if (xs.mesh->cfg.space() == RigidSpace::R3)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                out += num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + ";";
            }
            else if (xs.mesh->cfg.se3)
            {
                const auto *p = s->as<ob::SE3StateSpace::StateType>();
                const auto &q = p->rotation();
                out += num(p->getX()) + " " + num(p->getY()) + " " + num(p->getZ()) + " " + num(q.w) + " " +
                       num(q.x) + " " + num(q.y) + " " + num(q.z) + ";";
            }
            else
            {
                const auto *p = s->as<ob::SE2StateSpace::StateType>();
                out += num(p->getX()) + " " + num(p->getY()) + " " + num(p->getYaw()) + ";";
            }
        }
        return out;
    }

    void cfgExperimentParameters(const ExperimentSetup &xs, std::map<std::string, std::string> &parameters)
    {
        const LoadedCfgProblem &p = *xs.mesh;
        const MeshRigidModel &model = *p.spec.model;
        parameters["world TEXT"] = p.cfg.name;
        parameters["world_file TEXT"] = fs::absolute(xs.experiment->worldFile).lexically_normal().string();
        parameters["world_type TEXT"] = p.cfg.world3d ? "world3d" : "omplapp";
        parameters["space TEXT"] = p.cfg.spaceName();
        if (!p.cfg.car.empty())
            parameters["turning_radius REAL"] = num(p.cfg.turningRadius);
        if (!p.cfg.world3d)
        {
            parameters["environment_mesh TEXT"] = fs::absolute(p.cfg.world).lexically_normal().string();
            parameters["robot_mesh TEXT"] = fs::absolute(p.cfg.robot).lexically_normal().string();
        }
        parameters["obstacle_count INTEGER"] =
            std::to_string(p.cfg.world3d ? model.obstacles().size() : model.environmentTriangles());
        parameters["robot_triangles INTEGER"] = std::to_string(model.robotTriangles());
        parameters["robot_reach REAL"] = num(model.reach());
        parameters["motion_validator TEXT"] = p.spec.motionValidator;
        parameters["objective TEXT"] = p.spec.objective;
        parameters["query TEXT"] = xs.experiment->query;
        std::ostringstream q;
        q.precision(9);
        const auto pose = [&](const RigidPose &r)
        {
            q << "(" << r.position.x() << "," << r.position.y();
            if (p.cfg.space() == RigidSpace::R3)
                q << "," << r.position.z();
            else if (p.cfg.se3)
                q << "," << r.position.z() << "|" << r.orientation.w() << "," << r.orientation.x() << ","
                  << r.orientation.y() << "," << r.orientation.z();
            else
                q << "," << 2.0 * std::atan2(r.orientation.z(), r.orientation.w());
            q << ")";
        };
        pose(p.spec.start);
        q << "->";
        pose(p.spec.goal);
        parameters["query_points TEXT"] = q.str();
    }
} // namespace mhplan::bench::detail
