// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target map: mhplan::fuzz::map (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::map)
