// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the planar memetic toolkit's segment caches (docs/variants.md, "Checks"), private to
   ompl_planners/memetic: open-addressing hash tables (abseil's flat_hash_map), keyed by the exact coordinates
   of a segment's two ends. The verdict cache takes a lookup for every motion the local search asks about,
   most of them new (bisection probes); a node-based map spent a quarter to a half of a planar run in the app
   set-up on its allocations, page faults and pointer chasing. */
#ifndef MHPLAN_OMPL_PLANNERS_MEMETIC_DETAIL_SEGMENT_CACHES_
#define MHPLAN_OMPL_PLANNERS_MEMETIC_DETAIL_SEGMENT_CACHES_

#include "ompl_planners/memetic/MemeticToolkit.h"

#include <absl/container/flat_hash_map.h>

#include <utility>

namespace mhplan
{
    template <typename H> H AbslHashValue(H h, const MemeticToolkit::SegmentKey &k)
    {
        return H::combine(std::move(h), k.ax, k.ay, k.bx, k.by);
    }

    struct MemeticToolkit::SegmentCaches
    {
        /// MemeticMargin.cpp's verdict codes.
        absl::flat_hash_map<SegmentKey, char> verdicts;
        /// Per refused segment (the margin or the fine check), the fraction where: the fine check's first
        /// failing sample, the middle of the margin's refusing window.
        absl::flat_hash_map<SegmentKey, double> refusedAt;
    };
} // namespace mhplan

#endif
