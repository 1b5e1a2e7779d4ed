#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Compare two mhplan bench databases of the same campaign run with different layouts (Slurm array, GNU
parallel, --jobs): the same experiments, the same runs (experiment, planner, run index) with the same run
seeds, and for the iteration-bounded planners named by --exact the same results. Exit 0 when they agree,
1 with every difference listed.

  compare_databases.py A.db B.db --exact geometric_GA [--exact ...]
"""
import argparse
import sqlite3
import sys

RESULT_COLUMNS = ("status", "solved", "path_length", "solution_length", "iterations", "collision_free",
                  "min_clearance", "fitness_evaluations")


def runs(path):
    db = sqlite3.connect(path)
    cols = {row[1] for row in db.execute("PRAGMA table_info(runs)")}
    wanted = [c for c in RESULT_COLUMNS if c in cols]
    query = ("SELECT e.name, p.name, r.run_index, r.run_seed, r.cpu_time, " + ", ".join("r." + c for c in wanted) +
             " FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p ON r.plannerid = p.id")
    out = {}
    for row in db.execute(query):
        key = row[:3]
        if key in out:
            raise SystemExit("%s: run %s appears twice" % (path, key))
        out[key] = {"seed": row[3], "cpu_time": row[4], "results": dict(zip(wanted, row[5:]))}
    experiments = sorted(name for (name,) in db.execute("SELECT name FROM experiments"))
    return experiments, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--exact", action="append", default=[], help="planner whose results must be equal")
    args = ap.parse_args()
    exp_a, a = runs(args.a)
    exp_b, b = runs(args.b)
    problems = []
    if exp_a != exp_b:
        problems.append("experiments differ: %s vs %s" % (exp_a, exp_b))
    if len(exp_a) != len(set(exp_a)):
        problems.append("%s holds an experiment twice" % args.a)
    for key in sorted(set(a) | set(b)):
        if key not in a or key not in b:
            problems.append("run %s only in %s" % (key, args.a if key in a else args.b))
            continue
        if a[key]["seed"] != b[key]["seed"]:
            problems.append("run %s: seed %s vs %s" % (key, a[key]["seed"], b[key]["seed"]))
        for side, run in (("a", a[key]), ("b", b[key])):
            if run["cpu_time"] is None or run["cpu_time"] < 0:
                problems.append("run %s (%s): no cpu_time" % (key, side))
        if key[1] in args.exact and a[key]["results"] != b[key]["results"]:
            problems.append("run %s: results %s vs %s" % (key, a[key]["results"], b[key]["results"]))
    exact = sum(1 for key in a if key[1] in args.exact)
    if not a:
        problems.append("no runs")
    if exact == 0:
        problems.append("no runs of the exact planners %s" % args.exact)
    for p in problems:
        print("compare_databases: " + p)
    if problems:
        return 1
    print("compare_databases: %d experiments, %d runs agree (seeds; results of %d runs of %s)" %
          (len(exp_a), len(a), exact, ", ".join(args.exact)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
