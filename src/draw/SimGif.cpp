// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the animated GIF of a run: the frames rasterised (static world once, trails accumulated, robots and
   moving obstacles per frame), then encoded (GifWriter.cpp). */
#include "src/draw/SimRender.h"

#include "src/draw/detail/Palette.h"
#include "src/draw/detail/Raster.h"
#include "src/draw/detail/Timeline.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    using namespace draw_detail;

    namespace
    {
        /** The static world drawn once into a canvas. */
        void drawWorld(Canvas &c, const World &world, const View &v)
        {
            const Box &b = world.bounds;
            c.fillRect(v.x(b.xmin), v.y(b.ymax), v.x(b.xmax), v.y(b.ymin), kWorld);
            if (world.isGrid())
            {
                const OccupancyGrid &g = *world.grid;
                for (int iy = 0; iy < g.height(); ++iy)
                    for (int ix = 0; ix < g.width(); ++ix)
                        if (g.blocked(ix, iy))
                        {
                            const Box cb = g.cellBox(ix, iy);
                            c.fillRect(v.x(cb.xmin), v.y(cb.ymax), v.x(cb.xmax), v.y(cb.ymin), kGridCell);
                        }
            }
            for (const auto &circle : world.circles)
            {
                const double r = circle.radius * v.scale;
                c.fillDisc(v.x(circle.center.x), v.y(circle.center.y), r, kObstacleEdge);
                c.fillDisc(v.x(circle.center.x), v.y(circle.center.y), r - 1.0, kObstacle);
            }
            for (const auto &p : world.polygons)
            {
                std::vector<std::pair<double, double>> pts;
                for (const auto &q : p.vertices)
                    pts.emplace_back(v.x(q.x), v.y(q.y));
                c.fillPolygon(pts, kObstacle);
                for (std::size_t k = 0; k < pts.size(); ++k)
                {
                    const auto &a = pts[k];
                    const auto &e = pts[(k + 1) % pts.size()];
                    c.line(a.first, a.second, e.first, e.second, kObstacleEdge);
                }
            }
            // Border of the bounds.
            const double x0 = v.x(b.xmin) - 1, y0 = v.y(b.ymax) - 1, x1 = v.x(b.xmax), y1 = v.y(b.ymin);
            c.line(x0, y0, x1, y0, kBlack);
            c.line(x1, y0, x1, y1, kBlack);
            c.line(x1, y1, x0, y1, kBlack);
            c.line(x0, y1, x0, y0, kBlack);
        }
    } // namespace

    std::vector<std::vector<std::uint8_t>>
    renderSimulationFrames(const Scenario &scenario, const SimulationResult &result,
                           const GifOptions &options, int &width, int &height,
                           std::vector<std::array<std::uint8_t, 3>> &palette)
    {
        if (options.width < 16 || options.width > 4096)
            throw std::invalid_argument("GifOptions::width must be in [16, 4096] pixels (got " +
                                        std::to_string(options.width) + ")");
        if (options.maxFrames < 2)
            throw std::invalid_argument("GifOptions::maxFrames must be >= 2 (got " +
                                        std::to_string(options.maxFrames) + ")");
        const Box &b = scenario.world.bounds;
        if (!(b.width() > 0.0) || !(b.height() > 0.0))
            throw std::invalid_argument("renderSimulationFrames: the scenario's world has empty bounds");

        palette = gifPalette();
        View v;
        v.bounds = b;
        v.margin = 4.0;
        v.scale = (options.width - 2.0 * v.margin) / b.width();
        const int label = options.timeLabel ? 16 : 0;
        width = options.width;
        const int worldH = static_cast<int>(std::lround(b.height() * v.scale + 2.0 * v.margin));
        height = std::min(4096, worldH + label);

        Canvas base(width, height, kWhite);
        drawWorld(base, scenario.world, v);

        const std::vector<std::size_t> indices = frameIndices(result.times.size(), options.maxFrames);
        std::vector<std::vector<std::uint8_t>> frames;
        if (indices.empty())
        {
            frames.push_back(base.pixels());
            return frames;
        }
        const double trail = std::max(1.0, std::round(v.scale * 0.02));
        const int trailWidth = std::min(3, static_cast<int>(trail));
        const std::size_t robots = result.robots.size();
        std::vector<long> drawn(robots, -1); // last trail sample drawn per robot
        long obstacleDrawn = -1;             // last trace index drawn
        for (std::size_t idx : indices)
        {
            const double t = result.times[idx];
            // Moving obstacles' traces, beneath everything else.
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                const long last = std::min<long>(static_cast<long>(idx), static_cast<long>(pos.size()) - 1);
                for (long k = std::max(1L, obstacleDrawn + 1); k <= last; ++k)
                    base.line(v.x(pos[static_cast<std::size_t>(k) - 1].x),
                              v.y(pos[static_cast<std::size_t>(k) - 1].y),
                              v.x(pos[static_cast<std::size_t>(k)].x),
                              v.y(pos[static_cast<std::size_t>(k)].y), kTrace, 1, kWorld);
            }
            obstacleDrawn = static_cast<long>(idx);
            // Robot trails so far.
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                const long last = lastSampleAtOrBefore(r.times, t);
                for (long k = std::max(1L, drawn[i] + 1); k <= last; ++k)
                {
                    const Vec2 &a = r.positions[static_cast<std::size_t>(k) - 1];
                    const Vec2 &e = r.positions[static_cast<std::size_t>(k)];
                    base.line(v.x(a.x), v.y(a.y), v.x(e.x), v.y(e.y), trailIndex(i), trailWidth);
                }
                drawn[i] = std::max(drawn[i], last);
            }

            Canvas frame = base;
            for (std::size_t i = 0; i < robots && i < result.goalPositions.size(); ++i)
            {
                const auto &g = result.goalPositions[i];
                if (g.empty() || lastSampleAtOrBefore(result.robots[i].times, t) < 0)
                    continue;
                const Vec2 &p = g[std::min(idx, g.size() - 1)];
                frame.cross(v.x(p.x), v.y(p.y), 3.0, robotIndex(i));
            }
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                if (pos.empty())
                    continue;
                const Vec2 &p = pos[std::min(idx, pos.size() - 1)];
                const double radius =
                    o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2;
                const double r = std::max(2.0, radius * v.scale);
                frame.fillDisc(v.x(p.x), v.y(p.y), r, kMovingObstacleEdge);
                frame.fillDisc(v.x(p.x), v.y(p.y), r - 1.0, kMovingObstacle);
            }
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                const long k = lastSampleAtOrBefore(r.times, t);
                if (k < 0)
                    continue;
                const Vec2 &p = r.positions[static_cast<std::size_t>(k)];
                const double heading = static_cast<std::size_t>(k) < r.headings.size()
                                           ? r.headings[static_cast<std::size_t>(k)]
                                           : 0.0;
                const double radius = i < scenario.robots.size() ? scenario.robots[i].radius : 0.105;
                const double rr = std::max(3.0, radius * v.scale);
                const double cx = v.x(p.x), cy = v.y(p.y);
                frame.fillDisc(cx, cy, rr, robotIndex(i));
                frame.ring(cx, cy, rr, 1.0, kBlack);
                const double c = std::cos(heading), sn = std::sin(heading);
                frame.line(cx + c * rr * 0.4, cy - sn * rr * 0.4, cx + c * (rr + 2.0), cy - sn * (rr + 2.0),
                           kBlack);
            }
            if (options.timeLabel)
            {
                std::ostringstream s;
                s << "t = " << std::fixed << std::setprecision(2) << t << " s";
                frame.fillRect(0, worldH, width, height, kWhite);
                frame.text(static_cast<int>(v.margin), worldH + 2, s.str(), kBlack, 2);
            }
            frames.push_back(std::move(frame.pixels()));
        }
        return frames;
    }

    std::vector<std::uint8_t> simulationGif(const Scenario &scenario, const SimulationResult &result,
                                            const GifOptions &options)
    {
        if (!(options.fps > 0.0) || options.fps > 100.0)
            throw std::invalid_argument("GifOptions::fps must be in (0, 100] (got " +
                                        std::to_string(options.fps) + ")");
        if (!(options.holdLast >= 0.0) || options.holdLast > 600.0)
            throw std::invalid_argument("GifOptions::holdLast must be in [0, 600] s (got " +
                                        std::to_string(options.holdLast) + ")");
        int w = 0, h = 0;
        std::vector<std::array<std::uint8_t, 3>> palette;
        const auto frames = renderSimulationFrames(scenario, result, options, w, h, palette);
        // Browsers play delays below 2 cs as 10 cs: never go below 2.
        const int delay = std::max(2, static_cast<int>(std::lround(100.0 / options.fps)));
        std::vector<int> delays(frames.size(), delay);
        delays.back() = std::min(65535, delay + static_cast<int>(std::lround(options.holdLast * 100.0)));
        return encodeGif(w, h, palette, frames, delays);
    }

    void writeSimulationGif(const Scenario &scenario, const SimulationResult &result, const std::string &path,
                            const GifOptions &options)
    {
        const std::vector<std::uint8_t> bytes = simulationGif(scenario, result, options);
        std::ofstream out(path, std::ios::binary);
        if (!out)
            throw InputError(path + ": cannot open for writing");
        out.write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out)
            throw InputError(path + ": write failed");
    }
} // namespace mhplan
