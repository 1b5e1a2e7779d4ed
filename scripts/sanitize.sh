#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite built with AddressSanitizer (+ LeakSanitizer) and UndefinedBehaviorSanitizer (gcc,
# RelWithDebInfo, frame pointers kept) in a build directory of its own, run through CTest; any report fails
# the run (UBSan halts on the first error). Usage: scripts/sanitize.sh [--ci] [BUILD_DIR] (default
# build-sanitize). Known leaks of OMPL 1.5.2 itself are suppressed, each documented, in
# tests/sanitizer/lsan.supp.
# Excluded: the tests that only configure and build (consumer_package, layering_*): they check the build,
# not memory; and the tests of outside systems (ROS nodes, a Slurm cluster, GNU parallel, Planner Arena in a
# browser), whose own processes are not mhplan's code. The normal pass (scripts/test.sh) runs them all.
# --ci: CI's pass (.ci/run), which must fit CI's 30 minutes on 2 cores beside the test command and the fuzz
# pass: only the test executables of CI_TESTS are built (with the CLI they run) and run. They cover every
# layer: geometry and grids, the world, grid and MovingAI readers (and the kept fuzz findings), every
# registered planner solving a seed world (test_registry), the lattice searches, the N-D planners and the
# papers' operators (test_astar, test_nd, test_fidelity), the simulator and every controller, the CLI and
# its JSON output (running the instrumented mhplan binary) and the campaign runner with its child
# processes and databases (test_bench_sim). Left out (the whole pass runs them): the planner contract
# suite, the metaheuristics' quality runs at the papers' budgets, the FCL sweeps, the exact optimum, the
# memetic and GMS operator suites, scaling, the other campaign suites (tiny campaign, fault injection,
# Slurm scripts, MovingAI), rendering, metrics, allocation counts and the Python tools.
set -euo pipefail
cd "$(dirname "$0")/.."
CI=0
if [ "${1:-}" = "--ci" ]; then
  CI=1
  shift
fi
CI_TESTS=(test_geometry test_grid test_world_io test_input_hardening test_fuzz_regressions test_registry
  test_astar test_nd test_fidelity test_simulation test_controllers test_cli test_cli_json test_bench_sim)
# Within those: the brute-force oracle of grid segment clearance (173 s of the 575 s the --ci tests took
# under ASan on a loaded machine; the grid's other clearance and segment tests stay).
CI_SKIP='GridCollision\.SegmentClearanceMatchesBruteForce'
BUILD_DIR="${1:-${MHPLAN_SANITIZE_BUILD_DIR:-build-sanitize}}"
JOBS=$(nproc 2>/dev/null || echo 2)
FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# Eigen frees its vectors with its own aligned allocator when it sees __SANITIZE_ADDRESS__, plain free()
# otherwise. pagmo's cmaes and xnes allocate their Eigen members inside libpagmo (built without ASan: plain
# malloc) and are destroyed by inline destructors compiled here: without this define ASan reports a
# heap-buffer-overflow in Eigen's handmade_aligned_free that no normal build has. glibc's and ASan's malloc
# both return 16-byte aligned memory, all that Eigen's default (SSE) alignment needs.
CXXDEFS="-DEIGEN_MALLOC_ALREADY_ALIGNED=1"
. scripts/ccache-env.sh
LAUNCHER=("${MHPLAN_LAUNCHER[@]}")
# Each GoogleTest case may take an hour here (MHPLAN_TEST_TIMEOUT, 600 s in the normal build): the quality
# runs of the global BFO on the Dubins and Reeds-Shepp spaces take over 600 s under the sanitizers.
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=g++ \
    -DCMAKE_CXX_FLAGS="$FLAGS $CXXDEFS" -DCMAKE_EXE_LINKER_FLAGS="$FLAGS" -DCMAKE_SHARED_LINKER_FLAGS="$FLAGS" \
    -DMHPLAN_BUILD_BENCHMARKS=OFF -DMHPLAN_ROS=OFF -DMHPLAN_TEST_TIMEOUT=3600 "${LAUNCHER[@]}" >/dev/null
else
  cmake -DMHPLAN_TEST_TIMEOUT=3600 "$BUILD_DIR" >/dev/null
fi
TARGETS=()
if [ $CI = 1 ]; then
  TARGETS=(--target mhplan)
  for t in "${CI_TESTS[@]}"; do TARGETS+=(--target "$t"); done
fi
if ! cmake --build "$BUILD_DIR" -j "$JOBS" "${TARGETS[@]}" > "$BUILD_DIR/build-output.txt" 2>&1; then
  grep -E "error|warning" "$BUILD_DIR/build-output.txt" | head -50 >&2 || true
  echo "sanitize: build failed (full output in $BUILD_DIR/build-output.txt)" >&2
  exit 1
fi
grep -E "warning:" "$BUILD_DIR/build-output.txt" >&2 || true
export ASAN_OPTIONS="detect_leaks=1:fast_unwind_on_malloc=0:strict_init_order=1:detect_stack_use_after_return=0:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# The sanitizer build runs about 3-5 times slower: tests with wall-clock limits scale them by this factor.
export MHPLAN_TEST_TIME_SCALE=4
SELECT=(-E '^(consumer_package|layering_|ros_|slurm_|gnu_parallel|arena)')
if [ $CI = 1 ]; then
  SELECT=(-L "^($(IFS='|'; echo "${CI_TESTS[*]}"))\$" -E "^(${CI_SKIP})\$")
fi
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" --timeout 3600 "${SELECT[@]}"
