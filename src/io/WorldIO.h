// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: reading and writing world files. */
#ifndef MHPLAN_WORLD_IO_H
#define MHPLAN_WORLD_IO_H

#include "src/base/World.h"
#include "src/io/YamlReader.h"

#include <cstddef>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The largest coordinate (in absolute value) of bounds, obstacles and query points, and the
        largest radius; beyond it lengths lose the precision the planners and the optimum solver need. */
    constexpr double kMaxCoordinate = 1e9;
    /** \brief The most vertices of one polygon. It bounds the exact-optimum solver (computeOptimum), which
        joins every pair of convex vertices by their tangents and checks each against the edges near it (an
        edge index per polygon, docs/conventions.md): about 9 s for one 2,000-vertex polygon with 1,000
        convex vertices. Collision queries are linear in it (the simplicity check is an O(n log n) sweep,
        under 1 ms at 2,000). */
    constexpr std::size_t kMaxPolygonVertices = 2000;
    /** \brief Largest robot polygon (its convex pieces are FCL shapes queried at every pose). */
    constexpr std::size_t kMaxRobotVertices = 64;
    /** \brief Largest robot-frame coordinate of a robot polygon. */
    constexpr double kMaxRobotCoordinate = 1e6;
    /** \brief The smallest extent of the bounds in x and y. */
    constexpr double kMinExtent = 1e-6;

    /** \brief Why \e b cannot bound a world (not finite, xmin >= xmax, a coordinate beyond kMaxCoordinate,
        an extent below kMinExtent), or an empty string when it can. */
    std::string boundsProblem(const Box &b);

    /** \brief Load a world in the format its extension names (worldFormats): a YAML world file (.yaml/.yml,
        see environments/README.md), a MovingAI map (.map) or a PGM image (.pgm, threshold 0.5 of the
        maximum grey value, dark = blocked). Throws
        InputError naming the file, line and field on any problem (malformed YAML, unknown keys, negative
        radii, self-intersecting polygons, start or goal out of bounds or in collision), and any file that
        is not a regular file (a FIFO, a device) or exceeds its limit before reading it (InputFile.h).
        \e contents, when given, receives the bytes that were parsed (read once, so a fingerprint of them
        describes exactly the world returned). */
    World loadWorld(const std::string &path, std::string *contents = nullptr);

    /** \brief A world file format loadWorld reads (docs/conventions.md, "Adding a world format"): the file
        extensions it is chosen by (lower case, without the dot), the most bytes a file may have, and its
        parser, which turns the file's whole text into a World (\e path names the file in messages) and
        refuses bad input with InputError "FILE:LINE: ...". \e limitNote, when not empty, replaces the
        reader's size complaint: "FILE: the world file is larger than N bytes; <limitNote>". */
    struct WorldFormat
    {
        std::vector<std::string> extensions;
        std::size_t maxBytes{0};
        std::function<World(const std::string &text, const std::string &path)> parse;
        std::string limitNote;
    };

    /** \brief Every world format loadWorld reads, the built-in ones first (YAML, MovingAI map, PGM; the
        registration list in WorldIO.cpp), in registration order: the order of the accepted list in
        messages and of the extensions a shipped world's name is tried with. */
    const std::vector<WorldFormat> &worldFormats();

    /** \brief Register one more world format (a program's or a test's own). Throws std::invalid_argument
        when it has no extension or no parser, or when one of its extensions is taken. */
    void registerWorldFormat(WorldFormat format);

    /** \brief Remove a format registered by registerWorldFormat (tests), named by one of its extensions;
        false when there is none or it is a built-in one. */
    bool unregisterWorldFormat(const std::string &extension);

    /** \brief Parse a YAML world from text; \e fileName is used in error messages and to resolve relative
        grid file paths (relative to its directory). */
    World parseWorldYaml(const std::string &text, const std::string &fileName);

    /** \brief Read the world keys of a YAML mapping (the world file format); \e extraKeys are further
        top-level keys the caller reads itself (a scenario file extends the world format this way). Errors
        as parseWorldYaml, with \e r's file name. */
    World readWorldNode(const YamlReader &r, const YAML::Node &root,
                        const std::set<std::string> &extraKeys = {});

    /** \brief Write a geometric or grid world as YAML (grids inline as rows of '.' and '@'). */
    std::string worldToYaml(const World &world);

    /** \brief Validate a world's queries against its own collision model (throws InputError). */
    void validateWorldQueries(const World &world);
} // namespace mhplan

#endif
