// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/LRSMA.h"
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
        constexpr ParamRange kLevyBeta{"levy_beta", 0.1, 0.01, 1.99, "exponent beta of the Levy flights"};
        constexpr ParamRange kLevyStep{"levy_step", 0, 0.001, 1,
                                       "Levy step as a share of the bounds' extent"};
        constexpr ParamRange kStagnationTolerance{"stagnation_tolerance", 0, 0.1, 1000000000,
                                                  "Fmin of the stagnation monitor: improvement that counts"};
        constexpr ParamRange kStagnationLimit{
            "stagnation_limit", 1, 1, 1000,
            "Tmax: iterations without such an improvement before the rotation"};
        constexpr ParamRange kRotationFraction{"rotation_fraction", 0, 0.05, 1,
                                               "p_r, the share of the population rotated on stagnation"};
        constexpr ParamRange kTemperature{"temperature", 0.000000001, 1, 1000000000000,
                                          "temperature of the elite annealing"};
    } // namespace

    LRSMA::LRSMA(const ob::SpaceInformationPtr &si) : LRSMA(si, "LRSMA") {}

    LRSMA::LRSMA(const ob::SpaceInformationPtr &si, const std::string &name)
        : SlimeMould(si, name, PopulationDefaults{30, 30, 3, PathDecoding::Spline})
    {
        declareRanged<double>(params(), this, kLevyBeta, &LRSMA::setLevyBeta, &LRSMA::getLevyBeta);
        declareRanged<double>(params(), this, kLevyStep, &LRSMA::setLevyStep, &LRSMA::getLevyStep);
        declareRanged<double>(params(), this, kStagnationTolerance, &LRSMA::setStagnationTolerance,
                              &LRSMA::getStagnationTolerance);
        declareRanged<unsigned int>(params(), this, kStagnationLimit, &LRSMA::setStagnationLimit,
                                    &LRSMA::getStagnationLimit);
        declareRanged<double>(params(), this, kRotationFraction, &LRSMA::setRotationFraction,
                              &LRSMA::getRotationFraction);
        declareRanged<double>(params(), this, kTemperature, &LRSMA::setTemperature, &LRSMA::getTemperature);
        declareChoice(params(), this, "rotation_product", &LRSMA::setRotationProduct,
                      &LRSMA::getRotationProduct, "elementwise,dot",
                      "rotation applied elementwise (R (.) X) or as a matrix product (R . X)");
    }

    void LRSMA::setLevyBeta(double beta)
    {
        storeChecked(kLevyBeta, beta_, beta);
    }

    void LRSMA::setLevyStep(double step)
    {
        storeChecked(kLevyStep, levyStep_, step);
    }

    void LRSMA::setStagnationTolerance(double fmin)
    {
        storeChecked(kStagnationTolerance, fmin_, fmin);
    }

    void LRSMA::setStagnationLimit(unsigned int tmax)
    {
        storeChecked(kStagnationLimit, tmax_, tmax);
    }

    void LRSMA::setRotationFraction(double pr)
    {
        storeChecked(kRotationFraction, pr_, pr);
    }

    void LRSMA::setTemperature(double temp)
    {
        storeChecked(kTemperature, temperature_, temp);
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
        monitor_.reset();
        rotations_ = 0;
    }

    bool LRSMA::initialisePopulation()
    {
        trial_.assign(dimension(), 0.0);
        rank_.resize(getPopulationSize());
        monitor_ = StagnationMonitor(fmin_, tmax_);
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
        if (monitor_.update(dF))
        {
            ++rotations_;
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
