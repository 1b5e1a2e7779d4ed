#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The overhead of a campaign (benchmarks/README.md, "Overhead"): run CAMPAIGN twice, with N1 and with N2 runs
# per planner and experiment, into a scratch folder, and split "wall time minus the planners' solve times"
# into a fixed part and a part per run (the difference between the two, over the difference in runs).
# Usage: benchmarks/overhead.sh [MHPLAN] [CAMPAIGN] [N1] [N2] [TIME]
#   defaults: build/mhplan benchmarks/seeds.yaml 2 6 0.01
set -euo pipefail
MHPLAN=${1:-build/mhplan}
CAMPAIGN=${2:-benchmarks/seeds.yaml}
N1=${3:-2}
N2=${4:-6}
TIME=${5:-0.01}
SCRATCH=$(mktemp -d)
trap 'rm -rf "$SCRATCH"' EXIT
declare -A RUNS OVER
for n in "$N1" "$N2"; do
  out="$SCRATCH/out-$n.txt"
  "$MHPLAN" bench "$CAMPAIGN" --runs "$n" --time "$TIME" --logs "$SCRATCH/logs-$n" \
    --database "$SCRATCH/db-$n.db" --no-progress > "$out" 2> "$SCRATCH/err-$n.txt"
  # "runs:        688 (0 recorded as Crash)" and "wall time:   55.4 s (solve 47.0 s wall, ...)"
  RUNS[$n]=$(sed -n 's/^runs: *\([0-9]*\).*/\1/p' "$out")
  OVER[$n]=$(sed -n 's/^wall time: *\([0-9.]*\) s (solve \([0-9.]*\) s wall.*/\1 \2/p' "$out" | awk '{print $1 - $2}')
  echo "runs $n per planner: ${RUNS[$n]} runs, wall time minus solve ${OVER[$n]} s ($(grep '^wall time' "$out"))"
done
awk -v r1="${RUNS[$N1]}" -v r2="${RUNS[$N2]}" -v o1="${OVER[$N1]}" -v o2="${OVER[$N2]}" 'BEGIN {
  per = (o2 - o1) / (r2 - r1); printf "per run: %.2f ms; fixed: %.1f s; load average now: ", 1000 * per, o1 - per * r1 }'
cut -d' ' -f1-3 /proc/loadavg
