#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report's Validity set-ups section (analysis/mhplan_analysis/setups.py) on a hand-built database: the
set-up of each experiment (databases from before set-ups are exact), paths failing the dense check per set-up
and planner, and checks per run and per improvement."""
import os
import sys
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "analysis"))

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import setups  # noqa: E402


def run(rid, eid, planner, free, gap, state, motion, improvements, outcome="exact"):
    return dbmod.Run(rid, eid, planner, {"collision_free": free, "optimality_gap": gap, "state_checks": state,
                                         "motion_checks": motion, "improvements": improvements}, outcome)


class SetupsSection(unittest.TestCase):
    def test_rows_per_setup_and_planner(self):
        exps = [dbmod.Experiment(1, "w-q", {"world": "w"}),  # an older database: no validity_setup column
                dbmod.Experiment(2, "w-q-app", {"world": "w", "validity_setup": "app", "validity_resolution": 0.002})]
        runs = [run(1, 1, "A", 1, 0.5, 10, 100, 4), run(2, 1, "A", 1, 1.5, 30, 300, 2),
                run(3, 2, "A", 0, 0.1, 1000, 50, 5), run(4, 2, "A", 1, 0.2, 2000, 70, 0),
                run(5, 2, "B", 0, None, 5, 9, 1, outcome="approximate")]
        database = dbmod.Database("x.db", exps, ["A", "B"], runs, [], [])
        self.assertEqual(setups.label(exps[0]), "exact")
        self.assertIn("resolution 0.002", setups.label(exps[1]))
        rows = setups.rows(database, exps)
        self.assertEqual([(r[0].split(" ")[0], r[1]) for r in rows], [("exact", "A"), ("app", "A"), ("app", "B")])
        exact, app_a, app_b = rows
        self.assertEqual(exact[2:7], (2, 2, 2, 0, 0))
        self.assertAlmostEqual(exact[7], 1.0)
        self.assertAlmostEqual(exact[8], 20.0)
        self.assertAlmostEqual(exact[9], 200.0)
        self.assertAlmostEqual(exact[11], 87.5)  # motion checks per improvement: the median of 100/4 and 300/2
        self.assertEqual(app_a[2:7], (2, 2, 2, 1, 1))  # one exact path fails the dense check
        self.assertAlmostEqual(app_a[7], 0.2)  # the gap of collision-free exact runs only
        self.assertAlmostEqual(app_a[11], 10.0)  # the run without improvements does not count
        self.assertEqual(app_b[2:7], (1, 0, 1, 1, 0))
        html = "".join(setups.section(database, exps, lambda h, r: "%s%s" % (h, r), lambda v, d=3, s="": str(v)))
        self.assertIn("Validity set-ups", html)
        self.assertIn("exact: 1 experiment", html)


if __name__ == "__main__":
    unittest.main()
