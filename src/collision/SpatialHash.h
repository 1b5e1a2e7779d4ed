// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: a uniform-grid ("spatial hash") collision back end for geometric worlds with many obstacles. */
#ifndef MHPLAN_SPATIAL_HASH_H
#define MHPLAN_SPATIAL_HASH_H

#include "src/collision/Collision.h"

#include <cstdint>
#include <vector>

namespace mhplan
{
    /** \brief Exact collision queries over a uniform grid of buckets laid over the world's bounds.

        Every obstacle is listed in each bucket that its bounding box, grown by the robot radius plus a
        margin of 1e-9 of the world's size, overlaps (buckets at the grid's border also take what lies
        beyond it). The bucket side is the median of the obstacles' grown box sides (at least the side
        that gives 4M buckets), so a bucket holds about one or two obstacles whatever their number.
        Each query runs the analytic model's own per-obstacle tests (AnalyticCollisionModel, the oracle)
        on a subset of the obstacles that provably contains every obstacle that can decide the answer, so
        the answers are the oracle's, bit for bit:
        - isValid(p): the obstacles of p's bucket (only they can contain p within the robot radius);
        - segmentValid(a, b): the obstacles of every bucket the segment crosses (a column-by-column walk
          of the buckets whose intervals meet the segment; the grown boxes cover the swept disc);
        - clearance(p): rings of buckets around p's bucket, grown until the nearest value found is below
          the distance from p to the first ring not searched (minus twice the radius and the margin, with
          a rounding allowance), which certifies that no obstacle outside can be nearer;
        - segmentClearance(a, b): the same with rings around the segment's bucket rectangle.
        Queries allocate nothing; the model is immutable and thread-safe. Chosen by CollisionBackend::Auto
        for geometric worlds with more than kAutoAnalyticMaxObstacles obstacles. */
    class SpatialHashCollisionModel : public CollisionModel
    {
      public:
        explicit SpatialHashCollisionModel(const World &world);
        double clearance(const Vec2 &p) const override;
        bool isValid(const Vec2 &p) const override;
        bool segmentValid(const Vec2 &a, const Vec2 &b) const override;
        double segmentClearance(const Vec2 &a, const Vec2 &b) const override;
        std::string name() const override { return "hash"; }

        /** \brief Buckets across and down, and their side (metres). */
        int columns() const { return nx_; }
        int rows() const { return ny_; }
        double cellSize() const { return h_; }

      private:
        /** A circle as the analytic model tests it (reach^2 = (R + r)^2 precomputed identically). */
        struct CircleEntry
        {
            Vec2 center;
            double radius;
            double reach2;
            double reach;
        };

        int cellX(double x) const;
        int cellY(double y) const;
        std::size_t cell(int ix, int iy) const { return static_cast<std::size_t>(iy) * nx_ + ix; }
        /** Minimum over the obstacles of bucket \e c of the analytic clearance terms at p (before -r). */
        double bucketPointMin(std::size_t c, const Vec2 &p, double best) const;
        double bucketSegmentMin(std::size_t c, const Vec2 &a, const Vec2 &b, double best) const;
        bool bucketSegmentValid(std::size_t c, const Vec2 &a, const Vec2 &b, const Box &sb) const;
        /** Lower bound on the distance from the box [cx0, cx1] x [cy0, cy1] of buckets (grown by k) to an
            obstacle listed in no bucket of it, given the query box \e q; +inf when it covers the grid. */
        double ringBound(const Box &q, int cx0, int cx1, int cy0, int cy1) const;
        template <typename Visit>
        void visitRing(int cx0, int cx1, int cy0, int cy1, int k, Visit visit) const;

        std::vector<CircleEntry> circleItems_;
        std::vector<std::uint32_t> circleStart_;
        std::vector<Polygon> polygons_;
        std::vector<std::uint32_t> polygonItems_;
        std::vector<std::uint32_t> polygonStart_;
        Vec2 origin_;
        double h_{1.0};
        double invH_{1.0};
        int nx_{1};
        int ny_{1};
        /** Growth of the boxes beyond the robot radius, and the rounding allowance of the certificates. */
        double margin_{0.0};
    };
} // namespace mhplan

#endif
