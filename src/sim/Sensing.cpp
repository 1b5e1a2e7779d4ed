// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: surface distances of sensed obstacles (detail/Sensing.h). */
#include "src/sim/detail/Sensing.h"

#include <sstream>

namespace mhplan
{
    namespace detail
    {
        double surfaceDistance(const Simulation &sim, const SensedObstacle &o, const Vec2 &p, Vec2 *nearest)
        {
            using Shape = SensedObstacle::Shape;
            switch (o.shape)
            {
            case Shape::Disc:
            {
                const double d = distance(p, o.center);
                if (nearest != nullptr)
                    *nearest = o.center + unit(p - o.center) * o.radius;
                return d - o.radius;
            }
            case Shape::Wall:
            {
                const double d = dot(p - o.center, o.normal);
                if (nearest != nullptr)
                    *nearest = p - o.normal * d;
                return d;
            }
            case Shape::Polygon:
            {
                const std::vector<Vec2> &v = o.polygon->vertices;
                double best = kInf;
                Vec2 bestPoint = p;
                for (std::size_t k = 0; k < v.size(); ++k)
                {
                    const Vec2 q = closestPointOnSegment(p, v[k], v[(k + 1) % v.size()]);
                    const double d = distance(p, q);
                    if (d < best)
                    {
                        best = d;
                        bestPoint = q;
                    }
                }
                if (nearest != nullptr)
                    *nearest = bestPoint;
                return pointInPolygon(p, v) ? -best : best;
            }
            case Shape::Grid:
            {
                const CollisionModel &model = sim.staticModel();
                const double c = model.clearance(p);
                if (nearest != nullptr)
                {
                    const double h = sim.scenario().world.grid->cellSize() / 20.0;
                    const Vec2 g(model.clearance(p + Vec2(h, 0.0)) - model.clearance(p - Vec2(h, 0.0)),
                                 model.clearance(p + Vec2(0.0, h)) - model.clearance(p - Vec2(0.0, h)));
                    *nearest = p - unit(g) * c;
                }
                return c;
            }
            }
            return kInf;
        }

        std::string formatNumber(double v)
        {
            std::ostringstream out;
            out.precision(12);
            out << v;
            return out.str();
        }
    } // namespace detail
} // namespace mhplan
