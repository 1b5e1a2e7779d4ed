// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the FCL shapes the collision layer's FCL models share (planar polygons as prisms). */
#ifndef MHPLAN_COLLISION_DETAIL_FCL_SHAPES_H
#define MHPLAN_COLLISION_DETAIL_FCL_SHAPES_H

#include "src/base/World.h"

#include <fcl/geometry/collision_geometry.h>

#include <memory>
#include <vector>

namespace mhplan::detail
{
    /** \brief Height of the prisms that stand for planar shapes (any positive value: every query lives in the
        plane z = 0, so prisms of one height overlap in z and their 3D distance is the planar one). */
    constexpr double kPrismHeight = 1.0;

    /** \brief Convex pieces whose union covers the polygon: the polygon itself when it is convex, else the
        triangles of an ear-clipping triangulation; if ear clipping stalls on a numerically awkward
        remainder, the remainder's bounding box (a superset: conservative for collision). */
    std::vector<std::vector<Vec2>> convexPieces(const Polygon &poly);

    /** \brief An FCL convex prism over a counter-clockwise convex polygon, in the polygon's coordinates. */
    std::shared_ptr<fcl::CollisionGeometryd> makePrism(const std::vector<Vec2> &pts);
} // namespace mhplan::detail

#endif
