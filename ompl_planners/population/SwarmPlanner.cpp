// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/SwarmPlanner.h"

#include <algorithm>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    SwarmPlanner::SwarmPlanner(const ob::SpaceInformationPtr &si, const std::string &name)
        : PopulationPlanner(si, name, PopulationDefaults{30, 30, 3, PathDecoding::Spline})
    {
        // [LRSMA] section 5.2's framework for every compared algorithm: spline decoding, fitness S.
        setFitness("lrsma");
    }

    void SwarmPlanner::clearPopulation()
    {
        x_.clear();
        next_.clear();
        fit_.clear();
        nextFit_.clear();
    }

    bool SwarmPlanner::initialisePopulation()
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        x_.assign(std::size_t(n) * d, 0.0);
        next_.assign(std::size_t(n) * d, 0.0);
        fit_.assign(n, 0.0);
        nextFit_.assign(n, 0.0);
        startSwarm();
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            randomPosition(x_.data() + std::size_t(i) * d);
            fit_[i] = evaluate(x_.data() + std::size_t(i) * d);
        }
        evaluated();
        return true;
    }

    bool SwarmPlanner::populationView(double *&x, double *&fitness)
    {
        x = x_.data();
        fitness = fit_.data();
        return !x_.empty();
    }

    bool SwarmPlanner::moveRound()
    {
        const unsigned int n = getPopulationSize();
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            clampToBounds(next(i));
            nextFit_[i] = evaluate(next(i));
        }
        x_.swap(next_);
        fit_.swap(nextFit_);
        evaluated();
        return true;
    }

    void LeaderArchive::reset(unsigned int k, unsigned int dimension)
    {
        d_ = dimension;
        x_.assign(std::size_t(k) * dimension, 0.0);
        fitness_.assign(k, std::numeric_limits<double>::infinity());
    }

    bool LeaderArchive::offer(const double *x, double f)
    {
        const unsigned int k = size();
        unsigned int r = 0;
        while (r < k && !(f < fitness_[r]))
        {
            if (f == fitness_[r])
                return false; // an equal leader is not taken twice (docs/algorithms.md 10.3)
            ++r;
        }
        if (r == k)
            return false;
        // Push the worse leaders down one rank (the last drops out), then take rank r.
        for (unsigned int s = k - 1; s > r; --s)
        {
            fitness_[s] = fitness_[s - 1];
            std::copy_n(x_.data() + std::size_t(s - 1) * d_, d_, x_.data() + std::size_t(s) * d_);
        }
        fitness_[r] = f;
        std::copy_n(x, d_, x_.data() + std::size_t(r) * d_);
        return true;
    }
} // namespace mhplan
