// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/draw/SimRender.h"

#include "mhplan/draw/Svg.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace mhplan
{
    namespace
    {
        /** Robot colours: matplotlib's tab10 then its light companions; the greys are replaced so robots do
            not look like obstacles. */
        const std::array<const char *, 20> kRobotColors = {
            "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
            "#393b79", "#bcbd22", "#17becf", "#aec7e8", "#ffbb78", "#98df8a", "#ff9896",
            "#c5b0d5", "#c49c94", "#f7b6d2", "#637939", "#dbdb8d", "#9edae5"};

        using Rgb = std::array<std::uint8_t, 3>;

        Rgb parseHex(const char *hex)
        {
            Rgb c{};
            for (int k = 0; k < 3; ++k)
                c[static_cast<std::size_t>(k)] =
                    static_cast<std::uint8_t>(std::stoi(std::string(hex + 1 + 2 * k, 2), nullptr, 16));
            return c;
        }

        // Fixed palette of the GIF.
        enum : std::uint8_t
        {
            kWhite = 0,
            kWorld = 1,
            kObstacle = 2,
            kObstacleEdge = 3,
            kGridCell = 4,
            kBlack = 5,
            kTrace = 6,
            kMovingObstacle = 7,
            kMovingObstacleEdge = 8,
            kRobotBase = 9,                                                          // 20 robot colours
            kTrailBase = kRobotBase + static_cast<std::uint8_t>(kRobotColors.size()) // 20 lighter ones
        };

        std::vector<Rgb> gifPalette()
        {
            std::vector<Rgb> p = {{255, 255, 255}, {250, 250, 250}, {136, 136, 136},
                                  {51, 51, 51},    {68, 68, 68},    {0, 0, 0},
                                  {200, 200, 200}, {230, 85, 13},   {166, 54, 3}};
            for (const char *c : kRobotColors)
                p.push_back(parseHex(c));
            for (const char *c : kRobotColors)
            {
                Rgb rgb = parseHex(c);
                for (auto &v : rgb)
                    v = static_cast<std::uint8_t>((v + 2 * 255) / 3); // two thirds toward white
                p.push_back(rgb);
            }
            return p;
        }

        std::uint8_t robotIndex(std::size_t i)
        {
            return static_cast<std::uint8_t>(kRobotBase + i % kRobotColors.size());
        }
        std::uint8_t trailIndex(std::size_t i)
        {
            return static_cast<std::uint8_t>(kTrailBase + i % kRobotColors.size());
        }

        /** A 3x5 pixel font for the time label: each glyph is 5 rows of 3 bits (MSB = left column). */
        const std::array<std::uint8_t, 5> *glyph(char ch)
        {
            static const std::array<std::uint8_t, 5> digits[10] = {
                {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
                {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
            static const std::array<std::uint8_t, 5> dot = {0, 0, 0, 0, 2};
            static const std::array<std::uint8_t, 5> t = {2, 7, 2, 2, 3};
            static const std::array<std::uint8_t, 5> s = {0, 3, 6, 3, 6};
            static const std::array<std::uint8_t, 5> eq = {0, 7, 0, 7, 0};
            static const std::array<std::uint8_t, 5> space = {0, 0, 0, 0, 0};
            if (ch >= '0' && ch <= '9')
                return &digits[ch - '0'];
            switch (ch)
            {
            case '.':
                return &dot;
            case 't':
                return &t;
            case 's':
                return &s;
            case '=':
                return &eq;
            default:
                return &space;
            }
        }

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

        /** Index of the last sample with time <= t (times ascending), or -1 when there is none. */
        long lastSampleAtOrBefore(const std::vector<double> &times, double t)
        {
            const auto it = std::upper_bound(times.begin(), times.end(), t + 1e-9);
            return static_cast<long>(it - times.begin()) - 1;
        }

        /** Evenly spaced indices 0..n-1, at most maxFrames of them (both ends included). */
        std::vector<std::size_t> frameIndices(std::size_t n, int maxFrames)
        {
            std::vector<std::size_t> out;
            if (n == 0)
                return out;
            const std::size_t f = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(2, maxFrames)));
            if (f == 1)
                return {0};
            for (std::size_t k = 0; k < f; ++k)
                out.push_back(static_cast<std::size_t>(std::llround(
                    static_cast<double>(k) * static_cast<double>(n - 1) / static_cast<double>(f - 1))));
            return out;
        }

        std::string formatNumber(double v, int precision = 3)
        {
            if (std::isinf(v))
                return v > 0 ? "inf" : "-inf";
            std::ostringstream s;
            s << std::fixed << std::setprecision(precision) << v;
            return s.str();
        }

        /** The static world drawn once into a canvas. */
        void drawWorld(Canvas &c, const World &world, const View &v)
        {
            const Box &b = world.bounds;
            c.fillRect(v.x(b.xmin), v.y(b.ymax), v.x(b.xmax), v.y(b.ymin), kWorld);
            if (world.isGrid())
            {
                const OccupancyGrid &g = *world.grid;
                for (int iy = 0; iy < g.height(); ++iy)
                    for (int ix = 0; ix < g.width(); ++ix)
                        if (g.blocked(ix, iy))
                        {
                            const Box cb = g.cellBox(ix, iy);
                            c.fillRect(v.x(cb.xmin), v.y(cb.ymax), v.x(cb.xmax), v.y(cb.ymin), kGridCell);
                        }
            }
            for (const auto &circle : world.circles)
            {
                const double r = circle.radius * v.scale;
                c.fillDisc(v.x(circle.center.x), v.y(circle.center.y), r, kObstacleEdge);
                c.fillDisc(v.x(circle.center.x), v.y(circle.center.y), r - 1.0, kObstacle);
            }
            for (const auto &p : world.polygons)
            {
                std::vector<std::pair<double, double>> pts;
                for (const auto &q : p.vertices)
                    pts.emplace_back(v.x(q.x), v.y(q.y));
                c.fillPolygon(pts, kObstacle);
                for (std::size_t k = 0; k < pts.size(); ++k)
                {
                    const auto &a = pts[k];
                    const auto &e = pts[(k + 1) % pts.size()];
                    c.line(a.first, a.second, e.first, e.second, kObstacleEdge);
                }
            }
            // Border of the bounds.
            const double x0 = v.x(b.xmin) - 1, y0 = v.y(b.ymax) - 1, x1 = v.x(b.xmax), y1 = v.y(b.ymin);
            c.line(x0, y0, x1, y0, kBlack);
            c.line(x1, y0, x1, y1, kBlack);
            c.line(x1, y1, x0, y1, kBlack);
            c.line(x0, y1, x0, y0, kBlack);
        }

        void putLe16(std::vector<std::uint8_t> &out, int v)
        {
            out.push_back(static_cast<std::uint8_t>(v & 0xFF));
            out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
        }
    } // namespace

    std::string robotColor(std::size_t i)
    {
        return kRobotColors[i % kRobotColors.size()];
    }

    // ----------------------------------------------------------------------------------------------------
    // GIF

    std::vector<std::uint8_t> lzwEncode(const std::vector<std::uint8_t> &indices, int minCodeSize)
    {
        if (minCodeSize < 2 || minCodeSize > 8)
            throw std::invalid_argument("lzwEncode: minCodeSize must be in [2, 8] (got " +
                                        std::to_string(minCodeSize) + ")");
        const int clear = 1 << minCodeSize;
        const int eoi = clear + 1;
        const int maxCodes = 4096;
        // child[prefix * alphabet + symbol] = code of prefix+symbol, 0 = none (0 is never a new code).
        const std::size_t alphabet = static_cast<std::size_t>(clear);
        std::vector<std::uint16_t> child(static_cast<std::size_t>(maxCodes) * alphabet, 0);

        std::vector<std::uint8_t> out;
        out.reserve(indices.size() / 2 + 16);
        std::uint32_t acc = 0;
        int bits = 0;
        auto write = [&](int code, int size)
        {
            acc |= static_cast<std::uint32_t>(code) << bits;
            bits += size;
            while (bits >= 8)
            {
                out.push_back(static_cast<std::uint8_t>(acc & 0xFF));
                acc >>= 8;
                bits -= 8;
            }
        };

        int size = minCodeSize + 1;
        int next = eoi + 1;
        write(clear, size);
        if (!indices.empty())
        {
            int prefix = indices[0];
            if (prefix >= clear)
                throw std::invalid_argument("lzwEncode: index " + std::to_string(prefix) +
                                            " does not fit minCodeSize " + std::to_string(minCodeSize));
            for (std::size_t i = 1; i < indices.size(); ++i)
            {
                const int c = indices[i];
                if (c >= clear)
                    throw std::invalid_argument("lzwEncode: index " + std::to_string(c) +
                                                " does not fit minCodeSize " + std::to_string(minCodeSize));
                std::uint16_t &slot =
                    child[static_cast<std::size_t>(prefix) * alphabet + static_cast<std::size_t>(c)];
                if (slot != 0)
                {
                    prefix = slot;
                    continue;
                }
                write(prefix, size);
                // The decoder learns each code one step later, so the code just added decides the width of
                // the next code written.
                const int added = next++;
                slot = static_cast<std::uint16_t>(added);
                if (added >= (1 << size) && size < 12)
                    ++size;
                if (next == maxCodes)
                {
                    write(clear, size);
                    std::fill(child.begin(), child.end(), 0);
                    size = minCodeSize + 1;
                    next = eoi + 1;
                }
                prefix = c;
            }
            write(prefix, size);
            // The decoder adds one more code after reading the last one: same width rule before EOI.
            if (next >= (1 << size) && size < 12)
                ++size;
        }
        write(eoi, size);
        if (bits > 0)
            out.push_back(static_cast<std::uint8_t>(acc & 0xFF));
        return out;
    }

    std::vector<std::uint8_t> encodeGif(int w, int h, const std::vector<std::array<std::uint8_t, 3>> &palette,
                                        const std::vector<std::vector<std::uint8_t>> &frames,
                                        const std::vector<int> &delaysCs)
    {
        if (w < 1 || w > 65535 || h < 1 || h > 65535)
            throw std::invalid_argument("encodeGif: width and height must be in [1, 65535] (got " +
                                        std::to_string(w) + " x " + std::to_string(h) + ")");
        if (palette.size() < 2 || palette.size() > 256)
            throw std::invalid_argument("encodeGif: palette must have 2..256 colours (got " +
                                        std::to_string(palette.size()) + ")");
        if (frames.empty())
            throw std::invalid_argument("encodeGif: frames must not be empty");
        if (delaysCs.size() != 1 && delaysCs.size() != frames.size())
            throw std::invalid_argument(
                "encodeGif: delaysCs must hold 1 or frames.size() = " + std::to_string(frames.size()) +
                " values (got " + std::to_string(delaysCs.size()) + ")");
        const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        for (std::size_t k = 0; k < frames.size(); ++k)
        {
            if (frames[k].size() != n)
                throw std::invalid_argument("encodeGif: frame " + std::to_string(k) + " has " +
                                            std::to_string(frames[k].size()) +
                                            " pixels, expected w * h = " + std::to_string(n));
            for (std::uint8_t p : frames[k])
                if (p >= palette.size())
                    throw std::invalid_argument("encodeGif: frame " + std::to_string(k) + " uses index " +
                                                std::to_string(p) + " beyond the palette's " +
                                                std::to_string(palette.size()) + " colours");
        }
        for (int d : delaysCs)
            if (d < 0 || d > 65535)
                throw std::invalid_argument("encodeGif: delays must be in [0, 65535] cs (got " +
                                            std::to_string(d) + ")");

        // With fewer than 256 colours, one more index marks "unchanged" (transparent) pixels in the frames
        // after the first: long runs of it compress far better than the unchanged pixels themselves.
        const bool useTransparency = palette.size() < 256;
        const std::size_t transparent = palette.size();
        const std::size_t indexCount = palette.size() + (useTransparency ? 1 : 0);
        int tableBits = 1;
        while ((1u << tableBits) < indexCount)
            ++tableBits;
        const int minCodeSize = std::max(2, tableBits);

        std::vector<std::uint8_t> out;
        for (char ch : std::string("GIF89a"))
            out.push_back(static_cast<std::uint8_t>(ch));
        // Logical screen descriptor: global colour table, 8 bits colour resolution.
        putLe16(out, w);
        putLe16(out, h);
        out.push_back(static_cast<std::uint8_t>(0x80 | 0x70 | (tableBits - 1)));
        out.push_back(0); // background colour index
        out.push_back(0); // pixel aspect ratio: not given
        for (std::size_t k = 0; k < (std::size_t{1} << tableBits); ++k)
            for (int ch = 0; ch < 3; ++ch)
                out.push_back(k < palette.size() ? palette[k][static_cast<std::size_t>(ch)] : 0);
        // NETSCAPE2.0: loop forever.
        out.push_back(0x21);
        out.push_back(0xFF);
        out.push_back(11);
        for (char ch : std::string("NETSCAPE2.0"))
            out.push_back(static_cast<std::uint8_t>(ch));
        out.push_back(3);
        out.push_back(1);
        putLe16(out, 0);
        out.push_back(0);

        std::vector<std::uint8_t> sub;
        for (std::size_t k = 0; k < frames.size(); ++k)
        {
            const std::vector<std::uint8_t> &f = frames[k];
            // The rectangle that changed since the previous frame (whole image for the first).
            int x0 = 0, y0 = 0, x1 = w - 1, y1 = h - 1;
            if (k > 0)
            {
                const std::vector<std::uint8_t> &prev = frames[k - 1];
                x0 = w;
                y0 = h;
                x1 = -1;
                y1 = -1;
                for (int y = 0; y < h; ++y)
                {
                    const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
                    if (std::memcmp(&f[row], &prev[row], static_cast<std::size_t>(w)) == 0)
                        continue;
                    y0 = std::min(y0, y);
                    y1 = y;
                    for (int x = 0; x < w; ++x)
                        if (f[row + static_cast<std::size_t>(x)] != prev[row + static_cast<std::size_t>(x)])
                        {
                            x0 = std::min(x0, x);
                            x1 = std::max(x1, x);
                        }
                }
                if (x1 < 0) // unchanged: one pixel, same value
                {
                    x0 = x1 = 0;
                    y0 = y1 = 0;
                }
            }
            const int rw = x1 - x0 + 1, rh = y1 - y0 + 1;
            sub.resize(static_cast<std::size_t>(rw) * static_cast<std::size_t>(rh));
            const bool masked = k > 0 && useTransparency;
            for (int y = 0; y < rh; ++y)
            {
                const std::size_t from = static_cast<std::size_t>(y0 + y) * static_cast<std::size_t>(w) +
                                         static_cast<std::size_t>(x0);
                std::uint8_t *row = &sub[static_cast<std::size_t>(y) * static_cast<std::size_t>(rw)];
                std::memcpy(row, &f[from], static_cast<std::size_t>(rw));
                if (masked)
                    for (std::size_t x = 0; x < static_cast<std::size_t>(rw); ++x)
                        if (row[x] == frames[k - 1][from + x])
                            row[x] = static_cast<std::uint8_t>(transparent);
            }

            // Graphic control extension: disposal 1 (leave in place), the delay, the transparent index.
            out.push_back(0x21);
            out.push_back(0xF9);
            out.push_back(4);
            out.push_back(static_cast<std::uint8_t>(0x04 | (masked ? 1 : 0)));
            putLe16(out, delaysCs.size() == 1 ? delaysCs[0] : delaysCs[k]);
            out.push_back(static_cast<std::uint8_t>(masked ? transparent : 0));
            out.push_back(0);
            // Image descriptor: no local colour table, not interlaced.
            out.push_back(0x2C);
            putLe16(out, x0);
            putLe16(out, y0);
            putLe16(out, rw);
            putLe16(out, rh);
            out.push_back(0);
            out.push_back(static_cast<std::uint8_t>(minCodeSize));
            const std::vector<std::uint8_t> codes = lzwEncode(sub, minCodeSize);
            for (std::size_t pos = 0; pos < codes.size(); pos += 255)
            {
                const std::size_t len = std::min<std::size_t>(255, codes.size() - pos);
                out.push_back(static_cast<std::uint8_t>(len));
                out.insert(out.end(), codes.begin() + static_cast<long>(pos),
                           codes.begin() + static_cast<long>(pos + len));
            }
            out.push_back(0);
        }
        out.push_back(0x3B);
        return out;
    }

    std::vector<std::uint8_t> encodeGif(int w, int h, const std::vector<std::array<std::uint8_t, 3>> &palette,
                                        const std::vector<std::vector<std::uint8_t>> &frames, int delayCs)
    {
        return encodeGif(w, h, palette, frames, std::vector<int>{delayCs});
    }

    std::vector<std::vector<std::uint8_t>>
    renderSimulationFrames(const Scenario &scenario, const SimulationResult &result,
                           const GifOptions &options, int &width, int &height,
                           std::vector<std::array<std::uint8_t, 3>> &palette)
    {
        if (options.width < 16 || options.width > 4096)
            throw std::invalid_argument("GifOptions::width must be in [16, 4096] pixels (got " +
                                        std::to_string(options.width) + ")");
        if (options.maxFrames < 2)
            throw std::invalid_argument("GifOptions::maxFrames must be >= 2 (got " +
                                        std::to_string(options.maxFrames) + ")");
        const Box &b = scenario.world.bounds;
        if (!(b.width() > 0.0) || !(b.height() > 0.0))
            throw std::invalid_argument("renderSimulationFrames: the scenario's world has empty bounds");

        palette = gifPalette();
        View v;
        v.bounds = b;
        v.margin = 4.0;
        v.scale = (options.width - 2.0 * v.margin) / b.width();
        const int label = options.timeLabel ? 16 : 0;
        width = options.width;
        const int worldH = static_cast<int>(std::lround(b.height() * v.scale + 2.0 * v.margin));
        height = std::min(4096, worldH + label);

        Canvas base(width, height, kWhite);
        drawWorld(base, scenario.world, v);

        const std::vector<std::size_t> indices = frameIndices(result.times.size(), options.maxFrames);
        std::vector<std::vector<std::uint8_t>> frames;
        if (indices.empty())
        {
            frames.push_back(base.pixels());
            return frames;
        }
        const double trail = std::max(1.0, std::round(v.scale * 0.02));
        const int trailWidth = std::min(3, static_cast<int>(trail));
        const std::size_t robots = result.robots.size();
        std::vector<long> drawn(robots, -1); // last trail sample drawn per robot
        long obstacleDrawn = -1;             // last trace index drawn
        for (std::size_t idx : indices)
        {
            const double t = result.times[idx];
            // Moving obstacles' traces, beneath everything else.
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                const long last = std::min<long>(static_cast<long>(idx), static_cast<long>(pos.size()) - 1);
                for (long k = std::max(1L, obstacleDrawn + 1); k <= last; ++k)
                    base.line(v.x(pos[static_cast<std::size_t>(k) - 1].x),
                              v.y(pos[static_cast<std::size_t>(k) - 1].y),
                              v.x(pos[static_cast<std::size_t>(k)].x),
                              v.y(pos[static_cast<std::size_t>(k)].y), kTrace, 1, kWorld);
            }
            obstacleDrawn = static_cast<long>(idx);
            // Robot trails so far.
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                const long last = lastSampleAtOrBefore(r.times, t);
                for (long k = std::max(1L, drawn[i] + 1); k <= last; ++k)
                {
                    const Vec2 &a = r.positions[static_cast<std::size_t>(k) - 1];
                    const Vec2 &e = r.positions[static_cast<std::size_t>(k)];
                    base.line(v.x(a.x), v.y(a.y), v.x(e.x), v.y(e.y), trailIndex(i), trailWidth);
                }
                drawn[i] = std::max(drawn[i], last);
            }

            Canvas frame = base;
            for (std::size_t i = 0; i < robots && i < result.goalPositions.size(); ++i)
            {
                const auto &g = result.goalPositions[i];
                if (g.empty() || lastSampleAtOrBefore(result.robots[i].times, t) < 0)
                    continue;
                const Vec2 &p = g[std::min(idx, g.size() - 1)];
                frame.cross(v.x(p.x), v.y(p.y), 3.0, robotIndex(i));
            }
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                if (pos.empty())
                    continue;
                const Vec2 &p = pos[std::min(idx, pos.size() - 1)];
                const double radius =
                    o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2;
                const double r = std::max(2.0, radius * v.scale);
                frame.fillDisc(v.x(p.x), v.y(p.y), r, kMovingObstacleEdge);
                frame.fillDisc(v.x(p.x), v.y(p.y), r - 1.0, kMovingObstacle);
            }
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                const long k = lastSampleAtOrBefore(r.times, t);
                if (k < 0)
                    continue;
                const Vec2 &p = r.positions[static_cast<std::size_t>(k)];
                const double heading = static_cast<std::size_t>(k) < r.headings.size()
                                           ? r.headings[static_cast<std::size_t>(k)]
                                           : 0.0;
                const double radius = i < scenario.robots.size() ? scenario.robots[i].radius : 0.105;
                const double rr = std::max(3.0, radius * v.scale);
                const double cx = v.x(p.x), cy = v.y(p.y);
                frame.fillDisc(cx, cy, rr, robotIndex(i));
                frame.ring(cx, cy, rr, 1.0, kBlack);
                const double c = std::cos(heading), sn = std::sin(heading);
                frame.line(cx + c * rr * 0.4, cy - sn * rr * 0.4, cx + c * (rr + 2.0), cy - sn * (rr + 2.0),
                           kBlack);
            }
            if (options.timeLabel)
            {
                std::ostringstream s;
                s << "t = " << std::fixed << std::setprecision(2) << t << " s";
                frame.fillRect(0, worldH, width, height, kWhite);
                frame.text(static_cast<int>(v.margin), worldH + 2, s.str(), kBlack, 2);
            }
            frames.push_back(std::move(frame.pixels()));
        }
        return frames;
    }

    std::vector<std::uint8_t> simulationGif(const Scenario &scenario, const SimulationResult &result,
                                            const GifOptions &options)
    {
        if (!(options.fps > 0.0) || options.fps > 100.0)
            throw std::invalid_argument("GifOptions::fps must be in (0, 100] (got " +
                                        std::to_string(options.fps) + ")");
        if (!(options.holdLast >= 0.0) || options.holdLast > 600.0)
            throw std::invalid_argument("GifOptions::holdLast must be in [0, 600] s (got " +
                                        std::to_string(options.holdLast) + ")");
        int w = 0, h = 0;
        std::vector<std::array<std::uint8_t, 3>> palette;
        const auto frames = renderSimulationFrames(scenario, result, options, w, h, palette);
        // Browsers play delays below 2 cs as 10 cs: never go below 2.
        const int delay = std::max(2, static_cast<int>(std::lround(100.0 / options.fps)));
        std::vector<int> delays(frames.size(), delay);
        delays.back() = std::min(65535, delay + static_cast<int>(std::lround(options.holdLast * 100.0)));
        return encodeGif(w, h, palette, frames, delays);
    }

    void writeSimulationGif(const Scenario &scenario, const SimulationResult &result, const std::string &path,
                            const GifOptions &options)
    {
        const std::vector<std::uint8_t> bytes = simulationGif(scenario, result, options);
        std::ofstream out(path, std::ios::binary);
        if (!out)
            throw InputError(path + ": cannot open for writing");
        out.write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out)
            throw InputError(path + ": write failed");
    }

    // ----------------------------------------------------------------------------------------------------
    // SVG

    std::string simulationSvg(const Scenario &scenario, const SimulationResult &result, bool animate,
                              int maxFrames, double fps)
    {
        const Box &b = scenario.world.bounds;
        if (!(b.width() > 0.0) || !(b.height() > 0.0))
            throw std::invalid_argument("simulationSvg: the scenario's world has empty bounds");
        if (animate && (maxFrames < 2 || !(fps > 0.0)))
            throw std::invalid_argument("simulationSvg: maxFrames must be >= 2 and fps > 0 (got " +
                                        std::to_string(maxFrames) + ", " + std::to_string(fps) + ")");
        View v;
        v.bounds = b;
        v.margin = 20.0;
        v.scale = 800.0 / std::max(b.width(), b.height());
        const double w = b.width() * v.scale + 2 * v.margin;
        const double worldH = b.height() * v.scale + 2 * v.margin;
        const std::size_t robots = result.robots.size();
        const int perRow = std::max(1, static_cast<int>((w - 2 * v.margin) / 150.0));
        const std::size_t swatchRows =
            (robots + static_cast<std::size_t>(perRow) - 1) / static_cast<std::size_t>(perRow);
        const double legendH = 3 * 18.0 + 18.0 * static_cast<double>(swatchRows) + 10.0;
        const double h = worldH + legendH;

        std::ostringstream s;
        s << std::fixed << std::setprecision(2);
        s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
          << "\" viewBox=\"0 0 " << w << " " << h << "\">\n";
        s << "<title>" << svgEscape(result.scenario.empty() ? scenario.name : result.scenario) << " - "
          << svgEscape(result.controller) << "</title>\n";
        s << "<rect x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h << "\" fill=\"white\"/>\n";
        s << worldSvgShapes(scenario.world, v.scale, v.margin);

        auto pointList = [&](const std::vector<Vec2> &pts)
        {
            std::ostringstream p;
            p << std::fixed << std::setprecision(2);
            for (const auto &q : pts)
                p << v.x(q.x) << "," << v.y(q.y) << " ";
            return p.str();
        };

        // Moving obstacles: traces and final positions.
        s << "<g class=\"moving-obstacles\">\n";
        for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
        {
            const auto &pos = result.obstaclePositions[o];
            if (pos.empty())
                continue;
            const double r =
                (o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2) * v.scale;
            s << "<polyline fill=\"none\" stroke=\"#bbbbbb\" stroke-width=\"1\" points=\"" << pointList(pos)
              << "\"/>\n";
            s << "<circle cx=\"" << v.x(pos.back().x) << "\" cy=\"" << v.y(pos.back().y) << "\" r=\"" << r
              << "\" fill=\"#e6550d\" fill-opacity=\"0.5\" stroke=\"#a63603\">";
            if (o < scenario.movingObstacles.size())
                s << "<title>" << svgEscape(scenario.movingObstacles[o].name) << "</title>";
            s << "</circle>\n";
        }
        s << "</g>\n";

        // Robots: trajectory, start, goals, final disc and heading.
        for (std::size_t i = 0; i < robots; ++i)
        {
            const RobotResult &r = result.robots[i];
            const std::string color = robotColor(i);
            const double radius = (i < scenario.robots.size() ? scenario.robots[i].radius : 0.105) * v.scale;
            s << "<g class=\"robot\">\n";
            // Moving goal: its trace (dashed).
            if (i < result.goalPositions.size() && !result.goalPositions[i].empty())
            {
                const auto &g = result.goalPositions[i];
                bool moves = false;
                for (const auto &p : g)
                    moves = moves || distance(p, g.front()) > 1e-9;
                if (moves)
                    s << "<polyline fill=\"none\" stroke=\"" << color
                      << "\" stroke-width=\"1\" stroke-dasharray=\"4 3\" stroke-opacity=\"0.6\" points=\""
                      << pointList(g) << "\"/>\n";
            }
            // The trajectory, thinned to points at least half a pixel apart.
            s << "<path class=\"trajectory\" fill=\"none\" stroke=\"" << color
              << "\" stroke-width=\"2\" stroke-linejoin=\"round\" d=\"";
            Vec2 lastKept;
            for (std::size_t k = 0; k < r.positions.size(); ++k)
            {
                const Vec2 &p = r.positions[k];
                if (k > 0 && k + 1 < r.positions.size() && distance(p, lastKept) * v.scale < 0.5)
                    continue;
                s << (k == 0 ? "M" : " L") << v.x(p.x) << " " << v.y(p.y);
                lastKept = p;
            }
            s << "\"><title>" << svgEscape(r.name) << " (" << toString(r.status) << ")</title></path>\n";
            if (!r.positions.empty())
            {
                const Vec2 &p0 = r.positions.front();
                s << "<circle cx=\"" << v.x(p0.x) << "\" cy=\"" << v.y(p0.y)
                  << "\" r=\"4\" fill=\"white\" stroke=\"" << color << "\" stroke-width=\"2\"><title>"
                  << svgEscape(r.name) << " start</title></circle>\n";
            }
            if (i < scenario.robots.size())
                for (std::size_t k = 0; k < scenario.robots[i].tasks.size(); ++k)
                {
                    Vec2 g = scenario.robots[i].tasks[k].goal.from;
                    if (scenario.robots[i].tasks[k].goal.kind != Motion::Kind::Fixed)
                    {
                        if (i >= result.goalPositions.size() || result.goalPositions[i].empty())
                            continue;
                        g = result.goalPositions[i].back();
                    }
                    const double gx = v.x(g.x), gy = v.y(g.y);
                    s << "<line x1=\"" << gx - 5 << "\" y1=\"" << gy - 5 << "\" x2=\"" << gx + 5 << "\" y2=\""
                      << gy + 5 << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
                    s << "<line x1=\"" << gx - 5 << "\" y1=\"" << gy + 5 << "\" x2=\"" << gx + 5 << "\" y2=\""
                      << gy - 5 << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
                }
            if (!r.positions.empty())
            {
                const Vec2 &pe = r.positions.back();
                const double heading = r.headings.empty() ? 0.0 : r.headings.back();
                const double cx = v.x(pe.x), cy = v.y(pe.y);
                s << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << radius << "\" fill=\"" << color
                  << "\" fill-opacity=\"0.8\" stroke=\"black\"/>\n";
                s << "<line x1=\"" << cx << "\" y1=\"" << cy << "\" x2=\""
                  << cx + std::cos(heading) * (radius + 3) << "\" y2=\""
                  << cy - std::sin(heading) * (radius + 3) << "\" stroke=\"black\"/>\n";
            }
            s << "</g>\n";
        }

        // SMIL replay: robots and moving obstacles as discs moving over the drawing.
        const std::vector<std::size_t> indices =
            animate ? frameIndices(result.times.size(), maxFrames) : std::vector<std::size_t>();
        if (indices.size() >= 2)
        {
            const double dur = static_cast<double>(indices.size()) / fps;
            s << "<g class=\"replay\">\n";
            auto animateAttr = [&](const std::string &attr, const std::vector<double> &values)
            {
                s << "<animate attributeName=\"" << attr << "\" dur=\"" << dur
                  << "s\" repeatCount=\"indefinite\" values=\"";
                for (std::size_t k = 0; k < values.size(); ++k)
                    s << (k ? ";" : "") << values[k];
                s << "\"/>";
            };
            for (std::size_t o = 0; o < result.obstaclePositions.size(); ++o)
            {
                const auto &pos = result.obstaclePositions[o];
                if (pos.empty())
                    continue;
                const double r =
                    (o < scenario.movingObstacles.size() ? scenario.movingObstacles[o].radius : 0.2) *
                    v.scale;
                std::vector<double> xs, ys;
                for (std::size_t idx : indices)
                {
                    const Vec2 &p = pos[std::min(idx, pos.size() - 1)];
                    xs.push_back(v.x(p.x));
                    ys.push_back(v.y(p.y));
                }
                s << "<circle r=\"" << r << "\" cx=\"" << xs[0] << "\" cy=\"" << ys[0]
                  << "\" fill=\"#e6550d\" fill-opacity=\"0.7\" stroke=\"#a63603\" stroke-dasharray=\"2 2\">";
                animateAttr("cx", xs);
                animateAttr("cy", ys);
                s << "</circle>\n";
            }
            for (std::size_t i = 0; i < robots; ++i)
            {
                const RobotResult &r = result.robots[i];
                if (r.positions.empty())
                    continue;
                const double radius =
                    std::max(3.0, (i < scenario.robots.size() ? scenario.robots[i].radius : 0.105) * v.scale);
                std::vector<double> xs, ys;
                std::string visibility;
                bool hides = false;
                for (std::size_t idx : indices)
                {
                    const long k = lastSampleAtOrBefore(r.times, result.times[idx]);
                    const Vec2 &p = r.positions[static_cast<std::size_t>(std::max(0L, k))];
                    xs.push_back(v.x(p.x));
                    ys.push_back(v.y(p.y));
                    visibility += std::string(visibility.empty() ? "" : ";") + (k < 0 ? "hidden" : "visible");
                    hides = hides || k < 0;
                }
                s << "<circle r=\"" << radius << "\" cx=\"" << xs[0] << "\" cy=\"" << ys[0] << "\" fill=\""
                  << robotColor(i) << "\" fill-opacity=\"0.7\" stroke=\"black\" stroke-dasharray=\"2 2\">";
                animateAttr("cx", xs);
                animateAttr("cy", ys);
                if (hides)
                    s << "<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" << dur
                      << "s\" repeatCount=\"indefinite\" values=\"" << visibility << "\"/>";
                s << "</circle>\n";
            }
            s << "</g>\n";
        }

        // Legend.
        double ly = worldH + 14.0;
        auto text = [&](double x, double y, const std::string &t)
        {
            s << "<text x=\"" << x << "\" y=\"" << y << "\" font-family=\"sans-serif\" font-size=\"13\">"
              << svgEscape(t) << "</text>\n";
        };
        text(v.margin, ly,
             (result.scenario.empty() ? scenario.name : result.scenario) + " | controller " +
                 result.controller + " | seed " + std::to_string(result.seed) + " | " +
                 std::to_string(result.done) + " done, " + std::to_string(result.stuck) + " stuck, " +
                 std::to_string(result.unfinished) + " unfinished");
        ly += 18.0;
        text(v.margin, ly,
             "makespan " + formatNumber(result.makespan, 2) + " s | flowtime " +
                 formatNumber(result.flowtime, 2) + " s | collisions " + std::to_string(result.collisions()) +
                 " (static " + std::to_string(result.staticCollisions) + ", moving " +
                 std::to_string(result.movingCollisions) + ", robot " +
                 std::to_string(result.robotCollisions) + ")");
        ly += 18.0;
        text(v.margin, ly,
             "min robot distance " + formatNumber(result.minRobotDistance) + " m | min obstacle clearance " +
                 formatNumber(result.minObstacleClearance) + " m | simulated " +
                 formatNumber(result.simulatedTime, 2) + " s");
        ly += 18.0;
        for (std::size_t i = 0; i < robots; ++i)
        {
            const double x = v.margin + 150.0 * static_cast<double>(i % static_cast<std::size_t>(perRow));
            const double y = ly + 18.0 * static_cast<double>(i / static_cast<std::size_t>(perRow));
            s << "<line x1=\"" << x << "\" y1=\"" << y - 4 << "\" x2=\"" << x + 20 << "\" y2=\"" << y - 4
              << "\" stroke=\"" << robotColor(i) << "\" stroke-width=\"3\"/>\n";
            text(x + 26, y, result.robots[i].name + " (" + toString(result.robots[i].status) + ")");
        }
        s << "</svg>\n";
        return s.str();
    }

    // ----------------------------------------------------------------------------------------------------
    // CSV

    std::string trajectoryCsv(const SimulationResult &result)
    {
        std::vector<std::tuple<double, std::size_t, std::size_t>> rows;
        for (std::size_t i = 0; i < result.robots.size(); ++i)
            for (std::size_t k = 0;
                 k < result.robots[i].times.size() && k < result.robots[i].positions.size(); ++k)
                rows.emplace_back(result.robots[i].times[k], i, k);
        std::sort(rows.begin(), rows.end());
        std::ostringstream s;
        s << "time,robot,x,y,heading\n" << std::setprecision(10);
        for (const auto &row : rows)
        {
            const RobotResult &r = result.robots[std::get<1>(row)];
            const std::size_t k = std::get<2>(row);
            s << std::get<0>(row) << "," << r.name << "," << r.positions[k].x << "," << r.positions[k].y
              << "," << (k < r.headings.size() ? r.headings[k] : 0.0) << "\n";
        }
        return s.str();
    }
} // namespace mhplan
