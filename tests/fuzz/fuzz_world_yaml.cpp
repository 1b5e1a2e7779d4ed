// SPDX-License-Identifier: BSD-3-Clause
/* libFuzzer target world_yaml: mhplan::fuzz::worldYaml (FuzzTargets.h). */
#include "FuzzTargets.h"

#include <cstdio>
#include <cstdlib>

MHPLAN_FUZZ_TARGET(mhplan::fuzz::worldYaml)
