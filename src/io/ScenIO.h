// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: MovingAI benchmark scenario files (.scen, "version 1"). */
#ifndef MHPLAN_SCEN_IO_H
#define MHPLAN_SCEN_IO_H

#include "src/base/World.h"

#include <istream>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief One line of a MovingAI .scen file (coordinates: x = column, y = row from the top). */
    struct ScenProblem
    {
        int line{0};
        int bucket{0};
        int sx{0}, sy{0}, gx{0}, gy{0};
        double optimal{0.0};
    };

    /** \brief Parse a scenario for \e grid ("version 1", then lines of 9 fields: bucket map width height
        start-x start-y goal-x goal-y optimal-length). Throws InputError naming \e fileName and the line (a
       bad header or field, a map size other than the grid's, a start or goal outside the map or blocked). */
    std::vector<ScenProblem> parseMovingAIScen(std::istream &in, const std::string &fileName,
                                               const OccupancyGrid &grid);
    std::vector<ScenProblem> loadMovingAIScen(const std::string &path, const OccupancyGrid &grid);

    /** \brief Which problems of a scenario to use: those of \e buckets (empty: every bucket), in each bucket
        every \e every-th problem in file order (1: all), of those the first \e perBucket (0: all). */
    struct ScenSelection
    {
        std::vector<int> buckets;
        unsigned int every{1};
        unsigned int perBucket{0};
    };
    /** \brief The selected problems, in file order. */
    std::vector<ScenProblem> selectScenProblems(const std::vector<ScenProblem> &problems,
                                                const ScenSelection &selection);

    /** \brief True when a .scen optimum (written with 6 significant digits in MovingAI's own files, in
        full precision in others) equals an octile length \e cells within the format's precision: a
        relative 1e-5 (twice the rounding of 6 significant digits), at least 1e-4 cells. */
    bool scenOptimumMatches(double scenOptimal, double cells);
} // namespace mhplan

#endif
