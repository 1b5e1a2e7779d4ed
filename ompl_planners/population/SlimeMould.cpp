// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/SlimeMould.h"
#include "src/base/Parameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kZ{"z", 0, 0.01, 1, "probability of a random restart of one slime mould"};
    } // namespace

    SlimeMould::SlimeMould(const ob::SpaceInformationPtr &si) : SlimeMould(si, std::string("SMA")) {}

    SlimeMould::SlimeMould(const ob::SpaceInformationPtr &si, const std::string &name)
        : SlimeMould(si, name, PopulationDefaults{30, 30, 3, PathDecoding::Spline})
    {
        // [LRSMA] section 5.2's framework: spline decoding (the constructor default) and the fitness S.
        setFitness("lrsma");
    }

    SlimeMould::SlimeMould(const ob::SpaceInformationPtr &si, const std::string &name,
                           const PopulationDefaults &defaults)
        : PopulationPlanner(si, name, defaults)
    {
        declareSlimeMouldParams();
    }

    void SlimeMould::declareSlimeMouldParams()
    {
        declareRanged<double>(params(), this, kZ, &SlimeMould::setZ, &SlimeMould::getZ);
    }

    void SlimeMould::setZ(double z)
    {
        storeChecked(kZ, z_, z);
    }

    void SlimeMould::clearPopulation()
    {
        x_.clear();
        next_.clear();
        fit_.clear();
        nextFit_.clear();
        bestX_.clear();
        bestF_ = std::numeric_limits<double>::infinity();
    }

    bool SlimeMould::initialisePopulation()
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        x_.assign(std::size_t(n) * d, 0.0);
        next_.assign(std::size_t(n) * d, 0.0);
        weights_.assign(std::size_t(n) * d, 1.0);
        fit_.assign(n, 0.0);
        nextFit_.assign(n, 0.0);
        score_.assign(n, 0.0);
        order_.resize(n);
        bestX_.assign(d, 0.0);
        vb_.assign(d, 0.0);
        vc_.assign(d, 0.0);
        bestF_ = std::numeric_limits<double>::infinity();
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            randomPosition(row(x_, i));
            fit_[i] = evaluate(row(x_, i));
        }
        updateBest();
        return true;
    }

    bool SlimeMould::populationView(double *&x, double *&fitness)
    {
        x = x_.data();
        fitness = fit_.data();
        return !x_.empty();
    }

    void SlimeMould::populationChanged()
    {
        updateBest();
    }

    void SlimeMould::updateBest()
    {
        const unsigned int n = getPopulationSize();
        unsigned int best = 0;
        for (unsigned int i = 1; i < n; ++i)
            if (fit_[i] < fit_[best])
                best = i;
        if (fit_[best] < bestF_)
        {
            bestF_ = fit_[best];
            std::copy_n(row(x_, best), dimension(), bestX_.begin());
        }
    }

    double SlimeMould::weightTerm(double bF, double wF, double s, bool maximise)
    {
        if (!maximise)
        {
            // Minimisation, as the original: bF - wF <= 0, the guard keeps the sign; ratio in [0, 1].
            const double span = bF - wF - std::numeric_limits<double>::epsilon();
            return std::log10((bF - s) / span + 1.0);
        }
        // Maximisation (bF >= wF): the same ratio with best and worst turned. A feasible path of low f1 can
        // rank above an infeasible one of higher f2, so the ratio is clamped to [0, 1] (mhplan's choice).
        const double span = bF - wF + std::numeric_limits<double>::epsilon();
        const double ratio = std::min(1.0, std::max(0.0, (bF - s) / span));
        return std::log10(ratio + 1.0);
    }

    double SlimeMould::oscillationProbability(double s, double best)
    {
        return std::tanh(std::abs(s - best));
    }

    bool SlimeMould::iterate(unsigned int t)
    {
        return slimeMouldStep(t);
    }

    bool SlimeMould::slimeMouldStep(unsigned int t)
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        const double T = getIterations();
        std::iota(order_.begin(), order_.end(), 0u);
        std::stable_sort(order_.begin(), order_.end(),
                         [&](unsigned int a, unsigned int b) { return fit_[a] < fit_[b]; });
        // The values the update reads (docs/algorithms.md 1.3, 4): the fitness itself ([LRSMA] S,
        // minimised), or with the [GMS] fitness the paper's maximised f1 / f2 (the sort above already ranks
        // feasibility first, then f descending, since fit_ holds the [GMS] key).
        const bool maximise = fitnessKind() == FitnessKind::FeasibleInfeasible;
        for (unsigned int i = 0; i < n; ++i)
            score_[i] = maximise ? gmsValueOfKey(fit_[i]) : fit_[i];
        const double bestScore = maximise ? gmsValueOfKey(bestF_) : bestF_;
        const double bF = score_[order_.front()], wF = score_[order_.back()];
        for (unsigned int k = 0; k < n; ++k)
        {
            const unsigned int i = order_[k];
            const double ratio = weightTerm(bF, wF, score_[i], maximise);
            const bool betterHalf = double(k + 1) <= n / 2.0;
            double *w = row(weights_, i);
            for (unsigned int j = 0; j < d; ++j)
            {
                const double r = rng_.uniform01();
                w[j] = betterHalf ? 1.0 + r * ratio : 1.0 - r * ratio;
            }
        }
        const double a = std::atanh(std::max(0.0, 1.0 - t / T));
        const double b = std::max(0.0, 1.0 - t / T);

        next_ = x_;
        for (unsigned int i = 0; i < n; ++i)
        {
            double *xi = row(next_, i);
            if (rng_.uniform01() < z_)
            {
                randomPosition(xi);
                continue;
            }
            const double p = oscillationProbability(score_[i], bestScore);
            for (unsigned int j = 0; j < d; ++j)
                vb_[j] = rng_.uniformReal(-a, a);
            for (unsigned int j = 0; j < d; ++j)
                vc_[j] = rng_.uniformReal(-b, b);
            const double *w = row(weights_, i);
            for (unsigned int j = 0; j < d; ++j)
            {
                const double r = rng_.uniform01();
                const auto A = static_cast<unsigned int>(rng_.uniformInt(0, int(n) - 1));
                const auto B = static_cast<unsigned int>(rng_.uniformInt(0, int(n) - 1));
                if (r < p)
                    xi[j] = bestX_[j] + vb_[j] * (w[j] * row(next_, A)[j] - row(next_, B)[j]);
                else
                    xi[j] = vc_[j] * xi[j];
            }
        }
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            clampToBounds(row(next_, i));
            nextFit_[i] = evaluate(row(next_, i));
        }
        x_.swap(next_);
        fit_.swap(nextFit_);
        updateBest();
        return true;
    }
} // namespace mhplan
