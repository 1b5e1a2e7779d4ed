#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Start a one-node Slurm cluster on this machine for tests, entirely inside DIR:
#   scripts/slurm/start-cluster.sh DIR [PORT]
# Debian's slurmctld and slurmd (package slurm-wlm), auth/none, proctrack/pgid, task/none, no accounting,
# every state, spool, log and pid file under DIR, ports PORT and PORT+1 (default: derived from our PID).
# On success it prints "export SLURM_CONF=DIR/slurm.conf" (what sbatch, squeue, ... need) and exits 0; it
# exits 77 (the "skipped" code of CTest's SKIP_RETURN_CODE) with the reason on stderr when Slurm is not
# installed or cannot start, after stopping whatever it started. Stop it with scripts/slurm/stop-cluster.sh DIR
# (or let MHPLAN_SLURM_OWNER=PID stop it when that process ends).
set -u
dir=${1:?usage: start-cluster.sh DIR [PORT]}
port=${2:-$((20000 + ($$ % 10000) * 2))}
here=$(cd "$(dirname "$0")" && pwd)

skip() {
    echo "slurm: $*" >&2
    "$here/stop-cluster.sh" "$dir" >/dev/null 2>&1
    exit 77
}
for tool in slurmctld slurmd sbatch squeue sinfo scontrol; do
    command -v "$tool" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin
    command -v "$tool" >/dev/null 2>&1 || skip "$tool not found (install Debian's slurm-wlm: scripts/setup-slurm.sh)"
done
[ "$(id -u)" = 0 ] || skip "the test cluster runs its daemons as root (SlurmdUser root); run as root"

mkdir -p "$dir/state" "$dir/spool" "$dir/log" || skip "cannot create $dir"
dir=$(cd "$dir" && pwd)
node=$(hostname -s)
# The node line as slurmd sees this machine (CPUs, sockets, cores, memory).
hw=$(slurmd -C 2>/dev/null | head -n 1 | sed 's/^NodeName=[^ ]* //')
[ -n "$hw" ] || skip "slurmd -C did not describe this machine"
cat >"$dir/slurm.conf" <<CONF
ClusterName=mhplantest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/none
CredType=cred/none
ProctrackType=proctrack/pgid
TaskPlugin=task/none
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MailProg=/bin/true
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
MessageTimeout=10
InactiveLimit=0
MinJobAge=300
KillWait=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
NodeName=$node NodeAddr=127.0.0.1 $hw State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
# Empty plugin stack and cgroup files of our own (the system's may ask for plugins we do not load).
: >"$dir/plugstack.conf"
echo "PlugStackConfig=$dir/plugstack.conf" >>"$dir/slurm.conf"
export SLURM_CONF="$dir/slurm.conf"

slurmctld -f "$SLURM_CONF" -c -i >"$dir/log/slurmctld.out" 2>&1 || skip "slurmctld did not start: $(tail -n 3 "$dir/log/slurmctld.log" "$dir/log/slurmctld.out" 2>/dev/null)"
slurmd -f "$SLURM_CONF" -N "$node" >"$dir/log/slurmd.out" 2>&1 || skip "slurmd did not start: $(tail -n 3 "$dir/log/slurmd.log" "$dir/log/slurmd.out" 2>/dev/null)"
# Wait (up to 30 s) until the node is idle.
i=0
while [ $i -lt 60 ]; do
    state=$(sinfo -h -n "$node" -o %t 2>/dev/null | head -n 1)
    case $state in idle*) break ;; esac
    i=$((i + 1))
    sleep 0.5
done
case $state in
idle*) ;;
*) skip "the node did not become idle (state '$state'): $(tail -n 5 "$dir/log/slurmctld.log" 2>/dev/null)" ;;
esac
# With MHPLAN_SLURM_OWNER=PID, a watcher stops the cluster when that process ends however it ends (a test
# killed by its timeout runs no trap).
owner=${MHPLAN_SLURM_OWNER:-}
case $owner in
'' | *[!0-9]*) ;;
*)
    (
        trap '' HUP
        while kill -0 "$owner" 2>/dev/null; do sleep 1; done
        "$here/stop-cluster.sh" "$dir"
    ) </dev/null >/dev/null 2>&1 &
    echo $! >"$dir/watcher.pid"
    ;;
esac
echo "export SLURM_CONF=$SLURM_CONF"
