// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: what the simulator's controllers sense (the obstacles around a robot, surface distances), shared
   by the controllers' sources; not installed. */
#ifndef MHPLAN_SIM_DETAIL_SENSING_H
#define MHPLAN_SIM_DETAIL_SENSING_H

#include "src/sim/Controllers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace mhplan
{
    namespace detail
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();

        inline Vec2 unit(const Vec2 &v)
        {
            const double n = norm(v);
            return n > 0.0 ? v / n : Vec2();
        }

        inline Vec2 capped(const Vec2 &v, double limit)
        {
            const double n = norm(v);
            return n > limit ? v * (limit / n) : v;
        }

        /** \brief Distance from \e p to the surface of \e o (negative inside); the nearest surface point in
            \e nearest when it is not null (for the grid: from the clearance's numerical gradient). */
        double surfaceDistance(const Simulation &sim, const SensedObstacle &o, const Vec2 &p, Vec2 *nearest);

        /** \brief Distance from \e p to the box (0 inside). */
        inline double boxDistance(const Box &b, const Vec2 &p)
        {
            const double dx = std::max({b.xmin - p.x, 0.0, p.x - b.xmax});
            const double dy = std::max({b.ymin - p.y, 0.0, p.y - b.ymax});
            return std::hypot(dx, dy);
        }

        /** \brief Calls f(obstacle, gap, nearest) for every obstacle whose surface is within \e range of the
            surface of robot \e self's disc placed at \e p (gap = surface distance minus the robot's radius):
            static circles and polygons (the nearest blocked cell in grid worlds), the walls when \e walls,
            moving obstacles and the other present robots. Allocates nothing. */
        template <class F>
        void forEachObstacle(const Simulation &sim, std::size_t self, const Vec2 &p, double range, bool walls,
                             F &&f)
        {
            using Shape = SensedObstacle::Shape;
            using Source = SensedObstacle::Source;
            const double r = sim.spec(self).radius;
            const World &world = sim.scenario().world;
            SensedObstacle o;
            Vec2 nearest;
            auto visit = [&]()
            {
                const double gap = surfaceDistance(sim, o, p, &nearest) - r;
                if (gap <= range)
                    f(o, gap, nearest);
            };
            o.source = Source::Static;
            if (world.isGrid())
            {
                o.shape = Shape::Grid;
                if (sim.staticModel().clearance(p) - r <= range)
                    visit();
            }
            o.shape = Shape::Disc;
            for (const Circle &c : world.circles)
            {
                o.center = c.center;
                o.radius = c.radius;
                visit();
            }
            o.shape = Shape::Polygon;
            for (const Polygon &poly : world.polygons)
            {
                if (boxDistance(poly.bbox, p) - r > range)
                    continue;
                o.polygon = &poly;
                visit();
            }
            if (walls)
            {
                const Box &b = world.bounds;
                o.shape = Shape::Wall;
                const Vec2 points[4] = {{b.xmin, p.y}, {b.xmax, p.y}, {p.x, b.ymin}, {p.x, b.ymax}};
                const Vec2 normals[4] = {{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}};
                for (int k = 0; k < 4; ++k)
                {
                    o.center = points[k];
                    o.normal = normals[k];
                    visit();
                }
            }
            o.shape = Shape::Disc;
            o.source = Source::Moving;
            const auto &moving = sim.scenario().movingObstacles;
            for (std::size_t j = 0; j < moving.size(); ++j)
            {
                o.center = sim.obstaclePositions()[j];
                o.radius = moving[j].radius;
                o.velocity = sim.obstacleVelocities()[j];
                visit();
            }
            o.source = Source::Robot;
            for (std::size_t k = 0; k < sim.robotCount(); ++k)
            {
                if (k == self || !sim.present(k))
                    continue;
                o.center = sim.state(k).position;
                o.radius = sim.spec(k).radius;
                o.velocity = sim.state(k).velocity;
                visit();
            }
        }

        /** \brief True when the robot disc (radius \e r) sweeping [a, b] stays off the disc obstacles of
            \e obstacles (moving obstacles and robots), each grown by the distance it travels in \e time at
            its current speed. */
        inline bool clearOfDiscs(const std::vector<SensedObstacle> &obstacles, const Vec2 &a, const Vec2 &b,
                                 double r, double time)
        {
            for (const SensedObstacle &o : obstacles)
                if (o.shape == SensedObstacle::Shape::Disc && o.source != SensedObstacle::Source::Static &&
                    pointSegmentDistance(o.center, a, b) < o.radius + r + norm(o.velocity) * time)
                    return false;
            return true;
        }

        /** \brief A number as the parameter tables print it (12 significant digits). */
        std::string formatNumber(double v);
    } // namespace detail
} // namespace mhplan

#endif
