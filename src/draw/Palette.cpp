// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/draw/SimRender.h"

#include "mhplan/draw/detail/Palette.h"

namespace mhplan
{
    std::string robotColor(std::size_t i)
    {
        return draw_detail::kRobotColors[i % draw_detail::kRobotColors.size()];
    }
} // namespace mhplan
