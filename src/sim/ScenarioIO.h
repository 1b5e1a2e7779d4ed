// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: reading scenario files (a world file extended with robots, moving obstacles and settings). */
#ifndef MHPLAN_SCENARIO_IO_H
#define MHPLAN_SCENARIO_IO_H

#include "src/sim/Simulation.h"

#include <string>

namespace mhplan
{
    /** \brief Load a scenario file (YAML, format in environments/README.md, "Scenario files"). Throws
        InputError naming the file, line and field on any problem (unknown keys, bad numbers, a robot start
        or a fixed goal out of bounds or inside a static obstacle, two robots overlapping at their start
        while both are present, a task assigned before its robot joins). */
    Scenario loadScenario(const std::string &path);

    /** \brief Parse a scenario from text; \e fileName is used in messages and to resolve relative paths. */
    Scenario parseScenarioYaml(const std::string &text, const std::string &fileName);
} // namespace mhplan

#endif
