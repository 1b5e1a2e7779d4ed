// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/registry/Registry.h"

#include "mhplan/planners/Registration.h"

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
} // namespace

namespace mhplan
{
    void registerOmplPlanners(PlannerRegistry &r)
    {
        // OMPL's geometric planners: name, origin, description, allocator, capabilities (cap::, checked by
        // tests/test_capabilities.cpp).
        r.add({"RRT", "ompl", "Rapidly-exploring random tree (LaValle 1998)", allocatorFor<og::RRT>(),
               cap::AllSpaces});
        r.add({"RRTConnect", "ompl", "Bidirectional RRT (Kuffner & LaValle 2000)",
               allocatorFor<og::RRTConnect>(), cap::AllSpaces});
        r.add({"RRTstar", "ompl", "Asymptotically optimal RRT* (Karaman & Frazzoli 2011)",
               allocatorFor<og::RRTstar>(), cap::AllSpaces | cap::Anytime});
        r.add({"InformedRRTstar", "ompl", "Informed RRT* (Gammell et al. 2014)",
               allocatorFor<og::InformedRRTstar>(), cap::AllSpaces | cap::Anytime});
        r.add({"SORRTstar", "ompl", "Sorted informed RRT* (Gammell et al. 2018)",
               allocatorFor<og::SORRTstar>(), cap::AllSpaces | cap::Anytime});
        r.add({"PRM", "ompl", "Probabilistic roadmap (Kavraki et al. 1996)", allocatorFor<og::PRM>(),
               cap::AllSpaces | cap::Anytime});
        r.add({"PRMstar", "ompl", "Asymptotically optimal PRM* (Karaman & Frazzoli 2011)",
               allocatorFor<og::PRMstar>(), cap::AllSpaces | cap::Anytime});
        r.add({"LazyPRMstar", "ompl", "Lazy PRM* (Bohlin & Kavraki 2000)", allocatorFor<og::LazyPRMstar>(),
               cap::AllSpaces | cap::Anytime});
        r.add({"BITstar", "ompl", "Batch informed trees, k-nearest (Gammell et al. 2015)",
               [](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
               { return std::make_shared<NamedBITstar>(si); },
               cap::AllSpaces | cap::Anytime});
        r.add({"ABITstar", "ompl", "Advanced BIT* (Strub & Gammell 2020)", allocatorFor<og::ABITstar>(),
               cap::AllSpaces | cap::Anytime});
        r.add({"AITstar", "ompl", "Adaptively informed trees (Strub & Gammell 2020)",
               allocatorFor<og::AITstar>(), cap::AllSpaces | cap::Anytime});
        r.add({"FMTstar", "ompl", "Fast marching tree (Janson et al. 2015)", allocatorFor<og::FMT>(),
               cap::AllSpaces});
        r.add({"BFMTstar", "ompl", "Bidirectional FMT* (Starek et al. 2015)", allocatorFor<og::BFMT>(),
               cap::AllSpaces});
        r.add({"KPIECE1", "ompl",
               "Kinodynamic planning by interior-exterior cell exploration (Sucan & Kavraki)",
               allocatorFor<og::KPIECE1>(), cap::AllSpaces});
        r.add({"EST", "ompl", "Expansive space trees (Hsu et al. 1997)", allocatorFor<og::EST>(),
               cap::AllSpaces});
        r.add({"SBL", "ompl", "Single-query bidirectional lazy planner (Sanchez & Latombe 2003)",
               allocatorFor<og::SBL>(), cap::AllSpaces});
        r.add({"STRIDE", "ompl",
               "Search tree with resolution independent density estimation (Gipson et al. 2013)",
               allocatorFor<og::STRIDE>(), cap::AllSpaces});
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

    void addPlannersToBenchmark(ompl::tools::Benchmark &benchmark, const std::vector<std::string> &names)
    {
        const PlannerRegistry &reg = builtinPlanners();
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
