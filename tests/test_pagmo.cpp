// SPDX-License-Identifier: BSD-3-Clause
/* The pagmo2 bridge (ompl_planners/pagmo, docs/algorithms.md 11): what is registered and what is refused,
   the algorithms' parameters, pagmo's own refusals at setup(), the smallest population, the termination
   condition inside an evolve() call, and pagmo's GWO and PSO against mhplan's on constructed cases (11.3).
   The registry-driven contract and determinism tests run every "pagmo:" planner too. */
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "ompl_planners/pagmo/PagmoPlanner.h"
#include "ompl_planners/population/GreyWolf.h"
#include "ompl_planners/population/ParticleSwarm.h"
#include "src/registry/Registry.h"
#include "RegistrySupport.h"

#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/gwo.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    og::SimpleSetupPtr seedProblem()
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case1.yaml");
        return makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    }

    std::string refusal(const std::string &algorithm)
    {
        PlannerRegistry r;
        try
        {
            registerPagmoPlanner(r, algorithm);
        }
        catch (const std::invalid_argument &e)
        {
            EXPECT_FALSE(r.has("pagmo:" + algorithm));
            return e.what();
        }
        return "";
    }

    /** \brief A two-dimensional sphere, f = |x - (1, 2)|^2, in [-10, 10]^2 (pagmo user-defined problem). */
    struct Sphere
    {
        pagmo::vector_double fitness(const pagmo::vector_double &x) const
        {
            return {(x[0] - 1) * (x[0] - 1) + (x[1] - 2) * (x[1] - 2)};
        }
        std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const
        {
            return {{-10, -10}, {10, 10}};
        }
    };

    /** \brief A population of the sphere with the given individuals (evaluated). */
    pagmo::population spherePopulation(const std::vector<pagmo::vector_double> &xs)
    {
        pagmo::population pop(pagmo::problem(Sphere{}), 0u, 1u);
        for (const auto &x : xs)
            pop.push_back(x);
        return pop;
    }
} // namespace

TEST(Pagmo, EveryCataloguedAlgorithmIsRegisteredWithItsParameters)
{
    const PlannerRegistry &registry = builtinPlanners();
    ASSERT_GE(pagmoAlgorithms().size(), 15u);
    og::SimpleSetupPtr ss = seedProblem();
    for (const PagmoAlgorithm &a : pagmoAlgorithms())
    {
        const std::string name = "pagmo:" + a.name;
        ASSERT_TRUE(registry.has(name)) << name;
        const PlannerEntry &e = registry.get(name);
        EXPECT_EQ(e.origin, "pagmo");
        EXPECT_EQ(test::familyOf(name), "population");
        EXPECT_TRUE(e.runsOn(cap::SE2)) << name;
        const ob::PlannerPtr p = e.allocate(ss->getSpaceInformation());
        EXPECT_EQ(p->getName(), name);
        for (const PagmoParameter &param : a.parameters)
        {
            ASSERT_TRUE(p->params().hasParam(param.range.name)) << name << " " << param.range.name;
            EXPECT_FALSE(parameterDescription(p->params()[param.range.name]).empty());
            EXPECT_FALSE(p->params()[param.range.name].getRangeSuggestion().empty());
        }
        // The planner's own parameters (population, encoding, fitness, seed) are there too.
        EXPECT_TRUE(p->params().hasParam("population_size"));
        EXPECT_TRUE(p->params().hasParam("seed"));
    }
    // pagmo's names of its parameters and its defaults.
    const ob::PlannerPtr de = registry.create("pagmo:de", ss->getSpaceInformation());
    EXPECT_EQ(de->params()["F"].getValue(), "0.8");
    EXPECT_EQ(de->params()["CR"].getValue(), "0.9");
    EXPECT_EQ(de->params()["variant"].getValue(), "2");
    const ob::PlannerPtr sga =
        registry.create("pagmo:sga", ss->getSpaceInformation(), {{"crossover", "sbx"}});
    EXPECT_EQ(sga->params()["crossover"].getValue(), "sbx");
}

TEST(Pagmo, UnknownAndUnsuitableAlgorithmsAreRefusedAtRegistration)
{
    const std::string unknown = refusal("no_such_algorithm");
    EXPECT_NE(unknown.find("unknown pagmo algorithm 'no_such_algorithm'"), std::string::npos) << unknown;
    for (const char *listed : {"cmaes", "de", "gwo", "pso", "sade", "simulated_annealing", "xnes"})
        EXPECT_NE(unknown.find(listed), std::string::npos) << listed << " not listed: " << unknown;
    EXPECT_NE(refusal("nsga2").find("several objectives"), std::string::npos);
    EXPECT_NE(refusal("moead").find("several objectives"), std::string::npos);
    EXPECT_NE(refusal("ipopt").find("gradients"), std::string::npos);
    EXPECT_NE(refusal("cstrs_self_adaptive").find("constrained"), std::string::npos);
    // The reason is pagmo's own: its multi-objective algorithms refuse mhplan's single-objective problem.
    pagmo::population pop =
        spherePopulation({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {6, 6}, {7, 7}});
    EXPECT_THROW(pagmo::algorithm(pagmo::nsga2(1u)).evolve(pop), std::invalid_argument);
    // Through the registry an unknown "pagmo:" name is an InputError listing what is registered.
    try
    {
        builtinPlanners().get("pagmo:nsga2");
        ADD_FAILURE() << "pagmo:nsga2 is registered";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("pagmo:de"), std::string::npos) << e.what();
    }
}

TEST(Pagmo, BadParametersAreRefusedByNameAndPagmosCombinationsAtSetup)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    og::SimpleSetupPtr ss = seedProblem();
    const PlannerRegistry &registry = builtinPlanners();
    EXPECT_THROW(registry.create("pagmo:de", ss->getSpaceInformation(), {{"F", "1.5"}}), InputError);
    EXPECT_THROW(registry.create("pagmo:de", ss->getSpaceInformation(), {{"variant", "2.5"}}), InputError);
    EXPECT_THROW(registry.create("pagmo:sga", ss->getSpaceInformation(), {{"mutation", "cauchy"}}),
                 InputError);
    EXPECT_THROW(registry.create("pagmo:de", ss->getSpaceInformation(), {{"no_such_parameter", "1"}}),
                 InputError);
    // Each value in range, but pagmo refuses the pair: setup() says so with pagmo's reason.
    ob::PlannerPtr ihs =
        registry.create("pagmo:ihs", ss->getSpaceInformation(), {{"ppar_min", "0.9"}, {"ppar_max", "0.1"}});
    ss->setPlanner(ihs);
    try
    {
        ss->setup();
        ADD_FAILURE() << "ppar_min > ppar_max accepted";
    }
    catch (const ompl::Exception &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("pagmo:ihs: pagmo's ihs refuses its parameters"), std::string::npos) << what;
    }
    // pagmo's pso would index past a swarm smaller than its ring neighbourhood (a crash): refused at setup.
    for (const char *name : {"pagmo:pso", "pagmo:pso_gen"})
    {
        ob::PlannerPtr pso = registry.create(name, ss->getSpaceInformation(), {{"neighb_param", "100"}});
        ss->setPlanner(pso);
        try
        {
            ss->setup();
            ADD_FAILURE() << name << ": a ring of 100 in a swarm of 30 accepted";
        }
        catch (const ompl::Exception &e)
        {
            EXPECT_NE(std::string(e.what()).find("'neighb_param' (100) must be at most 2 N + 1 = 61"),
                      std::string::npos)
                << e.what();
        }
        // The other topologies take any neighbourhood size.
        applyPlannerParameters(*pso, {{"neighb_type", "3"}});
        EXPECT_NO_THROW(ss->setup()) << name;
    }
    // pagmo's sga refuses an odd population with the sbx crossover only in evolve(): refused at setup.
    ob::PlannerPtr sga = registry.create("pagmo:sga", ss->getSpaceInformation(),
                                         {{"crossover", "sbx"}, {"population_size", "31"}});
    ss->setPlanner(sga);
    EXPECT_THROW(ss->setup(), ompl::Exception);
    applyPlannerParameters(*sga, {{"population_size", "32"}});
    EXPECT_NO_THROW(ss->setup());
}

TEST(Pagmo, TooSmallAPopulationIsRaisedToTheAlgorithmsMinimum)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p =
        builtinPlanners().create("pagmo:sade", ss->getSpaceInformation(),
                                 {{"population_size", "2"}, {"max_iterations", "1"}, {"seed", "3"}});
    ss->setPlanner(p);
    ss->setup();
    p->solve(ob::PlannerTerminationCondition([] { return false; }));
    EXPECT_EQ(static_cast<const PagmoPlanner &>(*p).pagmoPopulationSize(), 7u);
    // 7 initial individuals and one generation of 7 trial vectors.
    EXPECT_EQ(p->getPlannerProgressProperties().at("fitness evaluations INTEGER")(), "14");
}

TEST(Pagmo, TheTerminationConditionEndsAnEvolveCall)
{
    // simulated_annealing's evolve() runs its whole cooling schedule (1200 evaluations here): a condition
    // that holds after 50 checks stops it inside the first call, which is then not counted.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    og::SimpleSetupPtr ss = seedProblem();
    ob::PlannerPtr p =
        builtinPlanners().create("pagmo:simulated_annealing", ss->getSpaceInformation(), {{"seed", "3"}});
    ss->setPlanner(p);
    ss->setup();
    ob::IterationTerminationCondition fifty(50);
    p->solve(ob::PlannerTerminationCondition(fifty));
    const auto &props = p->getPlannerProgressProperties();
    EXPECT_EQ(props.at("iterations INTEGER")(), "0");
    EXPECT_LT(std::stoul(props.at("fitness evaluations INTEGER")()), 50u);
    EXPECT_GT(std::stoul(props.at("fitness evaluations INTEGER")()), 30u); // the first population, and more
}

TEST(Pagmo, PagmosGwoMovesAWolfAsMhplansHuntRuleFromOtherLeaders)
{
    // pagmo's gwo with gen = 1 runs its schedule's last step, a = 0: then A = 0 and every X_k is its leader,
    // so the first wolf moves to the mean of its three leaders, the value of GreyWolf::hunt with a = 0
    // whatever the random numbers: the same rule (docs/algorithms.md 11.3). The leaders differ: pagmo 2.18
    // ranks the population in descending order when a call starts, so its first leaders are the three
    // WORST wolves (here (9, -9), (-8, 7), (0, 0)), where mhplan's GWO follows the three best so far.
    const std::vector<pagmo::vector_double> xs{{9, -9}, {1.5, 2.5}, {0, 0}, {3, 2.5}, {-8, 7}};
    pagmo::population pop = spherePopulation(xs);
    pagmo::population after = pagmo::algorithm(pagmo::gwo(1u, 42u)).evolve(pop);
    // The sphere's values: (9, -9) 185, (-8, 7) 106, (0, 0) 5, (3, 2.5) 4.25, (1.5, 2.5) 0.5.
    const double r[3] = {0.3, 0.6, 0.9};
    for (unsigned int j = 0; j < 2; ++j)
    {
        const double worst[3] = {xs[0][j], xs[4][j], xs[2][j]};
        const double best[3] = {xs[1][j], xs[3][j], xs[2][j]};
        EXPECT_NEAR(after.get_x()[0][j], GreyWolf::hunt(xs[0][j], worst, 0.0, r, r), 1e-12) << j;
        EXPECT_GT(std::abs(after.get_x()[0][j] - GreyWolf::hunt(xs[0][j], best, 0.0, r, r)), 0.1) << j;
    }
}

TEST(Pagmo, PagmosCanonicalPsoMovesAParticleAsMhplansVelocityRule)
{
    // pagmo's pso variant 1 (canonical, inertia weight) with the gbest topology is mhplan's PSO rule
    // v = w v + c1 r1 (p - x) + c2 r2 (g - x). With w = 0 the initial velocity (random in pagmo, zero in
    // mhplan) drops out; with c1 = 0 and c2 = 1 the first particle moves by r2 (g - x) per coordinate
    // (ParticleSwarm::velocity), i.e. into the box between x and the global best, in both.
    const std::vector<pagmo::vector_double> xs{{-6, 8}, {1.5, 2.5}, {4, -3}};
    pagmo::population pop = spherePopulation(xs);
    pagmo::population after =
        pagmo::algorithm(pagmo::pso(1u, 0.0, 0.0, 1.0, 1.0, 1u, 1u, 4u, false, 7u)).evolve(pop);
    const pagmo::vector_double &g = xs[1];
    for (unsigned int j = 0; j < 2; ++j)
    {
        const double moved = after.get_x()[0][j];
        const double lo = std::min(xs[0][j], g[j]), hi = std::max(xs[0][j], g[j]);
        EXPECT_GE(moved, lo);
        EXPECT_LE(moved, hi);
        // The same end points from mhplan's rule with r2 = 0 and r2 = 1.
        EXPECT_DOUBLE_EQ(
            xs[0][j] + ParticleSwarm::velocity(5.0, xs[0][j], -1.0, g[j], 0.0, 0.0, 1.0, 0.4, 0.0), xs[0][j]);
        EXPECT_DOUBLE_EQ(
            xs[0][j] + ParticleSwarm::velocity(5.0, xs[0][j], -1.0, g[j], 0.0, 0.0, 1.0, 0.4, 1.0), g[j]);
    }
    // The moved particle is not where it was (r2 > 0 almost surely) and is nearer the global best.
    const double before = std::hypot(xs[0][0] - g[0], xs[0][1] - g[1]);
    const double now = std::hypot(after.get_x()[0][0] - g[0], after.get_x()[0][1] - g[1]);
    EXPECT_LT(now, before);
}
