#!/usr/bin/env bash
# Install what is missing, build, and run the main job: every shipped seed world planned with a set of
# planners, printed as one comparison table (later: the full benchmark campaign and its report).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${MHPLAN_BUILD_DIR:-build}"
scripts/setup.sh "$BUILD_DIR"
"$BUILD_DIR/mhplan" compare --time "${MHPLAN_DEMO_TIME:-1.0}" --seed "${MHPLAN_DEMO_SEED:-1}" "$@"
