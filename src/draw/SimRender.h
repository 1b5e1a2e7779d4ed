// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: drawing simulation runs (Simulation.h): an SVG of the trajectories (with an optional SMIL
   animation, SimSvg.cpp), an animated GIF (frames rasterised in SimGif.cpp, encoded by GifWriter.h), and the
   trajectories as CSV (SimCsv.cpp). */
#ifndef MHPLAN_SIM_RENDER_H
#define MHPLAN_SIM_RENDER_H

#include "src/draw/GifWriter.h"
#include "src/sim/Simulation.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief An SVG document of a run: the static world, every robot's trajectory in its own colour (one
        \c path element per robot, class "trajectory") with start and goal markers and its final disc and
        heading, the moving obstacles' traces (thin, light) and final positions, moving goals' traces, and a
        legend (controller, seed, makespan, flowtime, collisions, robot colours). With \e animate, dashed
        discs replay the run in a browser (SMIL; at most \e maxFrames key frames at \e fps frames per
        second; a viewer without SMIL shows them at the start). */
    std::string simulationSvg(const Scenario &scenario, const SimulationResult &result, bool animate = true,
                              int maxFrames = 300, double fps = 10.0);

    /** \brief Options of the animated GIF. */
    struct GifOptions
    {
        /** \brief Image width in pixels (the height follows the world's aspect ratio), in [16, 4096]. */
        int width{480};
        /** \brief Frames per second of the playback, in (0, 100]. */
        double fps{10.0};
        /** \brief At most this many frames (result.times is subsampled evenly), >= 2. */
        int maxFrames{300};
        /** \brief Draw the simulation time under the world. */
        bool timeLabel{true};
        /** \brief How long the last frame stays before the loop restarts, in seconds (>= 0). */
        double holdLast{2.0};
    };

    /** \brief The frames of the animation (palette indices, row-major, top row first) before encoding;
        \e palette receives the fixed palette. Throws std::invalid_argument for options out of range. */
    std::vector<std::vector<std::uint8_t>>
    renderSimulationFrames(const Scenario &scenario, const SimulationResult &result,
                           const GifOptions &options, int &width, int &height,
                           std::vector<std::array<std::uint8_t, 3>> &palette);

    /** \brief The animated GIF of a run as bytes (renderSimulationFrames + encodeGif). */
    std::vector<std::uint8_t> simulationGif(const Scenario &scenario, const SimulationResult &result,
                                            const GifOptions &options = GifOptions());

    /** \brief Write the animated GIF of a run to \e path; throws InputError naming the file if it cannot be
        written. */
    void writeSimulationGif(const Scenario &scenario, const SimulationResult &result, const std::string &path,
                            const GifOptions &options = GifOptions());

    /** \brief The trajectories as CSV: header "time,robot,x,y,heading", one row per recorded sample, ordered
        by time and then by robot index. */
    std::string trajectoryCsv(const SimulationResult &result);

    /** \brief The colour of robot \e i in drawings ("#rrggbb", 20 distinct colours, then repeating). */
    std::string robotColor(std::size_t i);
} // namespace mhplan

#endif
