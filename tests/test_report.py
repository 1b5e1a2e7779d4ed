#!/usr/bin/python3
"""The report from a small database: every figure is a valid image, every table number equals the SQL
aggregate computed here independently, and a database with a crashed planner or without progress data
still gives a report that says what is missing. The database is built the way mhplan bench builds one:
OMPL-format logs turned into SQLite by /usr/bin/ompl_benchmark_statistics."""

import math
import os
import random
import re
import sqlite3
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "analysis"))

from mhplan_analysis import report  # noqa: E402

STATUS = ["Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type", "Timeout",
          "Approximate solution", "Exact solution", "Crash", "Abort"]


def write_log(path, experiment, world, world_file, optimum, planners, with_progress=True, seed=1):
    """An OMPL 1.5 benchmark log. planners: name -> list of runs (status, time, length, clearance, progress)."""
    rng = random.Random(seed)
    lines = ["OMPL version 1.5.2", "Experiment %s" % experiment, "3 experiment properties",
             "world TEXT = %s" % world, "world_file TEXT = %s" % world_file, "exact_optimum REAL = %r" % optimum,
             "Running on testhost", "Starting at 2026-11-23 12:00:00", "<<<|", "setup", "|>>>", "<<<|", "cpu", "|>>>",
             "%d is the random seed" % seed, "1 seconds per run", "1024 MB per run", "5 runs per planner",
             "3.5 seconds spent to collect the data", "1 enum types", "status|" + "|".join(STATUS),
             "%d planners" % len(planners)]
    for name, runs in planners.items():
        lines += [name, "0 common properties", "6 properties for each run", "time REAL", "status ENUM",
                  "solved BOOLEAN", "path length REAL", "optimality gap REAL", "min clearance REAL",
                  "%d runs" % len(runs)]
        for status, t, length, clearance, _ in runs:
            gap = "" if length is None else repr(100.0 * (length - optimum) / optimum)
            lines.append("%r; %d; %d; %s; %s; %s; " % (t, status, 1 if status in (5, 6) else 0,
                                                     "" if length is None else repr(length), gap,
                                                     "" if clearance is None else repr(clearance)))
        if with_progress and any(r[4] for r in runs):
            lines += ["2 progress properties for each run", "time REAL", "best cost REAL", "%d runs" % len(runs)]
            for *_, progress in runs:
                lines.append("".join("%r,%r,;" % (t, c) for t, c in progress))
            lines.append(".")
        else:
            lines.append(".")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def make_runs(rng, optimum, n, status=6, with_progress=True):
    runs = []
    for _ in range(n):
        length = optimum * (1.0 + rng.uniform(0.0, 0.2))
        t = rng.uniform(0.05, 1.0)
        progress = []
        if with_progress:
            c = length * 1.3
            for k in range(1, 8):
                progress.append((t * k / 8.0, c))
                c = max(length, c * 0.95)
            progress.append((t, length))
        runs.append((status, t, length if status in (5, 6) else None, rng.uniform(0.0, 0.5), progress))
    return runs


def build_database(tmp, crash=False, progress=True):
    rng = random.Random(3)
    logs = []
    world_file = os.path.join(ROOT, "environments", "bfo_case1.yaml")
    planners = {"SMA": make_runs(rng, 14.2734, 5, with_progress=progress),
                "RRTstar": make_runs(rng, 14.2734, 5, with_progress=progress)}
    if crash:
        planners["Crasher"] = [(7, 0.01, None, None, [])] * 3 + [(4, 1.0, None, None, [])] * 2
    log = os.path.join(tmp, "a.log")
    write_log(log, "bfo_case1/default", "bfo_case1", world_file, 14.2734, planners, progress)
    logs.append(log)
    planners = {"SMA": make_runs(rng, 28.5, 5, with_progress=progress),
                "LRSMA": make_runs(rng, 28.5, 4, with_progress=progress) + [(5, 1.0, 35.0, 0.1, [])]}
    log = os.path.join(tmp, "b.log")
    write_log(log, "lrsma_scenario1/default", "lrsma_scenario1",
              os.path.join(ROOT, "environments", "lrsma_scenario1.yaml"), 28.5, planners, progress)
    logs.append(log)
    dbpath = os.path.join(tmp, "bench.db")
    subprocess.run(["/usr/bin/ompl_benchmark_statistics", "-d", dbpath] + logs, check=True,
                   stdout=subprocess.DEVNULL)
    # Saved paths, as mhplan bench stores them: one row per run.
    conn = sqlite3.connect(dbpath)
    conn.execute("CREATE TABLE paths (runid INTEGER PRIMARY KEY, points TEXT)")
    for (runid,) in conn.execute("SELECT id FROM runs WHERE status = 6").fetchall():
        conn.execute("INSERT INTO paths VALUES (?, ?)", (runid, "0 0;3 6;7 4;10 10"))
    conn.commit()
    conn.close()
    return dbpath


def png_ok(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return False
    w = int.from_bytes(head[16:20], "big")
    h = int.from_bytes(head[20:24], "big")
    return w > 100 and h > 100


class ReportTest(unittest.TestCase):
    def test_full_report(self):
        with tempfile.TemporaryDirectory() as tmp:
            dbpath = build_database(tmp, crash=True)
            out = os.path.join(tmp, "report")
            index = report.write_report(dbpath, out)
            with open(index) as f:
                text = f.read()
            images = re.findall(r"src='([^']+)'", text)
            self.assertGreaterEqual(len(images), 6)
            for img in images:
                self.assertTrue(png_ok(os.path.join(out, img)), img)
            self.assertTrue(any(i.startswith("paths_") for i in images))
            self.assertTrue(any(i.startswith("convergence_") for i in images))
            # Independent SQL aggregates against the report's tables.
            conn = sqlite3.connect(dbpath)
            q = """SELECT e.name, p.name, COUNT(*), SUM(r.status = 6), MIN(CASE WHEN r.status = 6 THEN r.path_length END),
                          AVG(CASE WHEN r.status = 6 THEN r.path_length END), AVG(r.time), SUM(r.status = 7)
                   FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p ON r.plannerid = p.id
                   GROUP BY e.id, p.id"""
            database = report.dbmod.load(dbpath)
            rows = {(e.name, r["planner"]): r for e in database.experiments for r in report.table_rows(database, e)}
            for exp, planner, n, exact, mn, avg, avg_time, crashed in conn.execute(q):
                r = rows[(exp, planner)]
                self.assertEqual(r["runs"], n)
                self.assertEqual(r["counts"]["exact"], exact)
                self.assertEqual(r["counts"]["crashed"], crashed)
                if mn is None:
                    self.assertIsNone(r["min"])
                else:
                    self.assertAlmostEqual(r["min"], mn, places=9)
                    self.assertAlmostEqual(r["mean"], avg, places=9)
                self.assertAlmostEqual(r["mean_time"], avg_time, places=9)
                # The table shows these numbers.
                if mn is not None:
                    self.assertIn("%.4f" % mn, text)
            # Standard deviation (ddof = 1) of exact lengths, recomputed in SQL.
            for exp, planner, var in conn.execute(
                    """SELECT e.name, p.name, (SUM(r.path_length * r.path_length) - SUM(r.path_length) * SUM(r.path_length) / COUNT(*)) / (COUNT(*) - 1)
                       FROM runs r JOIN experiments e ON r.experimentid = e.id JOIN plannerConfigs p ON r.plannerid = p.id
                       WHERE r.status = 6 GROUP BY e.id, p.id"""):
                self.assertAlmostEqual(rows[(exp, planner)]["std"], math.sqrt(max(var, 0.0)), places=7)
            # Median gap equals the SQL median of the stored gap column.
            for exp, planner in [("bfo_case1/default", "SMA"), ("lrsma_scenario1/default", "LRSMA")]:
                gaps = sorted(g for (g,) in conn.execute(
                    """SELECT r.optimality_gap FROM runs r JOIN experiments e ON r.experimentid = e.id
                       JOIN plannerConfigs p ON r.plannerid = p.id WHERE e.name = ? AND p.name = ? AND r.status = 6""",
                    (exp, planner)))
                mid = len(gaps) // 2
                median = gaps[mid] if len(gaps) % 2 else 0.5 * (gaps[mid - 1] + gaps[mid])
                self.assertAlmostEqual(rows[(exp, planner)]["median_gap"], median, places=9)
            # The papers' numbers stand beside ours.
            self.assertIn("29.81", text)  # LRSMA scenario 1 mean in the paper's Table 3
            self.assertIn("14.535", text)  # [BFO] case 1 ATBFO best
            self.assertIn("Crasher", text)

    def test_missing_progress_and_failed_planner(self):
        with tempfile.TemporaryDirectory() as tmp:
            dbpath = build_database(tmp, crash=True, progress=False)
            conn = sqlite3.connect(dbpath)
            conn.execute("DROP TABLE progress")
            conn.execute("DROP TABLE paths")
            conn.commit()
            conn.close()
            out = os.path.join(tmp, "report")
            with open(report.write_report(dbpath, out)) as f:
                text = f.read()
            self.assertIn("no progress table", text)
            self.assertIn("no saved paths", text)
            self.assertIn("Gaps in the data", text)
            for img in re.findall(r"src='([^']+)'", text):
                self.assertTrue(png_ok(os.path.join(out, img)), img)

    def test_not_a_database(self):
        with tempfile.TemporaryDirectory() as tmp:
            bogus = os.path.join(tmp, "x.db")
            sqlite3.connect(bogus).execute("CREATE TABLE t (a)").connection.commit()
            proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "analysis", "report.py"), bogus, "-o", tmp],
                                  capture_output=True, text=True)
            self.assertEqual(proc.returncode, 1)
            self.assertIn("not an OMPL benchmark database", proc.stderr)
            proc = subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "analysis", "report.py"), bogus + ".missing"],
                                  capture_output=True, text=True)
            self.assertEqual(proc.returncode, 1)
            self.assertIn("no such database", proc.stderr)


if __name__ == "__main__":
    unittest.main()
