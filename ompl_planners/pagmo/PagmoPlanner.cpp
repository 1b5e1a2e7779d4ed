// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/pagmo/PagmoPlanner.h"
#include "ompl_planners/pagmo/detail/PagmoHandle.h"

#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <climits>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        /** \brief Thrown by the fitness when the termination condition holds: ends the evolve() call. */
        struct Interrupted
        {
        };

        /** \brief The problem pagmo sees (a pagmo user-defined problem): minimise the planner's fitness over
            the waypoint vector in the space's bounds. */
        struct PathProblem
        {
            PagmoPlanner *planner{nullptr};
            pagmo::vector_double lb, ub;
            pagmo::vector_double fitness(const pagmo::vector_double &x) const
            {
                return {planner->pagmoFitness(x)};
            }
            std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const { return {lb, ub}; }
            std::string get_name() const { return "mhplan waypoint path"; }
        };

        /** \brief The "what:" line of a pagmo exception message (pagmo adds the function and the file). */
        std::string pagmoReason(const std::string &message)
        {
            const auto at = message.find("what: ");
            std::string reason = at == std::string::npos ? message : message.substr(at + 6);
            while (!reason.empty() && (reason.back() == '\n' || reason.back() == ' '))
                reason.pop_back();
            return reason;
        }
    } // namespace

    struct PagmoPlanner::State
    {
        std::unique_ptr<PagmoAlgorithmHandle> algorithm;
        std::unique_ptr<pagmo::population> population;
    };

    PagmoPlanner::PagmoPlanner(const ob::SpaceInformationPtr &si, const PagmoAlgorithm &algorithm)
        : PopulationPlanner(si, "pagmo:" + algorithm.name,
                            PopulationDefaults{30, 30, 3, PathDecoding::Polyline}),
          algorithm_(algorithm), state_(std::make_unique<State>())
    {
        for (const PagmoParameter &p : algorithm_.parameters)
            values_.push_back(p.value);
        declarePagmoParameters();
    }

    PagmoPlanner::~PagmoPlanner() = default;

    void PagmoPlanner::declarePagmoParameters()
    {
        for (std::size_t i = 0; i < algorithm_.parameters.size(); ++i)
        {
            const PagmoParameter &p = algorithm_.parameters[i];
            const std::string name = p.range.name;
            if (p.kind == PagmoParameter::Kind::Switch)
            {
                params().add(std::make_shared<DescribedParam<bool>>(
                    name,
                    [this, i](bool v)
                    {
                        values_[i] = v ? 1.0 : 0.0;
                        invalidate();
                    },
                    [this, i] { return values_[i] != 0.0; }, p.range.description));
                params()[name].setRangeSuggestion("0,1");
                continue;
            }
            params().add(std::make_shared<DescribedParam<std::string>>(
                name, [this, i](const std::string &text) { setValue(i, text); },
                [this, i] { return getValue(i); }, p.range.description));
            params()[name].setRangeSuggestion(
                p.kind == PagmoParameter::Kind::Word ? std::string(p.words) : rangeSuggestion(p.range));
        }
    }

    void PagmoPlanner::setValue(std::size_t i, const std::string &text)
    {
        const PagmoParameter &p = algorithm_.parameters[i];
        double v = 0.0;
        if (p.kind == PagmoParameter::Kind::Word)
        {
            std::stringstream in(p.words);
            std::string w;
            int index = -1;
            for (int k = 0; std::getline(in, w, ','); ++k)
                if (w == text)
                    index = k;
            if (index < 0)
                throw std::invalid_argument("parameter '" + std::string(p.range.name) + "' must be one of {" +
                                            p.words + "}; got '" + text + "'");
            v = index;
        }
        else
        {
            v = parseParameter(p.range, text);
            checkParameter(p.range, v);
            if (p.kind == PagmoParameter::Kind::Integer && v != std::floor(v))
                throw std::invalid_argument("parameter '" + std::string(p.range.name) +
                                            "' must be an integer in [" + formatParameter(p.range.lo) + ", " +
                                            formatParameter(p.range.hi) + "]; got " + text);
        }
        if (v != values_[i])
            invalidate();
        values_[i] = v;
    }

    std::string PagmoPlanner::getValue(std::size_t i) const
    {
        const PagmoParameter &p = algorithm_.parameters[i];
        if (p.kind == PagmoParameter::Kind::Word)
        {
            std::stringstream in(p.words);
            std::string w;
            for (int k = 0; std::getline(in, w, ','); ++k)
                if (k == static_cast<int>(values_[i]))
                    return w;
        }
        return formatParameter(values_[i]);
    }

    double PagmoPlanner::pagmoParameter(const std::string &name) const
    {
        for (std::size_t i = 0; i < algorithm_.parameters.size(); ++i)
            if (name == algorithm_.parameters[i].range.name)
                return values_[i];
        throw std::invalid_argument(getName() + " has no parameter '" + name + "'");
    }

    unsigned int PagmoPlanner::pagmoPopulationSize() const
    {
        return std::max(getPopulationSize(), algorithm_.minimumPopulation(values_));
    }

    void PagmoPlanner::setup()
    {
        PopulationPlanner::setup();
        // pagmo checks combinations of values (e.g. ihs: ppar_min <= ppar_max) when the algorithm is built.
        try
        {
            algorithm_.make({values_, pagmoPopulationSize(), getIterations(), 1u});
        }
        catch (const std::invalid_argument &e)
        {
            refuseSetup("pagmo's " + algorithm_.name + " refuses its parameters: " + pagmoReason(e.what()));
        }
        if (algorithm_.check)
        {
            const std::string why = algorithm_.check(values_, pagmoPopulationSize());
            if (!why.empty())
                refuseSetup(why);
        }
    }

    void PagmoPlanner::clearPopulation()
    {
        state_->algorithm.reset();
        state_->population.reset();
    }

    double PagmoPlanner::pagmoFitness(const std::vector<double> &x)
    {
        if (stopRequested())
            throw Interrupted{};
        buffer_.assign(x.begin(), x.end());
        clampToBounds(buffer_.data()); // an algorithm without force_bounds may step outside
        return evaluate(buffer_.data());
    }

    bool PagmoPlanner::initialisePopulation()
    {
        const unsigned int n = pagmoPopulationSize(), d = dimension();
        if (n > getPopulationSize())
            OMPL_WARN("%s: pagmo's %s needs at least %u individuals; population_size %u raised to %u",
                      getName().c_str(), algorithm_.name.c_str(), n, getPopulationSize(), n);
        // pagmo's seeds come from the planner's RNG (docs/algorithms.md 11.2).
        const auto populationSeed = static_cast<unsigned int>(rng_.uniformInt(0, INT_MAX));
        const auto algorithmSeed = static_cast<unsigned int>(rng_.uniformInt(0, INT_MAX));
        PathProblem problem;
        problem.planner = this;
        for (unsigned int j = 0; j < d; ++j)
        {
            problem.lb.push_back(lower(j));
            problem.ub.push_back(upper(j));
        }
        state_->population = std::make_unique<pagmo::population>(pagmo::problem(problem), 0u, populationSeed);
        std::vector<double> x(d);
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            randomPosition(x.data());
            const double f = evaluate(x.data());
            state_->population->push_back(x, {f});
        }
        state_->algorithm = algorithm_.make({values_, n, getIterations(), algorithmSeed});
        return true;
    }

    bool PagmoPlanner::iterate(unsigned int)
    {
        try
        {
            pagmo::population next = state_->algorithm->algorithm.evolve(*state_->population);
            *state_->population = std::move(next);
            return true;
        }
        catch (const Interrupted &)
        {
            return false;
        }
        catch (const std::exception &e)
        {
            // What pagmo checks only when it evolves (setup() checks what is known of it beforehand).
            const std::string text =
                getName() + ": pagmo's " + algorithm_.name + " failed: " + pagmoReason(e.what());
            OMPL_ERROR("%s", text.c_str());
            throw ompl::Exception(text);
        }
    }

    void registerPagmoPlanner(PlannerRegistry &registry, const std::string &name)
    {
        const PagmoAlgorithm &algorithm = pagmoAlgorithm(name);
        registry.add({"pagmo:" + name, "pagmo",
                      "pagmo2's " + algorithm.description + " on mhplan's waypoint encoding and fitness",
                      [&algorithm](const ob::SpaceInformationPtr &si) -> ob::PlannerPtr
                      { return std::make_shared<PagmoPlanner>(si, algorithm); },
                      cap::AllSpaces | cap::Anytime});
    }

    void registerPagmoPlanners(PlannerRegistry &registry)
    {
        for (const PagmoAlgorithm &a : pagmoAlgorithms())
            registerPagmoPlanner(registry, a.name);
    }
} // namespace mhplan
