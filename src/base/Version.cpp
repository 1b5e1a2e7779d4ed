// SPDX-License-Identifier: BSD-3-Clause
#include "src/base/Version.h"

#include "src/base/VersionConfig.h"

#include <ompl/config.h>

namespace mhplan
{
    std::string version()
    {
        return MHPLAN_VERSION_STRING;
    }

    std::string omplVersion()
    {
        const std::string fromHeader = OMPL_VERSION;
        if (!fromHeader.empty())
            return fromHeader;
        const std::string fromCMake = MHPLAN_OMPL_VERSION_STRING;
        if (!fromCMake.empty())
            return fromCMake;
        return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
               std::to_string(OMPL_PATCH_VERSION);
    }
} // namespace mhplan
