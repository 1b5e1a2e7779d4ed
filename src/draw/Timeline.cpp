// SPDX-License-Identifier: BSD-3-Clause
#include "src/draw/detail/Timeline.h"

#include <algorithm>
#include <cmath>

namespace mhplan
{
    namespace draw_detail
    {
        long lastSampleAtOrBefore(const std::vector<double> &times, double t)
        {
            const auto it = std::upper_bound(times.begin(), times.end(), t + 1e-9);
            return static_cast<long>(it - times.begin()) - 1;
        }

        std::vector<std::size_t> frameIndices(std::size_t n, int maxFrames)
        {
            std::vector<std::size_t> out;
            if (n == 0)
                return out;
            const std::size_t f = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(2, maxFrames)));
            if (f == 1)
                return {0};
            for (std::size_t k = 0; k < f; ++k)
                out.push_back(static_cast<std::size_t>(std::llround(
                    static_cast<double>(k) * static_cast<double>(n - 1) / static_cast<double>(f - 1))));
            return out;
        }
    } // namespace draw_detail
} // namespace mhplan
