/* mhplan: exact collision model of an occupancy-grid world. */
#ifndef MHPLAN_GRID_COLLISION_H
#define MHPLAN_GRID_COLLISION_H

#include "Collision.h"

namespace mhplan
{
    /** \brief Blocked cells are closed squares. clearance() is exact: an exact Euclidean distance transform
        (Felzenszwalb-Huttenlocher, with nearest-blocked-cell features) bounds the search, then the distance
        to the nearby blocked squares is computed in closed form. segmentValid() visits every cell the swept
        disc touches. A "pinch" corner, where two blocked cells meet diagonally with both other cells free, is
        an obstacle point: nothing passes through it (so paths cannot squeeze between diagonal walls). */
    class GridCollisionModel : public CollisionModel
    {
      public:
        explicit GridCollisionModel(const World &world);

        double clearance(const Vec2 &p) const override;
        bool isValid(const Vec2 &p) const override;
        bool segmentValid(const Vec2 &a, const Vec2 &b) const override;
        double segmentClearance(const Vec2 &a, const Vec2 &b) const override;
        std::string name() const override { return "grid"; }

        const OccupancyGrid &grid() const { return *grid_; }

      private:
        std::shared_ptr<const OccupancyGrid> grid_;
        /** \brief Distance (in metres) from each cell centre to the nearest blocked cell centre. */
        std::vector<float> edt_;
    };
} // namespace mhplan

#endif
