// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the registration of mhplan's own planners, beside the planners. */
#ifndef MHPLAN_PLANNERS_REGISTRATION_H
#define MHPLAN_PLANNERS_REGISTRATION_H

#include "src/base/PlannerRegistry.h"

namespace mhplan
{
    /** \brief Add every mhplan planner (origin "mhplan") to \e registry: the lattice baselines, the potential
        field walks and bacterial foraging, and the population planners with their variants. */
    void registerMhplanPlanners(PlannerRegistry &registry);
} // namespace mhplan

#endif
