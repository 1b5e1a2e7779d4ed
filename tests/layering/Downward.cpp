// SPDX-License-Identifier: BSD-3-Clause
// Compiled as a sim-layer source: every layer below the simulator is reachable. The control for the upward
// fixtures (tests/CMakeLists.txt: layering_downward): it must build.
#include "src/base/World.h"
#include "src/collision/Problem.h"
#include "src/io/WorldIO.h"
#include "src/registry/Registry.h"
#include "src/sim/Simulation.h"
