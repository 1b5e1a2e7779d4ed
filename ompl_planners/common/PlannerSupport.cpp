// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/planners/common/PlannerSupport.h"

#include <iomanip>
#include <sstream>

namespace ob = ompl::base;

namespace mhplan
{
    void addPathToPlannerData(const ob::SpaceInformation &si, std::size_t count,
                              const std::function<void(ob::State *, std::size_t)> &fill, bool lastIsGoal,
                              ob::PlannerData &data, std::vector<ob::State *> &owned)
    {
        unsigned int previous = ob::PlannerData::INVALID_INDEX;
        for (std::size_t i = 0; i < count; ++i)
        {
            ob::State *s = si.allocState();
            owned.push_back(s);
            fill(s, i);
            const ob::PlannerDataVertex v(s);
            const unsigned int index = i == 0                           ? data.addStartVertex(v)
                                       : (i + 1 == count && lastIsGoal) ? data.addGoalVertex(v)
                                                                        : data.addVertex(v);
            if (i > 0)
                data.addEdge(previous, index);
            previous = index;
        }
    }

    void freeStates(const ob::SpaceInformation &si, std::vector<ob::State *> &owned)
    {
        for (ob::State *s : owned)
            si.freeState(s);
        owned.clear();
    }

    std::string formatCost(double cost)
    {
        std::ostringstream out;
        out << std::setprecision(17) << cost;
        return out.str();
    }
} // namespace mhplan
