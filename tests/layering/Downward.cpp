// SPDX-License-Identifier: BSD-3-Clause
// Compiled as a sim-layer source: every layer below the simulator is reachable. The control for the upward
// fixtures (tests/CMakeLists.txt: layering_downward): it must build.
#include "mhplan/base/World.h"
#include "mhplan/collision/Problem.h"
#include "mhplan/io/WorldIO.h"
#include "mhplan/registry/Registry.h"
#include "mhplan/sim/Simulation.h"
