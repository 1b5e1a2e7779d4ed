#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Build the libFuzzer targets (tests/fuzz, clang with ASan + UBSan) in their own build directory and run
# one of them, or all one after the other, for SECONDS each on one core.
#   scripts/fuzz.sh TARGET|all SECONDS      e.g. scripts/fuzz.sh world_yaml 600, scripts/fuzz.sh all 30
# MHPLAN_FUZZ_RUNS=N stops a target after N executions (SECONDS stays the cap).
# Targets: world_yaml map pgm grid_rows scen scenario campaign cli_values, and report_db: the report's database
# reader (analysis/mhplan_analysis/db.py, Python: tests/fuzz/fuzz_report_db.py, no clang build needed).
# Seed corpora come from the shipped files (environments/, benchmarks/, tests/data/) and the kept crashing
# inputs (tests/data/fuzz_regressions/); the growing corpus stays in $BUILD_DIR/corpus/TARGET. A finding
# (crash, leak, undefined behaviour, an escaped exception other than InputError, an allocation over
# -malloc_limit_mb, a slow input over -timeout) stops the run with its input in $BUILD_DIR/artifacts/TARGET/
# and this script exits non-zero. Executions per target are printed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
TARGETS=(world_yaml map pgm grid_rows scen scenario campaign cli_values report_db)
if [ $# -ne 2 ]; then
  echo "usage: scripts/fuzz.sh TARGET|all SECONDS (targets: ${TARGETS[*]})" >&2
  exit 2
fi
WHICH="$1"
SECONDS_EACH="$2"
BUILD_DIR="${MHPLAN_FUZZ_BUILD_DIR:-build-fuzz}"
if [ "$WHICH" = all ]; then
  RUN=("${TARGETS[@]}")
else
  case " ${TARGETS[*]} " in
    *" $WHICH "*) RUN=("$WHICH") ;;
    *) echo "scripts/fuzz.sh: unknown target '$WHICH'; accepted: all ${TARGETS[*]}" >&2; exit 2 ;;
  esac
fi

# report_db: the report's reader is Python; its fuzzer mutates databases itself (seeded, deterministic).
if [ "$WHICH" = report_db ]; then
  mkdir -p "$BUILD_DIR/artifacts/report_db"
  exec /usr/bin/python3 tests/fuzz/fuzz_report_db.py "$SECONDS_EACH" "${MHPLAN_FUZZ_SEED:-1}" \
    "$BUILD_DIR/artifacts/report_db"
fi
REPORT_DB=0
if [ "$WHICH" = all ]; then
  RUN=("${TARGETS[@]:0:${#TARGETS[@]}-1}")
  REPORT_DB=1
fi

command -v clang++ >/dev/null || { echo "scripts/fuzz.sh: needs clang++ (apt-get install clang)" >&2; exit 1; }
. scripts/ccache-env.sh
LAUNCHER=("${MHPLAN_LAUNCHER[@]}")
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DMHPLAN_BUILD_FUZZERS=ON -DMHPLAN_BUILD_TESTS=OFF -DMHPLAN_BUILD_BENCHMARKS=OFF "${LAUNCHER[@]}" >/dev/null
fi
FUZZ_TARGETS=()
for t in "${RUN[@]}"; do FUZZ_TARGETS+=(--target "fuzz_$t"); done
if ! cmake --build "$BUILD_DIR" -j "${MHPLAN_JOBS:-2}" "${FUZZ_TARGETS[@]}" > "$BUILD_DIR/build-output.txt" 2>&1; then
  grep -E "error|warning" "$BUILD_DIR/build-output.txt" | head -40 >&2 || true
  echo "scripts/fuzz.sh: build failed (full output in $BUILD_DIR/build-output.txt)" >&2
  exit 1
fi

# seeds TARGET DIR: write the seed corpus of TARGET into DIR.
seeds() {
  local t="$1" dir="$2" f
  mkdir -p "$dir"
  case "$t" in
    world_yaml) cp environments/*.yaml tests/data/*.yaml "$dir"/ ;;
    map) cp tests/data/*.map "$dir"/ ;;
    pgm) # first byte: threshold (low 7 bits) and negate (high bit)
      for f in tests/data/*.pgm; do { printf '\100'; cat "$f"; } > "$dir/$(basename "$f")"; done ;;
    grid_rows) for f in tests/data/grid_small.map tests/data/grid_crlf.map tests/data/astar_random.map; do
        tail -n +5 "$f" > "$dir/$(basename "$f").rows"; done
      { echo '# {cell_size: 0.5, origin: [1, 2]}'; tail -n +5 tests/data/grid_small.map; } > "$dir/with_keys.rows" ;;
    scen) printf 'version 1\n0\tfuzz.map\t8\t6\t0\t0\t7\t5\t9.24264\n1\tfuzz.map\t8\t6\t1\t0\t6\t4\t5.8\n' \
        > "$dir/small.scen" ;;
    scenario) cp environments/scenarios/*.yaml "$dir"/ ;;
    campaign) cp benchmarks/*.yaml tests/data/bench_tiny.yaml "$dir"/ ;;
    cli_values)
      printf '\000--start\n1,2\n--goal=9,9\n--bounds\n0,10,0,10\n--time\n0.5\n--seed\n7\n' > "$dir/basic"
      printf '\001--set\nrange=0.5\n--set\ngoal_bias=0.1\n' > "$dir/set1"
      printf '\007--set\npopulation_size=20\n--set\nmax_iterations=30\n' > "$dir/set7"
      printf '\011--set=resolution=0.1\n--time=inf\n' > "$dir/set9" ;;
  esac
  if [ -d tests/data/fuzz_regressions ]; then
    for f in tests/data/fuzz_regressions/"$t"-*; do [ -f "$f" ] && cp "$f" "$dir"/; done
  fi
  return 0
}

status=0
declare -A EXECS
for t in "${RUN[@]}"; do
  corpus="$BUILD_DIR/corpus/$t"
  seedDir="$BUILD_DIR/seeds/$t"
  artifacts="$BUILD_DIR/artifacts/$t/"
  rm -rf "$seedDir"
  seeds "$t" "$seedDir"
  mkdir -p "$corpus" "$artifacts"
  log="$BUILD_DIR/fuzz-$t.log"
  echo "fuzz $t: ${SECONDS_EACH} s (log $log)"
  set +e
  ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}" \
  UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}" \
    "$BUILD_DIR/tests/fuzz/fuzz_$t" -max_total_time="$SECONDS_EACH" -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -timeout=20 -max_len=8192 -print_final_stats=1 ${MHPLAN_FUZZ_RUNS:+-runs=$MHPLAN_FUZZ_RUNS} -artifact_prefix="$artifacts" "$corpus" "$seedDir" \
    > "$log" 2>&1
  rc=$?
  set -e
  EXECS[$t]=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  if [ $rc -ne 0 ]; then
    echo "fuzz $t: FINDING (rc $rc), input in $artifacts; the report:" >&2
    grep -E "ERROR|SUMMARY|runtime error|escaped exception|Test unit written" "$log" | head -20 >&2 || true
    status=1
  fi
done
if [ "$REPORT_DB" = 1 ]; then
  mkdir -p "$BUILD_DIR/artifacts/report_db"
  /usr/bin/python3 tests/fuzz/fuzz_report_db.py "$SECONDS_EACH" "${MHPLAN_FUZZ_SEED:-1}" \
    "$BUILD_DIR/artifacts/report_db" || status=1
fi
echo "executions per target:"
for t in "${RUN[@]}"; do echo "  $t ${EXECS[$t]:-?}"; done
exit $status
