#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The report in a real browser (issue 29): run tests/report_browser/campaign.yaml (a small SE(2) campaign),
# write its report with 'mhplan report', open index.html in headless Chromium (report_check.js) and check what
# a reader sees: every figure loaded and drawn, the path figure with the robot's footprints, the statistics
# tables filled (no empty table, no NaN), the machine load stated. Screenshot in WORK_DIR.
#   tests/report_browser/report_test.sh MHPLAN_BINARY WORK_DIR
# Exit 77 (CTest: skipped) when Chromium or puppeteer-core is not installed (scripts/setup.sh --arena).
set -euo pipefail
MHPLAN="$1"
WORK="$2"
HERE="$(cd "$(dirname "$0")" && pwd)"
ARENA_DIR="${MHPLAN_ARENA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/mhplan/arena}"
CHROMIUM="${CHROMIUM:-/usr/bin/chromium}"

command -v node >/dev/null || { echo "SKIPPED: report browser test: no node"; exit 77; }
[ -x "$CHROMIUM" ] || { echo "SKIPPED: report browser test: no Chromium at $CHROMIUM"; exit 77; }
[ -d "$ARENA_DIR/node/node_modules/puppeteer-core" ] ||
  { echo "SKIPPED: report browser test: no puppeteer-core (scripts/setup.sh --arena)"; exit 77; }

rm -rf "$WORK"
mkdir -p "$WORK"
T0=$(date +%s.%N)
"$MHPLAN" bench "$HERE/campaign.yaml" --database "$WORK/se2.db" --logs "$WORK/se2.logs" --jobs 1 \
  --no-progress > "$WORK/bench.txt" 2>&1 || { cat "$WORK/bench.txt"; echo "FAILED: the campaign"; exit 1; }
T1=$(date +%s.%N)
"$MHPLAN" report "$WORK/se2.db" -o "$WORK/report" > "$WORK/report.txt" 2>&1 ||
  { cat "$WORK/report.txt"; echo "FAILED: mhplan report"; exit 1; }
T2=$(date +%s.%N)
NODE_PATH="$ARENA_DIR/node/node_modules" CHROMIUM="$CHROMIUM" \
  node "$HERE/report_check.js" "$WORK/report/index.html" "$WORK" || { echo "FAILED: the browser checks"; exit 1; }
T3=$(date +%s.%N)
awk -v a="$T0" -v b="$T1" -v c="$T2" -v d="$T3" -v w="$WORK" 'BEGIN {
  printf "report browser test: campaign %.1f s, report %.1f s, browser %.1f s; screenshot in %s\n", b - a, c - b, d - c, w }'
echo "PASSED"
