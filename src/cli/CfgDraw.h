// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: pictures of OMPL.app problems (CfgDraw.cpp, docs/omplapp.md "Pictures"). */
#ifndef MHPLAN_CLI_CFG_DRAW_H
#define MHPLAN_CLI_CFG_DRAW_H

#include "src/cli/Commands.h"
#include "src/io/CfgIO.h"

#include <string>
#include <vector>

namespace mhplan::cli
{
    /** \brief Where to draw the robot along \e path: poses every max(1.5 reach, travel / 60) metres of the
        robot's travel as the space interpolates it, wherever it turned by 30 degrees since the last one,
        and the last pose. */
    std::vector<Eigen::Isometry3d> footprintPlacements(const MeshRigidModel &model,
                                                       const ompl::base::SpaceInformationPtr &si,
                                                       const ompl::geometric::PathGeometric &path);

    /** \brief The problem seen from above as SVG: the volume's x-y box, the environment's triangles
        projected (class "environment"), the robot at its start ("start") and goal ("goal"), and with \e path
        the path ("path") and the robot's footprint at footprintPlacements ("footprint"). */
    std::string cfgProblemSvg(const LoadedCfgProblem &p, const ompl::base::SpaceInformationPtr &si,
                              const ompl::geometric::PathGeometric *path);

    /** \brief `mhplan worlds PROBLEM.cfg ... [--json]`: the problems' meshes as the planner uses them. */
    int cmdWorldsCfg(const Argv &argv);
} // namespace mhplan::cli

#endif
