// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the 1D distance transform of the grid collision model's exact EDT (GridCollision.cpp). */
#ifndef MHPLAN_COLLISION_DETAIL_DISTANCE_TRANSFORM_H
#define MHPLAN_COLLISION_DETAIL_DISTANCE_TRANSFORM_H

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhplan::detail
{
    /** \brief 1D squared Euclidean distance transform of f (Felzenszwalb & Huttenlocher 2012): d[q] =
        min over p of (q - p)^2 + f[p]. Infinite f values are not sites. v, z are scratch (n and n + 1).
     */
    inline void distanceTransform1D(const double *f, int n, double *d, int *v, double *z)
    {
        int k = -1;
        for (int q = 0; q < n; ++q)
        {
            if (!std::isfinite(f[q]))
                continue;
            double s = -std::numeric_limits<double>::infinity();
            while (k >= 0)
            {
                const int p = v[k];
                s = ((f[q] + static_cast<double>(q) * q) - (f[p] + static_cast<double>(p) * p)) /
                    (2.0 * (q - p));
                if (s <= z[k])
                    --k;
                else
                    break;
            }
            if (k < 0)
                s = -std::numeric_limits<double>::infinity();
            ++k;
            v[k] = q;
            z[k] = s;
            z[k + 1] = std::numeric_limits<double>::infinity();
        }
        if (k < 0)
        {
            std::fill(d, d + n, std::numeric_limits<double>::infinity());
            return;
        }
        int j = 0;
        for (int q = 0; q < n; ++q)
        {
            while (z[j + 1] < q)
                ++j;
            const double dq = q - v[j];
            d[q] = dq * dq + f[v[j]];
        }
    }
} // namespace mhplan::detail

#endif
