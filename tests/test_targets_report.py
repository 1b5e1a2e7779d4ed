#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 31's targets table (analysis/mhplan_analysis/targets.py) on a hand-built database: per set-up and
planner the exact runs, gap percentiles with unsolved runs at +infinity, runs within 1 % and their times from
the improvements table, first-solution times, dense-check failures; the targets under it; the report section
shown only when an experiment has an exact optimum; the Markdown command."""

import os
import sqlite3
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ANALYSIS = os.path.join(os.path.dirname(HERE), "analysis")
sys.path.insert(0, ANALYSIS)

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import report, stats, targets  # noqa: E402

INF = float("inf")


def make_db(path, optimum=10.0):
    """Experiment 1: exact set-up, experiment 2: app at 0.002; planners GA-MEM and InformedRRTstar.
    Runs: (experiment, planner, status, gap, path_length, collision_free, improvements [(time, cost)])."""
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE experiments (id INTEGER PRIMARY KEY, name TEXT, exact_optimum REAL, "
                 "validity_setup TEXT, validity_resolution REAL)")
    conn.execute("CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY, name TEXT)")
    conn.execute("CREATE TABLE runs (id INTEGER PRIMARY KEY, experimentid INTEGER, plannerid INTEGER, "
                 "status INTEGER, time REAL, optimality_gap REAL, path_length REAL, collision_free INTEGER)")
    conn.execute("CREATE TABLE improvements (runid INTEGER, time REAL, cost REAL, source TEXT)")
    conn.executemany("INSERT INTO experiments VALUES (?, ?, ?, ?, ?)",
                     [(1, "w-q0", optimum, "exact", None), (2, "w-q0-app", optimum, "app", 0.002)])
    conn.executemany("INSERT INTO plannerConfigs VALUES (?, ?)",
                     [(1, "geometric_GA-MEM"), (2, "geometric_InformedRRTstar")])
    runs = [(1, 1, 6, 0.0, 10.0, 1, [(0.2, 12.0), (0.5, 10.0)]),
            (1, 1, 6, 0.5, 10.05, 0, [(0.1, 10.05)]),          # within 1 % at once; fails the dense check
            (1, 1, 6, 2.0, 10.2, 1, [(0.3, 10.2)]),            # 2 % above: never within 1 %
            (1, 1, 4, None, None, None, [])]                   # no solution
    runs += [(1, 2, 6, g, 10.0 * (1 + g / 100), 1, [(0.01, 11.0), (0.1 * (k + 1), 10.0 * (1 + g / 100))])
             for k, g in enumerate((0.1, 0.2, 0.3, 0.4))]
    runs += [(2, 1, 6, None, 10.0, 1, [(0.005, 10.0)]),        # no gap column value: from the length
             (2, 1, 6, 0.0, 10.0, 1, [(0.005, 10.0)]),
             (2, 2, 6, 0.5, 10.05, 0, [(0.02, 10.05)]),
             (2, 2, 6, 0.5, 10.05, 1, [(0.02, 10.05)])]
    for i, (exp, planner, status, gap, length, free, improvements) in enumerate(runs, start=1):
        conn.execute("INSERT INTO runs VALUES (?, ?, ?, ?, 1.0, ?, ?, ?)", (i, exp, planner, status, gap, length, free))
        conn.executemany("INSERT INTO improvements VALUES (?, ?, ?, 'callback')", [(i, t, c) for t, c in improvements])
    conn.commit()
    conn.close()


class Targets(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.db = os.path.join(cls.tmp.name, "t.db")
        make_db(cls.db)
        cls.database = dbmod.load(cls.db)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_percentiles_put_unsolved_runs_last(self):
        self.assertAlmostEqual(stats.percentile([0.1, 0.2, 0.3, 0.4], 90), 0.37)
        self.assertAlmostEqual(stats.percentile([0.0, 0.5, 2.0, INF], 50), 1.25)
        self.assertEqual(stats.percentile([0.0, 0.5, 2.0, INF], 75), INF)
        self.assertIsNone(stats.percentile([], 50))

    def test_rows_per_setup_and_planner(self):
        table = targets.rows(self.database)
        self.assertEqual([(s, p) for s, p, _ in table], [("exact", "GA-MEM"), ("exact", "InformedRRTstar"),
                                                         ("app 0.002", "GA-MEM"), ("app 0.002", "InformedRRTstar")])
        mem, irrt, app_mem, app_irrt = (r for _, _, r in table)
        self.assertEqual((mem["runs"], mem["exact"], mem["within"], mem["dense_failures"]), (4, 3, 2, 1))
        self.assertAlmostEqual(mem["p50"], 1.25)
        self.assertEqual((mem["p75"], mem["p90"]), (INF, INF))
        self.assertAlmostEqual(mem["t1_reached"], 0.3)  # the median of 0.5 and 0.1
        self.assertEqual(mem["t1"], INF)  # half the runs never got within 1 %
        self.assertAlmostEqual(mem["first"], 0.25)  # 0.1, 0.2, 0.3, inf
        self.assertEqual((irrt["exact"], irrt["within"], irrt["dense_failures"]), (4, 4, 0))
        self.assertAlmostEqual(irrt["p75"], 0.325)
        self.assertAlmostEqual(irrt["p90"], 0.37)
        self.assertAlmostEqual(irrt["t1"], 0.25)
        self.assertAlmostEqual(irrt["first"], 0.01)
        self.assertAlmostEqual(app_mem["p90"], 0.0)
        self.assertAlmostEqual(app_mem["t1"], 0.005)
        self.assertEqual(app_irrt["dense_failures"], 1)
        # A run whose path fails the dense check never counts as within 1 % in the clean columns.
        self.assertEqual((mem["within_clean"], mem["t1_clean"]), (1, INF))
        self.assertEqual((app_irrt["within"], app_irrt["within_clean"], app_irrt["t1_clean"]), (2, 1, INF))
        self.assertAlmostEqual(app_mem["t1_clean"], 0.005)

    def test_targets_per_setup(self):
        verdicts = dict(targets.verdicts(targets.rows(self.database)))
        exact = {what: (measured, met) for what, measured, met in verdicts["exact"]}
        self.assertEqual(exact["every memetic run exact"], ("GA-MEM 3/4", False))
        self.assertEqual(exact["no memetic path fails the dense check"], ("GA-MEM 1", False))
        p90 = exact["best memetic's 90th-percentile gap at or below the best OMPL planner's"]
        self.assertEqual(p90, ("GA-MEM inf vs InformedRRTstar 0.370 %", False))
        t1 = exact["best memetic's median time to within 1 % (all runs) at or below the best OMPL planner's"]
        self.assertEqual(t1, ("GA-MEM inf vs InformedRRTstar 0.250 s", False))
        self.assertEqual(len(exact), 4)  # the reference lines are the app set-up's
        self.assertIsNone(targets._at_most(INF, INF))  # neither got there: undecided, never "met"
        self.assertTrue(targets._at_most(3.0, INF))
        app = {what: met for what, _, met in verdicts["app 0.002"]}
        self.assertEqual(len(app), 7)
        clean = "best memetic's median time to within 1 % with a path passing the dense check (all runs) no " \
                "slower than InformedRRTstar's"
        self.assertTrue(app[clean])  # GA-MEM 0.005 s vs inf: Informed RRT*'s clean run is one of two
        self.assertTrue(all(app.values()))

    def test_report_section_only_with_optima(self):
        out = os.path.join(self.tmp.name, "out")
        with open(report.write_report(self.db, out)) as f:
            text = f.read()
        self.assertIn("<h2>Targets (issue 31)</h2>", text)
        self.assertIn("<td>app 0.002</td><td>GA-MEM</td><td>2/2</td>", text)
        self.assertLess(text.index("Validity set-ups"), text.index("Targets (issue 31)"))
        bare = os.path.join(self.tmp.name, "bare.db")
        make_db(bare, optimum=None)
        with open(report.write_report(bare, os.path.join(self.tmp.name, "bare"))) as f:
            self.assertNotIn("Targets (issue 31)", f.read())

    def test_markdown_command(self):
        env = dict(os.environ, PYTHONPATH=ANALYSIS)
        r = subprocess.run([sys.executable, "-m", "mhplan_analysis.targets", self.db], env=env,
                           capture_output=True, text=True, timeout=60)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("| exact | GA-MEM | 3/4 | 1.250 | inf | inf | 2/4 | 0.300 | inf | 0.250 | 1 |", r.stdout)
        self.assertIn("Targets, app 0.002:", r.stdout)
        bare = os.path.join(self.tmp.name, "bare2.db")
        make_db(bare, optimum=None)
        r = subprocess.run([sys.executable, "-m", "mhplan_analysis.targets", bare], env=env, capture_output=True,
                           text=True, timeout=60)
        self.assertEqual(r.returncode, 1)
        self.assertIn("no planning experiment with an exact optimum", r.stderr)


if __name__ == "__main__":
    unittest.main()
