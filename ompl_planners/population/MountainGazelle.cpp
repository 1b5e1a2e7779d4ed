// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/population/MountainGazelle.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ob = ompl::base;

namespace mhplan
{
    MountainGazelle::MountainGazelle(const ob::SpaceInformationPtr &si) : MountainGazelle(si, "MGO") {}

    MountainGazelle::MountainGazelle(const ob::SpaceInformationPtr &si, const std::string &name)
        : PopulationPlanner(si, name, PopulationDefaults{30, 30, 3, PathDecoding::Polyline})
    {
    }

    void MountainGazelle::clearPopulation()
    {
        pool_.clear();
        poolFit_.clear();
    }

    bool MountainGazelle::initialisePopulation()
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        pool_.assign(std::size_t(5) * n * d, 0.0);
        sorted_.assign(std::size_t(n) * d, 0.0);
        poolFit_.assign(std::size_t(5) * n, 0.0);
        sortedFit_.assign(n, 0.0);
        order_.resize(std::size_t(5) * n);
        male_.assign(d, 0.0);
        cof_.assign(std::size_t(4) * d, 0.0);
        bh_.assign(d, 0.0);
        f_.assign(d, 0.0);
        dv_.assign(d, 0.0);
        perm_.resize(n);
        for (unsigned int i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            randomPosition(row(pool_, i));
            poolFit_[i] = evaluate(row(pool_, i));
        }
        // Sort the population and take the male gazelle.
        sortPopulation();
        return true;
    }

    void MountainGazelle::sortPopulation()
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        std::iota(order_.begin(), order_.begin() + n, 0u);
        std::stable_sort(order_.begin(), order_.begin() + n,
                         [&](unsigned int a, unsigned int b) { return poolFit_[a] < poolFit_[b]; });
        for (unsigned int k = 0; k < n; ++k)
        {
            std::copy_n(row(pool_, order_[k]), d, sorted_.begin() + std::size_t(k) * d);
            sortedFit_[k] = poolFit_[order_[k]];
        }
        std::copy(sorted_.begin(), sorted_.end(), pool_.begin());
        std::copy(sortedFit_.begin(), sortedFit_.end(), poolFit_.begin());
        std::copy_n(pool_.begin(), d, male_.begin());
    }

    bool MountainGazelle::populationView(double *&x, double *&fitness)
    {
        x = pool_.data();
        fitness = poolFit_.data();
        return !pool_.empty();
    }

    void MountainGazelle::populationChanged()
    {
        sortPopulation();
    }

    const double *MountainGazelle::cofR()
    {
        return cof_.data() + std::size_t(rng_.uniformInt(0, 3)) * dimension();
    }

    bool MountainGazelle::iterate(unsigned int t)
    {
        const unsigned int n = getPopulationSize(), d = dimension();
        const double T = getIterations();
        const double a = -1.0 + t * (-1.0 / T);
        const unsigned int third = (n + 2) / 3; // ceil(N / 3)
        std::iota(perm_.begin(), perm_.end(), 0u);
        // The population rows 0..N-1 are sorted by fitness (rank k = row k).
        for (unsigned int i = 0; i < n; ++i)
        {
            const double *x = row(pool_, i);
            // Coefficient vectors.
            double *c1 = cof_.data(), *c2 = c1 + d, *c3 = c2 + d, *c4 = c3 + d;
            const double r3 = rng_.uniform01();
            const double r5 = rng_.uniform01();
            for (unsigned int j = 0; j < d; ++j)
            {
                c1[j] = (a + 1.0) + r3;
                c2[j] = a * rng_.gaussian01();
                c3[j] = rng_.uniform01();
                const double n3 = rng_.gaussian01(), n4 = rng_.gaussian01();
                c4[j] = n3 * n4 * n4 * std::cos(2.0 * r5 * n3);
            }
            // BH: a random gazelle of rank in [ceil(N/3), N] and the mean of ceil(N/3) random gazelles.
            const auto ra = static_cast<unsigned int>(rng_.uniformInt(int(third) - 1, int(n) - 1));
            for (unsigned int k = 0; k < third; ++k) // partial Fisher-Yates: distinct indices
                std::swap(perm_[k], perm_[static_cast<unsigned int>(rng_.uniformInt(int(k), int(n) - 1))]);
            const double r1 = rng_.uniform01(), r2 = rng_.uniform01();
            for (unsigned int j = 0; j < d; ++j)
            {
                double mean = 0.0;
                for (unsigned int k = 0; k < third; ++k)
                    mean += row(pool_, perm_[k])[j];
                mean /= third;
                bh_[j] = row(pool_, ra)[j] * std::floor(r1) + mean * std::ceil(r2);
            }
            const double decay = std::exp(2.0 - t * (2.0 / T));
            for (unsigned int j = 0; j < d; ++j)
                f_[j] = rng_.gaussian01() * decay;
            const double r6 = rng_.uniform01();
            for (unsigned int j = 0; j < d; ++j)
                dv_[j] = (std::abs(x[j]) + std::abs(male_[j])) * (2.0 * r6 - 1.0);
            int ri[6];
            for (int &v : ri)
                v = rng_.uniformInt(1, 2);
            const auto xr = static_cast<unsigned int>(rng_.uniformInt(0, int(n) - 1));
            const double *xrand = row(pool_, xr);

            double *tsm = row(pool_, n + 4 * i), *mh = tsm + d, *bmh = mh + d, *msf = bmh + d;
            {
                const double *cr = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    tsm[j] = male_[j] - std::abs((ri[0] * bh_[j] - ri[1] * x[j]) * f_[j]) * cr[j];
            }
            {
                const double *ca = cofR();
                const double *cb = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    mh[j] = (bh_[j] + ca[j]) + (ri[2] * male_[j] - ri[3] * xrand[j]) * cb[j];
            }
            {
                const double *cr = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    bmh[j] = (x[j] - dv_[j]) + (ri[4] * male_[j] - ri[5] * bh_[j]) * cr[j];
            }
            for (unsigned int j = 0; j < d; ++j)
                msf[j] = (upper(j) - lower(j)) * rng_.uniform01() + lower(j);
            for (unsigned int k = 0; k < 4; ++k)
            {
                double *child = tsm + std::size_t(k) * d;
                clampToBounds(child);
                if (stopRequested())
                    return false;
                poolFit_[n + 4 * i + k] = evaluate(child);
            }
        }
        // Merge, sort, keep the best N.
        const unsigned int total = 5 * n;
        std::iota(order_.begin(), order_.end(), 0u);
        std::partial_sort(order_.begin(), order_.begin() + n, order_.begin() + total,
                          [&](unsigned int p, unsigned int q)
                          { return poolFit_[p] < poolFit_[q] || (poolFit_[p] == poolFit_[q] && p < q); });
        for (unsigned int k = 0; k < n; ++k)
            std::copy_n(row(pool_, order_[k]), d, sorted_.begin() + std::size_t(k) * d);
        std::copy(sorted_.begin(), sorted_.end(), pool_.begin());
        for (unsigned int k = 0; k < n; ++k)
            sortedFit_[k] = poolFit_[order_[k]];
        std::copy(sortedFit_.begin(), sortedFit_.end(), poolFit_.begin());
        std::copy_n(pool_.begin(), d, male_.begin());
        return true;
    }
} // namespace mhplan
