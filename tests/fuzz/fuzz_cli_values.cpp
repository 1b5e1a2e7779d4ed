// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target cli_values: mhplan::fuzz::cliValues (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::cliValues)
