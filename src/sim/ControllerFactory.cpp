// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: controllers by name (see Controllers.h). */
#include "src/sim/Controllers.h"

#include "src/base/Parameters.h"
#include "src/sim/detail/Sensing.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <functional>
#include <iomanip>
#include <ostream>

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

    std::vector<ControllerParameterInfo> controllerParameters(const std::string &name,
                                                              const PlannerRegistry &registry)
    {
        const ControllerPtr c = makeController(name, registry);
        const auto *base = dynamic_cast<const ControllerBase *>(c.get());
        return base != nullptr ? base->parameterTable().describe() : std::vector<ControllerParameterInfo>{};
    }

    void printControllers(std::ostream &out, const std::vector<std::string> &names,
                          const PlannerRegistry &registry)
    {
        std::vector<std::string> list = names;
        std::string planExample;
        if (list.empty())
        {
            list = {"dapf", "aapf", "bfo", "atbfo"};
            if (!registry.names().empty())
                planExample = kPlanPrefix + registry.names().front();
        }
        auto print = [&](const std::string &title, const std::string &controller)
        {
            out << title << "\n";
            for (const ControllerParameterInfo &p : controllerParameters(controller, registry))
                out << "    " << std::left << std::setw(28) << p.name << " default " << std::setw(12)
                    << p.defaultValue << " range " << std::setw(16) << p.range << " " << p.description
                    << "\n";
        };
        for (const std::string &n : list)
        {
            print(n, n);
            if (n.compare(0, kPlanPrefix.size(), kPlanPrefix) == 0)
            {
                // The planner's own parameters, set with planner.<name>=value.
                auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
                space->setBounds(0.0, 1.0);
                auto si = std::make_shared<ompl::base::SpaceInformation>(space);
                ompl::msg::noOutputHandler();
                const ompl::base::PlannerPtr planner = registry.create(n.substr(kPlanPrefix.size()), si);
                ompl::msg::restorePreviousOutputHandler();
                std::map<std::string, std::string> values;
                planner->params().getParams(values);
                for (const auto &kv : values)
                    out << "    " << std::left << std::setw(28) << ("planner." + kv.first) << " default "
                        << std::setw(12) << kv.second << " range " << std::setw(16)
                        << planner->params()[kv.first].getRangeSuggestion() << " "
                        << parameterDescription(planner->params()[kv.first]) << "\n";
            }
        }
        if (!planExample.empty())
            print("plan:<PLANNER> (any planner of `mhplan planners`; planner.<name>=value sets the planner's "
                  "parameters)",
                  planExample);
    }
} // namespace mhplan
