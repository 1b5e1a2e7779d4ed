// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/Whale.h"
#include "src/base/Parameters.h"

#include <cmath>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kSpiral{"spiral", 0.01, 0.01, 10,
                                     "b, the shape constant of the bubble-net spiral"};
    } // namespace

    Whale::Whale(const ob::SpaceInformationPtr &si) : SwarmPlanner(si, "WOA")
    {
        declareRanged<double>(params(), this, kSpiral, &Whale::setSpiral, &Whale::getSpiral);
    }

    void Whale::setup()
    {
        SwarmPlanner::setup();
        if (!onRealVectorSpace())
            refuseSetup("plans in the plane only (docs/algorithms.md 10.2); the state space '" +
                        si_->getStateSpace()->getName() + "' is not a RealVectorStateSpace of dimension 2");
        if (spaceDimension() != 2)
            refuseSetup("plans in the plane only (docs/algorithms.md 10.2); the space has dimension " +
                        std::to_string(spaceDimension()));
    }

    void Whale::setSpiral(double b)
    {
        storeChecked(kSpiral, b_, b);
    }

    double Whale::moveCoordinate(Move move, double x, double target, double A, double C, double l, double b)
    {
        if (move == Move::Spiral)
            return std::abs(target - x) * std::exp(b * l) * std::cos(2.0 * kPi * l) + target;
        // Encircling (target = the leader) and search (target = a random whale) share the form.
        return target - A * std::abs(C * target - x);
    }

    void Whale::startSwarm()
    {
        leader_.reset(1, dimension());
    }

    void Whale::evaluated()
    {
        for (unsigned int i = 0; i < getPopulationSize(); ++i)
            leader_.offer(member(i), fitnessOf(i));
    }

    bool Whale::iterate(unsigned int t)
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        const double a = fallingCoefficient(t, getIterations());
        const double *best = leader_.position(0);
        for (unsigned int i = 0; i < n; ++i)
        {
            const double A = 2.0 * a * rng_.uniform01() - a;
            const double C = 2.0 * rng_.uniform01();
            const double p = rng_.uniform01();
            const double l = rng_.uniformReal(-1.0, 1.0);
            const Move move = choose(p, A);
            const double *target = best;
            if (move == Move::Search)
                target = member(static_cast<unsigned int>(rng_.uniformInt(0, int(n) - 1)));
            const double *x = member(i);
            double *nx = next(i);
            for (unsigned int j = 0; j < d; ++j)
                nx[j] = moveCoordinate(move, x[j], target[j], A, C, l, b_);
        }
        return moveRound();
    }
} // namespace mhplan
