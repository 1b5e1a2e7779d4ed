// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: BFO / ATBFO as a global search over waypoint vectors (docs/algorithms.md 6.4), for comparison with
   the other population planners on their own terms. The online BFO of [BFO] is BacterialWalk. */
#ifndef MHPLAN_BACTERIAL_FORAGING_H
#define MHPLAN_BACTERIAL_FORAGING_H

#include "ompl_planners/common/PopulationPlanner.h"
#include "ompl_planners/field/BacterialColony.h"
#include "ompl_planners/field/ColonyParameters.h"

#include <memory>

namespace mhplan
{
    /** \brief Bacterial Foraging Optimization (Passino 2002) and ATBFO (Abbas & Ali 2016, [BFO]) over the
        waypoint encoding of docs/algorithms.md 1.1 with PopulationPlanner's fitness ([LRSMA] S on
        geometric worlds; parameters \c waypoints, \c decoding, \c fitness ...): registry names "BFO-GLOBAL"
        and "ATBFO-GLOBAL" (mhplan's adaptation, 6.4: [BFO] runs the colony online, see BacterialWalk).

        The colony is BacterialColony (6.1, 6.2) with the parameters of ColonyParameters; its S bacteria
        are the population (\c population_size, default 100). One planner iteration is one chemotactic step
        of the whole colony; after the Ned elimination-dispersal events the loops start again from the
        current colony (until the termination condition or \c max_iterations). Positions are clamped to the
        bounds; C (\c step_size) is absolute, in the units of each coordinate, so larger worlds want a larger
        step. Dispersal draws a uniform waypoint vector. An optimizing planner with intermediate solutions,
        as the other population planners, on the problems PopulationPlanner supports: R^k and the state
        spaces of docs/spaces.md (SE(2), Dubins, Reeds-Shepp, SE(3), compounds; polyline decoding there). No
        [GMS] operators: the colony does not expose a population to them. Progress properties as
       PopulationPlanner's
        (\c fitness \c evaluations counts J evaluations). */
    class BacterialForaging : public PopulationPlanner, public ColonyParameters
    {
      public:
        /** \brief "BFO-GLOBAL" (adaptive tumble off) or "ATBFO-GLOBAL" (adaptive tumble on by default). */
        BacterialForaging(const ompl::base::SpaceInformationPtr &si, bool adaptiveTumble = false);
        ~BacterialForaging() override;

      protected:
        bool initialisePopulation() override;
        bool iterate(unsigned int t) override;
        void clearPopulation() override;

      private:
        class Adapter;
        std::unique_ptr<Adapter> adapter_;
        BacterialColony colony_{colonySettings_};
    };
} // namespace mhplan

#endif
