// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target pgm: mhplan::fuzz::pgm (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::pgm)
