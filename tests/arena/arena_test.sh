#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Planner Arena test, as a user would see it: run tests/arena/campaign.yaml, serve its database with
# 'mhplan arena' on a free loopback port, drive headless Chromium over it (arena_check.js: problem list,
# planners, problem parameters without simulation columns, the performance and progress plots of an mhplan
# and an OMPL planner), stop mhplan with SIGINT and
# check that it exits 0 and its R server is gone. Screenshots go to WORK_DIR.
#   tests/arena/arena_test.sh MHPLAN_BINARY WORK_DIR
# Exit 77 (CTest: skipped) when R's packages, Chromium or puppeteer-core are not installed
# (scripts/setup.sh --arena installs them).
set -euo pipefail
MHPLAN="$1"
WORK="$2"
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
ARENA_DIR="${MHPLAN_ARENA_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/mhplan/arena}"

if ! reason=$(bash "$ROOT/scripts/arena/install.sh" --check --browser 2>&1 >/dev/null); then
  echo "SKIPPED: Planner Arena test: $reason"
  exit 77
fi
command -v node >/dev/null || { echo "SKIPPED: Planner Arena test: no node"; exit 77; }

rm -rf "$WORK"
mkdir -p "$WORK"
T0=$(date +%s.%N)
"$MHPLAN" bench "$HERE/campaign.yaml" --database "$WORK/arena.db" --logs "$WORK/arena.logs" --jobs 2 \
  --no-progress > "$WORK/bench.txt" 2>&1 || { cat "$WORK/bench.txt"; echo "FAILED: the campaign"; exit 1; }
T1=$(date +%s.%N)
# The campaign's experiments (the campaign file names these two).
EXPERIMENTS=$(sqlite3 "$WORK/arena.db" "SELECT name FROM experiments ORDER BY id" | paste -sd, -)
[ "$EXPERIMENTS" = "bfo_case1-default,lrsma_scenario1-default" ] ||
  { echo "FAILED: the database holds experiments '$EXPERIMENTS'"; exit 1; }

# The simulation experiment went to its own database.
SIMS=$(sqlite3 "$WORK/arena-sim.db" "SELECT name FROM experiments" | paste -sd, -)
[ "$SIMS" = "mapf_2robots-sim" ] || { echo "FAILED: arena-sim.db holds experiments '$SIMS'"; exit 1; }

PORT=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
"$MHPLAN" arena "$WORK/arena.db" --port "$PORT" --host 127.0.0.1 --no-install > "$WORK/arena.txt" 2>&1 &
PID=$!
cleanup() {
  if kill -0 "$PID" 2>/dev/null; then kill -TERM "$PID" 2>/dev/null || true; wait "$PID" 2>/dev/null || true; fi
}
trap cleanup EXIT
for _ in $(seq 600); do
  grep -q "^Planner Arena: http" "$WORK/arena.txt" && break
  kill -0 "$PID" 2>/dev/null || { cat "$WORK/arena.txt"; echo "FAILED: mhplan arena ended before serving"; exit 1; }
  sleep 0.1
done
URL=$(sed -n 's/^Planner Arena: \(http[^ ]*\).*/\1/p' "$WORK/arena.txt")
[ "$URL" = "http://127.0.0.1:$PORT/" ] || { cat "$WORK/arena.txt"; echo "FAILED: no URL printed"; exit 1; }
T2=$(date +%s.%N)

status=0
NODE_PATH="$ARENA_DIR/node/node_modules" node "$HERE/arena_check.js" "$URL" "$WORK" "$EXPERIMENTS" \
  geometric_GA,geometric_RRTstar || status=$?
T3=$(date +%s.%N)

# Ctrl-C: mhplan forwards it, R stops, mhplan exits 0 and the port is free again.
kill -INT "$PID"
rc=0
wait "$PID" || rc=$?
trap - EXIT
grep -q "^Planner Arena: stopped" "$WORK/arena.txt" || { cat "$WORK/arena.txt"; echo "FAILED: no stop message"; exit 1; }
[ "$rc" = 0 ] || { cat "$WORK/arena.txt"; echo "FAILED: mhplan arena exited $rc after SIGINT"; exit 1; }
if /usr/bin/python3 -c "import socket,sys; s=socket.socket(); sys.exit(s.connect_ex(('127.0.0.1', $PORT)) != 0)"; then
  echo "FAILED: something still listens on port $PORT after mhplan arena stopped"
  exit 1
fi
[ "$status" = 0 ] || { cat "$WORK/arena.txt"; echo "FAILED: the browser checks"; exit 1; }
awk -v a="$T0" -v b="$T1" -v c="$T2" -v d="$T3" -v w="$WORK" 'BEGIN {
  printf "arena test: campaign %.1f s, server start %.1f s, browser %.1f s; screenshots in %s\n", b - a, c - b, d - c, w }'
echo "PASSED"
