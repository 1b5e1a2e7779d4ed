// SPDX-License-Identifier: BSD-3-Clause
/* mhplan worlds / generate: describe, validate and export worlds (text or JSON with their geometry), and
   generate new ones. */
#include "src/cli/CfgDraw.h"
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/draw/Svg.h"
#include "src/io/Generators.h"
#include "src/io/GridIO.h"
#include "src/io/WorldIO.h"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace mhplan::cli
{
    const CommandDoc &worldsDoc()
    {
        static const CommandDoc doc{
            "worlds [WORLD...] [--json]",
            "list the shipped worlds, or load, validate and describe the given world files",
            "With --json every world is exported with its geometry (bounds, circles, polygons, the grid's "
            "cells, queries): what the report draws, from the same loader that plans.",
            {{"WORLD",
              "world files (.yaml, .map) or names of shipped worlds (default: every shipped world)"}},
            {options::json("every world with its geometry and queries")},
            {"worlds", "worlds bfo_case1 --json", "worlds my_world.yaml"}};
        return doc;
    }

    const CommandDoc &generateDoc()
    {
        static const CommandDoc doc{
            "generate circles|rectangles|maze|grid [options]",
            "generate a random world (circles, rectangles, a maze or a random grid) as a world file",
            "The same seed gives the same world. Without --output the world is printed on stdout.",
            {{"KIND", "circles, rectangles, maze or grid"}},
            {{"--seed", "N", "generator seed, >= 0 (default 1)"},
             {"--count", "N", "number of obstacles (circles, rectangles), 0..10000000 (default 20)"},
             {"--min-size", "M", "smallest obstacle size: circle radius or rectangle side (m, default 0.2)"},
             {"--max-size", "M", "largest obstacle size (m, default 1)"},
             {"--bounds", "XMIN,XMAX,YMIN,YMAX", "world bounds (m, default 0,10,0,10)"},
             {"--radius", "R", "robot radius (m, default 0)"},
             {"--width", "W",
              "grid width in cells, or maze width in maze cells (a maze has 2W+1 grid cells; default 32)"},
             {"--height", "H", "grid or maze height (as --width; default 32)"},
             {"--cell-size", "S", "metres per grid cell (default 1)"},
             {"--density", "D", "share of blocked cells of a random grid (default 0.25)"},
             {"--name", "NAME", "the world's name (default: from kind and seed)"},
             {"--output", "FILE",
              "write FILE.yaml (any world) or FILE.map (a grid world, MovingAI format) instead of stdout; "
              "a name without an extension gets .yaml"}},
            {"generate circles --count 40 --seed 3 --output circles40.yaml",
             "generate maze --width 10 --height 10 --output maze.map"}};
        return doc;
    }

    int cmdGenerate(const Argv &argv)
    {
        const Args args("generate", argv,
                        {{"seed", "count", "min-size", "max-size", "bounds", "radius", "width", "height",
                          "cell-size", "density", "name", "output"},
                         {},
                         {}});
        checkOutputFile(args, "output");
        // A file the other commands read: FILE.yaml / .yml / .map; a name without an extension gets .yaml.
        std::string out = args.get("output");
        if (args.has("output"))
        {
            const std::string base = out.substr(out.find_last_of('/') + 1);
            const auto dot = base.find_last_of('.');
            const std::string ext = dot == std::string::npos ? "" : base.substr(dot + 1);
            if (base.empty() || base == "." || base == "..")
                throw InputError("mhplan generate: --output '" + out + "' names no file");
            if (dot == std::string::npos || dot == 0)
                out += ".yaml";
            else if (ext != "yaml" && ext != "yml" && ext != "map")
                throw InputError("mhplan generate: --output '" + out + "': the extension '." + ext +
                                 "' is not a world file; use .yaml (any world) or .map (a grid world)");
        }
        if (args.positional().size() != 1)
            throw InputError("mhplan generate: expected one kind: circles, rectangles, maze or grid");
        const std::string kind = args.positional()[0];
        GeneratorOptions o;
        const long long seed = args.integer("seed", 1);
        if (seed < 0)
            throw InputError("mhplan generate: --seed must be >= 0");
        o.seed = static_cast<std::uint64_t>(seed);
        const long long count = args.integer("count", static_cast<long long>(o.count));
        if (count < 0 || count > 10000000)
            throw InputError("mhplan generate: --count must be in [0, 10000000] (got " + args.get("count") +
                             ")");
        o.count = static_cast<std::size_t>(count);
        o.minSize = args.number("min-size", o.minSize);
        o.maxSize = args.number("max-size", o.maxSize);
        o.robotRadius = args.number("radius", o.robotRadius);
        o.width = static_cast<int>(args.integer("width", o.width));
        o.height = static_cast<int>(args.integer("height", o.height));
        o.cellSize = args.number("cell-size", o.cellSize);
        o.density = args.number("density", o.density);
        if (args.has("bounds"))
        {
            const std::vector<double> b = parseNumberList("--bounds", args.get("bounds"));
            if (b.size() != 4)
                throw InputError("mhplan generate: --bounds expects xmin,xmax,ymin,ymax");
            o.bounds = {b[0], b[1], b[2], b[3]};
        }
        World world;
        if (kind == "circles")
            world = generateCircles(o);
        else if (kind == "rectangles")
            world = generateRectangles(o);
        else if (kind == "maze")
            world = generateMaze(o);
        else if (kind == "grid")
            world = generateGrid(o);
        else
            throw InputError("mhplan generate: unknown kind '" + kind +
                             "'; accepted: circles, rectangles, maze, grid");
        if (args.has("name"))
            world.name = args.get("name");
        const bool asMap = out.size() > 4 && out.substr(out.size() - 4) == ".map";
        if (asMap && !world.isGrid())
            throw InputError("mhplan generate: a .map output needs a grid world (maze or grid)");
        const std::string text = asMap ? movingAIMapText(*world.grid) : worldToYaml(world);
        if (out.empty())
            std::cout << text;
        else
        {
            writeTextFile(out, text);
            std::cerr << "wrote " << out << "\n";
        }
        return 0;
    }

    int cmdWorlds(const Argv &argv)
    {
        if (isCfgArgument(argv))
            return cmdWorldsCfg(argv); // OMPL.app problems: their meshes (CfgDraw.cpp)
        const Args args("worlds", argv, {{}, {}, {"json"}});
        std::vector<std::string> files = args.positional();
        if (files.empty())
            files = shippedWorldFiles();
        else
            for (auto &f : files)
                f = resolveWorldPath(f);
        std::vector<World> worlds;
        for (const auto &f : files)
            worlds.push_back(loadWorld(f)); // refuses a bad file before anything is printed
        if (args.has("json"))
        {
            JsonWriter out(std::cout);
            out.beginObject().field("command", "worlds").key("worlds").beginArray();
            for (std::size_t i = 0; i < worlds.size(); ++i)
                writeWorld(out, worlds[i], files[i]);
            out.endArray().endObject().finish();
            return 0;
        }
        std::cout << std::left << std::setw(22) << "name" << std::setw(9) << "type" << std::setw(11)
                  << "obstacles" << std::setw(9) << "radius" << std::setw(16) << "bounds"
                  << "queries / source\n";
        bool polygonRobot = false;
        for (std::size_t i = 0; i < worlds.size(); ++i)
        {
            const World &w = worlds[i];
            std::ostringstream bounds;
            bounds << w.bounds.width() << " x " << w.bounds.height();
            std::string queries;
            for (const auto &q : w.queries)
                queries += (queries.empty() ? "" : ",") + q.name;
            // A polygon robot's radius: its reach (the largest distance of a vertex from its reference
            // point).
            std::ostringstream radius;
            radius << std::setprecision(4) << (w.robotPolygon.empty() ? w.robotRadius : w.robotReach());
            if (!w.robotPolygon.empty())
            {
                radius << "*";
                polygonRobot = true;
            }
            std::cout << std::left << std::setw(22) << w.name << std::setw(9) << w.type() << std::setw(11)
                      << w.obstacleCount() << std::setw(9) << radius.str() << std::setw(16) << bounds.str()
                      << (queries.empty() ? "-" : queries) << " / "
                      << (w.source.empty() ? files[i] : w.source);
            if (w.isRigid())
            {
                std::cout << " [space " << toString(w.space);
                if (w.turningRadius > 0.0)
                    std::cout << ", turning radius " << w.turningRadius;
                if (!w.robotPolygon.empty())
                    std::cout << ", robot polygon of " << w.robotPolygon.size() << " vertices";
                std::cout << "]";
            }
            std::cout << "\n";
        }
        if (polygonRobot)
            std::cout << "\n* a polygon robot: its reach, the largest distance of a vertex from the robot's "
                         "reference point\n";
        return 0;
    }
} // namespace mhplan::cli
