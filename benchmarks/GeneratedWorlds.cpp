// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/GeneratedWorlds.h"

#include "benchmarks/Campaign.h"

#include "src/io/WorldIO.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace mhplan::bench
{
    std::string GeneratedWorldSpec::recipe() const
    {
        std::ostringstream s;
        s.precision(17);
        const FamilyOptions &f = family;
        s << "# mhplan generated world: name " << name << "; kind " << f.kind << "; count " << f.count
          << "; cells " << f.cells << "; coverage " << f.coverage << "; density " << f.density
          << "; robot_radius " << f.robotRadius << "; sizes " << f.minSize << " " << f.maxSize << "; seed "
          << f.seed << "; queries " << queries.count << " min_separation " << queries.minSeparation
          << " seed " << queries.seed;
        return s.str();
    }

    GeneratedWorldSpec readGeneratedWorld(const YamlReader &r, const YAML::Node &entry,
                                          const std::string &field)
    {
        GeneratedWorldSpec spec;
        spec.present = true;
        spec.line = static_cast<int>(entry.Mark().line) + 1;
        const YAML::Node g = entry["generate"];
        const std::string gf = field + ".generate";
        if (!g.IsMap())
            r.fail(g, gf,
                   "expected a mapping {kind, count, cells, coverage, density, robot_radius, min_size, "
                   "max_size, seed}");
        r.allowKeys(g, gf,
                    {"kind", "count", "cells", "coverage", "density", "robot_radius", "min_size", "max_size",
                     "seed"});
        FamilyOptions &f = spec.family;
        f.kind = r.nonEmptyText(r.require(g, "kind", gf), gf + ".kind");
        const bool grid = f.kind == "maze" || f.kind == "grid";
        if (!grid && f.kind != "circles" && f.kind != "rectangles" && f.kind != "polygons")
            r.fail(g["kind"], gf + ".kind",
                   "unknown kind '" + f.kind +
                       "'; accepted: circles, rectangles, polygons, "
                       "maze, grid");
        if (grid)
        {
            f.cells = static_cast<int>(r.integer(r.require(g, "cells", gf), gf + ".cells", 5, 8192));
            for (const char *k : {"count", "coverage", "min_size", "max_size"})
                if (g[k].IsDefined())
                    r.fail(g[k], gf + "." + k,
                           "not a key of a " + f.kind + " (grid kinds take cells and density)");
        }
        else
        {
            f.count =
                static_cast<std::size_t>(r.integer(r.require(g, "count", gf), gf + ".count", 1, 100000));
            for (const char *k : {"cells", "density"})
                if (g[k].IsDefined())
                    r.fail(g[k], gf + "." + k,
                           "not a key of " + f.kind + " (geometric kinds take count and coverage)");
        }
        if (g["coverage"].IsDefined())
            f.coverage = r.number(g["coverage"], gf + ".coverage", 0.01, 0.4);
        if (g["density"].IsDefined())
            f.density = r.number(g["density"], gf + ".density", 0.0, 0.45);
        if (g["robot_radius"].IsDefined())
            f.robotRadius = r.number(g["robot_radius"], gf + ".robot_radius", 0.0, 1e6);
        if (g["min_size"].IsDefined())
            f.minSize = r.number(g["min_size"], gf + ".min_size", 1e-9, 1e6);
        if (g["max_size"].IsDefined())
            f.maxSize = r.number(g["max_size"], gf + ".max_size", 1e-9, 1e6);
        if (f.maxSize < f.minSize)
            r.fail(g, gf + ".max_size", "must be >= min_size");
        f.seed =
            static_cast<std::uint64_t>(r.integer(r.require(g, "seed", gf), gf + ".seed", 0, 4294967295LL));

        const YAML::Node q = entry["queries"];
        const std::string qf = field + ".queries";
        if (!q.IsDefined() || !q.IsMap())
            r.fail(q.IsDefined() ? q : entry, qf,
                   "a generated world needs queries: {count, min_separation, seed} (min_separation: share of "
                   "the "
                   "diagonal)");
        r.allowKeys(q, qf, {"count", "min_separation", "seed"});
        spec.queries.count =
            static_cast<std::size_t>(r.integer(r.require(q, "count", qf), qf + ".count", 1, 1000));
        if (q["min_separation"].IsDefined())
            spec.queries.minSeparation = r.number(q["min_separation"], qf + ".min_separation", 0.0, 0.9);
        spec.queries.seed =
            static_cast<std::uint64_t>(r.integer(r.require(q, "seed", qf), qf + ".seed", 0, 4294967295LL));
        if (entry["name"].IsDefined())
            spec.name = r.nonEmptyText(entry["name"], field + ".name");
        return spec;
    }

    std::string materializeGeneratedWorld(const GeneratedWorldSpec &spec, const std::string &directory)
    {
        World world = generateFamilyWorld(spec.family);
        GeneratedWorldSpec named = spec;
        if (named.name.empty())
            named.name = world.name;
        const std::string head = named.recipe();
        const fs::path file = fs::path(directory) / (named.name + ".yaml");
        {
            std::ifstream in(file);
            std::string first;
            if (in && std::getline(in, first) && first == head)
                return file.string();
        }
        world.name = named.name;
        addRandomQueries(world, spec.queries);
        fs::create_directories(directory);
        const std::string tmp = temporaryFile(file.string());
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            out << head << "\n" << worldToYaml(world);
            if (!out)
                throw InputError("cannot write '" + tmp + "'");
        }
        fs::rename(tmp, file);
        return file.string();
    }
} // namespace mhplan::bench
