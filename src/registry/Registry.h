// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the built-in planner registry (OMPL's planners and mhplan's) and the helpers that draw from it. */
#ifndef MHPLAN_REGISTRY_REGISTRY_H
#define MHPLAN_REGISTRY_REGISTRY_H

#include "src/base/PlannerRegistry.h"

#include <map>
#include <string>
#include <vector>

namespace ompl::tools
{
    class Benchmark;
}

namespace mhplan
{
    /** \brief Add OMPL 1.5.2's geometric planners to \e registry (origin "ompl"), with OMPL.app's names as
     * aliases. */
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

    /** \brief One planner of addPlannersToBenchmark: a registered name (or alias), its parameters (as
        allocatePlanner takes them) and the name it gets in the benchmark (Planner::getName(), which OMPL's
        log and database record as "geometric_" + name; empty: the planner's own name). Two configurations of
        one planner need two display names, or their runs would merge in the database.

        Made from a text (implicitly, so that a list of texts is a list of planners) "NAME",
        "NAME[key=value,...]", "NAME@DISPLAY" or "NAME[key=value,...]@DISPLAY" (README, "Use from your OMPL
        program"; InputError naming the text and what is accepted when it is malformed), or from its three
        parts. The name and parameters are checked by addPlannersToBenchmark. */
    struct BenchmarkPlanner
    {
        std::string name;
        std::map<std::string, std::string> params;
        std::string displayName;

        BenchmarkPlanner() = default;
        BenchmarkPlanner(const char *text);        // NOLINT(google-explicit-constructor): a text is a planner
        BenchmarkPlanner(const std::string &text); // NOLINT(google-explicit-constructor)
        BenchmarkPlanner(std::string name, std::map<std::string, std::string> params,
                         std::string displayName = "");
    };

    /** \brief The BenchmarkPlanner of a text (see BenchmarkPlanner). */
    BenchmarkPlanner parseBenchmarkPlanner(const std::string &text);

    /** \brief Add planners to an existing OMPL benchmark in one call, each with its parameters and display
        name: addPlannersToBenchmark(b, {"SMA[population_size=60]@SMA-60", "RRTstar"}). Without a list, every
        mhplan planner (origin "mhplan") with its defaults. Every name and parameter is checked (on the
        benchmark's space) before anything is added: InputError for an unknown planner, parameter or
        out-of-range value, or a display name used twice. */
    void addPlannersToBenchmark(ompl::tools::Benchmark &benchmark,
                                const std::vector<BenchmarkPlanner> &planners = {});
} // namespace mhplan

#endif
