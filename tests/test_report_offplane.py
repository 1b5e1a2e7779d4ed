#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report off the plane (issue 29): on an SE(2) campaign with a polygon robot the path figure draws the
robot's footprint at start, goal and along each best path (so one sees it turn to pass the gap); the
convergence plot is drawn from the recorded improvements, at their exact times, on a log time axis, with
the reference line beneath every planner's line; the report states the CPU share and load the campaign
recorded and plots CPU time beside wall time; the smoothness axis has no negative tick; the profiles'
legend is readable. The database is written here with SQL, in the layout mhplan bench stores (OMPL's
tables plus improvements and paths; benchmarks/README.md)."""

import math
import os
import re
import sqlite3
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "analysis"))

from mhplan_analysis import comparisons, report, worlds  # noqa: E402
from mhplan_analysis import db as dbmod  # noqa: E402

UP = math.pi / 2
# The bar of se2_narrow_passage stands at start and goal and lies down in the 1 m gap of the wall at x = 5.
PATH = [(2.0, 3.0, UP), (4.0, 3.0, 0.0), (6.0, 3.0, 0.0), (8.0, 3.0, UP)]
STATUS = ["Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type", "Timeout",
          "Approximate solution", "Exact solution", "Crash", "Abort"]
# planner -> per run: (wall time, cpu time, path cost, smoothness, [(improvement time, cost), ...])
RUNS = {
    "RRTstar": [(1.0, 0.9, 9.0, 0.0, [(0.0123, 11.0), (0.31, 9.5), (0.77, 9.0)]),
                (1.0, 0.5, 9.2, 0.0, [(0.0456, 12.0), (0.52, 9.2)]),
                (1.0, 0.95, 9.1, 0.0, [(0.0211, 10.0), (0.6, 9.1)])],
    "PRMstar": [(1.0, 0.8, 9.3, 0.0, [(0.002, 9.8), (0.4, 9.3)]),
                (1.0, 0.7, 9.3, 0.0, [(0.003, 9.9), (0.45, 9.3)]),
                (1.0, 0.6, 9.4, 0.0, [(0.0025, 9.6), (0.5, 9.4)])],
}


def build(tmp):
    path = os.path.join(tmp, "se2.db")
    conn = sqlite3.connect(path)
    conn.executescript("""
        CREATE TABLE experiments (id INTEGER PRIMARY KEY, name TEXT, timelimit REAL, world TEXT, world_file TEXT,
            space TEXT, query TEXT, query_points TEXT, load_average REAL, cores_available INTEGER);
        CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY, name TEXT, settings TEXT);
        CREATE TABLE enums (name TEXT, value INTEGER, description TEXT);
        CREATE TABLE runs (id INTEGER PRIMARY KEY, experimentid INTEGER, plannerid INTEGER, time REAL,
            cpu_time REAL, status INTEGER, solved INTEGER, path_length REAL, collision_free INTEGER,
            smoothness REAL, min_clearance REAL);
        CREATE TABLE progress (runid INTEGER, time REAL, best_cost REAL);
        CREATE TABLE improvements (runid INTEGER, time REAL, cost REAL, source TEXT);
        CREATE TABLE paths (runid INTEGER PRIMARY KEY, points TEXT);
    """)
    conn.executemany("INSERT INTO enums VALUES ('status', ?, ?)", list(enumerate(STATUS)))
    conn.execute("INSERT INTO experiments VALUES (1, 'se2_narrow_passage-default', 1.0, 'se2_narrow_passage', ?, "
                 "'se2', 'default', ?, 1.25, 2)",
                 (os.path.join(ROOT, "environments", "se2_narrow_passage.yaml"),
                  "(2,3,%r)->(8,3,%r)" % (UP, UP)))
    runid = 0
    for pid, (planner, runs) in enumerate(RUNS.items(), start=1):
        conn.execute("INSERT INTO plannerConfigs VALUES (?, ?, '')", (pid, "geometric_" + planner))
        for wall, cpu, cost, smooth, improvements in runs:
            runid += 1
            conn.execute("INSERT INTO runs VALUES (?, 1, ?, ?, ?, 6, 1, ?, 1, ?, 0.1)",
                         (runid, pid, wall, cpu, cost, smooth))
            conn.executemany("INSERT INTO improvements VALUES (?, ?, ?, 'callback')",
                             [(runid, t, c) for t, c in improvements])
            # Coarse progress samples: the convergence plot must not be drawn from these.
            conn.executemany("INSERT INTO progress VALUES (?, ?, ?)", [(runid, t, c) for t, c in
                                                                      [(0.1, improvements[0][1]), (1.0, cost)]])
            conn.execute("INSERT INTO paths VALUES (?, ?)",
                         (runid, "".join("%r %r %r;" % p for p in PATH)))
    conn.commit()
    conn.close()
    return path


class Captured:
    """The figures report.py closes while the block runs (report.plt.close patched)."""

    def __enter__(self):
        self.figures = []
        self._close = report.plt.close

        def close(fig=None):
            self.figures.append(fig)

        report.plt.close = close
        return self

    def __exit__(self, *exc):
        report.plt.close = self._close
        for f in self.figures:
            self._close(f)


class OffPlaneReport(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.db = build(cls.tmp.name)
        cls.database = dbmod.load(cls.db)
        cls.exp = cls.database.experiments[0]

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_convergence_is_drawn_from_the_improvements_at_their_times(self):
        times, med, lo, hi, source = report.convergence_series(self.database, self.exp, "RRTstar", 1.0)
        self.assertEqual(source, "improvements")
        recorded = sorted({t for *_, imp in RUNS["RRTstar"] for t, _ in imp})
        self.assertEqual(list(times), recorded + [1.0])
        # The median of the three runs' best costs, recomputed at every improvement's time.
        for k, t in enumerate(times):
            best = sorted(min([c for s, c in imp if s <= t], default=math.inf) for *_, imp in RUNS["RRTstar"])
            expected = best[1] if math.isfinite(best[1]) else None
            if expected is None:
                self.assertTrue(math.isnan(med[k]), t)
            else:
                self.assertAlmostEqual(med[k], expected, places=12, msg=str(t))

        fig = report.convergence_figure(self.database, self.exp, report._planner_colors(["RRTstar", "PRMstar"]))
        try:
            ax = fig.axes[0]
            self.assertEqual(ax.get_xscale(), "log")
            lines = [l for l in ax.get_lines() if l.get_gid() != "reference"]
            reference = [l for l in ax.get_lines() if l.get_gid() == "reference"]
            self.assertEqual(len(lines), 2)
            self.assertEqual(len(reference), 1)
            # Beneath and thinner than every planner's line; every planner's line inside the axes.
            self.assertLess(reference[0].get_zorder(), min(l.get_zorder() for l in lines))
            self.assertLess(reference[0].get_linewidth(), min(l.get_linewidth() for l in lines))
            lo_y, hi_y = ax.get_ylim()
            for line in lines:
                ys = [y for y in line.get_ydata() if math.isfinite(y)]
                self.assertTrue(ys)
                self.assertTrue(all(lo_y <= y <= hi_y for y in ys), (line.get_label(), ys, lo_y, hi_y))
                self.assertEqual(line.get_drawstyle(), "steps-post")
            # Drawn on top of each other, the first line stays visible around the second.
            self.assertGreater(lines[0].get_linewidth(), lines[1].get_linewidth())
        finally:
            report.plt.close(fig)

    def test_the_robot_is_drawn_at_start_goal_and_along_the_path(self):
        world = worlds.load_world(os.path.join(ROOT, "environments", "se2_narrow_passage.yaml"))
        self.assertEqual(world.space, "se2")
        self.assertEqual(len(world.robot_polygon), 4)
        paths = report.load_paths(self.db)
        self.assertEqual(paths[1][1], PATH[1])
        with tempfile.TemporaryDirectory() as out, Captured() as cap:
            name, why = report.path_figure(self.database, self.exp, paths, self.exp.params["world_file"], out,
                                           report._planner_colors(list(RUNS)))
            self.assertIsNotNone(name)
            self.assertIsNone(why)
            ax = cap.figures[-1].axes[0]
            patches = {}
            for p in ax.patches:
                patches.setdefault(p.get_gid(), []).append(p)
            start = patches["footprint-start"][0].get_xy()[:4]
            for got, want in zip(start, worlds.place(world.robot_polygon, PATH[0])):
                self.assertAlmostEqual(got[0], want[0], places=9)
                self.assertAlmostEqual(got[1], want[1], places=9)
            self.assertIn("footprint-goal", patches)
            along = patches["footprint"]
            self.assertGreaterEqual(len(along), 6)

            def lying(p):
                (x0, y0), (x1, y1) = p.get_xy()[:2]
                return abs(x1 - x0) > 3 * abs(y1 - y0)

            # In the gap (4.5 < x < 5.5) the bar lies down; at the start it stands.
            in_gap = [p for p in along if 4.5 < sum(v[0] for v in p.get_xy()[:4]) / 4 < 5.5]
            self.assertTrue(in_gap)
            self.assertTrue(all(lying(p) for p in in_gap))
            self.assertFalse(lying(along[0]))

    def test_load_and_cpu_share_are_stated_and_cpu_time_plotted(self):
        conn = sqlite3.connect(self.db)
        cpu, wall = conn.execute("SELECT sum(cpu_time), sum(time) FROM runs").fetchone()
        conn.close()
        with tempfile.TemporaryDirectory() as out:
            with Captured() as cap:
                box, _ = report.box_plots(self.database, self.exp, out)
                titles = [a.get_title() for a in cap.figures[-1].axes]
                self.assertEqual(titles[:2], ["wall time [s]", "CPU time [s]"])
                wall_ax, cpu_ax = cap.figures[-1].axes[:2]
                self.assertEqual(wall_ax.get_ylim(), cpu_ax.get_ylim())
            with open(report.write_report(self.db, out)) as f:
                text = f.read()
            self.assertIn("Machine load recorded by the campaign: the planners had %.0f %% of a core"
                          % (100.0 * cpu / wall), text)
            self.assertIn("load average at the experiments' ends was 1.25 on 2 core(s)", text)
            self.assertIn("only %.0f %% of a core" % (100.0 * cpu / wall), text)  # < 80 %: a gap noted
            # Nothing empty: every figure referenced exists and the tables hold both planners.
            for img in re.findall(r"src='([^']+)'", text):
                self.assertGreater(os.path.getsize(os.path.join(out, img)), 1000, img)
            self.assertIn("paths_se2_narrow_passage-default.png", text)
            self.assertIn("convergence_se2_narrow_passage-default.png", text)

    def test_smoothness_axis_has_no_negative_tick(self):
        for values in ([0.0, 0.0, 0.0], [0.0, 0.3], [0.0, 5.0, 4000.0]):
            fig, ax = report.plt.subplots()
            ax.boxplot([values])
            report.attribute_scale(ax, "smoothness", values)
            fig.canvas.draw()
            lo, hi = ax.get_ylim()
            self.assertGreaterEqual(lo, 0.0, values)
            self.assertGreaterEqual(hi, max(values), values)
            visible = [t for t in ax.get_yticks() if lo <= t <= hi]
            self.assertTrue(visible)
            self.assertTrue(all(t >= 0 for t in visible), (values, visible))
            report.plt.close(fig)

    def test_profile_legend_is_readable(self):
        with tempfile.TemporaryDirectory() as out, Captured() as cap:
            name = comparisons.profile_figure(self.database, [self.exp], report._optimum, out,
                                              report._planner_colors(list(RUNS)))
            self.assertEqual(name, "profiles.png")
            legends = [a.get_legend() for a in cap.figures[-1].axes if a.get_legend()]
            self.assertEqual(len(legends), 1)
            for t in legends[0].get_texts():
                self.assertGreaterEqual(t.get_fontsize(), 10)
            for line in legends[0].get_lines():
                self.assertGreaterEqual(line.get_linewidth(), 2.5)


if __name__ == "__main__":
    unittest.main()
