#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Install the Debian packages mhplan needs (only those missing), then configure and build out of source.
# Idempotent and quiet when everything is present. Usage: scripts/setup.sh [--arena] [BUILD_DIR]
#   --arena  also OMPL's Planner Arena for 'mhplan arena' and its browser test (R's packages, Chromium,
#            puppeteer-core; scripts/arena/install.sh), not installed by default.
set -euo pipefail
cd "$(dirname "$0")/.."
ARENA=0
if [ "${1:-}" = "--arena" ]; then ARENA=1; shift; fi
BUILD_DIR="${1:-${MHPLAN_BUILD_DIR:-build}}"

PACKAGES=(
  g++ cmake make clang
  libompl-dev libfcl-dev libassimp-dev libeigen3-dev libyaml-cpp-dev
  libboost-filesystem-dev libboost-system-dev libboost-serialization-dev libboost-program-options-dev
  libgtest-dev libbenchmark-dev libpagmo-dev libabsl-dev
  ompl-demos sqlite3 libsqlite3-dev libgif-dev
  python3-matplotlib python3-numpy python3-yaml ccache
)

. scripts/debian-packages.sh
mhplan_ensure_debs setup "missing Debian packages" "${PACKAGES[@]}" || exit 1

# The ROS 1 component (src/ros, docs/ros.md): Debian's ROS 1 core and messages, installed unless
# MHPLAN_NO_ROS=1 (about 80 packages, ~12 s to install from a warm apt cache). The build turns MHPLAN_ROS on
# when it finds them.
ROS_PACKAGES=(
  libroscpp-dev libgeometry-msgs-dev libnav-msgs-dev libstd-msgs-dev libros-rosgraph-msgs-dev
  python3-rosmaster python3-roslaunch python3-rostopic
)
ros_installed=0
if [ "${MHPLAN_NO_ROS:-0}" != "1" ]; then
  MHPLAN_DEBS_INSTALLED=0
  mhplan_ensure_debs setup "the ROS 1 packages (src/ros; MHPLAN_NO_ROS=1 skips them)" "${ROS_PACKAGES[@]}" || exit 1
  ros_installed=$MHPLAN_DEBS_INSTALLED
fi

if [ "$ARENA" = 1 ]; then
  scripts/arena/install.sh --browser >/dev/null
fi

JOBS=$(nproc 2>/dev/null || echo 2)
if [ "$ros_installed" = "1" ] && [ -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake "$BUILD_DIR" -DMHPLAN_ROS=ON >/dev/null # configured before ROS was there
fi
# The compiler cache (scripts/ccache-env.sh): a rebuild of an unchanged file, in any clone, is a cache hit.
. scripts/ccache-env.sh
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "${MHPLAN_LAUNCHER[@]}" >/dev/null
fi
# Show compiler diagnostics (the build is warning-free), not the progress lines.
if ! cmake --build "$BUILD_DIR" -j "$JOBS" > "$BUILD_DIR/build-output.txt" 2>&1; then
  grep -E "error|Error|warning" "$BUILD_DIR/build-output.txt" | head -50 >&2 || true
  echo "setup: build failed (full output in $BUILD_DIR/build-output.txt)" >&2
  exit 1
fi
grep -E "warning:" "$BUILD_DIR/build-output.txt" >&2 || true
