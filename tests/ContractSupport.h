// SPDX-License-Identifier: BSD-3-Clause
/* Test support for the planner contract (test_planner_contract.cpp) and the determinism tests
   (test_determinism.cpp): the registry they run on (every built-in mhplan planner plus a planner defined
   here, outside the library), the seed problem and the planner-kind predicates. */
#ifndef MHPLAN_TESTS_CONTRACT_SUPPORT_H
#define MHPLAN_TESTS_CONTRACT_SUPPORT_H

#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "ompl_planners/common/PopulationPlanner.h"
#include "src/registry/Registry.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>

#include "RegistrySupport.h"

#include <string>
#include <vector>

namespace mhplan::contract
{
    namespace ob = ompl::base;
    namespace og = ompl::geometric;

    /** \brief A planner defined here, outside the library, the way a user adds one: derive from
        PopulationPlanner and write the three hooks. Its first individual is the straight line from start to
        goal, the others and every later iteration are uniform random restarts. It proves that the contract
        below runs on any registered planner: it is registered in contractRegistry() and nowhere else (the
       contract and determinism tests include this header). */
    class StraightLineRestarts : public PopulationPlanner
    {
      public:
        explicit StraightLineRestarts(const ob::SpaceInformationPtr &si)
            : PopulationPlanner(si, "StraightLineRestarts",
                                PopulationDefaults{30, 30, 3, PathDecoding::Polyline})
        {
        }

      protected:
        bool initialisePopulation() override
        {
            x_.resize(dimension());
            const unsigned int k = spaceDimension(), m = dimension() / k;
            for (unsigned int i = 0; i < getPopulationSize(); ++i)
            {
                if (stopRequested())
                    return false;
                if (i == 0)
                    for (unsigned int w = 0; w < m; ++w)
                        for (unsigned int j = 0; j < k; ++j)
                            x_[w * k + j] =
                                startCoordinates()[j] + (goalCoordinates()[j] - startCoordinates()[j]) *
                                                            double(w + 1) / double(m + 1);
                else
                    randomPosition(x_.data());
                evaluate(x_.data());
            }
            return true;
        }
        bool iterate(unsigned int) override
        {
            for (unsigned int i = 0; i < getPopulationSize(); ++i)
            {
                if (stopRequested())
                    return false;
                randomPosition(x_.data());
                evaluate(x_.data());
            }
            return true;
        }
        void clearPopulation() override { x_.clear(); }

      private:
        std::vector<double> x_;
    };

    /** \brief True for a planner of ompl_planners/: mhplan's own (origin "mhplan") and pagmo2's algorithms
        through the bridge of ompl_planners/pagmo (origin "pagmo"). */
    inline bool fromOmplPlanners(const PlannerEntry &e)
    {
        return e.origin == "mhplan" || e.origin == "pagmo";
    }

    /** \brief The registry the contract runs on: every built-in planner of ompl_planners/, plus the planner
        above (one registration line, as in ompl_planners/Registration.cpp). */
    inline const PlannerRegistry &contractRegistry()
    {
        static const PlannerRegistry registry = []
        {
            PlannerRegistry r;
            const PlannerRegistry &builtin = builtinPlanners();
            for (const std::string &name : builtin.names())
                if (fromOmplPlanners(builtin.get(name)))
                    r.add(builtin.get(name));
            r.add({"StraightLineRestarts", "mhplan", "test planner: straight line, then random restarts",
                   allocatorFor<StraightLineRestarts>(), cap::AllSpaces | cap::Anytime});
            return r;
        }();
        return registry;
    }

    /** \brief Every planner of the contract registry. */
    inline std::vector<std::string> contractPlanners()
    {
        return contractRegistry().names();
    }

    /** \brief Every planner of ompl_planners/ the built-in registry knows (fromOmplPlanners): population
        planners with their improved variants, pagmo2's algorithms, the memetic variants, lattice searches
        and potential-field walks. */
    inline std::vector<std::string> mhplanPlanners()
    {
        std::vector<std::string> out;
        const PlannerRegistry &registry = builtinPlanners();
        for (const std::string &name : registry.names())
            if (fromOmplPlanners(registry.get(name)))
                out.push_back(name);
        return out;
    }

    inline og::SimpleSetupPtr seedProblem(const std::string &world = "bfo_case1")
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + world + ".yaml");
        return makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    }

    inline std::string progress(const ob::PlannerPtr &p, const std::string &name)
    {
        return p->getPlannerProgressProperties().at(name)();
    }

    inline ob::PlannerTerminationCondition never()
    {
        return ob::PlannerTerminationCondition([] { return false; });
    }

    /** \brief Deterministic lattice searches (AStar, ThetaStar): no seed, no population, no fitness; their
        iterations are node expansions, and a search needs many of them to reach the goal. */
    inline bool isLatticeSearch(const std::string &planner)
    {
        return test::familyOf(planner) == "lattice";
    }

    /** \brief Robot walks on the potential field (APF, BFO and ATBFO in their default online mode): not
        optimizing planners. Their iterations are robot steps (\c max_iterations bounds the steps per solve()
        call, 0 = walk on until the goal or the end of the walk), their fitness evaluations are evaluations of
        the field J, their best cost stays infinite until the walk reaches the goal (then it is exact, else
        approximate), they report one intermediate solution (the walk, when it reaches the goal), and they
        need a validity checker that computes clearance (the field's obstacle distance). */
    inline bool isWalk(const std::string &planner)
    {
        return test::familyOf(planner) == "walk";
    }

    /** \brief Fitness evaluations, or node expansions for a planner without a fitness. */
    inline unsigned long evaluations(const ob::PlannerPtr &p)
    {
        const auto &props = p->getPlannerProgressProperties();
        const auto it = props.find("fitness evaluations INTEGER");
        return std::stoul(it != props.end() ? it->second() : props.at("iterations INTEGER")());
    }

    /** \brief The iteration budget \e iterations of a population planner; lattice searches and walks run
        to the end. */
    inline std::string budget(const std::string &planner, const char *iterations)
    {
        return isLatticeSearch(planner) || isWalk(planner) ? "0" : iterations;
    }
} // namespace mhplan::contract

#endif
