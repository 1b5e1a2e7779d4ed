// SPDX-License-Identifier: BSD-3-Clause
/* The pagmo 2.18 algorithms the bridge offers (docs/algorithms.md 11.1): their parameters with pagmo's
   defaults and accepted ranges, how much of each one planner iteration runs (11.2), their smallest
   population, and the algorithms refused with the reason. */
#include "ompl_planners/pagmo/PagmoCatalogue.h"
#include "ompl_planners/pagmo/detail/PagmoHandle.h"

#include <pagmo/algorithms/bee_colony.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/de1220.hpp>
#include <pagmo/algorithms/gaco.hpp>
#include <pagmo/algorithms/gwo.hpp>
#include <pagmo/algorithms/ihs.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/pso_gen.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/algorithms/sea.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/algorithms/simulated_annealing.hpp>
#include <pagmo/algorithms/xnes.hpp>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    namespace
    {
        using K = PagmoParameter::Kind;

        PagmoParameter real(const char *name, double lo, double step, double hi, double value,
                            const char *what)
        {
            return {K::Real, {name, lo, step, hi, what}, value};
        }

        PagmoParameter integer(const char *name, double lo, double hi, double value, const char *what)
        {
            return {K::Integer, {name, lo, 1, hi, what}, value};
        }

        PagmoParameter flag(const char *name, bool value, const char *what)
        {
            return {K::Switch, {name, 0, 1, 1, what}, value ? 1.0 : 0.0};
        }

        /** \brief A word parameter; \e index is the default word's position in \e words. */
        PagmoParameter word(const char *name, const char *words, unsigned int index, const char *what)
        {
            const auto n =
                static_cast<double>(std::count(words, words + std::char_traits<char>::length(words), ','));
            return {K::Word, {name, 0, 1, n, what}, static_cast<double>(index), words};
        }

        /** \brief The \e index-th word of the list \e words. */
        std::string wordAt(const char *words, double index)
        {
            std::stringstream in(words);
            std::string w;
            for (int i = 0; std::getline(in, w, ','); ++i)
                if (i == static_cast<int>(index))
                    return w;
            return w;
        }

        template <typename A> std::unique_ptr<PagmoAlgorithmHandle> wrap(A a)
        {
            return std::make_unique<PagmoAlgorithmHandle>(pagmo::algorithm(std::move(a)));
        }

        unsigned int u(double v)
        {
            return static_cast<unsigned int>(v);
        }

        std::function<unsigned int(const std::vector<double> &)> atLeast(unsigned int n)
        {
            return [n](const std::vector<double> &) { return n; };
        }

        // pagmo's own stopping tolerances (ftol, xtol) are passed as 0: the planner's termination condition
        // ends a run, not a converged population (docs/algorithms.md 11.2).
        constexpr double kNoTolerance = 0.0;

        std::vector<PagmoParameter> psoParameters()
        {
            return {real("omega", 0, 0.05, 1, 0.7298,
                         "inertia weight (variants 1-4) or constriction factor (5, 6)"),
                    real("eta1", 0, 0.05, 4, 2.05, "cognitive (personal best) coefficient"),
                    real("eta2", 0, 0.05, 4, 2.05, "social (neighbourhood best) coefficient"),
                    real("max_vel", 0.001, 0.05, 1, 0.5, "velocity limit as a share of the bounds' width"),
                    integer("variant", 1, 6, 5,
                            "1 canonical inertia, 2-4 shared random numbers, 5 constriction (Clerc), 6 FIPS"),
                    integer("neighb_type", 1, 4, 2,
                            "topology: 1 gbest, 2 lbest ring, 3 von Neumann, 4 adaptive random"),
                    integer("neighb_param", 2, 10000, 4, "neighbourhood size (lbest, adaptive random)")};
        }

        /** \brief pagmo's pso and pso_gen index past the swarm (a crash, not an error) when the ring
            (lbest) neighbourhood's half-width neighb_param / 2 exceeds the swarm: measured with N = 2, 3, 30,
            neighb_param 2 N + 1 runs and 2 N + 2 crashes. */
        std::string ringFitsTheSwarm(const std::vector<double> &v, unsigned int n)
        {
            if (u(v[5]) == 2 && u(v[6]) / 2 > n)
                return "parameter 'neighb_param' (" + std::to_string(u(v[6])) +
                       ") must be at most 2 N + 1 = " + std::to_string(2 * n + 1) +
                       " for the population N = " + std::to_string(n) +
                       " with the ring topology neighb_type = 2 (pagmo would index past the swarm)";
            return "";
        }

        /** \brief pagmo's sga refuses an odd population with the sbx crossover only when it evolves. */
        std::string sbxNeedsAnEvenPopulation(const std::vector<double> &v, unsigned int n)
        {
            if (u(v[5]) == 3 && n % 2 != 0)
                return "parameter 'crossover' = 'sbx' needs an even population; population_size is " +
                       std::to_string(n);
            return "";
        }

        std::vector<PagmoAlgorithm> build()
        {
            std::vector<PagmoAlgorithm> a;
            a.push_back({"bee_colony",
                         "artificial bee colony (Karaboga & Basturk 2007)",
                         {integer("limit", 1, 100000, 20,
                                  "trials without improvement before a food source is abandoned")},
                         PagmoCall::Schedule,
                         atLeast(2),
                         [](const PagmoRun &r)
                         { return wrap(pagmo::bee_colony(r.iterations, u(r.values[0]), r.seed)); }});
            a.push_back(
                {"cmaes",
                 "covariance matrix adaptation evolution strategy (Hansen 2006)",
                 {real("cc", -1, 0.05, 1, -1,
                       "backward time horizon of the evolution path (-1 = pagmo's automatic value)"),
                  real("cs", -1, 0.05, 1, -1,
                       "makes partly up for the small variance loss in case the indicator is zero (-1 = "
                       "automatic)"),
                  real("c1", -1, 0.05, 1, -1, "learning rate of the rank-one update (-1 = automatic)"),
                  real("cmu", -1, 0.05, 1, -1, "learning rate of the rank-mu update (-1 = automatic)"),
                  real("sigma0", 0.000001, 0.05, 1, 0.5, "initial step size as a share of the bounds' width"),
                  flag("force_bounds", false,
                       "clip new individuals to the bounds (else only their evaluation is clamped)")},
                 PagmoCall::Generation,
                 atLeast(5),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(pagmo::cmaes(1, v[0], v[1], v[2], v[3], v[4], kNoTolerance, kNoTolerance,
                                              true, v[5] != 0.0, r.seed));
                 }});
            a.push_back(
                {"compass_search",
                 "compass search (Kolda, Lewis & Torczon 2003), on the best individual",
                 {integer("max_fevals", 1, 100000000, 900,
                          "evaluations of one search (one planner iteration)"),
                  real("start_range", 0.000001, 0.05, 1, 0.1, "initial step as a share of the bounds' width"),
                  real("stop_range", 0.000000001, 0.01, 1, 0.01, "the search stops below this step"),
                  real("reduction_coeff", 0.01, 0.05, 0.99, 0.5,
                       "step reduction after an unsuccessful poll")},
                 PagmoCall::OwnStopping,
                 atLeast(1),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(pagmo::compass_search(u(v[0]), v[1], v[2], v[3]));
                 }});
            a.push_back({"de",
                         "differential evolution (Storn & Price 1997)",
                         {real("F", 0, 0.05, 1, 0.8, "weight (scale) of the difference vectors"),
                          real("CR", 0, 0.05, 1, 0.9, "crossover probability"),
                          integer("variant", 1, 10, 2,
                                  "mutation variant (1 best/1/exp ... 10 rand-to-best/1/bin; pagmo's list)")},
                         PagmoCall::Generation,
                         atLeast(5),
                         [](const PagmoRun &r)
                         {
                             const auto &v = r.values;
                             return wrap(
                                 pagmo::de(1, v[0], v[1], u(v[2]), kNoTolerance, kNoTolerance, r.seed));
                         }});
            a.push_back(
                {"de1220",
                 "self-adaptive differential evolution choosing its mutation variant (pagmo's DE 1220)",
                 {integer("variant_adptv", 1, 2, 1,
                          "parameter adaptation: 1 jDE (Brest et al. 2006), 2 iDE (Elsayed et al. 2011)")},
                 PagmoCall::Generation,
                 atLeast(7),
                 [](const PagmoRun &r)
                 {
                     return wrap(pagmo::de1220(1, pagmo::de1220_statics<void>::allowed_variants,
                                               u(r.values[0]), kNoTolerance, kNoTolerance, true, r.seed));
                 }});
            a.push_back(
                {"gaco",
                 "extended ant colony optimization (Schlueter et al. 2009)",
                 {integer("ker", 2, 10000, 30,
                          "solutions kept in the archive (at most the population; pagmo's default is 63)"),
                  real("q", 0, 0.1, 1000000, 1, "convergence speed"),
                  real("oracle", 0, 1, 1000000000, 0, "oracle of the penalty method (0 = none)"),
                  real("acc", 0, 0.01, 1, 0.01, "accuracy of the constraint handling"),
                  integer("threshold", 1, 1000000, 1,
                          "generation from which the standard deviations fall faster"),
                  integer("n_gen_mark", 1, 1000000, 7, "speed of that fall"),
                  integer("impstop", 1, 1000000000, 100000,
                          "stop after this many generations without improvement"),
                  integer("evalstop", 1, 1000000000, 100000,
                          "stop after this many evaluations without improvement"),
                  real("focus", 0, 0.1, 1000000, 0, "focus on the best solutions (0 = none)")},
                 PagmoCall::Generation,
                 [](const std::vector<double> &v) { return u(v[0]); },
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(pagmo::gaco(1, u(v[0]), v[1], v[2], v[3], u(v[4]), u(v[5]), u(v[6]), u(v[7]),
                                             v[8], true, r.seed));
                 }});
            a.push_back({"gwo",
                         "grey wolf optimizer (Mirjalili et al. 2014), pagmo's implementation",
                         {},
                         PagmoCall::Schedule,
                         atLeast(3),
                         [](const PagmoRun &r) { return wrap(pagmo::gwo(r.iterations, r.seed)); }});
            a.push_back(
                {"ihs",
                 "harmony search, the IHS variant of Mahdavi et al. 2007",
                 {real("phmcr", 0, 0.05, 1, 0.85, "probability of choosing from memory"),
                  real("ppar_min", 0, 0.05, 1, 0.35, "minimum pitch adjustment rate"),
                  real("ppar_max", 0, 0.05, 1, 0.99, "maximum pitch adjustment rate"),
                  real("bw_min", 0.000000000001, 0.00001, 1000000, 0.00001, "minimum distance bandwidth"),
                  real("bw_max", 0.000000000001, 0.1, 1000000, 1, "maximum distance bandwidth")},
                 PagmoCall::Schedule,
                 atLeast(1),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(
                         pagmo::ihs(r.population * r.iterations, v[0], v[1], v[2], v[3], v[4], r.seed));
                 }});
            a.push_back({"pso", "particle swarm optimization (Kennedy & Eberhart 1995), pagmo's variants",
                         psoParameters(), PagmoCall::Generation, atLeast(2),
                         [](const PagmoRun &r)
                         {
                             const auto &v = r.values;
                             return wrap(pagmo::pso(1, v[0], v[1], v[2], v[3], u(v[4]), u(v[5]), u(v[6]),
                                                    true, r.seed));
                         }});
            a.push_back({"pso_gen", "generational particle swarm optimization (pagmo's pso_gen)",
                         psoParameters(), PagmoCall::Generation, atLeast(2),
                         [](const PagmoRun &r)
                         {
                             const auto &v = r.values;
                             return wrap(pagmo::pso_gen(1, v[0], v[1], v[2], v[3], u(v[4]), u(v[5]), u(v[6]),
                                                        true, r.seed));
                         }});
            a.push_back(
                {"sade",
                 "self-adaptive differential evolution (jDE, Brest et al. 2006; iDE, Elsayed et al. 2011)",
                 {integer("variant", 1, 18, 2, "mutation variant (pagmo's list of 18)"),
                  integer("variant_adptv", 1, 2, 1, "parameter adaptation: 1 jDE, 2 iDE")},
                 PagmoCall::Generation,
                 atLeast(7),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(pagmo::sade(1, u(v[0]), u(v[1]), kNoTolerance, kNoTolerance, true, r.seed));
                 }});
            a.push_back({"sea",
                         "(N+1)-evolutionary algorithm (pagmo's simple evolutionary algorithm)",
                         {},
                         PagmoCall::Offspring,
                         atLeast(1),
                         [](const PagmoRun &r) { return wrap(pagmo::sea(r.population, r.seed)); }});
            a.push_back({"sga",
                         "simple genetic algorithm (pagmo's sga)",
                         {real("cr", 0, 0.05, 1, 0.9, "crossover probability"),
                          real("eta_c", 1, 1, 100, 1, "distribution index of the sbx crossover"),
                          real("m", 0, 0.01, 1, 0.02, "mutation probability"),
                          real("param_m", 0, 0.1, 100, 1,
                               "mutation parameter (polynomial: distribution index; others: width)"),
                          integer("param_s", 1, 10000, 2,
                                  "selection parameter (tournament size, or the number truncated)"),
                          word("crossover", "exponential,binomial,single,sbx", 0, "crossover operator"),
                          word("mutation", "polynomial,gaussian,uniform", 0, "mutation operator"),
                          word("selection", "tournament,truncated", 0, "selection operator")},
                         PagmoCall::Generation,
                         [](const std::vector<double> &v) { return std::max(2u, u(v[4])); },
                         [](const PagmoRun &r)
                         {
                             const auto &v = r.values;
                             return wrap(pagmo::sga(1, v[0], v[1], v[2], v[3], u(v[4]),
                                                    wordAt("exponential,binomial,single,sbx", v[5]),
                                                    wordAt("polynomial,gaussian,uniform", v[6]),
                                                    wordAt("tournament,truncated", v[7]), r.seed));
                         }});
            a.push_back(
                {"simulated_annealing",
                 "simulated annealing (Corana et al. 1987), on the best individual",
                 {real("Ts", 0.000001, 1, 1000000000, 10, "starting temperature"),
                  real("Tf", 0.000001, 0.1, 1000000000, 0.1, "final temperature"),
                  integer("n_T_adj", 1, 1000000, 10, "temperature adjustments of one annealing"),
                  integer("n_range_adj", 1, 1000000, 1, "range adjustments per temperature"),
                  integer("bin_size", 1, 1000000, 20, "moves per range adjustment (and per coordinate)"),
                  real("start_range", 0, 0.05, 1, 1,
                       "starting range as a share of the bounds' width, in (0, 1]")},
                 PagmoCall::OwnStopping,
                 atLeast(1),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(
                         pagmo::simulated_annealing(v[0], v[1], u(v[2]), u(v[3]), u(v[4]), v[5], r.seed));
                 }});
            a.push_back(
                {"xnes",
                 "exponential natural evolution strategies (Glasmachers et al. 2010)",
                 {real("eta_mu", -1, 0.05, 1, -1, "learning rate of the mean (-1 = automatic)"),
                  real("eta_sigma", -1, 0.05, 1, -1, "learning rate of the step size (-1 = automatic)"),
                  real("eta_b", -1, 0.05, 1, -1, "learning rate of the covariance (-1 = automatic)"),
                  real("sigma0", -1, 0.05, 1, -1,
                       "initial step size as a share of the bounds' width (-1 = automatic)"),
                  flag("force_bounds", false,
                       "clip new individuals to the bounds (else only their evaluation is clamped)")},
                 PagmoCall::Generation,
                 atLeast(4),
                 [](const PagmoRun &r)
                 {
                     const auto &v = r.values;
                     return wrap(pagmo::xnes(1, v[0], v[1], v[2], v[3], kNoTolerance, kNoTolerance, true,
                                             v[4] != 0.0, r.seed));
                 }});
            for (PagmoAlgorithm &x : a)
                if (x.name == "pso" || x.name == "pso_gen")
                    x.check = ringFitsTheSwarm;
                else if (x.name == "sga")
                    x.check = sbxNeedsAnEvenPopulation;
            return a;
        }
    } // namespace

    const std::vector<PagmoAlgorithm> &pagmoAlgorithms()
    {
        static const std::vector<PagmoAlgorithm> algorithms = build();
        return algorithms;
    }

    const std::vector<std::pair<std::string, std::string>> &refusedPagmoAlgorithms()
    {
        static const std::vector<std::pair<std::string, std::string>> refused{
            {"cstrs_self_adaptive",
             "a meta-algorithm for constrained problems (mhplan's path fitness has no constraints)"},
            {"ipopt", "needs gradients (and this libpagmo is built without Ipopt)"},
            {"maco", "optimises several objectives (mhplan's path fitness is one)"},
            {"mbh", "a meta-algorithm around another, local algorithm (monotonic basin hopping): plan with "
                    "that one"},
            {"moead", "optimises several objectives (mhplan's path fitness is one)"},
            {"nlopt", "its local optimisers need gradients or are not built into this libpagmo (no NLopt)"},
            {"nsga2", "optimises several objectives (mhplan's path fitness is one)"},
            {"nspso", "optimises several objectives (mhplan's path fitness is one)"},
            {"null_algorithm", "does nothing (pagmo's placeholder)"}};
        return refused;
    }

    const PagmoAlgorithm &pagmoAlgorithm(const std::string &name)
    {
        for (const PagmoAlgorithm &a : pagmoAlgorithms())
            if (a.name == name)
                return a;
        for (const auto &r : refusedPagmoAlgorithms())
            if (r.first == name)
                throw std::invalid_argument("pagmo algorithm '" + name + "' cannot plan: " + r.second);
        std::string known;
        for (const PagmoAlgorithm &a : pagmoAlgorithms())
            known += (known.empty() ? "" : ", ") + a.name;
        throw std::invalid_argument("unknown pagmo algorithm '" + name +
                                    "'; the bridge runs pagmo 2.18's single-objective, derivative-free, "
                                    "unconstrained algorithms: " +
                                    known);
    }
} // namespace mhplan
