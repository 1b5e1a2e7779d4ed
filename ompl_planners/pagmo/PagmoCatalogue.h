// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the pagmo2 algorithms the pagmo bridge offers as planners, their parameters, and the ones it
   refuses (docs/algorithms.md 11). No pagmo header here: the bridge's pagmo code stays in its sources. */
#ifndef MHPLAN_PAGMO_CATALOGUE_H
#define MHPLAN_PAGMO_CATALOGUE_H

#include "src/base/Parameters.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief One parameter of a pagmo algorithm as the planner declares it: a number (\e integer or
        real) in \e range, a switch ("0,1"), or a word of \e words ("a,b,c"; its value is the index). */
    struct PagmoParameter
    {
        enum class Kind
        {
            Real,
            Integer,
            Switch,
            Word
        };
        Kind kind;
        ParamRange range;
        double value;
        const char *words{nullptr};
    };

    /** \brief How much of the algorithm one planner iteration (one evolve() call) runs (docs/algorithms.md
        11.2). */
    enum class PagmoCall
    {
        /** \brief One generation (gen = 1), the algorithm keeping its adapted state between calls (its
            \c memory switched on) or having none. */
        Generation,
        /** \brief N generations of one offspring each ((N+1)-EA): N evaluations per call. */
        Offspring,
        /** \brief The algorithm's whole schedule (gen = T, or N T improvisations for ihs): pagmo resets the
            schedule (gwo's a, ihs's bandwidth) or the counters (bee_colony's trials) at every call. */
        Schedule,
        /** \brief The algorithm's own stopping (simulated annealing's cooling, compass search's range). */
        OwnStopping
    };

    class PagmoAlgorithmHandle;

    /** \brief What the factory of a pagmo algorithm receives: the parameter values (in the order of
        PagmoAlgorithm::parameters), the population size N, the schedule length T and the seed. */
    struct PagmoRun
    {
        const std::vector<double> &values;
        unsigned int population;
        unsigned int iterations;
        unsigned int seed;
    };

    /** \brief A pagmo 2.18 single-objective, derivative-free algorithm that runs on unconstrained problems.
     */
    struct PagmoAlgorithm
    {
        /** \brief pagmo's name of the class (e.g. "de", "cmaes"); registered as "pagmo:<name>". */
        std::string name;
        std::string description;
        std::vector<PagmoParameter> parameters;
        PagmoCall call;
        /** \brief The smallest population pagmo accepts for these parameter values. */
        std::function<unsigned int(const std::vector<double> &)> minimumPopulation;
        /** \brief Build the pagmo algorithm (throws pagmo's std::invalid_argument for values it refuses). */
        std::function<std::unique_ptr<PagmoAlgorithmHandle>(const PagmoRun &)> make;
        /** \brief What pagmo does not check but needs, for the parameter values and the population size
            (an empty string when they are fine; else why, naming the parameter). */
        std::function<std::string(const std::vector<double> &, unsigned int)> check{};
    };

    /** \brief Every algorithm the bridge runs, in alphabetical order. */
    const std::vector<PagmoAlgorithm> &pagmoAlgorithms();

    /** \brief The algorithm \e name; throws std::invalid_argument for a pagmo algorithm that cannot plan
        (it needs gradients, constraints or several objectives, or wraps another algorithm; the message
        says which) and for an unknown name (listing the algorithms that exist). */
    const PagmoAlgorithm &pagmoAlgorithm(const std::string &name);

    /** \brief The pagmo 2.18 algorithms the bridge refuses, each with the reason. */
    const std::vector<std::pair<std::string, std::string>> &refusedPagmoAlgorithms();
} // namespace mhplan

#endif
