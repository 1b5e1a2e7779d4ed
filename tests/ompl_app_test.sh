#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# mhplan_ompl_app (benchmarks/ompl_app.cpp): its usage, its refusals of bad options (a message naming the
# option and a non-zero exit, never a run with a value read as 0), and one tiny run's table.
# Usage: ompl_app_test.sh PATH_TO_mhplan_ompl_app
set -euo pipefail
app="$1"
"$app" --help | grep -q "^usage: mhplan_ompl_app"
refused() {
  local out
  if out=$("$app" "$@" 2>&1); then
    echo "accepted: $*"; exit 1
  fi
  grep -qF -- "$EXPECT" <<<"$out" || { echo "for $*: $out"; exit 1; }
}
EXPECT="option '--time' wants a value" refused --time
EXPECT="--time '1s' (a number expected)" refused --time 1s
EXPECT="--queries '2.5' (a whole number" refused --queries 2.5
EXPECT="unknown option '--bogus'" refused --bogus 1
EXPECT="--params wants KEY=VALUE" refused --params nokey
out=$("$app" --queries 1 --time 0.05 --planners GA-MEM,RRTstar)
grep -q "^| GA-MEM | 1/1 |" <<<"$out" || { echo "$out"; exit 1; }
grep -q "^| RRTstar |" <<<"$out" || { echo "$out"; exit 1; }
echo "mhplan_ompl_app: usage, refusals and one run as documented"
