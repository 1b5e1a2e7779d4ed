// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the built-in planner registry (OMPL's planners and mhplan's) and the helpers that draw from it. */
#ifndef MHPLAN_REGISTRY_REGISTRY_H
#define MHPLAN_REGISTRY_REGISTRY_H

#include "mhplan/base/PlannerRegistry.h"

namespace ompl::tools
{
    class Benchmark;
}

namespace mhplan
{
    /** \brief Add OMPL 1.5.2's geometric planners to \e registry (origin "ompl"), with OMPL.app's names as aliases. */
    void registerOmplPlanners(PlannerRegistry &registry);

    /** \brief Add every built-in planner to \e registry: OMPL's (registerOmplPlanners) and mhplan's
        (registerMhplanPlanners). builtinPlanners() is a registry filled by this. */
    void registerBuiltinPlanners(PlannerRegistry &registry);

    /** \brief The registry of all built-in planners (registerBuiltinPlanners; built on first use, then
        read-only, safe to read from several threads). */
    const PlannerRegistry &builtinPlanners();

    /** \brief SelfConfig-style factory: planner \e name from the built-in registry on \e si, with \e params
        applied (InputError for an unknown name, parameter or out-of-range value). */
    ompl::base::PlannerPtr allocatePlanner(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                           const std::map<std::string, std::string> &params = {});

    /** \brief Add planners to an existing OMPL benchmark in one call: by default every mhplan planner
        (origin "mhplan"); \e names may list any registered planner. Names are checked before anything is
        added. */
    void addPlannersToBenchmark(ompl::tools::Benchmark &benchmark,
                                const std::vector<std::string> &names = {});
} // namespace mhplan

#endif
