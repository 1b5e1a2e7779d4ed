// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the greedy shortcut of the memetic planners' local search, shared by the planar and the state mode
   (docs/variants.md, "Memetic variants"; docs/spaces.md, "The memetic planners off the plane"). */
#ifndef MHPLAN_OMPL_PLANNERS_MEMETIC_PATH_SHORTCUT_H
#define MHPLAN_OMPL_PLANNERS_MEMETIC_PATH_SHORTCUT_H

#include <algorithm>
#include <cstddef>
#include <functional>

namespace mhplan
{
    /** \brief Greedy shortcut: from each kept waypoint jump to the farthest later waypoint it sees
        (\c visible(from, to): the motion is valid), doubling the jump while visible, then bisecting. On
        \c stop() the rest of the path is kept as it is. \c Path is a vector of waypoints. */
    template <typename Path, typename Visible>
    void greedyShortcut(Path &path, Visible &&visible, const std::function<bool()> &stop)
    {
        if (path.size() < 3)
            return;
        Path out;
        out.reserve(path.size());
        std::size_t i = 0;
        out.push_back(path[0]);
        const std::size_t last = path.size() - 1;
        while (i < last)
        {
            if (stop())
            {
                out.insert(out.end(), path.begin() + static_cast<std::ptrdiff_t>(i + 1), path.end());
                break;
            }
            std::size_t good = i + 1, bad = last + 1;
            for (std::size_t jump = 2;; jump *= 2)
            {
                const std::size_t j = std::min(last, i + jump);
                if (visible(path[i], path[j]))
                    good = j;
                else
                {
                    bad = j;
                    break;
                }
                if (j == last)
                    break;
            }
            while (bad - good > 1)
            {
                const std::size_t mid = (good + bad) / 2;
                if (visible(path[i], path[mid]))
                    good = mid;
                else
                    bad = mid;
            }
            out.push_back(path[good]);
            i = good;
        }
        path.swap(out);
    }
} // namespace mhplan

#endif
