// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target scenario: mhplan::fuzz::scenario (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::scenario)
