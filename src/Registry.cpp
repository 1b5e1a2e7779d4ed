#include "Registry.h"

#include "World.h"
#include "SlimeMould.h"
#include "LRSMA.h"
#include "MountainGazelle.h"
#include "Genetic.h"
#include "MemeticGenetic.h"
#include "MemeticOffsetPlanners.h"
#include "BacterialForaging.h"
#include "ArtificialPotentialField.h"
#include "AStar.h"
#include "ThetaStar.h"

#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/stride/STRIDE.h>

#include <ompl/tools/benchmark/Benchmark.h>

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    namespace
    {
        /** \brief Iterations without improvement before the improved variants restart (anytime mode only:
            max_iterations = 0; see PopulationPlanner::setStagnationRestart). */
        constexpr unsigned int kAnytimeRestart = 30;

        template <typename P> PlannerAllocator omplAllocator()
        {
            return [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            { return std::make_shared<P>(si); };
        }

        /** \brief A population planner named \e name with the [GMS] repair, simplification and node
            improvement on every individual after each iteration, and \e waypoints waypoints. */
        template <typename P> PlannerAllocator gmsVariant(const std::string &name, unsigned int waypoints)
        {
            return [name, waypoints](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            {
                auto p = std::make_shared<P>(si, name);
                p->setGmsRepair(1);
                p->setGmsSimplify(1);
                p->setGmsImprove(1);
                p->setGmsScope("all");
                p->setWaypoints(waypoints);
                p->setStagnationRestart(kAnytimeRestart);
                return p;
            };
        }

        bool parseDouble(const std::string &s, double &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            out = std::strtod(s.c_str(), &end);
            return errno == 0 && end == s.c_str() + s.size();
        }

        std::vector<std::string> split(const std::string &s, char sep)
        {
            std::vector<std::string> out;
            std::stringstream ss(s);
            std::string item;
            while (std::getline(ss, item, sep))
                out.push_back(item);
            return out;
        }
    } // namespace

    void registerBuiltinPlanners(PlannerRegistry &r)
    {
        // OMPL's geometric planners that make sense in 2D.
        r.add({"RRT", "ompl", "Rapidly-exploring random tree (LaValle 1998)", omplAllocator<og::RRT>()});
        r.add({"RRTConnect", "ompl", "Bidirectional RRT (Kuffner & LaValle 2000)",
               omplAllocator<og::RRTConnect>()});
        r.add({"RRTstar", "ompl", "Asymptotically optimal RRT* (Karaman & Frazzoli 2011)",
               omplAllocator<og::RRTstar>()});
        r.add({"InformedRRTstar", "ompl", "Informed RRT* (Gammell et al. 2014)",
               omplAllocator<og::InformedRRTstar>()});
        r.add({"SORRTstar", "ompl", "Sorted informed RRT* (Gammell et al. 2018)",
               omplAllocator<og::SORRTstar>()});
        r.add({"PRM", "ompl", "Probabilistic roadmap (Kavraki et al. 1996)", omplAllocator<og::PRM>()});
        r.add({"PRMstar", "ompl", "Asymptotically optimal PRM* (Karaman & Frazzoli 2011)",
               omplAllocator<og::PRMstar>()});
        r.add({"LazyPRMstar", "ompl", "Lazy PRM* (Bohlin & Kavraki 2000)", omplAllocator<og::LazyPRMstar>()});
        // OMPL reserves the name "BITstar" for the r-disc variant and renames its default k-nearest one.
        r.add({"BITstar", "ompl", "Batch informed trees, k-nearest (Gammell et al. 2015)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<og::BITstar>(si, "kBITstar"); }});
        r.add({"ABITstar", "ompl", "Advanced BIT* (Strub & Gammell 2020)", omplAllocator<og::ABITstar>()});
        r.add({"AITstar", "ompl", "Adaptively informed trees (Strub & Gammell 2020)",
               omplAllocator<og::AITstar>()});
        r.add({"FMTstar", "ompl", "Fast marching tree (Janson et al. 2015)", omplAllocator<og::FMT>()});
        r.add({"BFMTstar", "ompl", "Bidirectional FMT* (Starek et al. 2015)", omplAllocator<og::BFMT>()});
        r.add({"KPIECE1", "ompl",
               "Kinodynamic planning by interior-exterior cell exploration (Sucan & Kavraki)",
               omplAllocator<og::KPIECE1>()});
        r.add({"EST", "ompl", "Expansive space trees (Hsu et al. 1997)", omplAllocator<og::EST>()});
        r.add({"SBL", "ompl", "Single-query bidirectional lazy planner (Sanchez & Latombe 2003)",
               omplAllocator<og::SBL>()});
        r.add({"STRIDE", "ompl",
               "Search tree with resolution independent density estimation (Gipson et al. 2013)",
               omplAllocator<og::STRIDE>()});
        // mhplan's planners: one line each (see ompl_planners/).
        r.add({"AStar", "mhplan",
               "A* on an 8-connected lattice (grid cells, MovingAI rules) (Hart et al. 1968)",
               omplAllocator<AStar>()});
        r.add({"ThetaStar", "mhplan", "Theta*, any-angle A* on the same lattice (Nash et al. 2007)",
               omplAllocator<ThetaStar>()});
        r.add({"BFO", "mhplan", "Bacterial foraging optimization, online APF walk (Passino 2002; [BFO])",
               omplAllocator<BacterialForaging>()});
        r.add({"ATBFO", "mhplan", "Adaptive-tumble bacterial foraging, online APF walk (Abbas & Ali 2016)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<BacterialForaging>(si, true); }});
        r.add({"APF", "mhplan", "Artificial potential field descent (Khatib 1986; [BFO] eqs 3-6)",
               omplAllocator<ArtificialPotentialField>()});
        r.add({"SMA", "mhplan", "Slime mould algorithm (Li et al. 2020; [GMS], [LRSMA])",
               omplAllocator<SlimeMould>()});
        r.add({"LRSMA", "mhplan", "Levy-flight-rotation slime mould algorithm (Zheng et al. 2023)",
               omplAllocator<LRSMA>()});
        r.add({"MGO", "mhplan", "Mountain gazelle optimizer (Abdollahzadeh et al. 2022; [GMS])",
               omplAllocator<MountainGazelle>()});
        r.add({"SMA-GMS", "mhplan",
               "SMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               gmsVariant<SlimeMould>("SMA-GMS", 3)});
        r.add(
            {"LRSMA-GMS", "mhplan",
             "LRSMA, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual, "
             "5 waypoints",
             gmsVariant<LRSMA>("LRSMA-GMS", 5)});
        r.add({"MGO-GMS", "mhplan",
               "MGO, improved variant (not in the paper): [GMS] repair/simplify/improve on every individual",
               gmsVariant<MountainGazelle>("MGO-GMS", 3)});
        r.add(
            {"GA", "mhplan", "Genetic algorithm with the [GMS] repair operators", omplAllocator<Genetic>()});
        r.add({"GA-WALK", "mhplan",
               "GA, improved variant (not in the paper): initial and replacement individuals are random "
               "collision-free lattice walks",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               {
                   auto p = std::make_shared<Genetic>(si, "GA-WALK");
                   p->setInitialisation("walk");
                   p->setStagnationRestart(kAnytimeRestart);
                   return p;
               }});
        r.add({"GA-MEM", "mhplan",
               "GA, improved memetic variant (not in the paper): variable-length feasible paths from "
               "multi-resolution walks, path crossover, detour mutation, crowding, local search, restarts",
               omplAllocator<MemeticGenetic>()});
        r.add(
            {"SMA-MEM", "mhplan",
             "SMA, improved memetic variant (not in the paper): the SMA update on normal offsets at stations "
             "along the best path, feasible decoding, local search, restarts",
             omplAllocator<MemeticSlimeMould>()});
        r.add({"LRSMA-MEM", "mhplan",
               "LRSMA, improved memetic variant (not in the paper): SMA-MEM with LRSMA's Levy flight and "
               "rotation perturbation on station offsets",
               omplAllocator<MemeticLRSMA>()});
        r.add(
            {"MGO-MEM", "mhplan",
             "MGO, improved memetic variant (not in the paper): the four gazelle moves on normal offsets at "
             "stations along the best path, feasible decoding, local search, restarts",
             omplAllocator<MemeticGazelle>()});
    }

    const PlannerRegistry &PlannerRegistry::builtin()
    {
        static const PlannerRegistry registry = []
        {
            PlannerRegistry r;
            registerBuiltinPlanners(r);
            return r;
        }();
        return registry;
    }

    void PlannerRegistry::add(PlannerEntry entry)
    {
        if (entry.name.empty() || !entry.allocate)
            throw std::invalid_argument("planner registry: an entry needs a name and an allocator");
        const std::string name = entry.name;
        if (!entries_.emplace(name, std::move(entry)).second)
            throw std::invalid_argument("planner registry: '" + name + "' is registered twice");
    }

    const PlannerEntry &PlannerRegistry::get(const std::string &name) const
    {
        const auto it = entries_.find(name);
        if (it != entries_.end())
            return it->second;
        std::ostringstream msg;
        msg << "unknown planner '" << name << "'; registered planners:";
        for (const auto &n : names())
            msg << " " << n;
        throw InputError(msg.str());
    }

    std::vector<std::string> PlannerRegistry::names() const
    {
        std::vector<std::string> out;
        for (const auto &kv : entries_)
            out.push_back(kv.first);
        return out;
    }

    ob::PlannerPtr PlannerRegistry::create(const std::string &name, const ob::SpaceInformationPtr &si,
                                           const std::map<std::string, std::string> &params) const
    {
        ob::PlannerPtr planner = get(name).allocate(si);
        applyPlannerParameters(*planner, params);
        return planner;
    }

    std::string checkAgainstRange(const std::string &value, const std::string &range)
    {
        if (range.empty())
            return "";
        if (range.find(':') != std::string::npos)
        {
            const std::vector<std::string> parts = split(range, ':');
            double lo = 0.0, hi = 0.0, v = 0.0;
            if ((parts.size() != 2 && parts.size() != 3) || !parseDouble(parts.front(), lo) ||
                !parseDouble(parts.back(), hi))
                return ""; // not a numeric range: nothing to enforce
            if (!parseDouble(value, v))
                return "a number in [" + parts.front() + ", " + parts.back() + "]";
            if (v < lo || v > hi)
                return "a number in [" + parts.front() + ", " + parts.back() + "]";
            return "";
        }
        const std::vector<std::string> options = split(range, ',');
        for (const auto &o : options)
            if (o == value)
                return "";
        // Booleans are declared as "0,1"; accept the usual spellings too.
        if (range == "0,1" && (value == "true" || value == "false"))
            return "";
        return "one of {" + range + "}";
    }

    void applyPlannerParameters(ob::Planner &planner, const std::map<std::string, std::string> &params)
    {
        ob::ParamSet &ps = planner.params();
        for (const auto &kv : params)
        {
            if (!ps.hasParam(kv.first))
            {
                std::ostringstream msg;
                msg << "planner '" << planner.getName() << "' has no parameter '" << kv.first
                    << "'; its parameters:";
                std::vector<std::string> names;
                ps.getParamNames(names);
                if (names.empty())
                    msg << " (none)";
                for (const auto &n : names)
                    msg << " " << n;
                throw InputError(msg.str());
            }
            const std::string range = ps[kv.first].getRangeSuggestion();
            // The planner's own current value is always accepted (some OMPL defaults sit outside their
            // declared range suggestion, e.g. PRM's max_nearest_neighbors).
            const std::string problem =
                kv.second == ps[kv.first].getValue() ? std::string() : checkAgainstRange(kv.second, range);
            if (!problem.empty())
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first + "': value '" +
                                 kv.second + "' is out of range; expected " + problem);
            std::string value = kv.second;
            if (range == "0,1" && (value == "true" || value == "false"))
                value = value == "true" ? "1" : "0";
            bool ok = false;
            try
            {
                ok = ps.setParam(kv.first, value);
            }
            catch (const std::invalid_argument &e)
            {
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first +
                                 "': " + e.what());
            }
            if (!ok)
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first +
                                 "': cannot set value '" + kv.second + "'" +
                                 (range.empty() ? "" : " (expected " + range + ")"));
        }
    }

    void parseKeyValue(const std::string &item, std::map<std::string, std::string> &out)
    {
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("expected key=value, got '" + item + "'");
        out[item.substr(0, eq)] = item.substr(eq + 1);
    }

    ob::PlannerPtr allocatePlanner(const std::string &name, const ob::SpaceInformationPtr &si,
                                   const std::map<std::string, std::string> &params)
    {
        return PlannerRegistry::builtin().create(name, si, params);
    }

    void addPlannersToBenchmark(ompl::tools::Benchmark &benchmark, const std::vector<std::string> &names)
    {
        const PlannerRegistry &reg = PlannerRegistry::builtin();
        std::vector<std::string> chosen = names;
        if (chosen.empty())
            for (const auto &n : reg.names())
                if (reg.get(n).origin == "mhplan")
                    chosen.push_back(n);
        for (const auto &n : chosen)
            reg.get(n); // refuse unknown names before adding anything
        for (const auto &n : chosen)
            benchmark.addPlannerAllocator(reg.get(n).allocate);
    }
} // namespace mhplan
