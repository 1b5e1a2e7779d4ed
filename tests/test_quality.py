#!/usr/bin/python3
"""Time to quality and the Scaling section, from a constructed database (OMPL-format logs turned into
SQLite by /usr/bin/ompl_benchmark_statistics, then the improvements table as mhplan bench adds it):
per-run times to the first solution and to within 10 %, 1 % and 0.1 % equal an independent SQL computation;
medians count never-reached runs as +inf (and say "not reached" when more than half never got there); the
confidence intervals are order statistics with at least 95 % exact binomial coverage; the ranking's time to
within 1 % is the improvements-based one (not the progress samples'); the Scaling section's success rates,
median gaps and median times equal independent computations per (family, size, planner), and its figures
are valid images. Without an improvements table the progress samples are used."""

import math
import os
import random
import re
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "analysis"))
sys.path.insert(0, HERE)

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import quality, report, scaling  # noqa: E402
from test_report import STATUS, png_ok  # noqa: E402

LEVELS = {"first": None, "t10": 0.10, "t1": 0.01, "t01": 0.001}


def write_log(path, name, world, optimum, obstacles, radius, planners, progress):
    """A log of one experiment. planners: name -> runs (status, time, length); progress: name -> per run
    [(t, cost)] samples (may be empty)."""
    lines = ["OMPL version 1.5.2", "Experiment %s" % name, "5 experiment properties", "world TEXT = %s" % world,
             "exact_optimum REAL = %r" % optimum, "obstacle_count INTEGER = %d" % obstacles,
             "robot_radius REAL = %r" % radius, "kind TEXT = planning", "Running on testhost",
             "Starting at 2026-11-23 12:00:00", "<<<|", "setup", "|>>>", "<<<|", "cpu", "|>>>", "1 is the random seed",
             "1 seconds per run", "1024 MB per run", "6 runs per planner", "3 seconds spent to collect the data",
             "1 enum types", "status|" + "|".join(STATUS), "%d planners" % len(planners)]
    for pname, runs in planners.items():
        lines += [pname, "0 common properties", "6 properties for each run", "time REAL", "status ENUM",
                  "solved BOOLEAN", "path length REAL", "optimality gap REAL", "run index INTEGER",
                  "%d runs" % len(runs)]
        for k, (status, t, length) in enumerate(runs):
            exact = status == 6
            gap = repr(100.0 * (length - optimum) / optimum) if exact else ""
            lines.append("%r; %d; %d; %s; %s; %d; " % (t, status, 1 if exact else 0, repr(length) if exact else "", gap, k))
        samples = progress.get(pname)
        if samples:
            lines += ["2 progress properties for each run", "time REAL", "best cost REAL", "%d runs" % len(runs)]
            for run_samples in samples:
                lines.append("".join("%r,%r,;" % (t, c) for t, c in run_samples))
        lines.append(".")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def make_runs(rng, optimum, n, reach_1pct, fail=0):
    """n runs; the first reach_1pct end within 1 % of the optimum, fail runs find nothing. Improvements:
    a first solution 30 % above, then steps down to the final length."""
    runs, imps = [], []
    for k in range(n):
        if k >= n - fail:
            runs.append((4, 1.0, None))
            imps.append([])
            continue
        final = optimum * (1.0 + (rng.uniform(0.0, 0.009) if k < reach_1pct else rng.uniform(0.02, 0.08)))
        t0 = rng.uniform(0.001, 0.05)
        seq = [(t0, optimum * 1.3), (t0 + rng.uniform(0.01, 0.2), optimum * 1.09),
               (t0 + rng.uniform(0.3, 0.5), optimum * 1.05), (rng.uniform(0.6, 0.95), final)]
        seq = [(t, c) for t, c in seq if c > final] + [(seq[-1][0], final)]
        runs.append((6, 1.0, final))
        imps.append(seq)
    return runs, imps


def build(tmp, with_improvements=True):
    """Two families (circles at 10 and 100 obstacles, 2 queries each; a disc-robot circles world), three
    planners with different reach. Returns the database path."""
    rng = random.Random(5)
    logs, all_imps = [], []
    worlds = [("circles_10_s1", 10, 0.0), ("circles_100_s2", 100, 0.0), ("circles_100_s3", 100, 0.5)]
    for world, count, radius in worlds:
        for q in range(2):
            opt = rng.uniform(20.0, 60.0)
            planners, imps, progress = {}, {}, {}
            for pname, reach, fail in (("Good", 6, 0), ("Half", 3, 1), ("Poor", 1, 3)):
                runs, imp = make_runs(rng, opt, 6, reach, fail)
                planners[pname] = runs
                imps[pname] = imp
                # Progress samples every 0.2 s, coarser than the improvements (the fallback's data).
                progress[pname] = [[(0.2 * j, min([c for t, c in seq if t <= 0.2 * j] or [float("inf")]))
                                    for j in range(1, 6)] for seq in imp]
            name = "%s-q%d" % (world, q)
            log = os.path.join(tmp, name + ".log")
            write_log(log, name, world, opt, count, radius, planners, progress)
            logs.append(log)
            all_imps.append((name, imps))
    dbpath = os.path.join(tmp, "q.db")
    subprocess.run(["/usr/bin/ompl_benchmark_statistics", "-d", dbpath] + logs, check=True, stdout=subprocess.DEVNULL)
    if with_improvements:
        conn = sqlite3.connect(dbpath)
        conn.execute("CREATE TABLE improvements (runid INTEGER, time REAL, cost REAL, source TEXT)")
        for name, imps in all_imps:
            for pname, per_run in imps.items():
                for k, seq in enumerate(per_run):
                    (runid,) = conn.execute(
                        "SELECT r.id FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p "
                        "ON r.plannerid = p.id WHERE e.name = ? AND p.name = ? AND r.run_index = ?",
                        (name, pname, k)).fetchone()
                    for t, c in seq:
                        conn.execute("INSERT INTO improvements VALUES (?, ?, ?, 'callback')", (runid, t, c))
        conn.commit()
        conn.close()
    return dbpath


def sql_times(conn, exp, planner, tol):
    """Independent per-run times to quality: SQL over improvements, None for never."""
    out = []
    for runid, opt in conn.execute(
            "SELECT r.id, e.exact_optimum FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p "
            "ON r.plannerid = p.id WHERE e.name = ? AND p.name = ? ORDER BY r.run_index", (exp, planner)):
        target = 1e300 if tol is None else opt * (1.0 + tol)
        (t,) = conn.execute("SELECT min(time) FROM improvements WHERE runid = ? AND cost <= ?", (runid, target)).fetchone()
        out.append(t)
    return out


def censored_median(values):
    """Sample median with None as +inf (statistics.median of the sorted values)."""
    return statistics.median(sorted(math.inf if v is None else v for v in values))


class QualityTest(unittest.TestCase):
    def test_times_medians_and_intervals_equal_independent_computation(self):
        with tempfile.TemporaryDirectory() as tmp:
            dbpath = build(tmp)
            database = dbmod.load(dbpath)
            conn = sqlite3.connect(dbpath)
            checked = 0
            for exp in database.experiments:
                opt = dbmod.to_float(exp.params["exact_optimum"])
                for row in quality.rows(database, exp, opt):
                    for key, tol in LEVELS.items():
                        times = sql_times(conn, exp.name, row["planner"], tol)
                        s = row[key]
                        self.assertEqual(s["n"], len(times))
                        self.assertEqual(s["reached"], sum(1 for t in times if t is not None))
                        expected = censored_median(times)
                        if math.isinf(expected):
                            self.assertTrue(math.isinf(s["median"]))
                        else:
                            self.assertAlmostEqual(s["median"], expected, places=12)
                        # The interval is two order statistics around the median with >= 95 % coverage.
                        ordered = sorted(math.inf if t is None else t for t in times)
                        lo, hi = ordered.index(s["lo"]), len(ordered) - 1 - ordered[::-1].index(s["hi"])
                        self.assertLessEqual(s["lo"], s["median"])
                        self.assertGreaterEqual(s["hi"], s["median"])
                        n = len(ordered)
                        coverage = sum(math.comb(n, i) for i in range(lo + 1, hi + 1)) / 2.0 ** n
                        self.assertGreaterEqual(coverage + 1e-12, min(0.95, 1 - 2 * 0.5 ** n))
                        checked += 1
            self.assertEqual(checked, 6 * 3 * 4)
            # Censoring: "Poor" reaches 1 % in 1 of 6 runs and fails 3: not reached, but not dropped.
            exp = database.experiments[0]
            poor = [r for r in quality.rows(database, exp, dbmod.to_float(exp.params["exact_optimum"]))
                    if r["planner"] == "Poor"][0]
            self.assertTrue(math.isinf(poor["t1"]["median"]))
            self.assertEqual(poor["t1"]["n"], 6)
            self.assertIn("not reached", quality.fmt(poor["t1"]))
            # "Half" reaches it in 3 of 6 runs: an even count with half censored averages in +inf.
            half = [r for r in quality.rows(database, exp, dbmod.to_float(exp.params["exact_optimum"]))
                    if r["planner"] == "Half"][0]
            self.assertEqual(half["t1"]["reached"], 3)
            self.assertTrue(math.isinf(half["t1"]["median"]))
            self.assertFalse(math.isinf(half["t10"]["median"]))

    def test_ranking_and_scaling_section_use_the_improvements(self):
        with tempfile.TemporaryDirectory() as tmp:
            dbpath = build(tmp)
            out = os.path.join(tmp, "report")
            index = report.write_report(dbpath, out)
            with open(index) as f:
                text = f.read()
            database = dbmod.load(dbpath)
            conn = sqlite3.connect(dbpath)
            # The ranking's time to within 1 % is the improvements-based censored median.
            for exp in database.experiments:
                for r in report.table_rows(database, exp):
                    expected = censored_median(sql_times(conn, exp.name, r["planner"], 0.01))
                    got = r["t1"]["median"]
                    self.assertTrue(math.isinf(got) if math.isinf(expected) else abs(got - expected) < 1e-12)
                    if not math.isinf(expected):
                        self.assertIn("%.4f [" % expected, text)
            self.assertIn("<h2>Scaling</h2>", text)
            images = re.findall(r"src='(scaling_[^']+)'", text)
            self.assertEqual(len(images), 2)  # circles, circles with a disc robot
            for img in images:
                self.assertTrue(png_ok(os.path.join(out, img)), img)
            table = scaling.scaling_table(database, database.experiments)
            self.assertEqual(set(table), {"circles", "circles (disc robot, r = 0.5 m)"})
            self.assertEqual(table["circles"]["sizes"], [10, 100])
            for label, fam in table.items():
                radius = 0.5 if "disc" in label else 0.0
                for planner, by_size in fam["planners"].items():
                    for size, cell in by_size.items():
                        q = ("SELECT r.status, r.optimality_gap, r.id, e.exact_optimum FROM runs r JOIN experiments e ON "
                             "r.experimentid = e.id JOIN plannerConfigs p ON r.plannerid = p.id WHERE e.obstacle_count = ? "
                             "AND e.robot_radius = ? AND p.name = ?")
                        rows = conn.execute(q, (size, radius, planner)).fetchall()
                        self.assertEqual(cell["runs"], len(rows))
                        self.assertAlmostEqual(cell["success"], sum(1 for r in rows if r[0] == 6) / len(rows), places=12)
                        gaps = [g if s == 6 else None for s, g, _, _ in rows]
                        self.assertEqual(cell["gap"]["median"], censored_median(gaps))
                        times = []
                        for _, _, runid, opt in rows:
                            (t,) = conn.execute("SELECT min(time) FROM improvements WHERE runid = ? AND cost <= ?",
                                                (runid, opt * 1.01)).fetchone()
                            times.append(t)
                        self.assertEqual(cell["t1"]["median"], censored_median(times))
                        lo, hi = cell["success_ci"]
                        self.assertLessEqual(lo, cell["success"])
                        self.assertGreaterEqual(hi, cell["success"])

    def test_without_improvements_the_progress_samples_are_used(self):
        with tempfile.TemporaryDirectory() as tmp:
            dbpath = build(tmp, with_improvements=False)
            database = dbmod.load(dbpath)
            self.assertIsNone(database.improvements)
            self.assertTrue(any("improvements" in n for n in database.notes))
            exp = database.experiments[0]
            opt = dbmod.to_float(exp.params["exact_optimum"])
            conn = sqlite3.connect(dbpath)
            for r in quality.rows(database, exp, opt):
                times = []
                for (runid,) in conn.execute(
                        "SELECT r.id FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id WHERE r.experimentid = ? "
                        "AND p.name = ? ORDER BY r.run_index", (exp.id, r["planner"])):
                    (t,) = conn.execute("SELECT min(time) FROM progress WHERE runid = ? AND best_cost <= ?",
                                        (runid, opt * 1.01)).fetchone()
                    if t is None:  # the final exact path, at the run's time
                        (status, length, rt) = conn.execute("SELECT status, path_length, time FROM runs WHERE id = ?",
                                                            (runid,)).fetchone()
                        t = rt if status == 6 and length <= opt * 1.01 else None
                    times.append(t)
                expected = censored_median(times)
                got = r["t1"]["median"]
                self.assertTrue(math.isinf(got) if math.isinf(expected) else abs(got - expected) < 1e-12)


if __name__ == "__main__":
    unittest.main()
