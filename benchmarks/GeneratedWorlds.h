// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: campaign worlds generated at campaign time (the scaling suite). A world entry
       - generate: {kind: circles, count: 300, seed: 3, coverage: 0.3, robot_radius: 0.5}
         queries: {count: 10, min_separation: 0.5, seed: 4}
   is generated with fixed seeds (WorldFamilies.h) and written once to LOGS/worlds/NAME.yaml, which the
   campaign then uses like any world file (its contents enter the experiments' fingerprints, the report
   draws it). Nothing large is committed: the campaign file holds only the recipe. */
#ifndef MHPLAN_BENCH_GENERATED_WORLDS_H
#define MHPLAN_BENCH_GENERATED_WORLDS_H

#include "benchmarks/WorldFamilies.h"
#include "src/io/YamlReader.h"

#include <string>

namespace mhplan::bench
{
    /** \brief The recipe of a generated campaign world. */
    struct GeneratedWorldSpec
    {
        /** \brief False for an ordinary world entry. */
        bool present{false};
        /** \brief World name (default: the generator's, e.g. circles_300_s3). */
        std::string name;
        FamilyOptions family;
        QueryOptions queries;
        /** \brief Line of the entry in the campaign file (1-based), for messages. */
        int line{0};
        /** \brief Canonical text of the recipe (every option), the first line of the generated file. */
        std::string recipe() const;
    };

    /** \brief Read the keys 'generate' (a mapping: kind, count, cells, coverage, density, robot_radius,
        min_size, max_size, seed), 'queries' (a mapping: count, min_separation, seed) and 'name' of the world
        entry \e entry; throws InputError "FILE:LINE: field 'worlds[i].generate.count': ..." for unknown keys
        and values out of range. */
    GeneratedWorldSpec readGeneratedWorld(const YamlReader &r, const YAML::Node &entry,
                                          const std::string &field);

    /** \brief Generate the world of \e spec into \e directory (created if needed) as NAME.yaml unless a file
        generated from the same recipe is there already; returns its path. Throws InputError when the
        generator fails (the message names the recipe). */
    std::string materializeGeneratedWorld(const GeneratedWorldSpec &spec, const std::string &directory);
} // namespace mhplan::bench

#endif
