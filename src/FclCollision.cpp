#include "FclCollision.h"

namespace mhplan
{
    struct FclCollisionModel::Impl
    {
    };

    FclCollisionModel::FclCollisionModel(const World &world) : CollisionModel(world)
    {
        throw InputError("FCL collision model: not built yet");
    }
    FclCollisionModel::~FclCollisionModel() = default;
    double FclCollisionModel::clearance(const Vec2 &) const { return 0.0; }
    bool FclCollisionModel::isValid(const Vec2 &) const { return false; }
    bool FclCollisionModel::segmentValid(const Vec2 &, const Vec2 &) const { return false; }
    double FclCollisionModel::segmentClearance(const Vec2 &, const Vec2 &) const { return 0.0; }
}  // namespace mhplan
