// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the uniform bucket grid the tangent graph checks its segments and arcs against
   (src/optimum/TangentGraph.cpp). Not part of the installed API. */
#ifndef MHPLAN_OPTIMUM_DETAIL_BUCKET_INDEX_H
#define MHPLAN_OPTIMUM_DETAIL_BUCKET_INDEX_H

#include "src/base/Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mhplan
{
    namespace optimum_detail
    {
        /** Uniform bucket grid over a region: each bucket lists the obstacles whose (inflated) bounding box
            meets it. Queries visit only the buckets a segment or box crosses. Not thread-safe (stamps). */
        class BucketIndex
        {
          public:
            BucketIndex(const Box &region, std::size_t obstacles)
            {
                const double side = std::max(region.width(), region.height());
                const int per = std::clamp(
                    static_cast<int>(std::ceil(std::sqrt(static_cast<double>(obstacles)))), 1, 512);
                cell_ = std::max(side / per, 1e-12);
                x0_ = region.xmin;
                y0_ = region.ymin;
                nx_ = std::max(1, static_cast<int>(std::ceil(region.width() / cell_)));
                ny_ = std::max(1, static_cast<int>(std::ceil(region.height() / cell_)));
                buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
                stamp_.assign(obstacles, 0);
            }

            void insert(int id, const Box &bb)
            {
                const int ix0 = colOf(bb.xmin);
                const int ix1 = colOf(bb.xmax);
                const int iy0 = rowOf(bb.ymin);
                const int iy1 = rowOf(bb.ymax);
                if (bb.xmax < x0_ || bb.ymax < y0_ || bb.xmin > x0_ + nx_ * cell_ ||
                    bb.ymin > y0_ + ny_ * cell_)
                    return;
                for (int iy = iy0; iy <= iy1; ++iy)
                    for (int ix = ix0; ix <= ix1; ++ix)
                        buckets_[static_cast<std::size_t>(iy) * nx_ + ix].push_back(id);
            }

            /** Calls f(id) for each obstacle in the buckets the segment crosses (each once); stops and
                returns true as soon as f returns true. */
            template <typename F> bool anyOnSegment(const Vec2 &a, const Vec2 &b, F &&f) const
            {
                next();
                const double eps = 1e-9 * cell_;
                const int ca = colOf(a.x);
                const int cb = colOf(b.x);
                const int step = ca <= cb ? 1 : -1;
                const double dx = b.x - a.x;
                for (int c = ca;; c += step)
                {
                    double ylo, yhi;
                    if (ca == cb || dx == 0.0)
                    {
                        ylo = std::min(a.y, b.y);
                        yhi = std::max(a.y, b.y);
                    }
                    else
                    {
                        const double xl = std::max(std::min(a.x, b.x), x0_ + c * cell_);
                        const double xr = std::min(std::max(a.x, b.x), x0_ + (c + 1) * cell_);
                        const double yl = a.y + (b.y - a.y) * ((xl - a.x) / dx);
                        const double yr = a.y + (b.y - a.y) * ((xr - a.x) / dx);
                        ylo = std::min(yl, yr);
                        yhi = std::max(yl, yr);
                    }
                    const int r0 = rowOf(ylo - eps);
                    const int r1 = rowOf(yhi + eps);
                    for (int r = r0; r <= r1; ++r)
                        if (visit(c, r, f))
                            return true;
                    if (c == cb)
                        break;
                }
                return false;
            }

            template <typename F> bool anyInBox(const Box &bb, F &&f) const
            {
                next();
                for (int r = rowOf(bb.ymin), r1 = rowOf(bb.ymax); r <= r1; ++r)
                    for (int c = colOf(bb.xmin), c1 = colOf(bb.xmax); c <= c1; ++c)
                        if (visit(c, r, f))
                            return true;
                return false;
            }

          private:
            double x0_{0.0}, y0_{0.0}, cell_{1.0};
            int nx_{1}, ny_{1};
            std::vector<std::vector<int>> buckets_;
            mutable std::vector<std::uint32_t> stamp_;
            mutable std::uint32_t current_{0};

            int colOf(double x) const
            {
                return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
            }
            int rowOf(double y) const
            {
                return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
            }
            void next() const
            {
                if (++current_ == 0)
                {
                    std::fill(stamp_.begin(), stamp_.end(), 0);
                    current_ = 1;
                }
            }
            template <typename F> bool visit(int c, int r, F &f) const
            {
                for (int id : buckets_[static_cast<std::size_t>(r) * nx_ + c])
                {
                    if (stamp_[id] == current_)
                        continue;
                    stamp_[id] = current_;
                    if (f(id))
                        return true;
                }
                return false;
            }
        };
    } // namespace optimum_detail
} // namespace mhplan

#endif
