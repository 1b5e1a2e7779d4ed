// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: exact collision model of an occupancy-grid world. */
#ifndef MHPLAN_GRID_COLLISION_H
#define MHPLAN_GRID_COLLISION_H

#include "src/collision/Collision.h"

#include <cstdint>
#include <vector>

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
        /** \brief For each cell (index iy * width + ix), the first and last column of its maximal run of
            equal cells (all free or all blocked) in its row: the nearest blocked (or free) cell of a row on
            either side in O(1). */
        std::vector<std::int32_t> runStart_, runEnd_;

        int locateX(double x) const;
        int locateY(double y) const;
        double cellX0(int ix) const { return grid_->origin().x + ix * grid_->cellSize(); }
        double cellY0(int iy) const { return grid_->origin().y + iy * grid_->cellSize(); }
        bool isPinchVertex(int vx, int vy) const;
        double blockedDistance2(const Vec2 &p, int ix, int iy, double maxGap, double stopBelow) const;
        double freeDistance2(const Vec2 &p, int ix, int iy) const;
        double edtLowerBound(const Vec2 &p, int ix, int iy) const;
        double penetrationDepth(const Vec2 &p) const;
        double maxSegmentPenetration(const Vec2 &a, const Vec2 &b) const;
        double pieceMaxPenetration2(const Vec2 &a, const Vec2 &b, double t0, double t1, int ix, int iy) const;
        template <typename Visitor>
        bool forEachBlockedInBand(const Vec2 &a, const Vec2 &b, double radius, Visitor &&visit) const;
    };
} // namespace mhplan

#endif
