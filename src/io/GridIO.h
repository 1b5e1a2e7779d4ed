// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: occupancy grids from MovingAI .map files and PGM images. */
#ifndef MHPLAN_GRID_IO_H
#define MHPLAN_GRID_IO_H

#include "src/base/World.h"

#include <istream>
#include <string>

namespace mhplan
{
    /** \brief The largest grid a reader accepts (8192 x 8192 cells, 64 MiB of cells): a larger .map, .pgm,
        inline grid or generated grid is refused with a message that states this limit. A reader's memory
        grows with its input, never with the size a header declares. */
    constexpr long long kMaxGridCells = 1LL << 26;

    /** \brief Input text safe to echo in a message: printable ASCII kept, other bytes as \xHH, cut after 60
        characters. */
    std::string printableText(const std::string &s);

    /** \brief Parse a MovingAI octile map ("type octile", "height H", "width W", "map", then H rows of W
        characters: '.', 'G', 'S' free; '@', 'O', 'T', 'W' blocked). Throws InputError naming \e fileName and
        the line on any problem (bad header, wrong row length, unknown character, missing rows). */
    OccupancyGrid parseMovingAIMap(std::istream &in, const std::string &fileName, double cellSize = 1.0);
    OccupancyGrid loadMovingAIMap(const std::string &path, double cellSize = 1.0);

    /** \brief Write a grid as a MovingAI octile map ('.' free, '@' blocked). */
    std::string movingAIMapText(const OccupancyGrid &grid);

    /** \brief Parse a PGM image (P2 ASCII or P5 binary, 8 or 16 bit). A pixel is blocked when its value is
        below threshold * maxval (dark = occupied, as ROS map_server does), or above it when \e negate. */
    OccupancyGrid parsePgm(std::istream &in, const std::string &fileName, double cellSize = 1.0,
                           double threshold = 0.5, bool negate = false);
    OccupancyGrid loadPgm(const std::string &path, double cellSize = 1.0, double threshold = 0.5,
                          bool negate = false);

    /** \brief A world from a bare grid file (no queries): bounds from the grid, point robot. */
    World gridWorld(const std::string &name, std::shared_ptr<const OccupancyGrid> grid);
} // namespace mhplan

#endif
