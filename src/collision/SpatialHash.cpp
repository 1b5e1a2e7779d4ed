// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/SpatialHash.h"
#include "src/collision/ContactRule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        /** At most this many buckets across and down (4M buckets). */
        constexpr int kMaxSide = 2048;
        /** Slack of the bucket walk along a segment, in bucket units (the boxes are grown by far more). */
        constexpr double kWalkSlack = 1e-9;
    } // namespace

    SpatialHashCollisionModel::SpatialHashCollisionModel(const World &world)
        : CollisionModel(world), polygons_(world.polygons)
    {
        if (world.isGrid())
            throw InputError("the spatial hash collision model handles geometric worlds only; '" +
                             world.name + "' is a grid world (use the grid back end)");
        const double size = std::max(bounds_.width(), bounds_.height());
        margin_ = 1e-9 * size;
        const double grow = radius_ + margin_;
        std::vector<Box> boxes;
        boxes.reserve(world.circles.size() + world.polygons.size());
        for (const Circle &c : world.circles)
            boxes.push_back(Box{c.center.x - c.radius, c.center.x + c.radius, c.center.y - c.radius,
                                c.center.y + c.radius}
                                .inflated(grow));
        for (const Polygon &p : world.polygons)
            boxes.push_back(p.bbox.inflated(grow));

        // Bucket side: the median grown box side, so that a bucket meets about (1 + 1)^2 * coverage boxes.
        std::vector<double> sides;
        sides.reserve(boxes.size());
        for (const Box &b : boxes)
            sides.push_back(std::max(b.width(), b.height()));
        double h = size;
        if (!sides.empty())
        {
            std::nth_element(sides.begin(), sides.begin() + sides.size() / 2, sides.end());
            h = sides[sides.size() / 2];
        }
        h = std::max(h, size / kMaxSide);
        if (!(h > 0.0) || !std::isfinite(h))
            h = size > 0.0 ? size : 1.0;
        h_ = h;
        invH_ = 1.0 / h;
        origin_ = {bounds_.xmin, bounds_.ymin};
        nx_ = std::clamp(static_cast<int>(std::ceil(bounds_.width() * invH_)), 1, kMaxSide);
        ny_ = std::clamp(static_cast<int>(std::ceil(bounds_.height() * invH_)), 1, kMaxSide);

        // Counting sort of (bucket, obstacle) pairs into compressed rows.
        const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
        circleStart_.assign(cells + 1, 0);
        polygonStart_.assign(cells + 1, 0);
        const std::size_t nc = world.circles.size();
        const auto forCells = [&](const Box &b, auto f)
        {
            const int x0 = cellX(b.xmin), x1 = cellX(b.xmax), y0 = cellY(b.ymin), y1 = cellY(b.ymax);
            for (int iy = y0; iy <= y1; ++iy)
                for (int ix = x0; ix <= x1; ++ix)
                    f(cell(ix, iy));
        };
        for (std::size_t i = 0; i < boxes.size(); ++i)
            forCells(boxes[i], [&](std::size_t c) { ++(i < nc ? circleStart_ : polygonStart_)[c + 1]; });
        for (std::size_t c = 0; c < cells; ++c)
        {
            circleStart_[c + 1] += circleStart_[c];
            polygonStart_[c + 1] += polygonStart_[c];
        }
        circleItems_.resize(circleStart_[cells]);
        polygonItems_.resize(polygonStart_[cells]);
        std::vector<std::uint32_t> fillC(circleStart_.begin(), circleStart_.end() - 1);
        std::vector<std::uint32_t> fillP(polygonStart_.begin(), polygonStart_.end() - 1);
        for (std::size_t i = 0; i < boxes.size(); ++i)
            forCells(boxes[i],
                     [&](std::size_t c)
                     {
                         if (i < nc)
                         {
                             const Circle &ci = world.circles[i];
                             // reach * reach exactly as the analytic model computes it per query.
                             const double reach = ci.radius + radius_;
                             circleItems_[fillC[c]++] = {ci.center, ci.radius, reach * reach, reach};
                         }
                         else
                             polygonItems_[fillP[c]++] = static_cast<std::uint32_t>(i - nc);
                     });
    }

    int SpatialHashCollisionModel::cellX(double x) const
    {
        const double u = std::floor((x - origin_.x) * invH_);
        if (!(u > 0.0))
            return 0;
        return u >= nx_ - 1 ? nx_ - 1 : static_cast<int>(u);
    }

    int SpatialHashCollisionModel::cellY(double y) const
    {
        const double u = std::floor((y - origin_.y) * invH_);
        if (!(u > 0.0))
            return 0;
        return u >= ny_ - 1 ? ny_ - 1 : static_cast<int>(u);
    }

    bool SpatialHashCollisionModel::isValid(const Vec2 &p) const
    {
        if (!inBounds(p))
            return false;
        const std::size_t c = cell(cellX(p.x), cellY(p.y));
        for (std::uint32_t i = circleStart_[c]; i < circleStart_[c + 1]; ++i)
            if (contact::pointHitsCircle(p, circleItems_[i].center, circleItems_[i].reach, tol_))
                return false;
        for (std::uint32_t i = polygonStart_[c]; i < polygonStart_[c + 1]; ++i)
            if (contact::pointHitsPolygon(p, polygons_[polygonItems_[i]], radius_, tol_))
                return false;
        return true;
    }

    bool SpatialHashCollisionModel::bucketSegmentValid(std::size_t c, const Vec2 &a, const Vec2 &b,
                                                       const Box &sb) const
    {
        for (std::uint32_t i = circleStart_[c]; i < circleStart_[c + 1]; ++i)
            if (contact::segmentHitsCircle(a, b, circleItems_[i].center, circleItems_[i].reach, tol_))
                return false;
        for (std::uint32_t i = polygonStart_[c]; i < polygonStart_[c + 1]; ++i)
        {
            const Polygon &poly = polygons_[polygonItems_[i]];
            if (sb.overlaps(poly.bbox) && contact::segmentHitsPolygon(a, b, poly, radius_, tol_))
                return false;
        }
        return true;
    }

    bool SpatialHashCollisionModel::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        if (!segmentInBounds(a, b))
            return false;
        const Box sb =
            Box{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)}.inflated(
                radius_);
        // Walk the bucket columns the segment spans; in each, the buckets between the segment's lowest and
        // highest point within the column (the grown boxes cover the swept disc, so the segment itself is
        // enough). Border columns extend to infinity like the border buckets.
        const double ax = (a.x - origin_.x) * invH_, ay = (a.y - origin_.y) * invH_;
        const double bx = (b.x - origin_.x) * invH_, by = (b.y - origin_.y) * invH_;
        const double xlo = std::min(ax, bx), xhi = std::max(ax, bx);
        const int ix0 = cellX(a.x < b.x ? a.x : b.x);
        const int ix1 = cellX(a.x < b.x ? b.x : a.x);
        const double dx = bx - ax;
        const bool steep = !(std::abs(dx) > 1e-12);
        for (int ix = ix0; ix <= ix1; ++ix)
        {
            double ylo = std::min(ay, by), yhi = std::max(ay, by);
            if (!steep)
            {
                const double x0 = ix == 0 ? xlo : std::max(xlo, static_cast<double>(ix));
                const double x1 = ix == nx_ - 1 ? xhi : std::min(xhi, static_cast<double>(ix + 1));
                const double y0 = ay + (x0 - ax) * (by - ay) / dx;
                const double y1 = ay + (x1 - ax) * (by - ay) / dx;
                ylo = std::max(std::min(y0, y1), ylo);
                yhi = std::min(std::max(y0, y1), yhi);
            }
            const double ulo = std::floor(ylo - kWalkSlack), uhi = std::floor(yhi + kWalkSlack);
            const int iy0 = ulo <= 0.0 ? 0 : (ulo >= ny_ - 1 ? ny_ - 1 : static_cast<int>(ulo));
            const int iy1 = uhi <= 0.0 ? 0 : (uhi >= ny_ - 1 ? ny_ - 1 : static_cast<int>(uhi));
            for (int iy = iy0; iy <= iy1; ++iy)
                if (!bucketSegmentValid(cell(ix, iy), a, b, sb))
                    return false;
        }
        return true;
    }

    double SpatialHashCollisionModel::bucketPointMin(std::size_t c, const Vec2 &p, double best) const
    {
        for (std::uint32_t i = circleStart_[c]; i < circleStart_[c + 1]; ++i)
            best = std::min(best, distance(p, circleItems_[i].center) - circleItems_[i].radius);
        for (std::uint32_t i = polygonStart_[c]; i < polygonStart_[c + 1]; ++i)
            best = std::min(best, pointPolygonSignedDistance(p, polygons_[polygonItems_[i]].vertices));
        return best;
    }

    double SpatialHashCollisionModel::bucketSegmentMin(std::size_t c, const Vec2 &a, const Vec2 &b,
                                                       double best) const
    {
        for (std::uint32_t i = circleStart_[c]; i < circleStart_[c + 1]; ++i)
            best =
                std::min(best, pointSegmentDistance(circleItems_[i].center, a, b) - circleItems_[i].radius);
        for (std::uint32_t i = polygonStart_[c]; i < polygonStart_[c + 1]; ++i)
            best = std::min(best, deepestSegmentPenetration(a, b, polygons_[polygonItems_[i]].vertices));
        return best;
    }

    double SpatialHashCollisionModel::ringBound(const Box &q, int cx0, int cx1, int cy0, int cy1) const
    {
        // An obstacle listed in no bucket of the rectangle has its grown box beyond one of the sides that
        // are not on the grid's border (border buckets take everything beyond the border).
        double bound = kInf;
        if (cx0 > 0)
            bound = std::min(bound, q.xmin - (origin_.x + cx0 * h_));
        if (cx1 < nx_ - 1)
            bound = std::min(bound, origin_.x + (cx1 + 1) * h_ - q.xmax);
        if (cy0 > 0)
            bound = std::min(bound, q.ymin - (origin_.y + cy0 * h_));
        if (cy1 < ny_ - 1)
            bound = std::min(bound, origin_.y + (cy1 + 1) * h_ - q.ymax);
        return bound;
    }

    template <typename Visit>
    void SpatialHashCollisionModel::visitRing(int cx0, int cx1, int cy0, int cy1, int k, Visit visit) const
    {
        const int X0 = cx0 - k, X1 = cx1 + k, Y0 = cy0 - k, Y1 = cy1 + k;
        const int xa = std::max(X0, 0), xb = std::min(X1, nx_ - 1);
        if (k == 0)
        {
            for (int iy = std::max(Y0, 0); iy <= std::min(Y1, ny_ - 1); ++iy)
                for (int ix = xa; ix <= xb; ++ix)
                    visit(cell(ix, iy));
            return;
        }
        if (Y0 >= 0)
            for (int ix = xa; ix <= xb; ++ix)
                visit(cell(ix, Y0));
        if (Y1 <= ny_ - 1)
            for (int ix = xa; ix <= xb; ++ix)
                visit(cell(ix, Y1));
        const int ya = std::max(Y0 + 1, 0), yb = std::min(Y1 - 1, ny_ - 1);
        if (X0 >= 0)
            for (int iy = ya; iy <= yb; ++iy)
                visit(cell(X0, iy));
        if (X1 <= nx_ - 1)
            for (int iy = ya; iy <= yb; ++iy)
                visit(cell(X1, iy));
    }

    double SpatialHashCollisionModel::clearance(const Vec2 &p) const
    {
        const int cx = cellX(p.x), cy = cellY(p.y);
        const Box q{p.x, p.x, p.y, p.y};
        double best = kInf;
        for (int k = 0;; ++k)
        {
            visitRing(cx, cx, cy, cy, k, [&](std::size_t c) { best = bucketPointMin(c, p, best); });
            const double bound = ringBound(q, cx - k, cx + k, cy - k, cy + k);
            // Unlisted obstacles are at least bound - r - margin away; a further margin covers rounding.
            if (bound == kInf || best < bound - radius_ - 2.0 * margin_)
                break;
        }
        return best - radius_;
    }

    double SpatialHashCollisionModel::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        const Box q{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
        const int cx0 = cellX(q.xmin), cx1 = cellX(q.xmax), cy0 = cellY(q.ymin), cy1 = cellY(q.ymax);
        double best = kInf;
        for (int k = 0;; ++k)
        {
            visitRing(cx0, cx1, cy0, cy1, k, [&](std::size_t c) { best = bucketSegmentMin(c, a, b, best); });
            const double bound = ringBound(q, cx0 - k, cx1 + k, cy0 - k, cy1 + k);
            if (bound == kInf || best < bound - radius_ - 2.0 * margin_)
                break;
        }
        return best - radius_;
    }
} // namespace mhplan
