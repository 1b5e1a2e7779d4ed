// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target grid_rows: mhplan::fuzz::gridRows (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::gridRows)
