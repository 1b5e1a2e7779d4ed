// SPDX-License-Identifier: BSD-3-Clause
#include "src/registry/Registry.h"

#include "ompl_planners/Registration.h"

#include <ompl/geometric/planners/cforest/CForest.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/est/ProjEST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rlrt/BiRLRT.h>
#include <ompl/geometric/planners/rlrt/RLRT.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTXstatic.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/rrt/pRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sbl/pSBL.h>
#include <ompl/geometric/planners/sst/SST.h>
#include <ompl/geometric/planners/stride/STRIDE.h>

#include <ompl/base/spaces/RealVectorStateProjections.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <numeric>
#include <utility>
#include <set>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    /** \brief OMPL's BIT* (k-nearest, its default), named "BITstar" in its messages, benchmark logs and
        databases. OMPL 1.5.2 reserves "BITstar" for the r-disc variant: its constructor and setup() rename
        the k-nearest one "kBITstar" (setup() with a warning), so users who asked for "BITstar" read messages
        about a planner they never named. The name is handed to OMPL as it expects during setup() and given
        back afterwards (messages printed inside setup() itself, such as the notice that no objective was
        given, keep OMPL's name); the planner itself is unchanged. */
    class NamedBITstar : public ompl::geometric::BITstar
    {
      public:
        explicit NamedBITstar(const ompl::base::SpaceInformationPtr &si) : BITstar(si) { setName("BITstar"); }

        void setup() override
        {
            if (getUseKNearest())
                setName("kBITstar");
            BITstar::setup();
            setName("BITstar");
        }
    };

    /** \brief A planner of OMPL that uses the state space's default projection (EST's and KPIECE's families,
        SBL, PDST, STRIDE). OMPL 1.5.2's default projection of a
        RealVectorStateSpace of 1 or 2 dimensions, RealVectorIdentityProjectionEvaluator, fails an Eigen size
        assertion in Debian's build at its first projection; at setup the space's default is replaced by the
        orthogonal projection onto the same coordinates, the same map (docs/cli.md, "OMPL's planners"). */
    template <typename P> class WithWorkingProjection : public P
    {
      public:
        using P::P;

        void setup() override
        {
            const ob::StateSpacePtr &space = this->si_->getStateSpace();
            if (this->si_->isSetup() && space->hasDefaultProjection() &&
                dynamic_cast<const ob::RealVectorIdentityProjectionEvaluator *>(
                    space->getDefaultProjection().get()))
            {
                std::vector<unsigned int> components(space->getDimension());
                std::iota(components.begin(), components.end(), 0u);
                auto projection =
                    std::make_shared<ob::RealVectorOrthogonalProjectionEvaluator>(space, components);
                projection->setup();
                space->registerDefaultProjection(projection);
            }
            P::setup();
        }
    };
} // namespace

namespace mhplan
{
    void registerOmplPlanners(PlannerRegistry &r)
    {
        // Every geometric planner of OMPL 1.5.2 that plans from a SpaceInformation alone (docs/cli.md,
        // "OMPL's planners"); all of them work on any state space OMPL's samplers cover (R^k, SE(2), SE(3),
        // Dubins, Reeds-Shepp), those that need a projection (EST's and KPIECE's families, SBL, PDST,
        // STRIDE) using the default projection OMPL registers for R^k, SE(2) and SE(3).
        // Capabilities (cap::, checked against each planner's behaviour by tests/test_capabilities.cpp):
        // every one runs on every space; the asymptotically (near-)optimal ones are anytime.
        const std::set<std::string> anytime{
            "LBTRRT",   "RRTstar", "InformedRRTstar", "SORRTstar", "RRTsharp",    "RRTXstatic",
            "SST",      "PRM",     "PRMstar",         "LazyPRM",   "LazyPRMstar", "SPARS",
            "SPARStwo", "BITstar", "ABITstar",        "AITstar",   "CForest"};
        const auto add =
            [&r, &anytime](const std::string &name, const std::string &description, PlannerAllocator a)
        {
            r.add({name, "ompl", description, std::move(a),
                   cap::AllSpaces | (anytime.count(name) != 0 ? cap::Anytime : 0u)});
        };
        // RRT family
        add("RRT", "Rapidly-exploring random tree (LaValle 1998)", allocatorFor<og::RRT>());
        add("RRTConnect", "Bidirectional RRT (Kuffner & LaValle 2000)", allocatorFor<og::RRTConnect>());
        add("LazyRRT", "RRT that checks edges only on a candidate solution (Kuffner & LaValle 2000)",
            allocatorFor<og::LazyRRT>());
        add("pRRT", "Parallel RRT (threads growing one tree)", allocatorFor<og::pRRT>());
        add("TRRT", "Transition-based RRT for cost maps (Jaillet et al. 2010)", allocatorFor<og::TRRT>());
        add("BiTRRT", "Bidirectional T-RRT (Devaurs et al. 2013)", allocatorFor<og::BiTRRT>());
        add("LBTRRT", "Lower-bound tree RRT, asymptotically near-optimal (Salzman & Halperin 2014)",
            allocatorFor<og::LBTRRT>());
        add("RRTstar", "Asymptotically optimal RRT* (Karaman & Frazzoli 2011)", allocatorFor<og::RRTstar>());
        add("InformedRRTstar", "Informed RRT* (Gammell et al. 2014)", allocatorFor<og::InformedRRTstar>());
        add("SORRTstar", "Sorted informed RRT* (Gammell et al. 2018)", allocatorFor<og::SORRTstar>());
        add("RRTsharp", "RRT# (Arslan & Tsiotras 2013)", allocatorFor<og::RRTsharp>());
        add("RRTXstatic", "RRTX for static worlds (Otte & Frazzoli 2015)", allocatorFor<og::RRTXstatic>());
        add("RLRT", "Range-limited random tree (Kleinbort et al. 2016)", allocatorFor<og::RLRT>());
        add("BiRLRT", "Bidirectional range-limited random tree (Kleinbort et al. 2016)",
            allocatorFor<og::BiRLRT>());
        add("SST", "Stable sparse RRT (Li et al. 2016)", allocatorFor<og::SST>());
        // PRM family
        add("PRM", "Probabilistic roadmap (Kavraki et al. 1996)", allocatorFor<og::PRM>());
        add("PRMstar", "Asymptotically optimal PRM* (Karaman & Frazzoli 2011)", allocatorFor<og::PRMstar>());
        add("LazyPRM", "Lazy PRM (Bohlin & Kavraki 2000)", allocatorFor<og::LazyPRM>());
        add("LazyPRMstar", "Lazy PRM* (Bohlin & Kavraki 2000)", allocatorFor<og::LazyPRMstar>());
        add("SPARS", "Sparse roadmap spanner (Dobson et al. 2012)", allocatorFor<og::SPARS>());
        add("SPARStwo", "Sparse roadmap spanner 2 (Dobson & Bekris 2013)", allocatorFor<og::SPARStwo>());
        // informed trees and marching trees
        add("BITstar", "Batch informed trees, k-nearest (Gammell et al. 2015)",
            [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
            { return std::make_shared<NamedBITstar>(si); });
        add("ABITstar", "Advanced BIT* (Strub & Gammell 2020)", allocatorFor<og::ABITstar>());
        add("AITstar", "Adaptively informed trees (Strub & Gammell 2020)", allocatorFor<og::AITstar>());
        add("FMTstar", "Fast marching tree (Janson et al. 2015)", allocatorFor<og::FMT>());
        add("BFMTstar", "Bidirectional FMT* (Starek et al. 2015)", allocatorFor<og::BFMT>());
        add("CForest", "Coupled forest of RRT* trees in parallel (Otte & Correll 2013)",
            allocatorFor<og::CForest>());
        // projection-based explorers
        add("EST", "Expansive space trees (Hsu et al. 1997)", allocatorFor<og::EST>());
        add("BiEST", "Bidirectional EST (Hsu et al. 1997)", allocatorFor<og::BiEST>());
        add("ProjEST", "EST over a projection's grid (Sucan & Kavraki)",
            allocatorFor<WithWorkingProjection<og::ProjEST>>());
        add("SBL", "Single-query bidirectional lazy planner (Sanchez & Latombe 2003)",
            allocatorFor<WithWorkingProjection<og::SBL>>());
        add("pSBL", "Parallel SBL (threads growing the two trees)",
            allocatorFor<WithWorkingProjection<og::pSBL>>());
        add("KPIECE1", "Kinodynamic planning by interior-exterior cell exploration (Sucan & Kavraki)",
            allocatorFor<WithWorkingProjection<og::KPIECE1>>());
        add("BKPIECE1", "Bidirectional KPIECE (Sucan & Kavraki)",
            allocatorFor<WithWorkingProjection<og::BKPIECE1>>());
        add("LBKPIECE1", "Lazy bidirectional KPIECE (Sucan & Kavraki)",
            allocatorFor<WithWorkingProjection<og::LBKPIECE1>>());
        add("PDST", "Path-directed subdivision tree (Ladd & Kavraki 2004)",
            allocatorFor<WithWorkingProjection<og::PDST>>());
        add("STRIDE", "Search tree with resolution independent density estimation (Gipson et al. 2013)",
            allocatorFor<WithWorkingProjection<og::STRIDE>>());

        // OMPL.app's names (its benchmark configuration files) and OMPL's own getName() where it differs.
        for (const auto &[alias, name] :
             std::vector<std::pair<std::string, std::string>>{{"kpiece", "KPIECE1"},
                                                              {"bkpiece", "BKPIECE1"},
                                                              {"lbkpiece", "LBKPIECE1"},
                                                              {"fmt", "FMTstar"},
                                                              {"bfmt", "BFMTstar"},
                                                              {"spars2", "SPARStwo"},
                                                              {"kBITstar", "BITstar"}})
            r.addAlias(alias, name);
    }

    void registerBuiltinPlanners(PlannerRegistry &r)
    {
        registerOmplPlanners(r);
        registerMhplanPlanners(r);
    }

    const PlannerRegistry &builtinPlanners()
    {
        static const PlannerRegistry registry = []
        {
            PlannerRegistry r;
            registerBuiltinPlanners(r);
            return r;
        }();
        return registry;
    }

    ob::PlannerPtr allocatePlanner(const std::string &name, const ob::SpaceInformationPtr &si,
                                   const std::map<std::string, std::string> &params)
    {
        return builtinPlanners().create(name, si, params);
    }

    BenchmarkPlanner::BenchmarkPlanner(const char *text) : BenchmarkPlanner(std::string(text)) {}

    BenchmarkPlanner::BenchmarkPlanner(const std::string &text)
    {
        *this = parseBenchmarkPlanner(text);
    }

    BenchmarkPlanner::BenchmarkPlanner(std::string name, std::map<std::string, std::string> params,
                                       std::string displayName)
        : name(std::move(name)), params(std::move(params)), displayName(std::move(displayName))
    {
    }

    BenchmarkPlanner parseBenchmarkPlanner(const std::string &text)
    {
        const std::string accepted = "expected NAME, NAME[key=value,...], NAME@DISPLAY or "
                                     "NAME[key=value,...]@DISPLAY";
        auto refuse = [&](const std::string &why)
        { throw InputError("planner '" + text + "': " + why + " (" + accepted + ")"); };
        BenchmarkPlanner out;
        std::string rest = text;
        const auto at = rest.find('@', rest.rfind(']') == std::string::npos ? 0 : rest.rfind(']'));
        if (at != std::string::npos)
        {
            out.displayName = rest.substr(at + 1);
            rest = rest.substr(0, at);
            if (out.displayName.empty())
                refuse("empty display name after '@'");
            if (out.displayName.find_first_of("@[]") != std::string::npos)
                refuse("the display name holds '@', '[' or ']'");
        }
        const auto open = rest.find('[');
        if (open != std::string::npos)
        {
            if (rest.back() != ']')
                refuse("'[' without a closing ']' at the end");
            const std::string list = rest.substr(open + 1, rest.size() - open - 2);
            rest = rest.substr(0, open);
            std::size_t from = 0;
            while (from <= list.size() && !list.empty())
            {
                const auto comma = list.find(',', from);
                const std::string item =
                    list.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
                if (item.find('=') == std::string::npos || item.front() == '=')
                    refuse("parameter '" + item + "' is not key=value");
                parseKeyValue(item, out.params);
                if (comma == std::string::npos)
                    break;
                from = comma + 1;
            }
        }
        else if (rest.find(']') != std::string::npos)
            refuse("']' without '['");
        out.name = rest;
        if (out.name.empty())
            refuse("no planner name");
        return out;
    }

    namespace
    {
        /** The geometric SimpleSetup of an OMPL benchmark (OMPL 1.5.2 keeps it protected; reached through a
            pointer to the member, the legal way a derived class offers); null for a control benchmark. */
        struct BenchmarkAccess : ompl::tools::Benchmark
        {
            static og::SimpleSetup *setup(ompl::tools::Benchmark &b)
            {
                return b.*(&BenchmarkAccess::gsetup_);
            }
        };
    } // namespace

    void addPlannersToBenchmark(ompl::tools::Benchmark &benchmark,
                                const std::vector<BenchmarkPlanner> &chosen)
    {
        const PlannerRegistry &reg = builtinPlanners();
        std::vector<BenchmarkPlanner> planners = chosen;
        if (planners.empty())
            for (const auto &n : reg.names())
                if (reg.get(n).origin == "mhplan")
                    planners.push_back({n, {}, ""});
        og::SimpleSetup *setup = BenchmarkAccess::setup(benchmark);
        if (setup == nullptr)
            throw InputError(
                "addPlannersToBenchmark: the benchmark plans with controls; mhplan's registry holds "
                "geometric planners (ompl::tools::Benchmark(geometric::SimpleSetup &, ...))");
        // Check everything on the benchmark's own space before adding anything.
        std::set<std::string> shown;
        for (const BenchmarkPlanner &p : planners)
        {
            const ob::PlannerPtr probe = reg.create(p.name, setup->getSpaceInformation(), p.params);
            const std::string display = p.displayName.empty() ? probe->getName() : p.displayName;
            if (!shown.insert(display).second)
                throw InputError("addPlannersToBenchmark: two planners named '" + display +
                                 "' (their runs would merge): give one a display name, NAME@DISPLAY");
        }
        for (const BenchmarkPlanner &p : planners)
            benchmark.addPlannerAllocator(
                [p](const ob::SpaceInformationPtr &si)
                {
                    ob::PlannerPtr planner = builtinPlanners().create(p.name, si, p.params);
                    if (!p.displayName.empty())
                        planner->setName(p.displayName);
                    return planner;
                });
    }

} // namespace mhplan
