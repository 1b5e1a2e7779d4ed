// SPDX-License-Identifier: BSD-3-Clause
#include "src/draw/detail/Raster.h"

namespace mhplan
{
    namespace draw_detail
    {
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
    } // namespace draw_detail
} // namespace mhplan
