// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the indexed-colour rasteriser of the GIF frames (a canvas of palette indices, its 3x5 pixel font)
   and the world-to-pixel mapping shared with the SVG drawing. Not part of the installed API. */
#ifndef MHPLAN_DRAW_DETAIL_RASTER_H
#define MHPLAN_DRAW_DETAIL_RASTER_H

#include "src/base/Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace mhplan
{
    namespace draw_detail
    {
        /** A 3x5 pixel font for the time label: each glyph is 5 rows of 3 bits (MSB = left column);
           characters other than digits, '.', 't', 's' and '=' are blank. */
        const std::array<std::uint8_t, 5> *glyph(char ch);

        /** A plain indexed-colour rasteriser; pixel (x, y) covers [x, x+1) x [y, y+1), y down. */
        class Canvas
        {
          public:
            Canvas(int w, int h, std::uint8_t fill)
                : w_(w), h_(h), px_(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill)
            {
            }

            std::vector<std::uint8_t> &pixels() { return px_; }
            const std::vector<std::uint8_t> &pixels() const { return px_; }

            void set(int x, int y, std::uint8_t c)
            {
                if (x >= 0 && y >= 0 && x < w_ && y < h_)
                    px_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) +
                        static_cast<std::size_t>(x)] = c;
            }
            /** Paint only over \e under (draw "beneath" what is already there). */
            void setIf(int x, int y, std::uint8_t c, std::uint8_t under)
            {
                if (x >= 0 && y >= 0 && x < w_ && y < h_)
                {
                    std::uint8_t &p = px_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) +
                                          static_cast<std::size_t>(x)];
                    if (p == under)
                        p = c;
                }
            }

            /** Pixels whose centres lie in [x0, x1] x [y0, y1]. */
            void fillRect(double x0, double y0, double x1, double y1, std::uint8_t c)
            {
                const int ia = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
                const int ib = std::min(w_ - 1, static_cast<int>(std::floor(x1 - 0.5)));
                const int ja = std::max(0, static_cast<int>(std::ceil(y0 - 0.5)));
                const int jb = std::min(h_ - 1, static_cast<int>(std::floor(y1 - 0.5)));
                for (int y = ja; y <= jb; ++y)
                    for (int x = ia; x <= ib; ++x)
                        set(x, y, c);
            }

            /** Pixels whose centres lie in the disc. */
            void fillDisc(double cx, double cy, double r, std::uint8_t c)
            {
                const int ja = std::max(0, static_cast<int>(std::floor(cy - r)));
                const int jb = std::min(h_ - 1, static_cast<int>(std::ceil(cy + r)));
                for (int y = ja; y <= jb; ++y)
                {
                    const double dy = y + 0.5 - cy;
                    const double q = r * r - dy * dy;
                    if (q < 0.0)
                        continue;
                    const double half = std::sqrt(q);
                    fillSpan(y, cx - half, cx + half, c);
                }
            }

            /** Pixels whose centres lie within [r - width, r] of the centre. */
            void ring(double cx, double cy, double r, double width, std::uint8_t c)
            {
                const double ri = std::max(0.0, r - width);
                const int ja = std::max(0, static_cast<int>(std::floor(cy - r)));
                const int jb = std::min(h_ - 1, static_cast<int>(std::ceil(cy + r)));
                const int ia = std::max(0, static_cast<int>(std::floor(cx - r)));
                const int ib = std::min(w_ - 1, static_cast<int>(std::ceil(cx + r)));
                for (int y = ja; y <= jb; ++y)
                    for (int x = ia; x <= ib; ++x)
                    {
                        const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                        if (d <= r && d >= ri)
                            set(x, y, c);
                    }
            }

            /** Even-odd scanline fill of a polygon (pixel centres inside). */
            void fillPolygon(const std::vector<std::pair<double, double>> &pts, std::uint8_t c)
            {
                if (pts.size() < 3)
                    return;
                double ymin = pts[0].second, ymax = pts[0].second;
                for (const auto &p : pts)
                {
                    ymin = std::min(ymin, p.second);
                    ymax = std::max(ymax, p.second);
                }
                const int ja = std::max(0, static_cast<int>(std::floor(ymin)));
                const int jb = std::min(h_ - 1, static_cast<int>(std::ceil(ymax)));
                std::vector<double> xs;
                for (int y = ja; y <= jb; ++y)
                {
                    const double yc = y + 0.5;
                    xs.clear();
                    for (std::size_t k = 0; k < pts.size(); ++k)
                    {
                        const auto &a = pts[k];
                        const auto &b = pts[(k + 1) % pts.size()];
                        if ((a.second <= yc) != (b.second <= yc))
                            xs.push_back(a.first +
                                         (yc - a.second) / (b.second - a.second) * (b.first - a.first));
                    }
                    std::sort(xs.begin(), xs.end());
                    for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
                        fillSpan(y, xs[k], xs[k + 1], c);
                }
            }

            /** A straight line (Bresenham between the pixels holding the end points) drawn with a square
                brush of \e thickness pixels; with \e onlyOver >= 0 it paints only pixels of that colour. */
            void line(double x0, double y0, double x1, double y1, std::uint8_t c, int thickness = 1,
                      int onlyOver = -1)
            {
                int xa = static_cast<int>(std::floor(x0)), ya = static_cast<int>(std::floor(y0));
                const int xb = static_cast<int>(std::floor(x1)), yb = static_cast<int>(std::floor(y1));
                const int dx = std::abs(xb - xa), sx = xa < xb ? 1 : -1;
                const int dy = -std::abs(yb - ya), sy = ya < yb ? 1 : -1;
                int err = dx + dy;
                const int lo = -(thickness - 1) / 2, hi = thickness / 2;
                for (;;)
                {
                    for (int oy = lo; oy <= hi; ++oy)
                        for (int ox = lo; ox <= hi; ++ox)
                        {
                            if (onlyOver >= 0)
                                setIf(xa + ox, ya + oy, c, static_cast<std::uint8_t>(onlyOver));
                            else
                                set(xa + ox, ya + oy, c);
                        }
                    if (xa == xb && ya == yb)
                        break;
                    const int e2 = 2 * err;
                    if (e2 >= dy)
                    {
                        err += dy;
                        xa += sx;
                    }
                    if (e2 <= dx)
                    {
                        err += dx;
                        ya += sy;
                    }
                }
            }

            void cross(double x, double y, double half, std::uint8_t c)
            {
                line(x - half, y - half, x + half, y + half, c, 2);
                line(x - half, y + half, x + half, y - half, c, 2);
            }

            /** Text in the 3x5 font scaled by \e scale, top-left at (x, y). */
            void text(int x, int y, const std::string &s, std::uint8_t c, int scale)
            {
                for (char ch : s)
                {
                    const auto &g = *glyph(ch);
                    for (int row = 0; row < 5; ++row)
                        for (int col = 0; col < 3; ++col)
                            if (g[static_cast<std::size_t>(row)] & (4 >> col))
                                for (int a = 0; a < scale; ++a)
                                    for (int b = 0; b < scale; ++b)
                                        set(x + col * scale + b, y + row * scale + a, c);
                    x += 4 * scale;
                }
            }

          private:
            void fillSpan(int y, double xa, double xb, std::uint8_t c)
            {
                const int ia = std::max(0, static_cast<int>(std::ceil(xa - 0.5)));
                const int ib = std::min(w_ - 1, static_cast<int>(std::floor(xb - 0.5)));
                for (int x = ia; x <= ib; ++x)
                    px_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) +
                        static_cast<std::size_t>(x)] = c;
            }

            int w_, h_;
            std::vector<std::uint8_t> px_;
        };

        /** World to pixel mapping (y up in the world, down in the image). */
        struct View
        {
            Box bounds;
            double scale{1.0};
            double margin{0.0};
            double x(double wx) const { return margin + (wx - bounds.xmin) * scale; }
            double y(double wy) const { return margin + (bounds.ymax - wy) * scale; }
        };
    } // namespace draw_detail
} // namespace mhplan

#endif
