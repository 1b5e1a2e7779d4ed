#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# mhplan bench --slurm on a real Slurm cluster: a one-node cluster (scripts/slurm/start-cluster.sh) in a
# temporary directory, stopped on every exit. The campaign tests/data/bench_slurm.yaml runs
#   1. on one machine with --jobs 2 (the reference),
#   2. as a 4-task array plus the merge job: the database must hold exactly the reference's runs (same
#      seeds; same results for the iteration-bounded GA),
#   3. again, with one array task killed while it runs: --status must report its experiments failed and
#      missing, the merge must not run, and resubmitting must submit only that shard and complete the
#      database (again equal to the reference).
# Exit 77 (CTest: skipped) with the reason when Slurm is not installed or cannot start.
#   tests/slurm/slurm_test.sh MHPLAN SOURCE_DIR
set -u
mhplan=${1:?usage: slurm_test.sh MHPLAN SOURCE_DIR}
src=${2:?usage: slurm_test.sh MHPLAN SOURCE_DIR}
campaign=$src/tests/data/bench_slurm.yaml
compare="/usr/bin/python3 $src/tests/slurm/compare_databases.py"
PATH=$PATH:/usr/sbin
work=$(mktemp -d /tmp/mhplan-slurm-test.XXXXXX)
cluster=$work/cluster
cleanup() {
    "$src/scripts/slurm/stop-cluster.sh" "$cluster"
    # Nothing of this test may outlive it.
    left=$(pgrep -f -- "$work" | grep -v "^$$\$" || true)
    [ -z "$left" ] || { echo "slurm_test: processes left running: $left" >&2; ps -o pid,args -p $left >&2; }
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

fail() {
    echo "slurm_test: FAILED: $*" >&2
    for f in "$cluster"/log/*.log "$work"/*.logs/slurm/*.out; do
        [ -f "$f" ] && { echo "--- $f" >&2; grep -v -e "Random number generation" -e "line 78 in" "$f" | tail -n 15 >&2; }
    done
    exit 1
}
now() { date +%s.%N; }
elapsed() { /usr/bin/python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$1" "$(now)"; }

t0=$(now)
MHPLAN_SLURM_OWNER=$$ "$src/scripts/slurm/start-cluster.sh" "$cluster" >"$work/env"
rc=$?
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || fail "start-cluster.sh exited $rc"
. "$work/env"
echo "slurm_test: cluster up in $(elapsed "$t0") s ($SLURM_CONF)"
cd "$work" || exit 1

# Wait until the cluster has no job left (at most $1 seconds).
wait_idle() {
    local i=0
    while [ -n "$(squeue -h -o %i 2>/dev/null)" ]; do
        i=$((i + 1))
        [ $i -gt $(($1 * 10)) ] && fail "jobs still queued after $1 s: $(squeue)"
        sleep 0.1
    done
}
# The array job id from the output of mhplan bench --slurm --submit.
array_id() { sed -n 's/^array job id: \([0-9]*\)$/\1/p' "$1"; }

# 1. The reference: one machine, two jobs.
t=$(now)
"$mhplan" bench "$campaign" --database "$work/ref.db" --jobs 2 --oversubscribe --no-progress >"$work/ref.out" 2>&1 ||
    fail "reference run: $(tail -n 5 "$work/ref.out")"
echo "slurm_test: --jobs 2 on one machine: $(elapsed "$t") s"

# 2. A 4-task array and the merge job.
t=$(now)
"$mhplan" bench "$campaign" --database "$work/array.db" --slurm --shards 4 --cpus 1 --mem 1000 --time 00:10:00 \
    --submit >"$work/submit1.out" 2>&1 || fail "submission: $(cat "$work/submit1.out")"
grep -q "^to run:       shards 1-4$" "$work/submit1.out" || fail "expected all four shards: $(cat "$work/submit1.out")"
id=$(array_id "$work/submit1.out")
[ -n "$id" ] || fail "no array job id in: $(cat "$work/submit1.out")"
grep -q -- "--mem=1000" "$work/array.db.logs/slurm/array.sbatch" || fail "--mem not in the array script"
wait_idle 300
echo "slurm_test: 4-task array + merge on Slurm: $(elapsed "$t") s"
[ -f "$work/array.db" ] || fail "the merge job built no database"
$compare "$work/ref.db" "$work/array.db" --exact geometric_GA || fail "array database differs from --jobs 2"
"$mhplan" bench "$campaign" --database "$work/array.db" --status >"$work/status1.out" ||
    fail "--status after a complete run: $(cat "$work/status1.out")"
grep -q "8 complete, 0 missing, 0 failed" "$work/status1.out" || fail "status: $(cat "$work/status1.out")"

# 3. Task 1 (experiments 0 and 4: bfo_case1-default, lrsma_scenario3-default) killed while it runs.
"$mhplan" bench "$campaign" --database "$work/kill.db" --slurm --shards 4 --submit >"$work/submit2.out" 2>&1 ||
    fail "submission: $(cat "$work/submit2.out")"
id=$(array_id "$work/submit2.out")
marker=$work/kill.db.logs/bfo_case1-default.log.running
i=0
until [ -f "$marker" ]; do
    i=$((i + 1))
    [ $i -gt 600 ] && fail "task 1 never started its first experiment"
    sleep 0.05
done
scancel --signal=KILL --full "${id}_1" || fail "scancel ${id}_1"
wait_idle 300
[ -f "$work/kill.db" ] && fail "the merge ran although task 1 failed"
"$mhplan" bench "$campaign" --database "$work/kill.db" --status >"$work/status2.out"
rc=$?
[ $rc -eq 1 ] || fail "--status of an incomplete campaign exited $rc: $(cat "$work/status2.out")"
grep -q "^failed	bfo_case1-default	.*killed" "$work/status2.out" || fail "killed experiment not failed: $(cat "$work/status2.out")"
grep -q "^missing	lrsma_scenario3-default" "$work/status2.out" || fail "unrun experiment not missing: $(cat "$work/status2.out")"
grep -q "6 complete, 1 missing, 1 failed" "$work/status2.out" || fail "status: $(cat "$work/status2.out")"
echo "slurm_test: after killing task ${id}_1:"
sed 's/^/    /' "$work/status2.out"
"$mhplan" bench "$campaign" --database "$work/kill.db" --slurm --shards 4 --submit >"$work/submit3.out" 2>&1 ||
    fail "resubmission: $(cat "$work/submit3.out")"
grep -q "^to run:       shards 1$" "$work/submit3.out" || fail "resubmission must run only shard 1: $(cat "$work/submit3.out")"
wait_idle 300
$compare "$work/ref.db" "$work/kill.db" --exact geometric_GA || fail "resubmitted database differs from --jobs 2"
"$mhplan" bench "$campaign" --database "$work/kill.db" --status >"$work/status3.out" ||
    fail "--status after the resubmission: $(cat "$work/status3.out")"
echo "slurm_test: passed in $(elapsed "$t0") s"
