# SPDX-License-Identifier: BSD-3-Clause
# Shared by the ROS scripts (sourced): a private rosmaster on a free loopback port, ROS_HOME/ROS_LOG_DIR in a
# temporary directory, and every process started here killed on exit (also on failure or interruption).
# Sets ROS_TMP, ROS_MASTER_URI; ros_start NAME CMD... starts a process (output in $ROS_TMP/NAME.log) and
# records its pid; ros_wait_exit PID SECONDS waits for one to end.
set -euo pipefail
ROS_PIDS=()
ROS_TMP=$(mktemp -d "${TMPDIR:-/tmp}/mhplan-ros.XXXXXX")
ros_cleanup() {
  local pid
  for pid in "${ROS_PIDS[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  sleep 0.3
  for pid in "${ROS_PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  for pid in "${ROS_PIDS[@]}"; do wait "$pid" 2>/dev/null || true; done
  [ -n "${ROS_KEEP_TMP:-}" ] || rm -rf "$ROS_TMP"
}
trap ros_cleanup EXIT
trap 'exit 130' INT TERM
export ROS_HOME="$ROS_TMP/home" ROS_LOG_DIR="$ROS_TMP/log" ROS_IP=127.0.0.1 ROS_HOSTNAME=127.0.0.1
mkdir -p "$ROS_HOME" "$ROS_LOG_DIR"
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI="http://127.0.0.1:$port"

ros_start() {
  local name=$1; shift
  "$@" > "$ROS_TMP/$name.log" 2>&1 &
  ROS_PIDS+=($!)
  LAST_PID=$!
}

ros_start_master() {
  ros_start master rosmaster --core -p "$port" -w 3
  local i
  for i in $(seq 1 100); do
    if /usr/bin/python3 -c "import xmlrpc.client,sys; xmlrpc.client.ServerProxy('$ROS_MASTER_URI').getPid('/t')" \
        >/dev/null 2>&1; then
      return 0
    fi
    sleep 0.1
  done
  echo "rosmaster did not come up on $ROS_MASTER_URI" >&2
  cat "$ROS_TMP/master.log" >&2
  return 1
}

# ros_wait_exit PID SECONDS: wait for PID to end, at most SECONDS; returns its exit code (124 on timeout).
ros_wait_exit() {
  local pid=$1 limit=$2 waited=0
  while kill -0 "$pid" 2>/dev/null; do
    sleep 0.1
    waited=$((waited + 1))
    if [ "$waited" -ge $((limit * 10)) ]; then return 124; fi
  done
  local rc=0
  wait "$pid" || rc=$?
  return $rc
}
