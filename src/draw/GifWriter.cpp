// SPDX-License-Identifier: BSD-3-Clause
#include "src/draw/GifWriter.h"

#include <gif_lib.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace mhplan
{
    namespace
    {
        /** giflib's output function: append to the std::vector<std::uint8_t> in UserData. */
        int appendBytes(GifFileType *gif, const GifByteType *data, int n)
        {
            auto *out = static_cast<std::vector<std::uint8_t> *>(gif->UserData);
            out->insert(out->end(), data, data + n);
            return n;
        }

        /** The open giflib encoder; closing it (and freeing it) on every path. */
        struct GifCloser
        {
            void operator()(GifFileType *gif) const
            {
                int error = 0;
                EGifCloseFile(gif, &error);
            }
        };
        using GifHandle = std::unique_ptr<GifFileType, GifCloser>;

        /** giflib's message for an error code (it has none for unknown codes). */
        std::string errorText(int error)
        {
            const char *text = GifErrorString(error);
            return text != nullptr ? text : "giflib error " + std::to_string(error);
        }

        void check(int status, const GifHandle &gif, const char *what)
        {
            if (status != GIF_OK)
                throw std::runtime_error(std::string("encodeGif: giflib ") + what +
                                         " failed: " + errorText(gif->Error));
        }
    } // namespace

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

        std::vector<GifColorType> colours(std::size_t{1} << tableBits, GifColorType{0, 0, 0});
        for (std::size_t k = 0; k < palette.size(); ++k)
            colours[k] = GifColorType{palette[k][0], palette[k][1], palette[k][2]};
        std::unique_ptr<ColorMapObject, void (*)(ColorMapObject *)> map(
            GifMakeMapObject(static_cast<int>(colours.size()), colours.data()), GifFreeMapObject);
        if (!map)
            throw std::runtime_error("encodeGif: giflib could not make the colour map");

        std::vector<std::uint8_t> out;
        int error = 0;
        GifHandle gif(EGifOpen(&out, appendBytes, &error));
        if (!gif)
            throw std::runtime_error(std::string("encodeGif: giflib could not open the encoder: ") +
                                     errorText(error));
        EGifSetGifVersion(gif.get(), true);
        // Logical screen: the global colour table, 8 bits colour resolution, background index 0.
        check(EGifPutScreenDesc(gif.get(), w, h, 8, 0, map.get()), gif, "screen descriptor");
        // NETSCAPE2.0: loop forever.
        const GifByteType loop[3] = {1, 0, 0};
        check(EGifPutExtensionLeader(gif.get(), APPLICATION_EXT_FUNC_CODE), gif, "loop extension");
        check(EGifPutExtensionBlock(gif.get(), 11, "NETSCAPE2.0"), gif, "loop extension");
        check(EGifPutExtensionBlock(gif.get(), 3, loop), gif, "loop extension");
        check(EGifPutExtensionTrailer(gif.get()), gif, "loop extension");

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

            // Graphic control: disposal 1 (leave in place), the delay, the transparent index.
            GraphicsControlBlock gcb;
            gcb.DisposalMode = DISPOSE_DO_NOT;
            gcb.UserInputFlag = false;
            gcb.DelayTime = delaysCs.size() == 1 ? delaysCs[0] : delaysCs[k];
            gcb.TransparentColor = masked ? static_cast<int>(transparent) : NO_TRANSPARENT_COLOR;
            GifByteType extension[4];
            const std::size_t len = EGifGCBToExtension(&gcb, extension);
            check(EGifPutExtension(gif.get(), GRAPHICS_EXT_FUNC_CODE, static_cast<int>(len), extension), gif,
                  "graphic control extension");
            // The rectangle: no local colour table, not interlaced; giflib writes the LZW code stream.
            check(EGifPutImageDesc(gif.get(), x0, y0, rw, rh, false, nullptr), gif, "image descriptor");
            check(EGifPutLine(gif.get(), sub.data(), static_cast<int>(sub.size())), gif, "image data");
        }
        // Closing writes the trailer.
        GifFileType *raw = gif.release();
        if (EGifCloseFile(raw, &error) != GIF_OK)
            throw std::runtime_error(std::string("encodeGif: giflib could not finish the file: ") +
                                     errorText(error));
        return out;
    }

    std::vector<std::uint8_t> encodeGif(int w, int h, const std::vector<std::array<std::uint8_t, 3>> &palette,
                                        const std::vector<std::vector<std::uint8_t>> &frames, int delayCs)
    {
        return encodeGif(w, h, palette, frames, std::vector<int>{delayCs});
    }
} // namespace mhplan
