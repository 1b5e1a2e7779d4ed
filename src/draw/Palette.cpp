// SPDX-License-Identifier: BSD-3-Clause
#include "src/draw/SimRender.h"

#include "src/draw/detail/Palette.h"

namespace mhplan
{
    std::string robotColor(std::size_t i)
    {
        return draw_detail::kRobotColors[i % draw_detail::kRobotColors.size()];
    }
} // namespace mhplan
