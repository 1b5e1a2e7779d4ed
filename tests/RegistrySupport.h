// SPDX-License-Identifier: BSD-3-Clause
/* Test support: the planner lists of the tests, drawn from the built-in registry by family tag, so that a
   registered planner is tested because it is registered (no hand-written lists to keep in step). */
#ifndef MHPLAN_TESTS_REGISTRY_SUPPORT_H
#define MHPLAN_TESTS_REGISTRY_SUPPORT_H

#include "mhplan/registry/Registry.h"

#include <functional>
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

    /** \brief Faithful planners of family \e family. */
    inline std::vector<std::string> faithful(const std::string &family)
    {
        return mhplanPlanners([&](const PlannerEntry &e) { return e.family == family && !e.improved; },
                              "a faithful '" + family + "' planner");
    }

    /** \brief Every planner of family \e family. */
    inline std::vector<std::string> ofFamily(const std::string &family)
    {
        return mhplanPlanners([&](const PlannerEntry &e) { return e.family == family; },
                              "of family '" + family + "'");
    }

    /** \brief The entry's family, "" for a planner the registry does not know (never throws). */
    inline std::string familyOf(const std::string &name)
    {
        const PlannerRegistry &registry = builtinPlanners();
        return registry.has(name) ? registry.get(name).family : std::string();
    }
} // namespace mhplan::test

#endif
