/* mhplan: random world generators (seeded, reproducible). */
#ifndef MHPLAN_GENERATORS_H
#define MHPLAN_GENERATORS_H

#include "World.h"

#include <cstdint>

namespace mhplan
{
    /** \brief Options shared by the generators. Sizes are in metres (grid: cells). */
    struct GeneratorOptions
    {
        std::uint64_t seed{1};
        Box bounds{0.0, 10.0, 0.0, 10.0};
        double robotRadius{0.0};
        std::size_t count{20};      ///< circles, rectangles
        double minSize{0.2};        ///< circle radius or rectangle side, minimum
        double maxSize{1.0};        ///< maximum
        int width{32};              ///< grid and maze: cells across
        int height{32};             ///< grid and maze: cells down
        double cellSize{1.0};       ///< grid and maze: metres per cell
        double density{0.25};       ///< grid: share of blocked cells
        /** \brief Start and goal: default bottom-left and top-right corners (centre of the corner cell for
            grids; a margin of maxSize... for geometric worlds the corners inset by the robot radius). */
        bool cornerQuery{true};
    };

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
}  // namespace mhplan

#endif
