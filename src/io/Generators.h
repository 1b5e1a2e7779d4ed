// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: random world generators (seeded, reproducible). */
#ifndef MHPLAN_GENERATORS_H
#define MHPLAN_GENERATORS_H

#include "src/base/World.h"

#include <cstdint>
#include <random>

namespace mhplan
{
    /** \brief Portable uniform numbers for the world generators (std distributions differ between standard
        libraries): a 64-bit Mersenne twister mapped to [0, 1) with 53 bits. */
    class PortableRandom
    {
      public:
        explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}
        double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
        double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
        std::size_t index(std::size_t n)
        {
            return static_cast<std::size_t>(uniform01() * static_cast<double>(n));
        }

      private:
        std::mt19937_64 engine_;
    };

    /** \brief Options shared by the generators. Sizes are in metres (grid: cells). */
    struct GeneratorOptions
    {
        std::uint64_t seed{1};
        Box bounds{0.0, 10.0, 0.0, 10.0};
        double robotRadius{0.0};
        std::size_t count{20}; ///< circles, rectangles
        double minSize{0.2};   ///< circle radius or rectangle side, minimum
        double maxSize{1.0};   ///< maximum
        int width{32};         ///< grid and maze: cells across
        int height{32};        ///< grid and maze: cells down
        double cellSize{1.0};  ///< grid and maze: metres per cell
        double density{0.25};  ///< grid: share of blocked cells
    };

    /** \brief Every generated world has one query "default" from the bottom-left to the top-right corner:
        the centres of the corner cells for grids, the corners inset by max(robot radius, 2% of the size)
        for geometric worlds. Random numbers come from a 64-bit Mersenne twister with the given seed and a
        portable uniform mapping, so a seed gives the same world on every platform. Throws InputError for
        impossible options (sizes, counts, density out of range). */

    /** \brief Random circles, not covering the corner start and goal. */
    World generateCircles(const GeneratorOptions &opt);
    /** \brief Random rotated rectangles, not covering the corner start and goal. */
    World generateRectangles(const GeneratorOptions &opt);
    /** \brief A perfect maze (randomised depth-first search) as an occupancy grid of (2w+1) x (2h+1) cells
        for w x h maze cells; start and goal in opposite corners. */
    World generateMaze(const GeneratorOptions &opt);
    /** \brief A random occupancy grid of the given density whose start and goal corners are connected
        (8-connected, MovingAI rule); resampled (deterministically) until they are. */
    World generateGrid(const GeneratorOptions &opt);

    /** \brief True when the two cells are connected 8-wise under the MovingAI rule (a diagonal move needs
       both side cells free). */
    bool gridCellsConnected(const OccupancyGrid &grid, int sx, int sy, int gx, int gy);
} // namespace mhplan

#endif
