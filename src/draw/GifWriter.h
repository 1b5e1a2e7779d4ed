// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: animated GIF89a files from frames of palette indices, encoded by giflib. */
#ifndef MHPLAN_DRAW_GIF_WRITER_H
#define MHPLAN_DRAW_GIF_WRITER_H

#include <array>
#include <cstdint>
#include <vector>

namespace mhplan
{
    /** \brief Encode frames as an animated GIF89a that loops forever (NETSCAPE2.0 extension), with giflib.

        \e palette has 2..256 colours (padded to a power of two with black); every frame holds \e w * \e h
        palette indices (row-major, top row first), each < palette.size(). \e delaysCs holds one delay per
        frame in hundredths of a second, or a single value for all. Frames after the first are stored as the
        smallest rectangle that differs from the previous frame (disposal "do not dispose"), so a decoder
        composites them onto the previous canvas; with fewer than 256 colours the unchanged pixels in that
        rectangle are written as a transparent index (palette.size()), whose long runs compress far better.
        Throws std::invalid_argument naming the parameter on misuse, std::runtime_error if giflib fails. */
    std::vector<std::uint8_t> encodeGif(int w, int h, const std::vector<std::array<std::uint8_t, 3>> &palette,
                                        const std::vector<std::vector<std::uint8_t>> &frames,
                                        const std::vector<int> &delaysCs);

    /** \brief encodeGif with one delay for every frame. */
    std::vector<std::uint8_t> encodeGif(int w, int h, const std::vector<std::array<std::uint8_t, 3>> &palette,
                                        const std::vector<std::vector<std::uint8_t>> &frames, int delayCs);
} // namespace mhplan

#endif
