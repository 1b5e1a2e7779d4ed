// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the quick reading of a world file's 'queries:' list (docs/conventions.md, "Large query lists"). */
#ifndef MHPLAN_QUERY_LIST_H
#define MHPLAN_QUERY_LIST_H

#include "src/base/World.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief A world file's text split into its 'queries:' list, read, and the rest of the text. */
    struct SplitQueries
    {
        /** \brief The queries in file order, named as the world reader names them ("default", "q1", ... when
            a query has no name). */
        std::vector<Query> queries;
        /** \brief Whether some query gives a heading [x, y, yaw] (only an SE(2)-based world may). */
        bool headings{false};
        /** \brief The file's text with the list replaced by "[]" and as many line breaks as it spanned, so
            that every other node keeps its line and column. */
        std::string rest;
    };

    /** \brief Read the top-level 'queries:' list of a YAML world from yaml-cpp's parse events, without
        building yaml-cpp's node tree (about 5 KB per query: a world of 10^5 queries took 470 MB and 2.3 s of
        CPU to load, 0.55 s to scan). Returns nothing whenever the list is not in the plain form the world
        reader accepts without complaint (a mapping of name, start and goal per query, plain or quoted
        numbers within the coordinate limits, unique names, no anchors, aliases or explicit tags; the file
        one block mapping; the text malformed YAML, ...): the caller then reads the file with yaml-cpp's
        tree, which names the problem. What it returns is what that reader would read. */
    std::optional<SplitQueries> splitQueries(const std::string &text);

    /** \brief How many times splitQueries returned a split since the program started (for tests). */
    std::size_t splitQueriesCount();
} // namespace mhplan

#endif
