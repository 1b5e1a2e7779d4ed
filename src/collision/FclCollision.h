// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: FCL-backed collision model for geometric worlds. */
#ifndef MHPLAN_FCL_COLLISION_H
#define MHPLAN_FCL_COLLISION_H

#include "src/collision/Collision.h"

#include <memory>

namespace mhplan
{
    /** \brief Collision model that keeps every obstacle as a prism (circles as cylinders, polygons as
        extruded convex pieces) in an FCL broadphase manager; the robot is a disc (cylinder). FCL's broadphase
        finds the candidate obstacles; the narrow phase is exact (the same closed-form distances as the
        analytic model), so both models agree to rounding. */
    class FclCollisionModel : public CollisionModel
    {
      public:
        explicit FclCollisionModel(const World &world);
        ~FclCollisionModel() override;

        double clearance(const Vec2 &p) const override;
        bool isValid(const Vec2 &p) const override;
        bool segmentValid(const Vec2 &a, const Vec2 &b) const override;
        double segmentClearance(const Vec2 &a, const Vec2 &b) const override;
        std::string name() const override { return "fcl"; }

      private:
        struct Impl;
        std::unique_ptr<Impl> impl_;
    };
} // namespace mhplan

#endif
