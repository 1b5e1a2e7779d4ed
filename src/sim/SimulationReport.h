// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the per-robot and run metrics of a simulation run as `mhplan sim` prints them (also printed by the
   ROS world node of src/ros, so that both runs read alike). */
#ifndef MHPLAN_SIMULATION_REPORT_H
#define MHPLAN_SIMULATION_REPORT_H

#include "src/sim/Simulation.h"

#include <iosfwd>

namespace mhplan
{
    /** \brief Print the robots' table (status, traversal time, path length, clearance, robot distance,
        collisions) and the run's metrics (robots done, flowtime, makespan, collisions, distances, steps,
        wall time, controller counters). */
    void printSimulationReport(std::ostream &out, const SimulationResult &r);
} // namespace mhplan

#endif
