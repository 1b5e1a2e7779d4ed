// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: which recorded samples of a run a drawing shows. Not part of the installed API. */
#ifndef MHPLAN_DRAW_DETAIL_TIMELINE_H
#define MHPLAN_DRAW_DETAIL_TIMELINE_H

#include <cstddef>
#include <vector>

namespace mhplan
{
    namespace draw_detail
    {
        /** Index of the last sample with time <= t (times ascending), or -1 when there is none. */
        long lastSampleAtOrBefore(const std::vector<double> &times, double t);

        /** Evenly spaced indices 0..n-1, at most maxFrames of them (both ends included). */
        std::vector<std::size_t> frameIndices(std::size_t n, int maxFrames);
    } // namespace draw_detail
} // namespace mhplan

#endif
