// SPDX-License-Identifier: BSD-3-Clause
/* mhplan optimum WORLD: the exact shortest path of the world's robot, its length and the path itself. */
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/cli/Help.h"
#include "src/cli/Json.h"
#include "src/optimum/Optimum.h"
#include "src/draw/Svg.h"
#include "src/io/WorldIO.h"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace mhplan::cli
{
    const CommandDoc &optimumDoc()
    {
        static const CommandDoc doc{
            "optimum WORLD [options]",
            "the exact shortest path of the world's disc robot: its length, method, pieces and points",
            "Geometric worlds: the tangent graph of the inflated obstacles (segments and arcs); grids: the "
            "any-angle optimum (or, with --octile, the 8-connected MovingAI optimum).",
            {{"WORLD", "a world file or the name of a shipped world"}},
            {options::query(),
             options::start(),
             options::goal(),
             {"--octile", "", "grid worlds: the 8-connected (octile) optimum instead of the any-angle one"},
             options::svg("the world, the query and the optimal path"),
             options::json("the optimum (length, method, graph size, pieces, path)"),
             {"--quiet", "", "leave out the pieces and the path's points (text output)"}},
            {"optimum bfo_case1", "optimum gms_grid20 --octile --json",
             "optimum lrsma_scenario2 --svg opt.svg"},
            "0 a path exists, 1 bad input, 2 internal error, 3 start and goal are not connected"};
        return doc;
    }

    int cmdOptimum(const Argv &argv)
    {
        const Args args("optimum", argv,
                        {{"query", "start", "goal", "svg"}, {}, {"octile", "json", "quiet"}});
        checkOutputFile(args, "svg");
        const World world = loadWorldArg(args);
        const Query query = queryFromArgs(world, args);
        const bool octile = args.has("octile");
        if (octile && !world.isGrid())
            throw InputError("mhplan optimum: --octile needs a grid world; '" + world.name + "' is " +
                             world.type());
        const OptimumResult r =
            octile ? computeGridOctileOptimum(world, query) : computeOptimum(world, query);
        if (args.has("svg") && r.found)
        {
            std::ostringstream label;
            label << std::setprecision(8) << "exact optimum (" << r.method << ") " << r.length;
            writeTextFile(args.get("svg"), worldSvg(world, &query, {{r.path, label.str(), "#1f77b4"}}));
        }
        if (args.has("json"))
        {
            JsonWriter out(std::cout);
            out.beginObject().field("command", "optimum");
            out.key("world");
            writeWorldSummary(out, world);
            out.key("query");
            writeQuery(out, query, world.isRigid());
            out.field("method", r.method)
                .field("found", r.found)
                .field("graph_nodes", r.graphNodes)
                .field("graph_edges", r.graphEdges)
                .field("seconds", r.seconds);
            out.key("length");
            r.found ? out.value(r.length) : out.null();
            out.key("length_cells");
            r.found &&world.isGrid() ? out.value(r.lengthCells) : out.null();
            out.key("cell_size");
            world.isGrid() ? out.value(world.grid->cellSize()) : out.null();
            out.key("pieces").beginArray();
            for (const auto &p : r.pieces)
            {
                out.beginObject().field("kind", p.arc ? "arc" : "segment");
                out.key("from").point(p.from);
                out.key("to").point(p.to);
                out.field("length", p.length);
                if (p.arc)
                {
                    out.key("center").point(p.center);
                    out.field("radius", p.radius);
                }
                out.endObject();
            }
            out.endArray();
            out.key("path").points(r.path);
            out.key("svg");
            args.has("svg") && r.found ? out.value(args.get("svg")) : out.null();
            out.endObject().finish();
            return r.found ? 0 : 3;
        }
        std::cout << "world:   " << world.name << " (" << world.type() << ", " << world.obstacleCount()
                  << " obstacles, robot radius " << world.robotRadius << ")\n";
        std::cout << "query:   " << query.name << " (" << query.start.x << ", " << query.start.y << ") -> ("
                  << query.goal.x << ", " << query.goal.y << ")\n";
        std::cout << "method:  " << r.method << " (" << r.graphNodes << " nodes, " << r.graphEdges
                  << " edges, " << std::setprecision(4) << r.seconds * 1e3 << " ms)\n";
        if (!r.found)
        {
            std::cout << "length:  no path: start and goal are not connected\n";
            return 3;
        }
        std::cout << std::setprecision(12) << "length:  " << r.length << "\n";
        if (world.isGrid())
            std::cout << "cells:   " << r.lengthCells << " (cell size " << world.grid->cellSize() << ")\n";
        if (!r.pieces.empty() && !args.has("quiet"))
        {
            std::cout << "pieces:  " << r.pieces.size() << "\n";
            for (const auto &p : r.pieces)
            {
                std::cout << "  " << (p.arc ? "arc    " : "segment") << " (" << p.from.x << ", " << p.from.y
                          << ") -> (" << p.to.x << ", " << p.to.y << ") length " << p.length;
                if (p.arc)
                    std::cout << " around (" << p.center.x << ", " << p.center.y << ") radius " << p.radius;
                std::cout << "\n";
            }
        }
        std::cout << "path:    " << r.path.size() << " points (arcs as circumscribed polylines)\n";
        if (!args.has("quiet"))
            for (const auto &p : r.path)
                std::cout << "  " << p.x << " " << p.y << "\n";
        if (args.has("svg"))
            std::cout << "svg:     " << args.get("svg") << "\n";
        return 0;
    }
} // namespace mhplan::cli
