#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# The GNU parallel one-liner of benchmarks/README.md ("GNU parallel"): the shards of
# tests/data/bench_slurm.yaml as parallel jobs, then one --merge-only; the database must hold exactly the
# runs of the same campaign with --jobs 2 (same seeds; same results for the iteration-bounded GA).
# Exit 77 (CTest: skipped) when GNU parallel is not installed.
#   tests/slurm/parallel_test.sh MHPLAN SOURCE_DIR
set -u
mhplan=${1:?usage: parallel_test.sh MHPLAN SOURCE_DIR}
src=${2:?usage: parallel_test.sh MHPLAN SOURCE_DIR}
campaign=$src/tests/data/bench_slurm.yaml
command -v parallel >/dev/null 2>&1 || { echo "parallel_test: GNU parallel not found (scripts/setup-slurm.sh installs it)" >&2; exit 77; }
parallel --version 2>/dev/null | head -n 1 | grep -q "GNU parallel" || { echo "parallel_test: 'parallel' is not GNU parallel (moreutils?)" >&2; exit 77; }
work=$(mktemp -d /tmp/mhplan-parallel-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

# More jobs than cores: refused before anything runs, unless --oversubscribe.
cores=$(nproc)
if "$mhplan" bench "$campaign" --database over.db --jobs $((cores + 1)) --no-progress >over.out 2>&1; then
    echo "parallel_test: --jobs $((cores + 1)) on $cores cores was not refused" >&2; exit 1
fi
grep -q -- "--oversubscribe" over.out && [ ! -e over.db.logs/bfo_case1-default.log ] ||
    { echo "parallel_test: bad refusal:" >&2; cat over.out >&2; exit 1; }

"$mhplan" bench "$campaign" --database ref.db --jobs 2 --oversubscribe --no-progress >ref.out 2>&1 || { tail ref.out; exit 1; }
# The documented one-liner (with this test's database): 4 shards, 2 at a time, then the merge.
parallel -j 2 --halt now,fail=1 "$mhplan" bench "$campaign" --database par.db --shard {}/4 --no-progress ::: 1 2 3 4 \
    >par.out 2>&1 && "$mhplan" bench "$campaign" --database par.db --merge-only --no-progress >>par.out 2>&1 ||
    { echo "parallel_test: the one-liner failed" >&2; grep -v -e "Random number" -e "line 78" par.out | tail -n 20 >&2; exit 1; }
grep -c "shard [1-4]/4" par.out | grep -q '^4$' || { echo "parallel_test: not four shards ran" >&2; cat par.out >&2; exit 1; }
/usr/bin/python3 "$src/tests/slurm/compare_databases.py" ref.db par.db --exact geometric_GA
