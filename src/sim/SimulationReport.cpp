// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the metrics of a simulation run as `mhplan sim` prints them (see SimulationReport.h). */
#include "src/sim/SimulationReport.h"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>

namespace mhplan
{
    namespace
    {
        std::string metres(double v, int precision = 3)
        {
            if (std::isinf(v))
                return "-";
            std::ostringstream s;
            s << std::fixed << std::setprecision(precision) << v;
            return s.str();
        }
    } // namespace

    void printSimulationReport(std::ostream &out, const SimulationResult &r)
    {
        out << "\n"
            << std::left << std::setw(10) << "robot" << std::setw(11) << "status" << std::right
            << std::setw(11) << "time [s]" << std::setw(11) << "length [m]" << std::setw(14)
            << "clearance [m]" << std::setw(13) << "robot d [m]" << std::setw(12) << "collisions"
            << "\n";
        for (const RobotResult &rr : r.robots)
            out << std::left << std::setw(10) << rr.name << std::setw(11) << toString(rr.status) << std::right
                << std::setw(11) << metres(rr.traversalTime, 2) << std::setw(11) << metres(rr.pathLength)
                << std::setw(14) << metres(rr.minObstacleClearance) << std::setw(13)
                << metres(rr.minRobotDistance) << std::setw(12) << rr.collisions << "\n";

        out << "\nrobots:     " << r.done << " done, " << r.stuck << " stuck, " << r.unfinished
            << " unfinished (of " << r.robots.size() << ")\n";
        out << "flowtime:   " << metres(r.flowtime, 3) << " s" << (r.allDone ? "" : " (lower bound)") << "\n";
        out << "makespan:   " << metres(r.makespan, 3) << " s" << (r.allDone ? "" : " (lower bound)") << "\n";
        out << "collisions: " << r.collisions() << " (static " << r.staticCollisions << ", moving "
            << r.movingCollisions << ", robot-robot " << r.robotCollisions << ")\n";
        out << "min robot distance:       " << metres(r.minRobotDistance) << " m\n";
        out << "min obstacle clearance:   " << metres(r.minObstacleClearance) << " m\n";
        out << "simulated:  " << metres(r.simulatedTime, 2) << " s in " << r.steps << " steps ("
            << r.robotSteps << " robot-steps)\n";
        out << "wall time:  " << std::setprecision(4) << r.wallTime << " s (" << std::setprecision(0)
            << std::fixed << (r.wallTime > 0.0 ? static_cast<double>(r.robotSteps) / r.wallTime : 0.0)
            << " robot-steps/s)\n"
            << std::defaultfloat;
        if (!r.counters.empty())
        {
            out << "counters:  ";
            for (const auto &kv : r.counters)
                out << " " << kv.first << "=" << std::setprecision(10) << kv.second;
            out << "\n";
        }
    }
} // namespace mhplan
