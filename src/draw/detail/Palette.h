// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the colours of drawn runs: the robots' colours and the fixed palette of the GIF frames with its
   named indices. Not part of the installed API. */
#ifndef MHPLAN_DRAW_DETAIL_PALETTE_H
#define MHPLAN_DRAW_DETAIL_PALETTE_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mhplan
{
    namespace draw_detail
    {
        /** Robot colours: matplotlib's tab10 then its light companions; the greys are replaced so robots do
            not look like obstacles. */
        inline constexpr std::array<const char *, 20> kRobotColors = {
            "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
            "#393b79", "#bcbd22", "#17becf", "#aec7e8", "#ffbb78", "#98df8a", "#ff9896",
            "#c5b0d5", "#c49c94", "#f7b6d2", "#637939", "#dbdb8d", "#9edae5"};

        using Rgb = std::array<std::uint8_t, 3>;

        inline Rgb parseHex(const char *hex)
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

        inline std::vector<Rgb> gifPalette()
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

        inline std::uint8_t robotIndex(std::size_t i)
        {
            return static_cast<std::uint8_t>(kRobotBase + i % kRobotColors.size());
        }
        inline std::uint8_t trailIndex(std::size_t i)
        {
            return static_cast<std::uint8_t>(kTrailBase + i % kRobotColors.size());
        }
    } // namespace draw_detail
} // namespace mhplan

#endif
