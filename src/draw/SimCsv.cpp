// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the trajectories of a run as CSV. */
#include "src/draw/SimRender.h"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <tuple>

namespace mhplan
{
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
