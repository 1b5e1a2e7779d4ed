// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/Registration.h"

#include "mhplan/planners/field/ArtificialPotentialField.h"
#include "mhplan/planners/field/BacterialForaging.h"
#include "mhplan/planners/lattice/AStar.h"
#include "mhplan/planners/lattice/ThetaStar.h"
#include "mhplan/planners/memetic/MemeticGenetic.h"
#include "mhplan/planners/memetic/MemeticOffsetPlanners.h"
#include "mhplan/planners/population/Genetic.h"
#include "mhplan/planners/population/LRSMA.h"
#include "mhplan/planners/population/MountainGazelle.h"
#include "mhplan/planners/population/SlimeMould.h"

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief Iterations without improvement before the improved variants restart (anytime mode only:
            max_iterations = 0; see PopulationPlanner::setStagnationRestart). */
        constexpr unsigned int kAnytimeRestart = 30;

        // PlannerEntry::improved and PlannerEntry::anyDimension, named.
        constexpr bool kFaithful = false, kImproved = true;
        constexpr bool kPlanar = false, kAnyDimension = true;

        /** \brief A population planner named \e name with the [GMS] repair, simplification and node
            improvement on every individual after each iteration, and \e waypoints waypoints. */
        template <typename P> PlannerAllocator gmsVariant(const std::string &name, unsigned int waypoints)
        {
            return [name, waypoints](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            {
                auto p = std::make_shared<P>(si, name);
                p->setGmsRepair(true);
                p->setGmsSimplify(true);
                p->setGmsImprove(true);
                p->setGmsScope("all");
                p->setWaypoints(waypoints);
                p->setStagnationRestart(kAnytimeRestart);
                return p;
            };
        }
    } // namespace

    void registerMhplanPlanners(PlannerRegistry &r)
    {
        // One line each.
        r.add({"AStar", "mhplan",
               "A* on an 8-connected lattice (grid cells, MovingAI rules) (Hart et al. 1968)",
               allocatorFor<AStar>(), "lattice", kFaithful, kPlanar});
        r.add({"ThetaStar", "mhplan", "Theta*, any-angle A* on the same lattice (Nash et al. 2007)",
               allocatorFor<ThetaStar>(), "lattice", kFaithful, kPlanar});
        r.add({"BFO", "mhplan", "Bacterial foraging optimization, online APF walk (Passino 2002; [BFO])",
               allocatorFor<BacterialForaging>(), "walk", kFaithful, kPlanar});
        r.add({"ATBFO", "mhplan", "Adaptive-tumble bacterial foraging, online APF walk (Abbas & Ali 2016)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<BacterialForaging>(si, true); },
               "walk", kFaithful, kPlanar});
        r.add({"APF", "mhplan", "Artificial potential field descent (Khatib 1986; [BFO] eqs 3-6)",
               allocatorFor<ArtificialPotentialField>(), "walk", kFaithful, kPlanar});
        r.add({"SMA", "mhplan", "Slime mould algorithm (Li et al. 2020; [GMS], [LRSMA])",
               allocatorFor<SlimeMould>(), "population", kFaithful, kAnyDimension});
        r.add({"LRSMA", "mhplan", "Levy-flight-rotation slime mould algorithm (Zheng et al. 2023)",
               allocatorFor<LRSMA>(), "population", kFaithful, kAnyDimension});
        r.add({"MGO", "mhplan", "Mountain gazelle optimizer (Abdollahzadeh et al. 2022; [GMS])",
               allocatorFor<MountainGazelle>(), "population", kFaithful, kAnyDimension});
        r.add({"SMA-GMS", "mhplan",
               "SMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               gmsVariant<SlimeMould>("SMA-GMS", 3), "population", kImproved, kPlanar});
        r.add(
            {"LRSMA-GMS", "mhplan",
             "LRSMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual, "
             "5 waypoints",
             gmsVariant<LRSMA>("LRSMA-GMS", 5), "population", kImproved, kPlanar});
        r.add({"MGO-GMS", "mhplan",
               "MGO, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               gmsVariant<MountainGazelle>("MGO-GMS", 3), "population", kImproved, kPlanar});
        r.add({"GA", "mhplan", "Genetic algorithm with the [GMS] repair operators", allocatorFor<Genetic>(),
               "population", kFaithful, kPlanar});
        r.add({"GA-WALK", "mhplan",
               "GA, improved variant (not in the paper): initial and replacement individuals are random "
               "collision-free lattice walks",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               {
                   auto p = std::make_shared<Genetic>(si, "GA-WALK");
                   p->setInitialisation("walk");
                   p->setStagnationRestart(kAnytimeRestart);
                   return p;
               },
               "population", kImproved, kPlanar});
        r.add({"GA-MEM", "mhplan",
               "GA, improved memetic variant (not in the paper): variable-length feasible paths from "
               "multi-resolution walks, path crossover, detour mutation, crowding, local search, restarts",
               allocatorFor<MemeticGenetic>(), "memetic", kImproved, kPlanar});
        r.add(
            {"SMA-MEM", "mhplan",
             "SMA, improved memetic variant (not in the paper): the SMA update on normal offsets at stations "
             "along the best path, feasible decoding, local search, restarts",
             allocatorFor<MemeticSlimeMould>(), "memetic", kImproved, kPlanar});
        r.add({"LRSMA-MEM", "mhplan",
               "LRSMA, improved memetic variant (not in the paper): SMA-MEM with LRSMA's Levy flight and "
               "rotation perturbation on station offsets",
               allocatorFor<MemeticLRSMA>(), "memetic", kImproved, kPlanar});
        r.add(
            {"MGO-MEM", "mhplan",
             "MGO, improved memetic variant (not in the paper): the four gazelle moves on normal offsets at "
             "stations along the best path, feasible decoding, local search, restarts",
             allocatorFor<MemeticGazelle>(), "memetic", kImproved, kPlanar});
    }
} // namespace mhplan
