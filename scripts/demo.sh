#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install what is missing, build, and run the main job: the default benchmark campaign (every shipped seed
# world x the five metaheuristics in their papers' settings x RRT*, Informed RRT*, PRM*, BIT* and A*) into
# results/seeds.db (OMPL logs + SQLite, Planner Arena compatible), then the HTML report results/report/.
# A re-run resumes: finished experiments are skipped. Extra arguments go to 'mhplan bench'.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${MHPLAN_BUILD_DIR:-build}"
scripts/setup.sh "$BUILD_DIR"
JOBS=$(nproc 2>/dev/null || echo 2)
"$BUILD_DIR/mhplan" bench benchmarks/seeds.yaml --jobs "$JOBS" "$@"
"$BUILD_DIR/mhplan" report results/seeds.db -o results/report >/dev/null
echo "report: $(pwd)/results/report/index.html"
# The simulation experiments are in their own database (Planner Arena: mhplan arena results/seeds-sim.db).
"$BUILD_DIR/mhplan" report results/seeds-sim.db -o results/report-sim >/dev/null
echo "simulations: $(pwd)/results/report-sim/index.html"
