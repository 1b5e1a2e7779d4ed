// SPDX-License-Identifier: BSD-3-Clause
/* mhplan CLI: one function per subcommand, dispatched from main.cpp's command table. */
#ifndef MHPLAN_CLI_COMMANDS_H
#define MHPLAN_CLI_COMMANDS_H

#include "src/base/World.h"

#include <string>
#include <vector>

namespace mhplan::cli
{
    using Argv = std::vector<std::string>;

    int cmdPlan(const Argv &argv);
    int cmdGenerate(const Argv &argv);
    int cmdWorlds(const Argv &argv);
    int cmdPlanners(const Argv &argv);
    int cmdControllers(const Argv &argv);
    int cmdScenarios(const Argv &argv);
    int cmdCompare(const Argv &argv);
    int cmdBench(const Argv &argv);
    int cmdReport(const Argv &argv);
    int cmdScen(const Argv &argv);
    int cmdOptimum(const Argv &argv);
    int cmdSim(const Argv &argv);
    int cmdArena(const Argv &argv);
    /** \brief True when an argument names an OMPL.app problem file (.cfg) or a 3D YAML world (isWorld3dFile,
        docs/worlds3d.md): plan, bench and worlds hand it to
        cmdPlanCfg and cmdBenchCfg (CfgCommands.cpp, docs/omplapp.md). */
    bool isCfgArgument(const Argv &argv);
    int cmdPlanCfg(const Argv &argv);
    int cmdBenchCfg(const Argv &argv);

    /** \brief The directory of shipped worlds: $MHPLAN_ENVIRONMENTS, else the source tree's environments/. */
    std::string environmentsDir();
    /** \brief A world argument: an existing file path, or the name of a shipped world
     * (environments/NAME.yaml). */
    std::string resolveWorldPath(const std::string &arg);
    /** \brief A scenario argument: an existing file, or the name of a shipped scenario
        (environments/scenarios/NAME.yaml). */
    std::string resolveScenarioPath(const std::string &arg);
    /** \brief Every shipped world file (sorted). */
    std::vector<std::string> shippedWorldFiles();
} // namespace mhplan::cli

#endif
