// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/ParticleSwarm.h"
#include "src/base/Parameters.h"

#include <algorithm>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kInertia{"inertia", 0, 0.05, 2, "w, the inertia weight of the velocity"};
        constexpr ParamRange kCognitive{"cognitive", 0, 0.05, 4, "c1, the pull towards the personal best"};
        constexpr ParamRange kSocial{"social", 0, 0.05, 4, "c2, the pull towards the global best"};
        constexpr ParamRange kVelocityLimit{"velocity_limit", 0, 0.05, 1,
                                            "vmax as a share of each coordinate's extent (0 = no limit)"};
    } // namespace

    ParticleSwarm::ParticleSwarm(const ob::SpaceInformationPtr &si) : SwarmPlanner(si, "PSO")
    {
        declareRanged<double>(params(), this, kInertia, &ParticleSwarm::setInertia,
                              &ParticleSwarm::getInertia);
        declareRanged<double>(params(), this, kCognitive, &ParticleSwarm::setCognitive,
                              &ParticleSwarm::getCognitive);
        declareRanged<double>(params(), this, kSocial, &ParticleSwarm::setSocial, &ParticleSwarm::getSocial);
        declareRanged<double>(params(), this, kVelocityLimit, &ParticleSwarm::setVelocityLimit,
                              &ParticleSwarm::getVelocityLimit);
    }

    void ParticleSwarm::setInertia(double w)
    {
        storeChecked(kInertia, w_, w);
    }

    void ParticleSwarm::setCognitive(double c1)
    {
        storeChecked(kCognitive, c1_, c1);
    }

    void ParticleSwarm::setSocial(double c2)
    {
        storeChecked(kSocial, c2_, c2);
    }

    void ParticleSwarm::setVelocityLimit(double share)
    {
        storeChecked(kVelocityLimit, vmaxShare_, share);
    }

    void ParticleSwarm::startSwarm()
    {
        const std::size_t size = std::size_t(getPopulationSize()) * dimension();
        v_.assign(size, 0.0);
        nextV_.assign(size, 0.0);
        pbest_.assign(size, 0.0);
        pbestFit_.assign(getPopulationSize(), std::numeric_limits<double>::infinity());
        global_.reset(1, dimension());
    }

    void ParticleSwarm::evaluated()
    {
        const unsigned int d = dimension();
        for (unsigned int i = 0; i < getPopulationSize(); ++i)
            if (fitnessOf(i) < pbestFit_[i])
            {
                pbestFit_[i] = fitnessOf(i);
                std::copy_n(member(i), d, pbest_.begin() + std::size_t(i) * d);
                global_.offer(member(i), fitnessOf(i));
            }
    }

    bool ParticleSwarm::iterate(unsigned int)
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        const double *g = global_.position(0);
        for (unsigned int i = 0; i < n; ++i)
        {
            const double *x = member(i);
            const double *p = pbest_.data() + std::size_t(i) * d;
            const double *v = v_.data() + std::size_t(i) * d;
            double *nv = nextV_.data() + std::size_t(i) * d;
            double *nx = next(i);
            for (unsigned int j = 0; j < d; ++j)
            {
                const double r1 = rng_.uniform01(), r2 = rng_.uniform01();
                double vj = velocity(v[j], x[j], p[j], g[j], w_, c1_, c2_, r1, r2);
                if (vmaxShare_ > 0.0)
                {
                    const double vmax = vmaxShare_ * (upper(j) - lower(j));
                    vj = std::min(std::max(vj, -vmax), vmax);
                }
                nv[j] = vj;
                nx[j] = x[j] + vj;
            }
        }
        if (!moveRound())
            return false;
        v_.swap(nextV_);
        return true;
    }
} // namespace mhplan
