// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target campaign: mhplan::fuzz::campaign (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::campaign)
