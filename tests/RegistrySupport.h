// SPDX-License-Identifier: BSD-3-Clause
/* Test support: the planner lists of the tests, drawn from the built-in registry by declared
   capabilities (PlannerEntry::capabilities) and by the planner's class (familyOf), so that a
   registered planner is tested because it is registered (no hand-written lists to keep in step). */
#ifndef MHPLAN_TESTS_REGISTRY_SUPPORT_H
#define MHPLAN_TESTS_REGISTRY_SUPPORT_H

#include "ompl_planners/common/PopulationPlanner.h"
#include "ompl_planners/field/ArtificialPotentialField.h"
#include "ompl_planners/field/BacterialWalk.h"
#include "ompl_planners/lattice/LatticePlanner.h"
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "src/registry/Registry.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <functional>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhplan::test
{
    /** \brief The names of the built-in mhplan planners (origin "mhplan") whose entry satisfies \e keep;
        throws when none does (an empty parameter list would run no test and pass). */
    inline std::vector<std::string> mhplanPlanners(const std::function<bool(const PlannerEntry &)> &keep,
                                                   const std::string &what)
    {
        std::vector<std::string> out;
        const PlannerRegistry &registry = builtinPlanners();
        for (const std::string &name : registry.names())
            if (registry.get(name).origin == "mhplan" && keep(registry.get(name)))
                out.push_back(name);
        if (out.empty())
            throw std::logic_error("no registered mhplan planner is " + what);
        return out;
    }

    /** \brief The family a built-in planner's class belongs to, by a dynamic_cast on the allocated planner
        (on a plane, nothing solved): "population" (a PopulationPlanner: fixed waypoint encoding), "memetic"
        (variable-length feasible paths), "lattice" (grid searches), "walk" (robot walks on a potential
        field), "" for OMPL's planners and a name the registry does not know (never throws). */
    inline std::string familyOf(const std::string &name)
    {
        static std::map<std::string, std::string> cache;
        static std::mutex mutex;
        const std::lock_guard<std::mutex> lock(mutex);
        const auto it = cache.find(name);
        if (it != cache.end())
            return it->second;
        const PlannerRegistry &registry = builtinPlanners();
        std::string family;
        if (registry.has(name))
        {
            auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
            space->setBounds(0.0, 1.0);
            auto si = std::make_shared<ompl::base::SpaceInformation>(space);
            const ompl::base::PlannerPtr p = registry.get(name).allocate(si);
            if (dynamic_cast<const PopulationPlanner *>(p.get()) != nullptr)
                family = "population";
            else if (dynamic_cast<const MemeticPlanner *>(p.get()) != nullptr)
                family = "memetic";
            else if (dynamic_cast<const LatticePlanner *>(p.get()) != nullptr)
                family = "lattice";
            else if (dynamic_cast<const ArtificialPotentialField *>(p.get()) != nullptr ||
                     dynamic_cast<const BacterialWalk *>(p.get()) != nullptr)
                family = "walk";
        }
        cache[name] = family;
        return family;
    }

    /** \brief Faithful planners (no cap::Improved) of family \e family (familyOf). */
    inline std::vector<std::string> faithful(const std::string &family)
    {
        return mhplanPlanners([&](const PlannerEntry &e)
                              { return familyOf(e.name) == family && !e.has(cap::Improved); },
                              "a faithful '" + family + "' planner");
    }

    /** \brief Every planner of family \e family (familyOf). */
    inline std::vector<std::string> ofFamily(const std::string &family)
    {
        return mhplanPlanners([&](const PlannerEntry &e) { return familyOf(e.name) == family; },
                              "of family '" + family + "'");
    }
} // namespace mhplan::test

#endif
