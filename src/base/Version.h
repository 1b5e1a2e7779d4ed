// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: version strings (OMPL's own, which Debian's build leaves empty, comes from its CMake package). */
#ifndef MHPLAN_VERSION_H
#define MHPLAN_VERSION_H

#include <string>

namespace mhplan
{
    /** \brief mhplan's version, e.g. "0.1.0". */
    std::string version();
    /** \brief The OMPL version mhplan was built against, e.g. "1.5.2" (never empty). */
    std::string omplVersion();
} // namespace mhplan

#endif
