// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/GreyWolf.h"

#include <cmath>

namespace ob = ompl::base;

namespace mhplan
{
    GreyWolf::GreyWolf(const ob::SpaceInformationPtr &si) : SwarmPlanner(si, "GWO") {}

    double GreyWolf::hunt(double x, const double leader[3], double a, const double r1[3], const double r2[3])
    {
        double sum = 0.0;
        for (unsigned int k = 0; k < 3; ++k)
        {
            const double A = 2.0 * a * r1[k] - a;
            const double C = 2.0 * r2[k];
            const double D = std::abs(C * leader[k] - x);
            sum += leader[k] - A * D;
        }
        return sum / 3.0;
    }

    void GreyWolf::startSwarm()
    {
        leaders_.reset(3, dimension());
    }

    void GreyWolf::evaluated()
    {
        for (unsigned int i = 0; i < getPopulationSize(); ++i)
            leaders_.offer(member(i), fitnessOf(i));
    }

    bool GreyWolf::iterate(unsigned int t)
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        const double a = fallingCoefficient(t, getIterations());
        // With fewer than three distinct solutions so far, the missing leaders are the best one.
        const unsigned int known = std::isfinite(leaders_.fitness(2))   ? 3
                                   : std::isfinite(leaders_.fitness(1)) ? 2
                                                                        : 1;
        for (unsigned int i = 0; i < n; ++i)
        {
            const double *x = member(i);
            double *nx = next(i);
            for (unsigned int j = 0; j < d; ++j)
            {
                double leader[3], r1[3], r2[3];
                for (unsigned int k = 0; k < 3; ++k)
                {
                    leader[k] = leaders_.position(k < known ? k : 0)[j];
                    r1[k] = rng_.uniform01();
                    r2[k] = rng_.uniform01();
                }
                nx[j] = hunt(x[j], leader, a, r1, r2);
            }
        }
        return moveRound();
    }
} // namespace mhplan
