// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: world families that grow (the scaling suite): disjoint obstacles at a set coverage in a box that
   grows with their number, mazes and random grids, and random queries far apart. Seeded and portable: a
   seed gives the same world on every platform (PortableRandom, Generators.h). */
#ifndef MHPLAN_WORLD_FAMILIES_H
#define MHPLAN_WORLD_FAMILIES_H

#include "src/base/World.h"

#include <cstdint>
#include <string>

namespace mhplan
{
    /** \brief A member of a world family. */
    struct FamilyOptions
    {
        /** \brief "circles", "rectangles" (rotated), "polygons" (non-convex stars), "maze" or "grid". */
        std::string kind{"circles"};
        /** \brief Geometric kinds: the number of obstacles (1..100000). */
        std::size_t count{100};
        /** \brief Grid kinds: cells across and down (maze: rounded down to an odd count, at least 5). */
        int cells{32};
        /** \brief Geometric kinds: the share of the box the obstacles cover (0.01..0.4); the box is the
            square whose area makes the obstacles' total area this share. */
        double coverage{0.25};
        /** \brief Grid kind: the share of blocked cells ([0, 0.45]). */
        double density{0.25};
        /** \brief Radius of the disc robot (>= 0). */
        double robotRadius{0.0};
        /** \brief Geometric kinds: obstacle size range (circle radius, rectangle side, star outer radius). */
        double minSize{1.0};
        double maxSize{3.0};
        std::uint64_t seed{1};
    };

    /** \brief Generate a family member. Geometric kinds: obstacles placed one by one at uniform positions
        (random sequential addition, largest first), each kept only when it stays at least 2 r + minSize / 20
       away from every other obstacle and from the bounds (so the free space of the disc robot is connected
       for convex obstacles); all are drawn first and the box side is sqrt(total area / coverage), so exactly
       that share is covered. The description records the coverage reached. Grid kinds: generateMaze (perfect
       maze) or generateGrid (start and goal corners connected). The world's name is KIND_COUNT_sSEED (grids:
       KIND_CELLSxCELLS_sSEED); it has the generator's corner query. Throws InputError for options out of
       range, or when the obstacles do not fit (count placed of requested in the message). */
    World generateFamilyWorld(const FamilyOptions &options);

    /** \brief Options of addRandomQueries. */
    struct QueryOptions
    {
        /** \brief Number of queries (1..1000), named q0, q1, ... */
        std::size_t count{10};
        /** \brief Least start-goal distance as a share of the bounds' diagonal ([0, 0.9]). */
        double minSeparation{0.5};
        std::uint64_t seed{1};
    };

    /** \brief Replace the world's queries with \e count random ones: start and goal uniform among the valid
        positions (grids: free cell centres), at least minSeparation x diagonal apart, and connected (grids:
        8-connected cells under the MovingAI rule; geometric worlds: computeOptimum finds a path). Throws
        InputError when 1000 x count draws give too few. */
    void addRandomQueries(World &world, const QueryOptions &options);
} // namespace mhplan

#endif
