// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: 3D YAML worlds (docs/worlds3d.md): boxes, spheres and meshes as obstacles, a point, sphere or mesh
   robot in R^3 or SE(3), read into the mesh problems' machinery (MeshProblemSpec, makeMeshSetup). */
#ifndef MHPLAN_WORLD3D_IO_H
#define MHPLAN_WORLD3D_IO_H

#include "src/io/CfgIO.h"

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief One obstacle as written: a solid box or sphere, or a mesh file (a surface). */
    struct World3dObstacle
    {
        enum class Kind
        {
            Box,
            Sphere,
            Mesh
        };
        Kind kind{Kind::Box};
        /** \brief Box: its centre and rotation; sphere: its centre. */
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
        Eigen::Vector3d size{Eigen::Vector3d::Zero()};
        double radius{0.0};
        /** \brief A mesh's file, resolved against the world file's folder. */
        std::string file;
        int line{0};
        /** \brief "obstacles[i].box" etc., for messages. */
        std::string field;
    };

    /** \brief One query: a start and a goal pose, and the lines they were on. */
    struct World3dQuery
    {
        std::string name;
        RigidPose start;
        RigidPose goal;
        int startLine{0};
        int goalLine{0};
        std::string field; // "queries[i]"
    };

    /** \brief A parsed 3D world (meshes not yet read). */
    struct World3d
    {
        std::string file;
        std::string name;
        std::string description;
        RigidSpace space{RigidSpace::R3};
        Eigen::AlignedBox3d bounds;
        /** \brief "point", "sphere" or "mesh". */
        std::string robot;
        double robotRadius{0.0};
        std::string robotFile;
        int robotLine{0};
        std::vector<World3dObstacle> obstacles;
        std::vector<World3dQuery> queries;
        std::string motionValidator{"certified"};
        double resolution{std::numeric_limits<double>::quiet_NaN()};
        double threshold{1e-6};

        /** \brief The mesh files it names (obstacles, then the robot), each with the field naming it
            ("FILE:LINE: field 'obstacles[2].mesh'"). */
        std::vector<std::pair<std::string, std::string>> meshFiles() const;
    };

    /** \brief True when \e path ends in .yaml or .yml and is a 3D world: a regular file whose top-level
        'space' is r3 or se3 (a malformed file counts when its text says so, so that its error is reported
        by the 3D reader). */
    bool isWorld3dFile(const std::string &path);

    /** \brief Parse a 3D world from text; InputError "FILE:LINE: field 'F': what" for unknown keys, wrong
        types, non-positive sizes, empty bounds, repeated query names, an orientation in an R^3 world. */
    World3d parseWorld3d(const std::string &text, const std::string &fileName);

    /** \brief The world as a 3D YAML world file that parseWorld3d reads back to the same world (mesh files
        as absolute paths; numbers with 17 significant digits; rotations as axis and angle). */
    std::string world3dYaml(const World3d &world);

    /** \brief The world's query \e query (empty: the first) as a problem of the mesh machinery: a CfgProblem
        whose world3d is set (loadCfgProblem reads its meshes, builds its scene and refuses a start or goal
        outside the bounds or in collision, naming the query's line). InputError names an unknown query. */
    CfgProblem world3dProblem(const std::shared_ptr<const World3d> &world, const std::string &query);

    /** \brief loadCfgProblem for a CfgProblem from world3dProblem. */
    LoadedCfgProblem loadWorld3dProblem(CfgProblem cfg, const MeshLimits &limits);
} // namespace mhplan

#endif
