#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The ROS 1 run end to end (docs/ros.md): a private rosmaster, the world node and one controller node per
# robot, each its own process. mapf_2robots with aapf: r1 starts alone, a second goal is assigned to r1 while
# it runs, and r2 joins by starting its node mid-run. Checks that both robots reached all their goals without
# contact (the world's count and an independent check of the recorded trajectories), that r2 joined late,
# and that every node ended by itself; everything is killed on exit. Exit 77 (skip) where ROS is absent.
# Usage: ros_join_test.sh SOURCE_DIR ROS_BIN_DIR
set -euo pipefail
SRC=$1
BIN=${2:-}
if [ -z "$BIN" ] || [ ! -x "$BIN/mhplan_ros_world" ]; then
  echo "SKIP: the ROS nodes are not built (ROS 1 not found at configure time, or MHPLAN_ROS=OFF; scripts/setup.sh installs it)"
  exit 77
fi
if ! command -v rosmaster >/dev/null 2>&1; then
  echo "SKIP: rosmaster not installed (Debian package python3-rosmaster; scripts/setup.sh installs it)"
  exit 77
fi
source "$SRC/tests/ros/ros_env.sh"
fail() {
  echo "FAIL: $*" >&2
  for f in "$ROS_TMP"/*.log; do echo "--- $f" >&2; tail -20 "$f" >&2; done
  exit 1
}

ros_start_master || fail "rosmaster did not start"
SC=mapf_2robots
# Simulated time at 4x wall time: the 2-robot run takes about 12 s and r2 can start while r1 drives. (At 10x
# a loaded machine (load 4 on 2 cores) made the robot nodes miss ticks and the robots touched: the test checks
# the protocol, not how fast the nodes keep up.)
ros_start world "$BIN/mhplan_ros_world" --scenario "$SC" --controller aapf --seed 1 --late r2 --realtime 4 \
  --results "$ROS_TMP/results.txt" --csv "$ROS_TMP/run.csv" --command-timeout 20
WORLD=$LAST_PID
ros_start r1 "$BIN/mhplan_ros_robot" --scenario "$SC" --robot r1 --controller aapf --seed 1
R1=$LAST_PID
for _ in $(seq 1 200); do grep -q "joined" "$ROS_TMP/r1.log" 2>/dev/null && break; sleep 0.05; done
grep -q "joined" "$ROS_TMP/r1.log" || fail "r1 did not join"
sleep 0.5
# A second goal for r1, assigned while it drives to its first.
"$BIN/mhplan_ros_task" --robot r1 --goal 3.0,5.5 > "$ROS_TMP/task.log" 2>&1 || fail "task assignment failed"
sleep 0.3
ros_start r2 "$BIN/mhplan_ros_robot" --scenario "$SC" --robot r2 --controller aapf --seed 1
R2=$LAST_PID

rc=0
ros_wait_exit "$WORLD" 60 || rc=$?
[ "$rc" -eq 0 ] || fail "world node exit code $rc (0 = every robot done)"
for pid in "$R1" "$R2"; do
  rc=0
  ros_wait_exit "$pid" 10 || rc=$?
  [ "$rc" -eq 0 ] || fail "robot node $pid exit code $rc"
done
cat "$ROS_TMP/results.txt"
grep -q "^robots: *2 done, 0 stuck, 0 unfinished" "$ROS_TMP/results.txt" || fail "not every robot done"
grep -q "^collisions: 0 " "$ROS_TMP/results.txt" || fail "the world counted contacts"
grep -q "task 2 for r1" "$ROS_TMP/world.log" || fail "the world did not take r1's second task"

# Independent check of the trajectories: goals reached in order, r2 joined late, no contact with the
# pillars (radius 0.2 m), the walls or the other robot (radius 0.105 m each).
/usr/bin/python3 - "$ROS_TMP/run.csv" <<'PY' || fail "trajectory check"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
traj = {}
for r in rows:
    traj.setdefault(r["robot"], []).append((float(r["time"]), float(r["x"]), float(r["y"])))
R, tol = 0.105, 0.05 + 1e-9
pillars = [(1.5 * i, 1.5 * j) for i in (1, 2, 3) for j in (1, 2, 3)]
def near(p, g): return math.hypot(p[1] - g[0], p[2] - g[1]) <= tol
r1, r2 = traj["r1"], traj["r2"]
assert r1[0][0] == 0.0, "r1 starts at t = 0"
assert r2[0][0] > 1.0, "r2 joined late (first sample at t = %.2f)" % r2[0][0]
first = next((k for k, p in enumerate(r1) if near(p, (5.6, 2.25))), None)
assert first is not None, "r1 never reached its first goal"
assert near(r1[-1], (3.0, 5.5)), "r1 ends at %s, not at its second goal" % (r1[-1],)
assert near(r2[-1], (0.4, 2.35)), "r2 ends at %s, not at its goal" % (r2[-1],)
for name, t in traj.items():
    for _, x, y in t:
        assert R - 1e-9 <= x <= 6 - R + 1e-9 and R - 1e-9 <= y <= 6 - R + 1e-9, "%s leaves the arena" % name
        for cx, cy in pillars:
            assert math.hypot(x - cx, y - cy) >= 0.2 + R - 1e-9, "%s touches the pillar at (%g, %g)" % (name, cx, cy)
at1 = {t: (x, y) for t, x, y in r1}
closest = min(math.hypot(x - at1[t][0], y - at1[t][1]) for t, x, y in r2 if t in at1)
assert closest >= 2 * R - 1e-9, "robots in contact (centre distance %.4f m)" % closest
print("trajectories: r2 joined at t = %.2f s, r1 reached goal 1 at t = %.2f s, closest robot centres %.3f m"
      % (r2[0][0], r1[first][0], closest))
PY
echo "PASS"
