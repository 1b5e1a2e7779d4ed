/* mhplan: controllers for the simulator (Simulation.h): classic distributed APF, the adaptive APF of
   [MAPF], the online BFO/ATBFO-APF step of [BFO], and plan-then-follow with any registered planner. */
#ifndef MHPLAN_CONTROLLERS_H
#define MHPLAN_CONTROLLERS_H

#include "Simulation.h"

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The controller names makeController accepts: "dapf", "aapf", "bfo", "atbfo", and
        "plan:<PLANNER>" for every planner name of the planner registry (e.g. "plan:ThetaStar"). */
    std::vector<std::string> controllerNames();

    /** \brief A controller by name with its default parameters; throws InputError listing the accepted
        names for an unknown one. */
    ControllerPtr makeController(const std::string &name);
} // namespace mhplan

#endif
