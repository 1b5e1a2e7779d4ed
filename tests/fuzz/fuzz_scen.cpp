// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target scen: mhplan::fuzz::scen (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::scen)
