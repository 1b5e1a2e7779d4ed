// SPDX-License-Identifier: BSD-3-Clause
/* mhplan optimum WORLD: the exact shortest path of the world's robot, its length and the path itself. */
#include "mhplan/cli/Commands.h"

#include "mhplan/cli/Args.h"
#include "mhplan/optimum/Optimum.h"
#include "mhplan/draw/Svg.h"
#include "mhplan/io/WorldIO.h"

#include <iomanip>
#include <iostream>

namespace mhplan::cli
{
    int cmdOptimum(const Argv &argv)
    {
        const Args args("optimum", argv, {{"query", "start", "goal", "svg"}, {}, {"octile"}});
        const World world = loadWorldArg(args);
        const Query query = queryFromArgs(world, args);
        const bool octile = args.has("octile");
        if (octile && !world.isGrid())
            throw InputError("mhplan optimum: --octile needs a grid world; '" + world.name + "' is " +
                             world.type());
        const OptimumResult r =
            octile ? computeGridOctileOptimum(world, query) : computeOptimum(world, query);
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
        if (!r.pieces.empty())
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
        for (const auto &p : r.path)
            std::cout << "  " << p.x << " " << p.y << "\n";
        if (args.has("svg"))
        {
            std::ostringstream label;
            label << std::setprecision(8) << "exact optimum (" << r.method << ") " << r.length;
            writeTextFile(args.get("svg"), worldSvg(world, &query, {{r.path, label.str(), "#1f77b4"}}));
            std::cout << "svg:     " << args.get("svg") << "\n";
        }
        return 0;
    }
} // namespace mhplan::cli
