// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/memetic/MemeticGenetic.h"

#include "src/base/Parameters.h"

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kCrossoverRate{"crossover_rate", 0, 0.05, 1, "crossover probability"};
        constexpr ParamRange kMutationRate{"mutation_rate", 0, 0.05, 1, "mutation probability per offspring"};
        constexpr ParamRange kImmigrantRate{"immigrant_rate", 0, 0.05, 1,
                                            "share of fresh random walks per generation"};
        constexpr ParamRange kTournamentSize{"tournament_size", 1, 1, 100,
                                             "individuals per selection tournament"};
    } // namespace

    MemeticGenetic::MemeticGenetic(const ob::SpaceInformationPtr &si, const std::string &name)
        : MemeticPlanner(si, name, 20)
    {
        declareRanged<double>(params(), this, kCrossoverRate, &MemeticGenetic::setCrossoverRate,
                              &MemeticGenetic::getCrossoverRate);
        declareRanged<double>(params(), this, kMutationRate, &MemeticGenetic::setMutationRate,
                              &MemeticGenetic::getMutationRate);
        declareRanged<double>(params(), this, kImmigrantRate, &MemeticGenetic::setImmigrantRate,
                              &MemeticGenetic::getImmigrantRate);
        declareRanged<unsigned int>(params(), this, kTournamentSize, &MemeticGenetic::setTournamentSize,
                                    &MemeticGenetic::getTournamentSize);
    }

    void MemeticGenetic::setCrossoverRate(double r)
    {
        checkParameter(kCrossoverRate, r);
        crossoverRate_ = r;
    }

    void MemeticGenetic::setMutationRate(double r)
    {
        checkParameter(kMutationRate, r);
        mutationRate_ = r;
    }

    void MemeticGenetic::setImmigrantRate(double r)
    {
        checkParameter(kImmigrantRate, r);
        immigrantRate_ = r;
    }

    void MemeticGenetic::setTournamentSize(unsigned int k)
    {
        checkParameter(kTournamentSize, k);
        tournamentSize_ = k;
    }

    std::size_t MemeticGenetic::tournament()
    {
        const int n = static_cast<int>(pop_.size());
        auto best = static_cast<std::size_t>(rng_.uniformInt(0, n - 1));
        for (unsigned int k = 1; k < tournamentSize_; ++k)
        {
            const auto c = static_cast<std::size_t>(rng_.uniformInt(0, n - 1));
            if (pop_[c].cost < pop_[best].cost)
                best = c;
        }
        return best;
    }

    bool MemeticGenetic::stateOffspring(std::size_t a, Individual &child)
    {
        // The same operators on paths of states (docs/spaces.md): crossover at close states, and a detour
        // through a state drawn near a piece or a re-connect of a piece (the state mode's re-walk).
        MemeticStateToolkit &tk = stateToolkit();
        const std::size_t n = pop_.size();
        bool changed = false;
        if (n > 1 && rng_.uniform01() < crossoverRate_)
        {
            std::size_t b = tournament();
            if (b == a)
                b = (a + 1 + static_cast<std::size_t>(rng_.uniformInt(0, int(n) - 2))) % n;
            const double radius = 2.5 * pop_[a].cost / 47.0;
            changed = tk.splice(pop_[a].states, pop_[b].states, radius, rng_.uniform01() < 0.5, child.states);
        }
        if (!changed)
            child.states = pop_[a].states;
        if (!changed || rng_.uniform01() < mutationRate_)
        {
            if (rng_.uniform01() < 0.35)
                changed = tk.detour(child.states, 0.3) || changed;
            else
                changed = tk.reconnect(child.states, 0.3, 2000, stopFunction()) || changed;
        }
        return changed;
    }

    bool MemeticGenetic::generation(unsigned long /*t*/)
    {
        const std::size_t n = pop_.size();
        Individual child;
        for (std::size_t k = 0; k < n; ++k)
        {
            if (stopRequested())
                return false;
            const std::size_t a = tournament();
            if (stateMode())
            {
                if (!stateOffspring(a, child))
                    continue;
                if (!improveAndEvaluate(child))
                    return false;
                crowdingInsert(child);
                continue;
            }
            bool changed = false;
            if (n > 1 && rng_.uniform01() < crossoverRate_)
            {
                std::size_t b = tournament();
                if (b == a)
                    b = (a + 1 + static_cast<std::size_t>(rng_.uniformInt(0, int(n) - 2))) % n;
                const double radius = 2.5 * MemeticToolkit::length(pop_[a].path) / 47.0;
                changed =
                    toolkit().splice(pop_[a].path, pop_[b].path, radius, rng_.uniform01() < 0.5, child.path);
            }
            if (!changed)
                child.path = pop_[a].path;
            if (!changed || rng_.uniform01() < mutationRate_)
            {
                const double u = rng_.uniform01();
                if (u < 0.25)
                    changed = toolkit().detour(child.path, 0.3) || changed;
                else if (u < 0.35)
                    changed = toolkit().flip(child.path) || changed;
                else
                    changed =
                        toolkit().rewalk(child.path, 0.3, getWalkNoise(), 4000, stopFunction()) || changed;
            }
            if (!changed)
                continue;
            if (!improveAndEvaluate(child))
                return false;
            crowdingInsert(child);
        }
        if (rng_.uniform01() < immigrantRate_)
        {
            Individual immigrant;
            if (walkIndividual(immigrant))
                crowdingInsert(immigrant);
            else if (stopRequested())
                return false;
        }
        return true;
    }
} // namespace mhplan
