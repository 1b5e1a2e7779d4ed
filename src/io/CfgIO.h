// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: OMPL.app's benchmark configuration files (.cfg), read as OMPL.app's benchmark program reads them
   (docs/omplapp.md): the problem (meshes, start, goal, volume, objective), the benchmark's settings and the
   planner instances with their parameters. */
#ifndef MHPLAN_CFG_IO_H
#define MHPLAN_CFG_IO_H

#include "src/collision/MeshRigidBody.h"
#include "src/io/MeshIO.h"

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mhplan
{
    struct World3d;

    /** \brief A value of the file and the line it was on. */
    struct CfgValue
    {
        std::string value;
        int line{0};
    };

    /** \brief One planner instance of the [planner] section: OMPL.app's name as written (the registry
        resolves it), its parameters, its context (problem keys for this instance only) and display name. */
    struct CfgPlannerInstance
    {
        std::string name;
        int line{0};
        std::map<std::string, CfgValue> params;
        std::map<std::string, CfgValue> context;
        /** \brief From NAME.name=...; empty: the planner's own name. */
        std::string displayName;
    };

    /** \brief A parsed .cfg file (meshes not yet read). */
    struct CfgProblem
    {
        std::string file;
        std::string name;
        /** \brief Mesh paths, resolved against the file's folder. */
        std::string world;
        std::string robot;
        /** \brief False: SE(2) (no z or axis keys); true: SE(3), or R^3 for a 3D YAML world. */
        bool se3{false};
        /** \brief A 3D YAML world's problem (docs/worlds3d.md): its scene replaces world and robot; its space
            may be R^3 (translation only). Null for a .cfg file. */
        std::shared_ptr<const World3d> world3d;
        /** \brief The state space: se2, se3 or r3. */
        RigidSpace space() const;
        /** \brief "se2", "se3", "r3", "dubins" or "reeds_shepp". */
        std::string spaceName() const;
        /** \brief "SE(2)", "SE(3)", "R^3", "Dubins" or "Reeds-Shepp". */
        std::string spaceLabel() const;
        RigidPose start;
        RigidPose goal;
        /** \brief The volume when the file gives it; empty: inferred (loadCfgProblem). */
        std::optional<Eigen::AlignedBox3d> volume;
        std::string objective{"length"};
        double objectiveThreshold{std::numeric_limits<double>::quiet_NaN()};
        double threshold{1e-6};
        /** \brief statespace = dubins or reedsshepp (SE(2) problems): "dubins" or "reeds_shepp", turning with
            turningradius (default 1, OMPL's); empty: a rigid body in SE(2)/SE(3). */
        std::string car;
        double turningRadius{1.0};
        /** \brief mhplan's keys: motion_validator (certified, discrete) and resolution. */
        std::string motionValidator{"certified"};
        double resolution{std::numeric_limits<double>::quiet_NaN()};
        /** \brief The other [problem] keys (OMPL.app's context: space information parameters and sampler),
            applied to every planner instance (loadCfgProblem checks them). */
        std::map<std::string, CfgValue> context;

        // [benchmark]
        std::optional<double> timeLimit;
        std::optional<double> memLimit;
        std::optional<unsigned> runCount;
        std::string output;
        /** \brief "" (none), "all" or "shortest" ("best" is read as "shortest"). */
        std::string savePaths;
        bool simplify{true};

        std::vector<CfgPlannerInstance> planners;
        /** \brief Line of each key read (section.key), for messages. */
        std::map<std::string, int> lines;
        /** \brief What was accepted but has no effect, to be printed (e.g. the mem_limit). */
        std::vector<std::string> notes;

        /** \brief "FILE:LINE: key 'KEY'" for messages about \e key (file only when the key is absent). */
        std::string where(const std::string &key) const;
    };

    /** \brief Parse a .cfg from text; \e fileName names it in messages and its folder resolves mesh paths.
        Throws InputError "FILE:LINE: key 'KEY': ..." for: a line outside a section or not key=value, an
        unknown section or key (naming those accepted), a repeated key, a value that does not parse,
        a control-based problem (control=...), an objective mhplan does not have, missing start/goal keys,
        a partial volume, an SE(3) pose with only some of its z and axis keys, a zero rotation axis. */
    CfgProblem parseCfg(const std::string &text, const std::string &fileName);

    /** \brief The largest .cfg file read: 4 MiB (OMPL.app's are a few hundred bytes). */
    constexpr std::size_t kMaxCfgBytes = std::size_t{4} << 20;

    /** \brief Read and parse a .cfg file (a regular file of at most kMaxCfgBytes), or a 3D YAML world
        (isWorld3dFile, docs/worlds3d.md) as the problem of its query \e query (empty: the first; a query
        given for a .cfg is refused). */
    CfgProblem loadCfg(const std::string &path, const std::string &query = "");

    /** \brief The problem with its meshes read: the OMPL set-up's specification. The volume, when the file
        has none, is the environment's box (x, y and, for SE(3), z) grown to hold the start and goal
        positions, as OMPL.app infers it. Mesh errors name the .cfg file, line and key. */
    struct LoadedCfgProblem
    {
        CfgProblem cfg;
        MeshProblemSpec spec;
    };
    LoadedCfgProblem loadCfgProblem(const std::string &path, const MeshLimits &limits = {});
    /** \brief The same for a problem already parsed (parseCfg). */
    LoadedCfgProblem loadCfgProblem(CfgProblem cfg, const MeshLimits &limits = {});

    /** \brief Copy the problem's settings (start, goal, threshold, objective, motion validator, resolution,
        car, context) into \e spec; the model and the volume are the caller's. */
    void applyCfgSettings(const CfgProblem &cfg, MeshProblemSpec &spec);
} // namespace mhplan

#endif
