// SPDX-License-Identifier: BSD-3-Clause
// Compiled as a base-layer source: the base may not include a planner (the registry once did). This must not
// build (tests/CMakeLists.txt: layering_base_includes_planner).
#include "ompl_planners/population/SlimeMould.h"
