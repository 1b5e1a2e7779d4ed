// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: exact collision model of an occupancy-grid world.

   Geometry. Blocked cells are closed squares; every cell outside the grid counts as blocked, so the obstacle
   set B is the union of the blocked squares and the complement of the grid's box. Free space F is the union
   of the free closed squares. The robot is a disc of radius r >= 0.
   - clearance(p) = dist(p, B) - r when p is not in B, and -dist(p, F) - r when p is in B (minus the
     distance to the closure of free space; -infinity when the grid has no free cell). Unlike the geometric
     models, the grid's border is an obstacle for clearance (cells outside the grid are blocked).
   - isValid(p): inBounds(p) and clearance(p) >= 0, and p is not a pinch corner (a grid vertex whose four
     cells are two diagonal blocked cells and two free ones). For r = 0 that is: p is not in the interior of
     B and not a pinch corner; for r > 0 the pinch rule follows from the distance test.
   - segmentValid(a, b): every point of the closed segment is valid.

   Data. edt_ is the exact Euclidean distance transform of the cell centres (Felzenszwalb & Huttenlocher,
   "Distance Transforms of Sampled Functions", Theory of Computing 8, 2012), computed on the grid padded by a
   ring of blocked cells. It gives O(1) lower and upper bounds on dist(p, B) from the distance of p's cell
   centre to the nearest blocked centre, which decide most point queries. Exact distances come from a row
   scan: within one row the nearest blocked (or free) cell on each side of p's column is read from the run
   tables runStart_/runEnd_, and rows are visited outwards from p until the vertical gap alone exceeds the
   best distance found, so a query costs O(1 + dist / cellSize). */
#include "src/collision/GridCollision.h"
#include "src/collision/detail/DistanceTransform.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mhplan
{
    namespace
    {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        constexpr double kSqrtHalf = 0.70710678118654752440;

        /** \brief Axis-aligned box given by its bounds. */
        struct CellBox
        {
            double x0, x1, y0, y1;
        };

        double pointBoxDistance2(const Vec2 &p, const CellBox &b)
        {
            const double dx = std::max({0.0, b.x0 - p.x, p.x - b.x1});
            const double dy = std::max({0.0, b.y0 - p.y, p.y - b.y1});
            return dx * dx + dy * dy;
        }

        double pointSegmentDistance2(const Vec2 &p, const Vec2 &a, const Vec2 &b)
        {
            const Vec2 ab = b - a;
            const double len2 = squaredNorm(ab);
            double t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
            t = std::clamp(t, 0.0, 1.0);
            return squaredNorm(p - (a + ab * t));
        }

        /** \brief Liang-Barsky: the parameter interval [t0, t1] of the segment a + t (b - a), t in [0, 1],
            inside the closed box; false when they do not meet. */
        bool clipSegment(const Vec2 &a, const Vec2 &b, const CellBox &box, double &t0, double &t1)
        {
            t0 = 0.0;
            t1 = 1.0;
            const double d[2] = {b.x - a.x, b.y - a.y};
            const double o[2] = {a.x, a.y};
            const double lo[2] = {box.x0, box.y0};
            const double hi[2] = {box.x1, box.y1};
            for (int k = 0; k < 2; ++k)
            {
                if (d[k] == 0.0)
                {
                    if (o[k] < lo[k] || o[k] > hi[k])
                        return false;
                    continue;
                }
                double ta = (lo[k] - o[k]) / d[k];
                double tb = (hi[k] - o[k]) / d[k];
                if (ta > tb)
                    std::swap(ta, tb);
                t0 = std::max(t0, ta);
                t1 = std::min(t1, tb);
                if (t0 > t1)
                    return false;
            }
            return true;
        }

        /** \brief Squared distance between the closed segment [a, b] and the closed box. */
        double segmentBoxDistance2(const Vec2 &a, const Vec2 &b, const CellBox &box)
        {
            double t0, t1;
            if (clipSegment(a, b, box, t0, t1))
                return 0.0;
            // Disjoint convex sets: the closest pair involves an endpoint of the segment or a box corner.
            double best = std::min(pointBoxDistance2(a, box), pointBoxDistance2(b, box));
            best = std::min(best, pointSegmentDistance2({box.x0, box.y0}, a, b));
            best = std::min(best, pointSegmentDistance2({box.x1, box.y0}, a, b));
            best = std::min(best, pointSegmentDistance2({box.x0, box.y1}, a, b));
            best = std::min(best, pointSegmentDistance2({box.x1, box.y1}, a, b));
            return best;
        }

        /** \brief Relative safety margins for the float distance transform bounds. */
        constexpr double kEdtRelMargin = 1e-6;
    } // namespace

    GridCollisionModel::GridCollisionModel(const World &world) : CollisionModel(world), grid_(world.grid)
    {
        if (!grid_)
            throw InputError("the grid collision model handles grid worlds only; '" + world.name +
                             "' is a geometric world (use the analytic or fcl back end)");
        const int w = grid_->width();
        const int h = grid_->height();
        const std::size_t n = static_cast<std::size_t>(w) * h;

        runStart_.resize(n);
        runEnd_.resize(n);
        for (int iy = 0; iy < h; ++iy)
        {
            const std::size_t row = static_cast<std::size_t>(iy) * w;
            int start = 0;
            for (int ix = 1; ix <= w; ++ix)
            {
                if (ix == w || grid_->blocked(ix, iy) != grid_->blocked(start, iy))
                {
                    for (int k = start; k < ix; ++k)
                    {
                        runStart_[row + k] = start;
                        runEnd_[row + k] = ix - 1;
                    }
                    start = ix;
                }
            }
        }

        // Exact EDT of the cell centres on the grid padded with a ring of blocked cells (the outside).
        const int pw = w + 2;
        const int ph = h + 2;
        std::vector<double> f(static_cast<std::size_t>(pw) * ph);
        for (int y = 0; y < ph; ++y)
            for (int x = 0; x < pw; ++x)
                f[static_cast<std::size_t>(y) * pw + x] = grid_->blocked(x - 1, y - 1) ? 0.0 : kInf;
        const int m = std::max(pw, ph);
        std::vector<double> in(m), out(m), z(m + 1);
        std::vector<int> v(m);
        for (int x = 0; x < pw; ++x)
        {
            for (int y = 0; y < ph; ++y)
                in[y] = f[static_cast<std::size_t>(y) * pw + x];
            detail::distanceTransform1D(in.data(), ph, out.data(), v.data(), z.data());
            for (int y = 0; y < ph; ++y)
                f[static_cast<std::size_t>(y) * pw + x] = out[y];
        }
        edt_.resize(n);
        const double s = grid_->cellSize();
        for (int y = 1; y <= h; ++y)
        {
            detail::distanceTransform1D(&f[static_cast<std::size_t>(y) * pw], pw, out.data(), v.data(),
                                        z.data());
            for (int x = 1; x <= w; ++x)
                edt_[static_cast<std::size_t>(y - 1) * w + (x - 1)] =
                    static_cast<float>(std::sqrt(out[x]) * s);
        }
    }

    int GridCollisionModel::locateX(double x) const
    {
        double u = std::floor((x - grid_->origin().x) / grid_->cellSize());
        u = std::clamp(u, -1e9, 1e9);
        int i = static_cast<int>(u);
        if (x < cellX0(i))
            --i;
        else if (x >= cellX0(i + 1))
            ++i;
        return i;
    }

    int GridCollisionModel::locateY(double y) const
    {
        double u = std::floor((y - grid_->origin().y) / grid_->cellSize());
        u = std::clamp(u, -1e9, 1e9);
        int j = static_cast<int>(u);
        if (y < cellY0(j))
            --j;
        else if (y >= cellY0(j + 1))
            ++j;
        return j;
    }

    bool GridCollisionModel::isPinchVertex(int vx, int vy) const
    {
        const OccupancyGrid &g = *grid_;
        const bool bl = g.blocked(vx - 1, vy - 1);
        const bool br = g.blocked(vx, vy - 1);
        const bool tl = g.blocked(vx - 1, vy);
        const bool tr = g.blocked(vx, vy);
        return (bl && tr && !br && !tl) || (br && tl && !bl && !tr);
    }

    /* Squared distance from p to B, for p outside B (so (ix, iy) is a free grid cell whose closure holds p).
       Rows are scanned outwards while their vertical gap is below maxGap and below the best distance; the
       scan stops early once a distance below stopBelow is found (0: never). */
    double GridCollisionModel::blockedDistance2(const Vec2 &p, int ix, int iy, double maxGap,
                                                double stopBelow) const
    {
        const int w = grid_->width();
        const int h = grid_->height();
        const double stop2 = stopBelow * stopBelow;
        double best = kInf;
        auto row = [&](int l, double hy)
        {
            if (l < 0 || l >= h)
            {
                best = std::min(best, hy * hy); // outside: the whole row is blocked
                return;
            }
            double hx = 0.0;
            const std::size_t idx = static_cast<std::size_t>(l) * w + ix;
            if (!grid_->blocked(ix, l))
            {
                const int k1 = runStart_[idx] - 1; // blocked (or outside)
                const int k2 = runEnd_[idx] + 1;
                hx = std::max(0.0, std::min(p.x - cellX0(k1 + 1), cellX0(k2) - p.x));
            }
            best = std::min(best, hx * hx + hy * hy);
        };
        for (int l = iy;; ++l)
        {
            const double hy = l == iy ? 0.0 : std::max(0.0, cellY0(l) - p.y);
            if (hy * hy >= best || hy >= maxGap)
                break;
            row(l, hy);
            if (best < stop2 && std::sqrt(best) < stopBelow)
                return best;
            if (l >= h)
                break;
        }
        for (int l = iy - 1;; --l)
        {
            const double hy = std::max(0.0, p.y - cellY0(l + 1));
            if (hy * hy >= best || hy >= maxGap)
                break;
            row(l, hy);
            if (best < stop2 && std::sqrt(best) < stopBelow)
                return best;
            if (l < 0)
                break;
        }
        return best;
    }

    /* Squared distance from p to the closure of free space. (ix, iy) is a grid cell (clamped into the grid)
       whose column and row contain p, or the border cell nearest to p when p lies outside the grid. */
    double GridCollisionModel::freeDistance2(const Vec2 &p, int ix, int iy) const
    {
        const int w = grid_->width();
        const int h = grid_->height();
        double best = kInf;
        auto gap = [](double v, double lo, double hi) { return std::max({0.0, lo - v, v - hi}); };
        auto row = [&](int l, double hy)
        {
            const std::size_t idx = static_cast<std::size_t>(l) * w + ix;
            if (!grid_->blocked(ix, l))
            {
                const double hx = gap(p.x, cellX0(ix), cellX0(ix + 1));
                best = std::min(best, hx * hx + hy * hy);
                return;
            }
            const int k1 = runStart_[idx] - 1; // free (or outside: none)
            const int k2 = runEnd_[idx] + 1;
            if (k1 >= 0)
            {
                const double hx = gap(p.x, cellX0(k1), cellX0(k1 + 1));
                best = std::min(best, hx * hx + hy * hy);
            }
            if (k2 < w)
            {
                const double hx = gap(p.x, cellX0(k2), cellX0(k2 + 1));
                best = std::min(best, hx * hx + hy * hy);
            }
        };
        for (int l = iy; l < h; ++l)
        {
            const double hy = gap(p.y, cellY0(l), cellY0(l + 1));
            if (hy * hy >= best)
                break;
            row(l, hy);
        }
        for (int l = iy - 1; l >= 0; --l)
        {
            const double hy = gap(p.y, cellY0(l), cellY0(l + 1));
            if (hy * hy >= best)
                break;
            row(l, hy);
        }
        return best;
    }

    double GridCollisionModel::penetrationDepth(const Vec2 &p) const
    {
        const int ix = std::clamp(locateX(p.x), 0, grid_->width() - 1);
        const int iy = std::clamp(locateY(p.y), 0, grid_->height() - 1);
        return std::sqrt(freeDistance2(p, ix, iy));
    }

    /* A lower bound on dist(p, B) from the EDT: every blocked centre is at least edt from p's cell centre c,
       and every point of a blocked square within s / sqrt(2) of its centre. -infinity outside the grid. */
    double GridCollisionModel::edtLowerBound(const Vec2 &p, int ix, int iy) const
    {
        if (!grid_->inside(ix, iy))
            return -kInf;
        const double s = grid_->cellSize();
        const double d = edt_[static_cast<std::size_t>(iy) * grid_->width() + ix];
        const double e = distance(p, grid_->cellCenter(ix, iy));
        return d * (1.0 - kEdtRelMargin) - e - s * (kSqrtHalf + kEdtRelMargin);
    }

    double GridCollisionModel::clearance(const Vec2 &p) const
    {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return std::numeric_limits<double>::quiet_NaN();
        const OccupancyGrid &g = *grid_;
        const int ix = locateX(p.x);
        const int iy = locateY(p.y);
        const bool onX = p.x == cellX0(ix);
        const bool onY = p.y == cellY0(iy);
        // p is in B when any cell whose closure holds p is blocked.
        const bool inB = g.blocked(ix, iy) || (onX && g.blocked(ix - 1, iy)) ||
                         (onY && g.blocked(ix, iy - 1)) || (onX && onY && g.blocked(ix - 1, iy - 1));
        if (!inB)
            return std::sqrt(blockedDistance2(p, ix, iy, kInf, 0.0)) - radius_;
        return 0.0 - penetrationDepth(p) - radius_; // +0 when touching
    }

    bool GridCollisionModel::isValid(const Vec2 &p) const
    {
        if (!inBounds(p))
            return false;
        const OccupancyGrid &g = *grid_;
        const int ix = locateX(p.x);
        const int iy = locateY(p.y);
        if (radius_ == 0.0)
        {
            const bool onX = p.x == cellX0(ix);
            const bool onY = p.y == cellY0(iy);
            bool free;
            if (!onX && !onY)
                free = !g.blocked(ix, iy);
            else if (onX && !onY)
                free = !(g.blocked(ix - 1, iy) && g.blocked(ix, iy));
            else if (!onX && onY)
                free = !(g.blocked(ix, iy - 1) && g.blocked(ix, iy));
            else
                return !(g.blocked(ix - 1, iy - 1) && g.blocked(ix, iy - 1) && g.blocked(ix - 1, iy) &&
                         g.blocked(ix, iy)) &&
                       !isPinchVertex(ix, iy);
            if (free)
                return true;
            // In B: valid when it penetrates by at most the contact tolerance (docs/contact.md), which only a
            // point within that distance of a grid line can.
            const double s = g.cellSize();
            const double gx = std::min(p.x - cellX0(ix), cellX0(ix + 1) - p.x);
            const double gy = std::min(p.y - cellY0(iy), cellY0(iy + 1) - p.y);
            if (std::min(gx, gy) > tol_ + 1e-12 * s)
                return false;
            return penetrationDepth(p) <= tol_;
        }
        if (g.blocked(ix, iy) && radius_ > tol_)
            return false; // p is in B, so the disc overlaps it by more than the tolerance
        const double s = g.cellSize();
        const double need = radius_ - tol_; // docs/contact.md
        const double d = edt_[static_cast<std::size_t>(iy) * g.width() + ix];
        const double e = distance(p, g.cellCenter(ix, iy));
        if (d * (1.0 - kEdtRelMargin) - e - s * (kSqrtHalf + kEdtRelMargin) >= radius_)
            return true; // clearly free
        // The nearest blocked square (by centre) lies within |p - its centre| - s / 2 of p.
        if (d * (1.0 + kEdtRelMargin) + e - s * (0.5 - kEdtRelMargin) < need)
            return false; // clearly colliding
        return std::sqrt(blockedDistance2(p, ix, iy, radius_, need)) >= need;
    }

    /* Calls visit(ix, iy) for every blocked grid cell that may lie within \e radius of the segment (a
       superset: each row's column range is that of the segment's part within the row's slab grown by radius,
       widened by radius), skipping free runs; stops and returns true as soon as visit returns true. */
    template <typename Visitor>
    bool GridCollisionModel::forEachBlockedInBand(const Vec2 &a, const Vec2 &b, double radius,
                                                  Visitor &&visit) const
    {
        const OccupancyGrid &g = *grid_;
        const int w = g.width();
        const int h = g.height();
        const double eps = 1e-9 * g.cellSize();
        const double r = radius + eps;
        const double ylo = std::min(a.y, b.y);
        const double yhi = std::max(a.y, b.y);
        const double xlo = std::min(a.x, b.x);
        const double xhi = std::max(a.x, b.x);
        const int l0 = std::max(0, locateY(ylo - r));
        const int l1 = std::min(h - 1, locateY(yhi + r));
        if (l0 > l1)
            return false;
        const double dx = b.x - a.x;
        const double dy = b.y - a.y;
        const bool upwards = a.y <= b.y;
        for (int n = 0; n <= l1 - l0; ++n)
        {
            const int l = upwards ? l0 + n : l1 - n;
            const double sy0 = std::max(ylo, cellY0(l) - r);
            const double sy1 = std::min(yhi, cellY0(l + 1) + r);
            if (sy0 > sy1)
                continue;
            double x0 = xlo;
            double x1 = xhi;
            if (dy != 0.0)
            {
                const double ta = std::clamp((sy0 - a.y) / dy, 0.0, 1.0);
                const double tb = std::clamp((sy1 - a.y) / dy, 0.0, 1.0);
                x0 = a.x + dx * ta;
                x1 = a.x + dx * tb;
                if (x0 > x1)
                    std::swap(x0, x1);
                x0 = std::max(x0, xlo);
                x1 = std::min(x1, xhi);
            }
            const int k0 = std::max(0, locateX(x0 - r));
            const int k1 = std::min(w - 1, locateX(x1 + r));
            const std::size_t rowIdx = static_cast<std::size_t>(l) * w;
            for (int k = k0; k <= k1;)
            {
                if (g.blocked(k, l))
                {
                    if (visit(k, l))
                        return true;
                    ++k;
                }
                else
                    k = runEnd_[rowIdx + k] + 1;
            }
        }
        return false;
    }

    bool GridCollisionModel::segmentValid(const Vec2 &a, const Vec2 &b) const
    {
        if (!segmentInBounds(a, b) || !isValid(a) || !isValid(b))
            return false;
        if (a == b)
            return true;
        const OccupancyGrid &g = *grid_;
        const double len = distance(a, b);
        // Two EDT balls around the endpoints covering the segment.
        const double la = edtLowerBound(a, locateX(a.x), locateY(a.y)) - radius_;
        const double lb = edtLowerBound(b, locateX(b.x), locateY(b.y)) - radius_;
        if (la + lb > len)
            return true;
        const Box gb = g.bounds();
        auto cellBox = [&](int k, int l) {
            return CellBox{cellX0(k), cellX0(k + 1), cellY0(l), cellY0(l + 1)};
        };
        if (radius_ > 0.0)
        {
            // The outside of the grid: the box is convex, so the segment is closest to it at an endpoint.
            auto inside = [&](const Vec2 &p) {
                return std::min({p.x - gb.xmin, gb.xmax - p.x, p.y - gb.ymin, gb.ymax - p.y});
            };
            if (std::min(inside(a), inside(b)) < radius_)
                return false;
            const double r2 = radius_ * radius_;
            const double halfTol = 0.5 * tol_; // a segment penetrates by at most e / 2 (docs/contact.md)
            const double half = 0.5 * g.cellSize();
            const double far = radius_ + kSqrtHalf * g.cellSize() * (1.0 + 1e-9);
            const double far2 = far * far;
            return !forEachBlockedInBand(
                a, b, radius_,
                [&](int k, int l)
                {
                    // The square lies between the discs of radii s/2 and s/sqrt(2)
                    // about its centre: most cells are decided by one distance.
                    const double c2 = pointSegmentDistance2({cellX0(k) + half, cellY0(l) + half}, a, b);
                    if (c2 >= far2)
                        return false;
                    if (std::sqrt(c2) - half < radius_ - halfTol)
                        return true;
                    const double d2 = segmentBoxDistance2(a, b, cellBox(k, l));
                    return d2 < r2 && std::sqrt(d2) < radius_ - halfTol;
                });
        }
        // Point robot: the segment must not enter the interior of B beyond rounding (docs/contact.md) nor
        // pass within e of a pinch corner. Both endpoints are valid, hence in the grid's closed box (up to
        // e), and so is the segment.
        const double pinchTol2 = tol_ * tol_;
        bool pinch = false;
        const double q = 0.25 * tol_;
        const auto near = [q](const Vec2 &p, const Vec2 &v) { return squaredNorm(p - v) <= q * q; };
        const bool hit = forEachBlockedInBand(
            a, b, 0.0,
            [&](int k, int l)
            {
                const CellBox box = cellBox(k, l);
                double t0, t1;
                if (!clipSegment(a, b, box, t0, t1))
                    return false;
                if (t1 > t0)
                {
                    const Vec2 m = a + (b - a) * (0.5 * (t0 + t1));
                    if (m.x > box.x0 && m.x < box.x1 && m.y > box.y0 && m.y < box.y1)
                    {
                        // Enters the open square. Accepted only by rounding's order (docs/contact.md): the
                        // clipped part lies within e / 4 of a side whose neighbour is free, or of a vertex of
                        // a free cell, so every point of it is within e / 4 of free space.
                        const Vec2 p0 = a + (b - a) * t0, p1 = a + (b - a) * t1;
                        const auto band = [&](double u0, double u1, double side, int nk, int nl) {
                            return std::abs(u0 - side) <= q && std::abs(u1 - side) <= q && !g.blocked(nk, nl);
                        };
                        bool shallow =
                            band(p0.x, p1.x, box.x0, k - 1, l) || band(p0.x, p1.x, box.x1, k + 1, l) ||
                            band(p0.y, p1.y, box.y0, k, l - 1) || band(p0.y, p1.y, box.y1, k, l + 1);
                        for (int vy = l; vy <= l + 1 && !shallow; ++vy)
                            for (int vx = k; vx <= k + 1 && !shallow; ++vx)
                            {
                                const Vec2 v{cellX0(vx), cellY0(vy)};
                                shallow = near(p0, v) && near(p1, v) &&
                                          !(g.blocked(vx - 1, vy - 1) && g.blocked(vx, vy - 1) &&
                                            g.blocked(vx - 1, vy) && g.blocked(vx, vy));
                            }
                        if (!shallow)
                            return true;
                    }
                }
                for (int vy = l; vy <= l + 1; ++vy)
                    for (int vx = k; vx <= k + 1; ++vx)
                        if (isPinchVertex(vx, vy) &&
                            pointSegmentDistance2({cellX0(vx), cellY0(vy)}, a, b) <= pinchTol2)
                            return pinch = true;
                return false;
            });
        if (pinch || hit)
            return false;
        // A segment lying on a grid line (up to the contact tolerance: a segment within rounding of the line
        // may not enter the open squares in floating point) needs a free cell on one side of each open edge
        // piece.
        const double lineTol = tol_;
        if (std::abs(a.y - b.y) <= lineTol)
        {
            const int l = locateY(0.5 * (a.y + b.y) + 0.5 * g.cellSize());
            const double y = cellY0(l);
            if (std::abs(a.y - y) <= lineTol && std::abs(b.y - y) <= lineTol)
            {
                const double xlo = std::min(a.x, b.x);
                const double xhi = std::max(a.x, b.x);
                for (int k = locateX(xlo), kEnd = locateX(xhi); k <= kEnd; ++k)
                    if (std::max(xlo, cellX0(k)) < std::min(xhi, cellX0(k + 1)) && g.blocked(k, l) &&
                        g.blocked(k, l - 1))
                        return false;
            }
        }
        if (std::abs(a.x - b.x) <= lineTol)
        {
            const int k = locateX(0.5 * (a.x + b.x) + 0.5 * g.cellSize());
            const double x = cellX0(k);
            if (std::abs(a.x - x) <= lineTol && std::abs(b.x - x) <= lineTol)
            {
                const double ylo = std::min(a.y, b.y);
                const double yhi = std::max(a.y, b.y);
                for (int l = locateY(ylo), lEnd = locateY(yhi); l <= lEnd; ++l)
                    if (std::max(ylo, cellY0(l)) < std::min(yhi, cellY0(l + 1)) && g.blocked(k, l) &&
                        g.blocked(k - 1, l))
                        return false;
            }
        }
        return true;
    }

    /* Max over t in [t0, t1] of the squared distance from a + t (b - a) to free space, where that part of
       the segment lies in the closed (possibly virtual, outside) cell (ix, iy). Within the piece the
       squared distance to each candidate free square is a quadratic in t (fixed signs), so the maximum of
       their lower envelope is at t0, t1 or where two of them cross. */
    double GridCollisionModel::pieceMaxPenetration2(const Vec2 &a, const Vec2 &b, double t0, double t1,
                                                    int ix, int iy) const
    {
        const OccupancyGrid &g = *grid_;
        const int w = g.width();
        const int h = g.height();
        const Vec2 d = b - a;
        const Vec2 p0 = a + d * t0;
        const Vec2 p1 = a + d * t1;
        const int cx = std::clamp(ix, 0, w - 1);
        const int cy = std::clamp(iy, 0, h - 1);
        const double d0 = std::sqrt(freeDistance2(p0, cx, cy));
        const double d1 = std::sqrt(freeDistance2(p1, cx, cy));
        if (!std::isfinite(d0) || !std::isfinite(d1))
            return kInf; // no free cell at all
        // 1-Lipschitz: every point of the piece is within ub of free space.
        const double ub = 0.5 * (d0 + d1 + distance(p0, p1)) + 1e-9 * g.cellSize();

        struct Quad
        {
            double cx, ex, cy, ey; // dx(t) = cx + ex t, dy(t) = cy + ey t
        };
        thread_local std::vector<Quad> cand; // reused: no heap allocation per query once warm
        cand.clear();
        auto addCell = [&](int k, int l)
        {
            Quad q{0.0, 0.0, 0.0, 0.0};
            if (k > ix)
                q = {cellX0(k) - a.x, -d.x, 0.0, 0.0};
            else if (k < ix)
                q = {a.x - cellX0(k + 1), d.x, 0.0, 0.0};
            if (l > iy)
            {
                q.cy = cellY0(l) - a.y;
                q.ey = -d.y;
            }
            else if (l < iy)
            {
                q.cy = a.y - cellY0(l + 1);
                q.ey = d.y;
            }
            cand.push_back(q);
        };
        const int l0 = std::max(0, locateY(std::min(p0.y, p1.y) - ub));
        const int l1 = std::min(h - 1, locateY(std::max(p0.y, p1.y) + ub));
        for (int l = l0; l <= l1; ++l)
        {
            const std::size_t idx = static_cast<std::size_t>(l) * w + cx;
            if (!g.blocked(cx, l))
            {
                addCell(cx, l);
                continue;
            }
            if (runStart_[idx] - 1 >= 0)
                addCell(runStart_[idx] - 1, l);
            if (runEnd_[idx] + 1 < w)
                addCell(runEnd_[idx] + 1, l);
        }
        auto envelope = [&](double t)
        {
            double best = kInf;
            for (const Quad &q : cand)
            {
                const double dx = q.cx + q.ex * t;
                const double dy = q.cy + q.ey * t;
                best = std::min(best, dx * dx + dy * dy);
            }
            return best;
        };
        double result = std::max(envelope(t0), envelope(t1));
        for (std::size_t u = 0; u < cand.size(); ++u)
        {
            for (std::size_t v = u + 1; v < cand.size(); ++v)
            {
                const Quad &p = cand[u];
                const Quad &q = cand[v];
                // (A t^2 + B t + C) of p minus that of q.
                const double A = (p.ex * p.ex + p.ey * p.ey) - (q.ex * q.ex + q.ey * q.ey);
                const double B = 2.0 * ((p.cx * p.ex + p.cy * p.ey) - (q.cx * q.ex + q.cy * q.ey));
                const double C = (p.cx * p.cx + p.cy * p.cy) - (q.cx * q.cx + q.cy * q.cy);
                double roots[2];
                int nr = 0;
                const double scaleA = p.ex * p.ex + p.ey * p.ey + q.ex * q.ex + q.ey * q.ey;
                if (std::abs(A) <= 1e-14 * scaleA)
                {
                    if (B != 0.0)
                        roots[nr++] = -C / B;
                }
                else
                {
                    const double disc = B * B - 4.0 * A * C;
                    if (disc >= 0.0)
                    {
                        const double sq = std::sqrt(disc);
                        const double qq = -0.5 * (B + std::copysign(sq, B));
                        if (qq != 0.0)
                        {
                            roots[nr++] = qq / A;
                            roots[nr++] = C / qq;
                        }
                        else
                            roots[nr++] = 0.0;
                    }
                }
                for (int k = 0; k < nr; ++k)
                    if (roots[k] > t0 && roots[k] < t1)
                        result = std::max(result, envelope(roots[k]));
            }
        }
        return result;
    }

    double GridCollisionModel::maxSegmentPenetration(const Vec2 &a, const Vec2 &b) const
    {
        const OccupancyGrid &g = *grid_;
        const int w = g.width();
        const int h = g.height();
        const Vec2 d = b - a;
        // Breakpoints where the segment crosses a grid line (lines outside the grid need no breaks: there
        // every free cell lies on one side).
        thread_local std::vector<double> ts; // reused: no heap allocation per query once warm
        ts.assign({0.0, 1.0});
        if (d.x != 0.0)
        {
            const int k0 = std::max(0, locateX(std::min(a.x, b.x)));
            const int k1 = std::min(w, locateX(std::max(a.x, b.x)) + 1);
            for (int k = k0; k <= k1; ++k)
            {
                const double t = (cellX0(k) - a.x) / d.x;
                if (t > 0.0 && t < 1.0)
                    ts.push_back(t);
            }
        }
        if (d.y != 0.0)
        {
            const int l0 = std::max(0, locateY(std::min(a.y, b.y)));
            const int l1 = std::min(h, locateY(std::max(a.y, b.y)) + 1);
            for (int l = l0; l <= l1; ++l)
            {
                const double t = (cellY0(l) - a.y) / d.y;
                if (t > 0.0 && t < 1.0)
                    ts.push_back(t);
            }
        }
        std::sort(ts.begin(), ts.end());
        double best = 0.0;
        for (std::size_t n = 0; n + 1 < ts.size(); ++n)
        {
            const double t0 = ts[n];
            const double t1 = ts[n + 1];
            if (!(t1 > t0))
                continue;
            const Vec2 m = a + d * (0.5 * (t0 + t1));
            const int ix = std::clamp(locateX(m.x), -1, w);
            const int iy = std::clamp(locateY(m.y), -1, h);
            if (g.inside(ix, iy) && !g.blocked(ix, iy))
                continue; // the piece lies in a free square
            best = std::max(best, pieceMaxPenetration2(a, b, t0, t1, ix, iy));
        }
        return std::sqrt(best);
    }

    double GridCollisionModel::segmentClearance(const Vec2 &a, const Vec2 &b) const
    {
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
            return std::numeric_limits<double>::quiet_NaN();
        if (a == b)
            return clearance(a);
        const double ca = clearance(a) + radius_; // signed distance to B
        const double cb = clearance(b) + radius_;
        if (ca <= 0.0 || cb <= 0.0)
            return 0.0 - maxSegmentPenetration(a, b) - radius_;
        // Both endpoints are free, so inside the grid, and the outside is farther than either endpoint's
        // distance. Every blocked square nearer than min(ca, cb) lies in the band of that radius.
        double best = std::min(ca, cb);
        double best2 = best * best;
        forEachBlockedInBand(
            a, b, best,
            [&](int k, int l)
            {
                const double far = std::sqrt(best2) + kSqrtHalf * grid_->cellSize() * (1.0 + 1e-9);
                if (pointSegmentDistance2(grid_->cellCenter(k, l), a, b) >= far * far)
                    return false; // the whole square is farther than the best so far
                best2 = std::min(
                    best2,
                    segmentBoxDistance2(a, b, CellBox{cellX0(k), cellX0(k + 1), cellY0(l), cellY0(l + 1)}));
                return best2 == 0.0;
            });
        if (best2 == 0.0)
            return 0.0 - maxSegmentPenetration(a, b) - radius_;
        return std::min(best, std::sqrt(best2)) - radius_;
    }
} // namespace mhplan
