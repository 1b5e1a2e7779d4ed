// SPDX-License-Identifier: BSD-3-Clause
// Compiled as a collision-layer source: the collision layer may not include the simulator. This must not
// build (tests/CMakeLists.txt: layering_collision_includes_sim).
#include "src/sim/Simulation.h"
