#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The by-bucket MovingAI section of the report (analysis/mhplan_analysis/movingai.py) on a hand-built
database: grouping by map and bucket, success counts, length / octile optimum, gap to the any-angle optimum."""
import os
import sys
import types
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "analysis"))

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import movingai  # noqa: E402


def experiment(eid, bucket, octile, anyangle, world="rooms"):
    return dbmod.Experiment(eid, "%s-b%d-l%d" % (world, bucket, eid), {
        "world": world, "scen_bucket": bucket, "scen_optimum": octile, "octile_optimum": octile,
        "octile_optimum_m": octile, "exact_optimum": anyangle})


def run(rid, eid, planner, length, outcome="exact"):
    return dbmod.Run(rid, eid, planner, {"solution_length": length}, outcome)


class MovingAISection(unittest.TestCase):
    def test_rows_by_map_and_bucket(self):
        exps = [experiment(1, 0, 2.0, 2.0), experiment(2, 1, 10.0, 8.0), experiment(3, 1, 20.0, 16.0),
                dbmod.Experiment(4, "bfo_case1-default", {"world": "bfo_case1", "exact_optimum": 14.0})]
        runs = [run(1, 1, "A", 2.0), run(2, 2, "A", 10.0), run(3, 3, "A", 20.0), run(4, 2, "B", 9.0),
                run(5, 3, "B", None, "failed"), run(6, 4, "A", 15.0)]
        database = dbmod.Database("x.db", exps, ["A", "B"], runs, ["solution_length"], [])
        self.assertTrue(movingai.is_movingai(exps[0]))
        self.assertFalse(movingai.is_movingai(exps[3]))
        rows = movingai.bucket_rows(database, [e for e in exps if movingai.is_movingai(e)],
                                    lambda r: r.values["solution_length"])
        self.assertEqual([r[:6] for r in rows], [("rooms", 0, "A", 1, 1, 1), ("rooms", 1, "A", 2, 2, 2),
                                                 ("rooms", 1, "B", 2, 2, 1)])
        self.assertAlmostEqual(rows[1][6], 1.0)   # A* lengths equal the octile optima
        self.assertAlmostEqual(rows[1][7], 25.0)  # 10 vs 8 and 20 vs 16: 25 % longer than any-angle
        self.assertAlmostEqual(rows[2][6], 0.9)   # 9 / 10
        self.assertAlmostEqual(rows[2][7], 12.5)  # 9 vs 8
        data = types.SimpleNamespace(database=database, planning=exps, length=lambda r: r.values["solution_length"])
        html = "".join(movingai.render(data, None))
        self.assertIn("by bucket", html)
        self.assertIn("<td>rooms</td><td>1</td><td>B</td><td>2</td><td>1/2</td><td>0.9000</td><td>12.50%</td>", html)
        self.assertNotIn("bfo_case1", html)


if __name__ == "__main__":
    unittest.main()
