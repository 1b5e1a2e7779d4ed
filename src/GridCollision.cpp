#include "GridCollision.h"

namespace mhplan
{
    GridCollisionModel::GridCollisionModel(const World &world) : CollisionModel(world), grid_(world.grid)
    {
        throw InputError("grid collision model: not built yet");
    }
    double GridCollisionModel::clearance(const Vec2 &) const { return 0.0; }
    bool GridCollisionModel::isValid(const Vec2 &) const { return false; }
    bool GridCollisionModel::segmentValid(const Vec2 &, const Vec2 &) const { return false; }
    double GridCollisionModel::segmentClearance(const Vec2 &, const Vec2 &) const { return 0.0; }
}  // namespace mhplan
