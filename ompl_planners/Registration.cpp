// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/Registration.h"

#include "ompl_planners/field/ArtificialPotentialField.h"
#include "ompl_planners/field/BacterialForaging.h"
#include "ompl_planners/field/BacterialWalk.h"
#include "ompl_planners/lattice/AStar.h"
#include "ompl_planners/lattice/ThetaStar.h"
#include "ompl_planners/memetic/MemeticGenetic.h"
#include "ompl_planners/memetic/MemeticOffsetPlanners.h"
#include "ompl_planners/pagmo/PagmoPlanner.h"
#include "ompl_planners/population/Genetic.h"
#include "ompl_planners/population/GreyWolf.h"
#include "ompl_planners/population/LRSMA.h"
#include "ompl_planners/population/MountainGazelle.h"
#include "ompl_planners/population/ParticleSwarm.h"
#include "ompl_planners/population/SlimeMould.h"
#include "ompl_planners/population/Whale.h"

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief Iterations without improvement before the improved variants restart (anytime mode only:
            max_iterations = 0; see PopulationPlanner::setStagnationRestart). */
        constexpr unsigned int kAnytimeRestart = 30;

        /** \brief Improved variant (not in any paper): a population planner named \e name with the [GMS]
            repair, simplification and node improvement on every individual after each iteration, \e
            waypoints waypoints, polyline decoding when \e polyline, the fitness \c auto, anytime restarts. */
        template <typename P>
        PlannerAllocator operatorVariant(const std::string &name, unsigned int waypoints, bool polyline)
        {
            return [name, waypoints, polyline](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            {
                auto p = std::make_shared<P>(si, name);
                if (polyline)
                    p->setDecoding("polyline");
                p->setFitness("auto");
                GmsSettings gms;
                gms.repair = gms.simplify = gms.improve = gms.scopeAll = true;
                p->setGmsSettings(gms);
                p->setWaypoints(waypoints);
                p->setStagnationRestart(kAnytimeRestart);
                return p;
            };
        }

        /** \brief The faithful [GMS] version of a population algorithm (docs/algorithms.md 1.3, 1.5): the
            [GMS] fitness (maximised reciprocals), polyline decoding of 3 waypoints, node repair, line-segment
            repair and node improvement on the initial population and on new (replacement) individuals, and
            every iteration simplification and revision of every individual and replacement of the worst 10 %
            by fresh random individuals. */
        template <typename P> PlannerAllocator gmsFaithful(const std::string &name)
        {
            return [name](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            {
                auto p = std::make_shared<P>(si, name);
                p->setDecoding("polyline");
                p->setFitness("gms");
                GmsSettings gms;
                gms.initial = gms.revise = gms.simplify = gms.scopeAll = true;
                gms.replaceFraction = 0.1;
                p->setGmsSettings(gms);
                return p;
            };
        }
    } // namespace

    void registerMhplanPlanners(PlannerRegistry &r)
    {
        // One line each: name, origin, description, allocator, capabilities (cap::,
        // src/base/PlannerRegistry.h).
        r.add({"AStar", "mhplan",
               "A* on an 8-connected lattice (grid cells, MovingAI rules) (Hart et al. 1968)",
               allocatorFor<AStar>(), cap::Planar | cap::Deterministic});
        r.add({"ThetaStar", "mhplan", "Theta*, any-angle A* on the same lattice (Nash et al. 2007)",
               allocatorFor<ThetaStar>(), cap::Planar | cap::Deterministic});
        r.add({"BFO", "mhplan", "Bacterial foraging optimization, online APF walk (Passino 2002; [BFO])",
               allocatorFor<BacterialWalk>(), cap::Planar | cap::NeedsClearance});
        r.add({"ATBFO", "mhplan", "Adaptive-tumble bacterial foraging, online APF walk (Abbas & Ali 2016)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<BacterialWalk>(si, true); },
               cap::Planar | cap::NeedsClearance});
        r.add({"BFO-GLOBAL", "mhplan",
               "BFO searching whole paths (waypoint vectors, the population planners' fitness), improved "
               "variant (not in the paper: [BFO] walks online)",
               allocatorFor<BacterialForaging>(), cap::AllSpaces | cap::Anytime | cap::Improved});
        r.add({"ATBFO-GLOBAL", "mhplan",
               "ATBFO searching whole paths (waypoint vectors), improved variant (not in the paper: [BFO] "
               "walks "
               "online)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<BacterialForaging>(si, true); },
               cap::AllSpaces | cap::Anytime | cap::Improved});
        r.add({"APF", "mhplan", "Artificial potential field descent (Khatib 1986; [BFO] eqs 3-6)",
               allocatorFor<ArtificialPotentialField>(),
               cap::Planar | cap::NeedsClearance | cap::Deterministic});
        r.add({"SMA", "mhplan",
               "Slime mould algorithm as [LRSMA] compares it (Li et al. 2020; [LRSMA] 3, 5.2): spline, "
               "fitness S",
               allocatorFor<SlimeMould>(), cap::AllSpaces | cap::Anytime});
        r.add({"LRSMA", "mhplan", "Levy-flight-rotation slime mould algorithm (Zheng et al. 2023)",
               allocatorFor<LRSMA>(), cap::AllSpaces | cap::Anytime});
        r.add({"PSO", "mhplan",
               "Particle swarm optimization as [LRSMA] compares it (Kennedy & Eberhart 1995; c1 = c2 = 0.4, "
               "w = 1): spline, fitness S",
               allocatorFor<ParticleSwarm>(), cap::AllSpaces | cap::Anytime});
        r.add({"WOA", "mhplan",
               "Whale optimization algorithm as [LRSMA] compares it (Mirjalili & Lewis 2016; a from 2 to 0): "
               "spline, fitness S",
               allocatorFor<Whale>(), cap::Planar | cap::Anytime});
        r.add({"GWO", "mhplan",
               "Grey wolf optimizer as [LRSMA] compares it (Mirjalili et al. 2014; a from 2 to 0): spline, "
               "fitness S",
               allocatorFor<GreyWolf>(), cap::AllSpaces | cap::Anytime});
        r.add({"MGO", "mhplan", "Mountain gazelle optimizer, the original (Abdollahzadeh et al. 2022)",
               allocatorFor<MountainGazelle>(), cap::AllSpaces | cap::Anytime});
        r.add({"SMA-GMS", "mhplan",
               "Slime mould algorithm as [GMS] runs it: the six [GMS] operators, maximised [GMS] fitness",
               gmsFaithful<SlimeMould>("SMA-GMS"), cap::Planar | cap::Anytime});
        r.add({"MGO-GMS", "mhplan",
               "Mountain gazelle optimizer as [GMS] runs it: the six [GMS] operators, [GMS] fitness",
               gmsFaithful<MountainGazelle>("MGO-GMS"), cap::Planar | cap::Anytime});
        r.add({"SMA-OPS", "mhplan",
               "SMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               operatorVariant<SlimeMould>("SMA-OPS", 3, true), cap::Planar | cap::Anytime | cap::Improved});
        r.add(
            {"LRSMA-OPS", "mhplan",
             "LRSMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual, "
             "5 waypoints",
             operatorVariant<LRSMA>("LRSMA-OPS", 5, false), cap::Planar | cap::Anytime | cap::Improved});
        r.add({"MGO-OPS", "mhplan",
               "MGO, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               operatorVariant<MountainGazelle>("MGO-OPS", 3, true),
               cap::Planar | cap::Anytime | cap::Improved});
        r.add({"GA", "mhplan", "Genetic algorithm of [GMS] with its six operators and maximised fitness",
               allocatorFor<Genetic>(), cap::Planar | cap::Anytime});
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
               cap::Planar | cap::Anytime | cap::Improved});
        r.add({"GA-MEM", "mhplan",
               "GA, improved memetic variant (not in the paper): variable-length feasible paths from "
               "multi-resolution walks, path crossover, detour mutation, crowding, local search, restarts",
               allocatorFor<MemeticGenetic>(), cap::AllSpaces | cap::Anytime | cap::Improved});
        r.add(
            {"SMA-MEM", "mhplan",
             "SMA, improved memetic variant (not in the paper): the SMA update on normal offsets at stations "
             "along the best path, feasible decoding, local search, restarts",
             allocatorFor<MemeticSlimeMould>(), cap::AllSpaces | cap::Anytime | cap::Improved});
        r.add({"LRSMA-MEM", "mhplan",
               "LRSMA, improved memetic variant (not in the paper): SMA-MEM with LRSMA's Levy flight and "
               "rotation perturbation on station offsets",
               allocatorFor<MemeticLRSMA>(), cap::AllSpaces | cap::Anytime | cap::Improved});
        r.add(
            {"MGO-MEM", "mhplan",
             "MGO, improved memetic variant (not in the paper): the four gazelle moves on normal offsets at "
             "stations along the best path, feasible decoding, local search, restarts",
             allocatorFor<MemeticGazelle>(), cap::AllSpaces | cap::Anytime | cap::Improved});
        // pagmo2's single-objective, derivative-free algorithms, one planner each ("pagmo:de", ...; origin
        // "pagmo"; docs/algorithms.md 11).
        registerPagmoPlanners(r);
    }
} // namespace mhplan
