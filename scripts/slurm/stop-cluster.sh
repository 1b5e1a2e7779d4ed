#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Stop the test cluster that scripts/slurm/start-cluster.sh DIR started: cancel its jobs, wait for their
# steps to end, stop slurmd and slurmctld by the process ids in DIR's pid files. Never touches another
# Slurm. Always exits 0; prints what it could not stop.
set -u
dir=${1:?usage: stop-cluster.sh DIR}
PATH=$PATH:/usr/sbin
[ -f "$dir/slurm.conf" ] || exit 0
export SLURM_CONF="$dir/slurm.conf"
if [ -f "$dir/slurmctld.pid" ]; then
    scancel --full --quiet --user=root >/dev/null 2>&1 || true
    i=0
    while [ $i -lt 40 ] && [ -n "$(squeue -h -o %i 2>/dev/null)" ]; do
        i=$((i + 1))
        sleep 0.25
    done
fi
# A process that exists and is not a zombie (an ended daemon waits for its parent, perhaps init, to reap it).
alive() {
    kill -0 "$1" 2>/dev/null || return 1
    state=$(sed 's/^.*) \(.\).*$/\1/' "/proc/$1/stat" 2>/dev/null)
    [ "$state" != Z ]
}
# Ask each daemon to stop (SIGTERM), then wait up to 10 s for it before SIGKILL.
for daemon in slurmd slurmctld; do
    pidfile="$dir/$daemon.pid"
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    case $pid in '' | *[!0-9]*) continue ;; esac
    # Only a process that is this daemon (pid files may be stale).
    if [ -r "/proc/$pid/cmdline" ] && tr '\0' ' ' <"/proc/$pid/cmdline" | grep -q "$daemon"; then
        kill -TERM "$pid" 2>/dev/null
        i=0
        while [ $i -lt 40 ] && alive "$pid"; do
            i=$((i + 1))
            sleep 0.25
        done
        alive "$pid" && { echo "stop-cluster: $daemon $pid ignored SIGTERM, killing it" >&2; kill -KILL "$pid" 2>/dev/null; }
    fi
    rm -f "$pidfile"
done
# The watcher of start-cluster.sh (unless it is the one stopping the cluster).
if [ -f "$dir/watcher.pid" ]; then
    pid=$(cat "$dir/watcher.pid")
    case $pid in '' | *[!0-9]*) ;; *) [ "$pid" != "$PPID" ] && kill -TERM "$pid" 2>/dev/null ;; esac
    rm -f "$dir/watcher.pid"
fi
exit 0
