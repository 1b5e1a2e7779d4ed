// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: controllers by name (see Controllers.h). */
#include "mhplan/sim/Controllers.h"

#include "mhplan/sim/detail/Sensing.h"

#include <functional>

#include <algorithm>
#include <cmath>

namespace mhplan
{
    using namespace detail;

    // ---------------------------------------------------------------------------------------------------
    // Names

    namespace
    {
        const std::map<std::string, std::function<ControllerPtr()>> &fieldControllers()
        {
            static const std::map<std::string, std::function<ControllerPtr()>> table = {
                {"dapf", [] { return std::make_shared<ApfController>(false); }},
                {"aapf", [] { return std::make_shared<ApfController>(true); }},
                {"bfo", [] { return std::make_shared<BfoController>(false); }},
                {"atbfo", [] { return std::make_shared<BfoController>(true); }}};
            return table;
        }

        const std::string kPlanPrefix = "plan:";
    } // namespace

    std::vector<std::string> controllerNames(const PlannerRegistry &registry)
    {
        std::vector<std::string> names = {"dapf", "aapf", "bfo", "atbfo"};
        for (const std::string &p : registry.names())
            names.push_back(kPlanPrefix + p);
        return names;
    }

    ControllerPtr makeController(const std::string &name, const PlannerRegistry &registry)
    {
        const auto it = fieldControllers().find(name);
        if (it != fieldControllers().end())
            return it->second();
        if (name.compare(0, kPlanPrefix.size(), kPlanPrefix) == 0 &&
            registry.has(name.substr(kPlanPrefix.size())))
            return std::make_shared<PlanFollowController>(name.substr(kPlanPrefix.size()), registry);
        std::string known;
        for (const std::string &n : controllerNames(registry))
            known += (known.empty() ? "" : ", ") + n;
        throw InputError("unknown controller '" + name + "'; known controllers: " + known);
    }
} // namespace mhplan
