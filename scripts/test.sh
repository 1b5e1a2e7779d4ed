#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install what is missing, build, and run every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${MHPLAN_BUILD_DIR:-build}"
scripts/setup.sh "$BUILD_DIR"
scripts/setup-slurm.sh  # the Slurm and GNU parallel tests (tests/slurm)
JOBS=$(nproc 2>/dev/null || echo 2)
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" --timeout 900
