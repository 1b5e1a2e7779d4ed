// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the SVG of a run: trajectories, markers, moving obstacles, legend, and the SMIL replay. */
#include "src/draw/SimRender.h"

#include "src/draw/Svg.h"
#include "src/draw/detail/Raster.h"
#include "src/draw/detail/Timeline.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace mhplan
{
    using draw_detail::frameIndices;
    using draw_detail::lastSampleAtOrBefore;
    using draw_detail::View;

    namespace
    {
        std::string formatNumber(double v, int precision = 3)
        {
            if (std::isinf(v))
                return v > 0 ? "inf" : "-inf";
            std::ostringstream s;
            s << std::fixed << std::setprecision(precision) << v;
            return s.str();
        }
    } // namespace

    std::string simulationSvg(const Scenario &scenario, const SimulationResult &result, bool animate,
                              int maxFrames, double fps)
    {
        const Box &b = scenario.world.bounds;
        if (!(b.width() > 0.0) || !(b.height() > 0.0))
            throw std::invalid_argument("simulationSvg: the scenario's world has empty bounds");
        if (animate && (maxFrames < 2 || !(fps > 0.0)))
            throw std::invalid_argument("simulationSvg: maxFrames must be >= 2 and fps > 0 (got " +
                                        std::to_string(maxFrames) + ", " + std::to_string(fps) + ")");
        View v;
        v.bounds = b;
        v.margin = 20.0;
        v.scale = 800.0 / std::max(b.width(), b.height());
        const double w = b.width() * v.scale + 2 * v.margin;
        const double worldH = b.height() * v.scale + 2 * v.margin;
        const std::size_t robots = result.robots.size();
        const int perRow = std::max(1, static_cast<int>((w - 2 * v.margin) / 150.0));
        const std::size_t swatchRows =
            (robots + static_cast<std::size_t>(perRow) - 1) / static_cast<std::size_t>(perRow);
        const double legendH = 3 * 18.0 + 18.0 * static_cast<double>(swatchRows) + 10.0;
        const double h = worldH + legendH;

        std::ostringstream s;
        s << std::fixed << std::setprecision(2);
        s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
          << "\" viewBox=\"0 0 " << w << " " << h << "\">\n";
        s << "<title>" << svgEscape(result.scenario.empty() ? scenario.name : result.scenario) << " - "
          << svgEscape(result.controller) << "</title>\n";
        s << "<rect x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h << "\" fill=\"white\"/>\n";
        s << worldSvgShapes(scenario.world, v.scale, v.margin);

        auto pointList = [&](const std::vector<Vec2> &pts)
        {
            std::ostringstream p;
            p << std::fixed << std::setprecision(2);
            for (const auto &q : pts)
                p << v.x(q.x) << "," << v.y(q.y) << " ";
            return p.str();
        };

        // Moving obstacles: traces and final positions.
        s << "<g class=\"moving-obstacles\">\n";
        for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
        {
            const auto &pos = result.obstaclePositions[o];
            if (pos.empty())
                continue;
            const double r =
                (o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2) * v.scale;
            s << "<polyline fill=\"none\" stroke=\"#bbbbbb\" stroke-width=\"1\" points=\"" << pointList(pos)
              << "\"/>\n";
            s << "<circle cx=\"" << v.x(pos.back().x) << "\" cy=\"" << v.y(pos.back().y) << "\" r=\"" << r
              << "\" fill=\"#e6550d\" fill-opacity=\"0.5\" stroke=\"#a63603\">";
            if (o < scenario.movingObstacles.size())
                s << "<title>" << svgEscape(scenario.movingObstacles[o].name) << "</title>";
            s << "</circle>\n";
        }
        s << "</g>\n";

        // Robots: trajectory, start, goals, final disc and heading.
        for (std::size_t i = 0; i < robots; ++i)
        {
            const RobotResult &r = result.robots[i];
            const std::string color = robotColor(i);
            const double radius = (i < scenario.robots.size() ? scenario.robots[i].radius : 0.105) * v.scale;
            s << "<g class=\"robot\">\n";
            // Moving goal: its trace (dashed).
            if (i < result.goalPositions.size() && !result.goalPositions[i].empty())
            {
                const auto &g = result.goalPositions[i];
                bool moves = false;
                for (const auto &p : g)
                    moves = moves || distance(p, g.front()) > 1e-9;
                if (moves)
                    s << "<polyline fill=\"none\" stroke=\"" << color
                      << "\" stroke-width=\"1\" stroke-dasharray=\"4 3\" stroke-opacity=\"0.6\" points=\""
                      << pointList(g) << "\"/>\n";
            }
            // The trajectory, thinned to points at least half a pixel apart.
            s << "<path class=\"trajectory\" fill=\"none\" stroke=\"" << color
              << "\" stroke-width=\"2\" stroke-linejoin=\"round\" d=\"";
            Vec2 lastKept;
            for (std::size_t k = 0; k < r.positions.size(); ++k)
            {
                const Vec2 &p = r.positions[k];
                if (k > 0 && k + 1 < r.positions.size() && distance(p, lastKept) * v.scale < 0.5)
                    continue;
                s << (k == 0 ? "M" : " L") << v.x(p.x) << " " << v.y(p.y);
                lastKept = p;
            }
            s << "\"><title>" << svgEscape(r.name) << " (" << toString(r.status) << ")</title></path>\n";
            if (!r.positions.empty())
            {
                const Vec2 &p0 = r.positions.front();
                s << "<circle cx=\"" << v.x(p0.x) << "\" cy=\"" << v.y(p0.y)
                  << "\" r=\"4\" fill=\"white\" stroke=\"" << color << "\" stroke-width=\"2\"><title>"
                  << svgEscape(r.name) << " start</title></circle>\n";
            }
            if (i < scenario.robots.size())
                for (std::size_t k = 0; k < scenario.robots[i].tasks.size(); ++k)
                {
                    Vec2 g = scenario.robots[i].tasks[k].goal.from;
                    if (scenario.robots[i].tasks[k].goal.kind != Motion::Kind::Fixed)
                    {
                        if (i >= result.goalPositions.size() || result.goalPositions[i].empty())
                            continue;
                        g = result.goalPositions[i].back();
                    }
                    const double gx = v.x(g.x), gy = v.y(g.y);
                    s << "<line x1=\"" << gx - 5 << "\" y1=\"" << gy - 5 << "\" x2=\"" << gx + 5 << "\" y2=\""
                      << gy + 5 << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
                    s << "<line x1=\"" << gx - 5 << "\" y1=\"" << gy + 5 << "\" x2=\"" << gx + 5 << "\" y2=\""
                      << gy - 5 << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
                }
            if (!r.positions.empty())
            {
                const Vec2 &pe = r.positions.back();
                const double heading = r.headings.empty() ? 0.0 : r.headings.back();
                const double cx = v.x(pe.x), cy = v.y(pe.y);
                s << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << radius << "\" fill=\"" << color
                  << "\" fill-opacity=\"0.8\" stroke=\"black\"/>\n";
                s << "<line x1=\"" << cx << "\" y1=\"" << cy << "\" x2=\""
                  << cx + std::cos(heading) * (radius + 3) << "\" y2=\""
                  << cy - std::sin(heading) * (radius + 3) << "\" stroke=\"black\"/>\n";
            }
            s << "</g>\n";
        }

        // SMIL replay: robots and moving obstacles as discs moving over the drawing.
        const std::vector<std::size_t> indices =
            animate ? frameIndices(result.times.size(), maxFrames) : std::vector<std::size_t>();
        if (indices.size() >= 2)
        {
            const double dur = static_cast<double>(indices.size()) / fps;
            s << "<g class=\"replay\">\n";
            auto animateAttr = [&](const std::string &attr, const std::vector<double> &values)
            {
                s << "<animate attributeName=\"" << attr << "\" dur=\"" << dur
                  << "s\" repeatCount=\"indefinite\" values=\"";
                for (std::size_t k = 0; k < values.size(); ++k)
                    s << (k ? ";" : "") << values[k];
                s << "\"/>";
            };
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                if (pos.empty())
                    continue;
                const double r =
                    (o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2) *
                    v.scale;
                std::vector<double> xs, ys;
                for (std::size_t idx : indices)
                {
                    const Vec2 &p = pos[std::min(idx, pos.size() - 1)];
                    xs.push_back(v.x(p.x));
                    ys.push_back(v.y(p.y));
                }
                s << "<circle r=\"" << r << "\" cx=\"" << xs[0] << "\" cy=\"" << ys[0]
                  << "\" fill=\"#e6550d\" fill-opacity=\"0.7\" stroke=\"#a63603\" stroke-dasharray=\"2 2\">";
                animateAttr("cx", xs);
                animateAttr("cy", ys);
                s << "</circle>\n";
            }
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                if (r.positions.empty())
                    continue;
                const double radius =
                    std::max(3.0, (i < scenario.robots.size() ? scenario.robots[i].radius : 0.105) * v.scale);
                std::vector<double> xs, ys;
                std::string visibility;
                bool hides = false;
                for (std::size_t idx : indices)
                {
                    const long k = lastSampleAtOrBefore(r.times, result.times[idx]);
                    const Vec2 &p = r.positions[static_cast<std::size_t>(std::max(0L, k))];
                    xs.push_back(v.x(p.x));
                    ys.push_back(v.y(p.y));
                    visibility += std::string(visibility.empty() ? "" : ";") + (k < 0 ? "hidden" : "visible");
                    hides = hides || k < 0;
                }
                s << "<circle r=\"" << radius << "\" cx=\"" << xs[0] << "\" cy=\"" << ys[0] << "\" fill=\""
                  << robotColor(i) << "\" fill-opacity=\"0.7\" stroke=\"black\" stroke-dasharray=\"2 2\">";
                animateAttr("cx", xs);
                animateAttr("cy", ys);
                if (hides)
                    s << "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" << dur
                      << "s\" repeatCount=\"indefinite\" values=\"" << visibility << "\"/>";
                s << "</circle>\n";
            }
            s << "</g>\n";
        }

        // Legend.
        double ly = worldH + 14.0;
        auto text = [&](double x, double y, const std::string &t)
        {
            s << "<text x=\"" << x << "\" y=\"" << y << "\" font-family=\"sans-serif\" font-size=\"13\">"
              << svgEscape(t) << "</text>\n";
        };
        text(v.margin, ly,
             (result.scenario.empty() ? scenario.name : result.scenario) + " | controller " +
                 result.controller + " | seed " + std::to_string(result.seed) + " | " +
                 std::to_string(result.done) + " done, " + std::to_string(result.stuck) + " stuck, " +
                 std::to_string(result.unfinished) + " unfinished");
        ly += 18.0;
        text(v.margin, ly,
             "makespan " + formatNumber(result.makespan, 2) + " s | flowtime " +
                 formatNumber(result.flowtime, 2) + " s | collisions " + std::to_string(result.collisions()) +
                 " (static " + std::to_string(result.staticCollisions) + ", moving " +
                 std::to_string(result.movingCollisions) + ", robot " +
                 std::to_string(result.robotCollisions) + ")");
        ly += 18.0;
        text(v.margin, ly,
             "min robot distance " + formatNumber(result.minRobotDistance) + " m | min obstacle clearance " +
                 formatNumber(result.minObstacleClearance) + " m | simulated " +
                 formatNumber(result.simulatedTime, 2) + " s");
        ly += 18.0;
        for (std::size_t i = 0; i < robots; ++i)
        {
            const double x = v.margin + 150.0 * static_cast<double>(i % static_cast<std::size_t>(perRow));
            const double y = ly + 18.0 * static_cast<double>(i / static_cast<std::size_t>(perRow));
            s << "<line x1=\"" << x << "\" y1=\"" << y - 4 << "\" x2=\"" << x + 20 << "\" y2=\"" << y - 4
              << "\" stroke=\"" << robotColor(i) << "\" stroke-width=\"3\"/>\n";
            text(x + 26, y, result.robots[i].name + " (" + toString(result.robots[i].status) + ")");
        }
        s << "</svg>\n";
        return s.str();
    }
} // namespace mhplan
