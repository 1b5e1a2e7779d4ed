#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Run scenarios through ROS 1 (a private rosmaster, the world node, one controller node per robot, each its
# own process) and in process (`mhplan sim`), and compare makespan, flowtime, trajectories and wall times
# (docs/ros.md). Usage: src/ros/compare_with_sim.sh BUILD_DIR CONTROLLER SCENARIO... (e.g. build aapf
# mapf_2robots mapf_15robots).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "$1" && pwd); C=$2; shift 2
BIN="$BUILD/ros/mhplan_ros/bin"
source "$SRC/tests/ros/ros_env.sh"
ros_start_master
printf "%-14s %-6s %9s %9s %10s %10s %8s %9s %9s %10s %10s\n" scenario ctrl "mk sim" "mk ros" "flow sim" "flow ros" \
  "max|dx|" "wall sim" "wall ros" "startup" "steps/s"
for SC in "$@"; do
  "$BUILD/mhplan" sim "$SC" --controller "$C" --seed 1 --csv "$ROS_TMP/sim.csv" > "$ROS_TMP/sim.txt" || true
  ros_start world "$BIN/mhplan_ros_world" --scenario "$SC" --controller "$C" --seed 1 --csv "$ROS_TMP/ros.csv" \
    --results "$ROS_TMP/ros.txt"
  W=$LAST_PID
  robots=()
  for r in $(/usr/bin/python3 -c "import yaml,sys; print(' '.join(r['name'] for r in yaml.safe_load(open(sys.argv[1]))['robots']))" \
      "$SRC/environments/scenarios/$SC.yaml"); do
    ros_start "$SC-$r" "$BIN/mhplan_ros_robot" --scenario "$SC" --robot "$r" --controller "$C" --seed 1
    robots+=($LAST_PID)
  done
  rc=0; ros_wait_exit "$W" 600 || rc=$?
  for p in "${robots[@]}"; do ros_wait_exit "$p" 10 || true; done
  [ "$rc" -eq 0 ] || [ "$rc" -eq 3 ] || { cat "$ROS_TMP/world.log" >&2; exit 1; }
  /usr/bin/python3 - "$SC" "$C" "$ROS_TMP" <<'PY'
import csv, re, sys
sc, c, d = sys.argv[1:4]
def field(path, key):
    m = re.search(r"^%s:\s+([0-9.]+)" % key, open(path).read(), re.M)
    return float(m.group(1))
sim, ros = d + "/sim.txt", d + "/ros.txt"
a = {(r["time"], r["robot"]): r for r in csv.DictReader(open(d + "/sim.csv"))}
b = {(r["time"], r["robot"]): r for r in csv.DictReader(open(d + "/ros.csv"))}
dx = max((abs(float(a[k][f]) - float(b[k][f])) for k in a.keys() & b.keys() for f in ("x", "y")), default=float("nan"))
same = "" if a.keys() == b.keys() else " (sample sets differ)"
t = open(ros).read()
wall_ros = float(re.search(r"steps in ([0-9.]+) s wall", t).group(1))
startup = float(re.search(r"startup ([0-9.]+) s", t).group(1))
rate = float(re.search(r"\(([0-9.]+) steps/s\)", t).group(1))
print("%-14s %-6s %9.3f %9.3f %10.3f %10.3f %8.1e %9.4f %9.3f %10.3f %10.0f%s" % (sc, c, field(sim, "makespan"), field(ros, "makespan"),
      field(sim, "flowtime"), field(ros, "flowtime"), dx, field(sim, "wall time"), wall_ros, startup, rate, same))
print("  ros: " + re.search(r"^ros:.*$", t, re.M).group(0)[12:])
PY
done
