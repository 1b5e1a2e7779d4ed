// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/DubinsGuard.h"

#include "src/collision/CarSpaces.h"

namespace ob = ompl::base;

namespace mhplan
{
    DubinsGuard::DubinsGuard(const ob::StateSpace *space)
    {
        const auto *dubins = dynamic_cast<const ob::DubinsStateSpace *>(space);
        if (dubins == nullptr || dynamic_cast<const SafeDubinsStateSpace *>(space) != nullptr)
            return;
        radius_ = detail::DubinsRadius::of(*dubins);
        symmetric_ = dubins->hasSymmetricDistance();
        safeSpace_ = std::make_shared<SafeDubinsStateSpace>(radius_, symmetric_);
    }

    double DubinsGuard::distance(const ob::SpaceInformation &si, const ob::State *a, const ob::State *b,
                                 bool isSafe) const
    {
        return isSafe ? si.distance(a, b) : safeSpace_->distance(a, b);
    }

    void DubinsGuard::interpolate(const ob::SpaceInformation &si, const ob::State *a, const ob::State *b,
                                  double t, ob::State *out, bool isSafe) const
    {
        if (isSafe)
            si.getStateSpace()->interpolate(a, b, t, out);
        else
            safeSpace_->interpolate(a, b, t, out);
    }
} // namespace mhplan
