// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the string-keyed planner registry shared by the CLI, the benchmark driver and the tests (the
   generic class; the built-in planners are registered by the registry layer, mhplan/registry/Registry.h). */
#ifndef MHPLAN_PLANNER_REGISTRY_H
#define MHPLAN_PLANNER_REGISTRY_H

#include <ompl/base/Planner.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mhplan
{
    using PlannerAllocator = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &)>;

    /** \brief One registry entry. */
    struct PlannerEntry
    {
        std::string name;
        /** \brief "ompl" for OMPL's own planners, "mhplan" for this project's. */
        std::string origin;
        std::string description;
        PlannerAllocator allocate;
        /** \brief The family the tests classify the planner by: "population" (a PopulationPlanner: fixed
            waypoint encoding), "memetic" (variable-length feasible paths), "lattice" (grid searches),
            "walk" (robot walks on a potential field); empty for OMPL's planners. */
        std::string family{};
        /** \brief True for an improved variant (not in the paper); false for a faithful planner. */
        bool improved{false};
        /** \brief True when the planner solves problems in any R^k (k >= 1) and on the other state spaces
            docs/spaces.md lists (SE(2), Dubins, Reeds-Shepp, SE(3), compounds); false when it is planar only
            (it refuses other spaces at setup()). */
        bool anyDimension{false};
    };

    /** \brief The allocator of planner type \e P constructed as P(si). */
    template <typename P> PlannerAllocator allocatorFor()
    {
        return [](const ompl::base::SpaceInformationPtr &si) -> ompl::base::PlannerPtr
        { return std::make_shared<P>(si); };
    }

    /** \brief Planner name -> allocator: a generic registry, filled by whoever owns one. The built-in
        registry, every planner mhplan knows, belongs to the registry layer (builtinPlanners() in
        mhplan/registry/Registry.h); adding a planner is one line in its family's registration
        (ompl_planners/Registration.cpp). Campaigns, controllers and the CLI take the registry they are
        handed. */
    class PlannerRegistry
    {
      public:
        /** \brief Add an entry; throws std::invalid_argument if the name is taken. */
        void add(PlannerEntry entry);
        bool has(const std::string &name) const { return entries_.count(name) != 0; }
        /** \brief The entry for \e name; throws InputError listing every registered name. */
        const PlannerEntry &get(const std::string &name) const;
        std::vector<std::string> names() const;

        /** \brief Allocate planner \e name on \e si and apply \e params (applyPlannerParameters). */
        ompl::base::PlannerPtr create(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                      const std::map<std::string, std::string> &params = {}) const;

      private:
        std::map<std::string, PlannerEntry> entries_;
    };

    /** \brief Set parameters on a planner, refusing (InputError) an unknown name (the message lists the
        planner's parameters), a value that does not parse, or a value outside the declared range suggestion
        ("lo:step:hi", "lo:hi" or a comma-separated list). */
    void applyPlannerParameters(ompl::base::Planner &planner,
                                const std::map<std::string, std::string> &params);

    /** \brief Check \e value against an OMPL range suggestion; returns an empty string when it fits, else a
        description of what is accepted. */
    std::string checkAgainstRange(const std::string &value, const std::string &range);

    /** \brief Parse "key=value" into the map; throws InputError on a malformed item. */
    void parseKeyValue(const std::string &item, std::map<std::string, std::string> &out);
} // namespace mhplan

#endif
