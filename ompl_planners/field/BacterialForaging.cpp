// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/BacterialForaging.h"

namespace ob = ompl::base;

namespace mhplan
{
    /** \brief The colony's view of the planner: the fitness, uniform waypoint vectors, the bounds and the
        termination condition. */
    class BacterialForaging::Adapter : public ColonyProblem
    {
      public:
        explicit Adapter(BacterialForaging &planner) : planner_(planner) {}
        double cost(const double *x) override { return planner_.evaluate(x); }
        void randomPosition(double *x) override { planner_.randomPosition(x); }
        void constrain(double *x) override { planner_.clampToBounds(x); }
        bool halt() override { return planner_.stopRequested(); }

      private:
        BacterialForaging &planner_;
    };

    BacterialForaging::BacterialForaging(const ob::SpaceInformationPtr &si, bool adaptiveTumble)
        : PopulationPlanner(si, adaptiveTumble ? "ATBFO-GLOBAL" : "BFO-GLOBAL",
                            PopulationDefaults{100, 30, 3, PathDecoding::Polyline}),
          ColonyParameters(adaptiveTumble), adapter_(std::make_unique<Adapter>(*this))
    {
        // BFO has no coefficient schedule: the base's schedule length T does not apply.
        params().remove("iterations");
        declareColonyParams(params());
    }

    BacterialForaging::~BacterialForaging() = default;

    bool BacterialForaging::initialisePopulation()
    {
        colony_.start(dimension(), getPopulationSize(), *adapter_);
        return colony_.evaluateAll(*adapter_);
    }

    bool BacterialForaging::iterate(unsigned int /*t*/)
    {
        return colony_.step(*adapter_, rng_) != BacterialColony::Step::Interrupted;
    }

    void BacterialForaging::clearPopulation()
    {
        colony_.reset();
    }
} // namespace mhplan
