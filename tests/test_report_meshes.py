#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report's pictures of OMPL.app problems (analysis/mhplan_analysis/meshes.py, docs/omplapp.md
"Pictures"): the meshes come from `mhplan worlds PROBLEM.cfg --json`; an SE(2) problem is drawn from above
with the robot's footprint along the best path, an SE(3) problem as three projections; the report's
path_figure hands experiments of world_type omplapp to it."""

import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "analysis"))

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import meshes, report  # noqa: E402

OMPLAPP = os.path.join(os.path.dirname(HERE), "environments", "omplapp")


def database(exp, paths):
    """A database of one experiment: planner P with one exact run per path (lengths 10, 11, ...)."""
    runs = [dbmod.Run(i + 1, exp.id, "P", {"path_length": 10.0 + i}, "exact") for i in range(len(paths))]
    return dbmod.Database("mem", [exp], ["P"], runs, ["path_length"], [])


class MeshPictures(unittest.TestCase):
    def test_export_has_the_meshes_as_planned(self):
        prob = meshes.load_problem(os.path.join(OMPLAPP, "bugtrap.cfg"))
        self.assertEqual(prob["space"], "se2")
        self.assertEqual(prob["environment"]["triangles"].shape, (60, 3))
        # The robot is centred on its origin in x and y (OMPL.app's robot centre).
        self.assertAlmostEqual(abs(prob["robot"]["vertices"][:, 0].mean()) + abs(prob["robot"]["vertices"][:, 1].mean()), 0.0, places=9)
        with self.assertRaises(ValueError):
            meshes.load_problem(os.path.join(HERE, "data", "bench_tiny.yaml.cfg"))

    def figure(self, cfg, exp_name, paths, world_type="omplapp", keep=None):
        exp = dbmod.Experiment(1, exp_name, {"world_type": world_type, "world_file": os.path.join(OMPLAPP, cfg)})
        with tempfile.TemporaryDirectory() as tmp:
            name, why = report.path_figure(database(exp, paths), exp, {i + 1: p for i, p in enumerate(paths)},
                                           exp.params["world_file"], tmp, {"P": "#d62728"})
            self.assertIsNotNone(name, why)
            self.assertIsNone(why)
            size = os.path.getsize(os.path.join(tmp, name))
            if keep:
                os.replace(os.path.join(tmp, name), keep)
        return name, size

    def test_3d_world_in_r3(self):
        # docs/worlds3d.md: an R^3 world's paths are (x, y, z); drawn as SE(3) projections with its boxes and
        # spheres as triangles and the ball robot at poses along the path.
        prob = meshes.load_problem(os.path.join(OMPLAPP, "..", "3d", "narrow_passage.yaml"))
        self.assertEqual(prob["space"], "r3")
        self.assertEqual(prob["environment"]["triangles"].shape, (5 * 12 + 80, 3))
        path = [(1.0, 3.0, 3.0), (5.0, 3.0, 3.0), (9.0, 3.0, 3.0)]
        name, size = self.figure(os.path.join("..", "3d", "narrow_passage.yaml"), "narrow_passage_3d", [path],
                                 "world3d", os.environ.get("MHPLAN_KEEP_FIGURE"))
        self.assertEqual(name, "paths_narrow_passage_3d.png")
        self.assertGreater(size, 10000)

    def test_se2_from_above_with_footprints(self):
        path = [(0.0, 0.0, 0.0), (0.0, 4.5, 1.5707963), (0.0, 6.0, 1.5707963)]
        name, size = self.figure("bugtrap.cfg", "bugtrap", [path])
        self.assertEqual(name, "paths_bugtrap.png")
        self.assertGreater(size, 10000)
        self.assertEqual(report.path_figure.footprints, 1)

    def test_se3_projections(self):
        q = (0.7071068, 0.0, 0.0, 0.7071068)
        path = [(-3.0, 0.0, 0.0) + q, (-1.0, 0.0, 0.0) + (1.0, 0.0, 0.0, 0.0), (1.0, 0.0, 0.0) + (1.0, 0.0, 0.0, 0.0), (3.0, 0.0, 0.0) + q]
        name, size = self.figure("passage.cfg", "passage", [path, path])
        self.assertEqual(name, "paths_passage.png")
        self.assertGreater(size, 10000)
        self.assertEqual(report.path_figure.footprints, 0)  # the 2D footprint paragraph does not apply

    def test_missing_problem_file_is_a_note(self):
        exp = dbmod.Experiment(1, "gone", {"world_type": "omplapp"})
        name, why = report.path_figure(database(exp, []), exp, {}, "/nonexistent/x.cfg", "/tmp", {})
        self.assertIsNone(name)
        self.assertIn("not found", why)


if __name__ == "__main__":
    unittest.main()
