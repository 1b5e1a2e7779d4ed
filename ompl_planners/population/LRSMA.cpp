// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/population/LRSMA.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{

    LRSMA::LRSMA(const ob::SpaceInformationPtr &si) : LRSMA(si, "LRSMA") {}

    LRSMA::LRSMA(const ob::SpaceInformationPtr &si, const std::string &name)
        : SlimeMould(si, name, PopulationDefaults{30, 30, 3, PathDecoding::Spline})
    {
        declareParam<double>("levy_beta", this, &LRSMA::setLevyBeta, &LRSMA::getLevyBeta, "0.1:0.01:1.99");
        declareParam<double>("levy_step", this, &LRSMA::setLevyStep, &LRSMA::getLevyStep, "0.:0.001:1.");
        declareParam<double>("stagnation_tolerance", this, &LRSMA::setStagnationTolerance,
                             &LRSMA::getStagnationTolerance, "0.:0.1:1000000000.");
        declareParam<unsigned int>("stagnation_limit", this, &LRSMA::setStagnationLimit,
                                   &LRSMA::getStagnationLimit, "1:1:1000");
        declareParam<double>("rotation_fraction", this, &LRSMA::setRotationFraction,
                             &LRSMA::getRotationFraction, "0.:0.05:1.");
        declareParam<double>("temperature", this, &LRSMA::setTemperature, &LRSMA::getTemperature,
                             "0.000000001:1.:1000000000000.");
        declareParam<std::string>("rotation_product", this, &LRSMA::setRotationProduct,
                                  &LRSMA::getRotationProduct, "elementwise,dot");
    }

    void LRSMA::setLevyBeta(double beta)
    {
        checkParameterRange("levy_beta", beta, 0.1, 1.99);
        beta_ = beta;
    }

    void LRSMA::setLevyStep(double step)
    {
        checkParameterRange("levy_step", step, 0.0, 1.0);
        levyStep_ = step;
    }

    void LRSMA::setStagnationTolerance(double fmin)
    {
        checkParameterRange("stagnation_tolerance", fmin, 0.0, 1e9);
        fmin_ = fmin;
    }

    void LRSMA::setStagnationLimit(unsigned int tmax)
    {
        checkParameterRange("stagnation_limit", tmax, 1, 1000);
        tmax_ = tmax;
    }

    void LRSMA::setRotationFraction(double pr)
    {
        checkParameterRange("rotation_fraction", pr, 0.0, 1.0);
        pr_ = pr;
    }

    void LRSMA::setTemperature(double temp)
    {
        checkParameterRange("temperature", temp, 1e-9, 1e12);
        temperature_ = temp;
    }

    void LRSMA::setRotationProduct(const std::string &product)
    {
        if (product != "elementwise" && product != "dot")
            throw std::invalid_argument(
                "parameter 'rotation_product' must be one of {elementwise, dot}; got '" + product + "'");
        elementwise_ = product == "elementwise";
    }

    void LRSMA::clearPopulation()
    {
        SlimeMould::clearPopulation();
        tau_ = 0;
    }

    bool LRSMA::initialisePopulation()
    {
        trial_.assign(dimension(), 0.0);
        rank_.resize(getPopulationSize());
        tau_ = 0;
        // Mantegna's sigma_u for the configured beta (eq 7).
        const double pi = kPi;
        sigmaU_ =
            std::pow(std::tgamma(1.0 + beta_) * std::sin(pi * beta_ / 2.0) /
                         (std::tgamma((1.0 + beta_) / 2.0) * beta_ * std::pow(2.0, (beta_ - 1.0) / 2.0)),
                     1.0 / beta_);
        if (!SlimeMould::initialisePopulation())
            return false;
        previousF_ = bestF_;
        return true;
    }

    double LRSMA::levy()
    {
        const double u = rng_.gaussian(0.0, sigmaU_);
        const double v = rng_.gaussian01();
        return u / std::pow(std::abs(v), 1.0 / beta_);
    }

    void LRSMA::rotate(const double *x, double *out)
    {
        const unsigned int d = dimension();
        const double omega = rng_.uniformReal(0.1, 1.0);
        double norm2 = 0.0;
        for (unsigned int j = 0; j < d; ++j)
            norm2 += x[j] * x[j];
        const double len = std::sqrt(norm2);
        if (elementwise_)
        {
            for (unsigned int j = 0; j < d; ++j)
            {
                const double r = rng_.uniformReal(-1.0, 1.0);
                out[j] = len > 0.0 ? x[j] + omega * r * x[j] / len : x[j];
            }
        }
        else
        {
            double dotRX = 0.0;
            for (unsigned int j = 0; j < d; ++j)
                dotRX += rng_.uniformReal(-1.0, 1.0) * x[j];
            for (unsigned int j = 0; j < d; ++j)
                out[j] = len > 0.0 ? x[j] + omega * dotRX / len : x[j];
        }
        clampToBounds(out);
    }

    bool LRSMA::iterate(unsigned int t)
    {
        if (!slimeMouldStep(t))
            return false;
        const unsigned int n = getPopulationSize(), d = dimension();

        // Variable-neighbourhood Levy flight on the elite (eqs 6-7).
        for (unsigned int index = 0; index < 3; ++index)
        {
            const double alpha = 1.0 + index * rng_.uniformReal(0.0, 0.5);
            for (unsigned int j = 0; j < d; ++j)
                trial_[j] = alpha * (bestX_[j] + levyStep_ * (upper(j) - lower(j)) * levy());
            clampToBounds(trial_.data());
            if (stopRequested())
                return false;
            const double f = evaluate(trial_.data());
            if (f < bestF_)
            {
                bestF_ = f;
                bestX_ = trial_;
                break;
            }
        }

        // Tolerance-based stagnation monitor (eq 8) and rotation perturbation (eq 9).
        const double dF = std::abs(bestF_ - previousF_);
        previousF_ = bestF_;
        if (dF < fmin_ && tau_ < tmax_)
            ++tau_;
        if (tau_ == tmax_ && dF < fmin_)
        {
            tau_ = 0;
            std::iota(rank_.begin(), rank_.end(), 0u);
            std::stable_sort(rank_.begin(), rank_.end(),
                             [&](unsigned int a, unsigned int b) { return fit_[a] < fit_[b]; });
            const auto count =
                std::min<unsigned int>(n, static_cast<unsigned int>(std::ceil(pr_ * n - 1e-9)));
            for (unsigned int k = 0; k < count; ++k)
            {
                const unsigned int i = rank_[k];
                rotate(row(x_, i), trial_.data());
                if (stopRequested())
                    return false;
                const double f = evaluate(trial_.data());
                if (f < fit_[i])
                {
                    fit_[i] = f;
                    std::copy(trial_.begin(), trial_.end(), row(x_, i));
                    if (f < bestF_)
                    {
                        bestF_ = f;
                        bestX_ = trial_;
                    }
                }
            }
        }
        if (dF >= fmin_)
            tau_ = 0;

        // Elite simulated annealing (4.3).
        rotate(bestX_.data(), trial_.data());
        if (stopRequested())
            return false;
        const double fr = evaluate(trial_.data());
        if (fr < bestF_ || std::exp(-(fr - bestF_) / temperature_) < rng_.uniform01())
        {
            bestF_ = fr;
            bestX_ = trial_;
        }
        return true;
    }
} // namespace mhplan
