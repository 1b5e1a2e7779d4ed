// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: a campaign's planners and controllers checked before any run, in throw-away processes. */
#include "benchmarks/ExperimentRuns.h"

#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/sim/Controllers.h"

#include <ompl/geometric/SimpleSetup.h>

namespace og = ompl::geometric;

namespace mhplan::bench::detail
{
    void validatePlanners(const Campaign &c, const PlannerRegistry &registry, const World &world,
                          const Query &query)
    {
        checkInChildProcess(
            [&]() -> std::string
            {
                const CollisionModelPtr model = makeCollisionModel(world, parseCollisionBackend(c.collision));
                const og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model);
                for (std::size_t i = 0; i < c.planners.size(); ++i)
                {
                    try
                    {
                        registry.create(c.planners[i].planner, ss->getSpaceInformation(),
                                        c.planners[i].params);
                    }
                    catch (const std::exception &ex)
                    {
                        return c.file + ": planners[" + std::to_string(i) + "] (" +
                               c.planners[i].displayName + "): " + ex.what();
                    }
                }
                return {};
            },
            "planners");
    }

    /** Check every controller and parameter of the simulations in a throw-away process (controllers may
        own planners and random number generators). Messages name the campaign file and line. */
    void validateControllers(const Campaign &c, const PlannerRegistry &registry)
    {
        checkInChildProcess(
            [&]() -> std::string
            {
                for (std::size_t si = 0; si < c.simulations.size(); ++si)
                    for (std::size_t ci = 0; ci < c.simulations[si].controllers.size(); ++ci)
                    {
                        const ControllerSpec &spec = c.simulations[si].controllers[ci];
                        try
                        {
                            const ControllerPtr controller = makeController(spec.controller, registry);
                            for (const auto &kv : spec.params)
                                controller->setParameter(kv.first, kv.second);
                        }
                        catch (const std::exception &ex)
                        {
                            return c.file + ":" + std::to_string(spec.line) + ": simulations[" +
                                   std::to_string(si) + "].controllers[" + std::to_string(ci) + "] (" +
                                   spec.displayName + "): " + ex.what();
                        }
                    }
                return {};
            },
            "controllers");
    }
} // namespace mhplan::bench::detail
