# SPDX-License-Identifier: BSD-3-Clause
"""The report's data access: ReportData reads a benchmark database once (runs indexed by experiment and
planner, the saved paths) and gives every section what it needs: the planning and simulation experiments,
optima and best-found references, path lengths, and the per-planner summary rows of every planning experiment
(computed once). Sections read only from it (docs/report.md)."""

import os

from . import db as dbmod
from . import quality, simulations, stats

# (key, candidate run columns in order of preference, axis label). The first column present is used.
ATTRIBUTES = [
    ("time", ["time"], "wall time [s]"),
    ("cpu_time", ["cpu_time"], "CPU time [s]"),
    ("length", ["path_length", "solution_length"], "path length [m]"),
    ("gap", ["optimality_gap"], "optimality gap [%]"),
    ("clearance", ["min_clearance", "solution_clearance"], "minimum clearance [m]"),
    ("smoothness", ["smoothness", "solution_smoothness"], "smoothness"),
]
SPACES_WITHOUT_OPTIMUM = ("se2", "dubins", "reeds_shepp")


def column(database, candidates):
    """The first of \\p candidates that the runs table has; None when none."""
    for c in candidates:
        if c in database.run_columns:
            return c
    return None


def optimum(exp):
    """The experiment's exact optimum (None when not recorded)."""
    return dbmod.to_float(dbmod.experiment_value(exp, "exact_optimum", "optimum", "optimum_length"))


def space(exp):
    """The experiment's state space when it is an SE(2)-based one (docs/spaces.md), else None."""
    value = dbmod.experiment_value(exp, "space")
    return value if value in SPACES_WITHOUT_OPTIMUM else None


def run_length(database, run):
    """The run's path length (path_length, else OMPL's solution_length); None without one."""
    col = column(database, ["path_length", "solution_length"])
    return dbmod.run_value(run, col) if col else None


def valid_exact_lengths(database, exp, planner=None):
    """(length, run) of the exact runs whose path passed the independent check (collision_free not 0)."""
    out = []
    for p in [planner] if planner else database.planners_of(exp.id):
        for r in database.runs_of(exp.id, p):
            if r.outcome != "exact" or dbmod.run_value(r, "collision_free") == 0:
                continue
            length = run_length(database, r)
            if length is not None:
                out.append((length, r))
    return out


def best_found(database, exp):
    """SE(2)-based experiments have no exact optimum: their gaps are measured to the best cost any planner
    found in the campaign on that problem (exact, collision-free runs). None for every other experiment."""
    if not space(exp) or optimum(exp):
        return None
    lengths = [l for l, _ in valid_exact_lengths(database, exp)]
    return min(lengths) if lengths else None


def best_found_gaps(database, exp, planner, chosen=None):
    """Gaps in % to best_found of the planner's valid exact runs (of \\p chosen runs when given)."""
    best = best_found(database, exp)
    if not best:
        return []
    ids = None if chosen is None else {r.id for r in chosen}
    return [100.0 * (l - best) / best for l, r in valid_exact_lengths(database, exp, planner) if ids is None or r.id in ids]


def table_rows(database, exp):
    """Per planner of one experiment: runs, outcome counts, length min/mean/std/median, time of the best run,
    mean time, median gap, median time to within 1% of the optimum (quality.summary: every improvement, censored
    runs at +inf, with its CI). Lengths only over exact runs."""
    opt = optimum(exp)
    gap_col = column(database, ["optimality_gap"])
    rows = []
    for planner in database.planners_of(exp.id):
        runs = database.runs_of(exp.id, planner)
        exact = [r for r in runs if r.outcome == "exact"]
        lengths = [(run_length(database, r), r) for r in exact]
        lengths = [(l, r) for l, r in lengths if l is not None]
        times = [dbmod.run_value(r, "time") for r in runs]
        best = min(lengths, key=lambda lr: lr[0]) if lengths else None
        gaps = [dbmod.run_value(r, gap_col) for r in exact] if gap_col else []
        if not gap_col and opt:
            gaps = [100.0 * (l - opt) / opt for l, _ in lengths]
        if best_found(database, exp):
            gaps = best_found_gaps(database, exp, planner)
        rows.append(
            {
                "planner": planner,
                "runs": len(runs),
                "counts": {o: sum(1 for r in runs if r.outcome == o) for o in dbmod.OUTCOMES},
                "min": best[0] if best else None,
                "mean": stats.mean([l for l, _ in lengths]),
                "std": stats.std([l for l, _ in lengths]),
                "median": stats.median([l for l, _ in lengths]),
                "best_time": dbmod.run_value(best[1], "time") if best else None,
                "mean_time": stats.mean(times),
                "median_gap": stats.median(gaps),
                "t1": quality.summary(database, runs, opt, 0.01),
            }
        )
    return rows


def load_paths(database_path):
    """Saved solution paths, runid -> [(x, y), ...], from the database's 'paths' table (runid, points as
    "x y;x y;...") when present; in SE(2)-based worlds [(x, y, yaw), ...] ("x y yaw;...")."""
    conn = dbmod.connect_readonly(database_path)
    try:
        cur = conn.cursor()
        cur.execute("SELECT name FROM sqlite_master WHERE type='table' AND name='paths'")
        if not cur.fetchone():
            return {}
        cur.execute("SELECT runid, points FROM paths")
        out = {}
        for runid, text in cur.fetchall():
            pts = [tuple(float(v) for v in item.split()) for item in (text or "").split(";") if item.strip()]
            if pts:
                out[runid] = pts
        return out
    finally:
        conn.close()


def load_summary(database, exps):
    """What the campaign recorded about the machine's load over experiments \\p exps: the share of a core the
    planners had while they planned (sum of the runs' cpu_time over the sum of their wall time; OMPL's
    'time'), the 1-minute load averages at the experiments' ends (experiment column load_average) and the
    cores available (cores_available). A dict with share, load_min, load_max, cores (each None when not
    recorded) and runs (runs with both times)."""
    cpu = wall = 0.0
    runs = 0
    ids = {e.id for e in exps}
    if "cpu_time" in database.run_columns:
        for r in database.runs:
            c, w = dbmod.run_value(r, "cpu_time"), dbmod.run_value(r, "time")
            if r.experiment in ids and c is not None and w is not None and w > 0:
                cpu, wall, runs = cpu + c, wall + w, runs + 1
    loads = [dbmod.to_float(dbmod.experiment_value(e, "load_average")) for e in exps]
    loads = [v for v in loads if v is not None]
    cores = [dbmod.to_float(dbmod.experiment_value(e, "cores_available")) for e in exps]
    cores = sorted({int(v) for v in cores if v is not None})
    return {"share": cpu / wall if wall > 0 else None, "runs": runs, "load_min": min(loads) if loads else None,
            "load_max": max(loads) if loads else None, "cores": cores or None}


class ReportData:
    """One database read once, with what the sections need. Attributes: path, database (db.Database),
    paths (runid -> points), world_dir, planning and moving (the planning and simulation experiments),
    campaign_planners (every planner of the planning experiments, sorted)."""

    def __init__(self, database_path, world_dir=None):
        self.path = database_path
        self.database = dbmod.load(database_path)
        self.paths = load_paths(database_path)
        self.world_dir = world_dir
        self.planning = [e for e in self.database.experiments if not simulations.is_simulation(e)]
        self.moving = [e for e in self.database.experiments if simulations.is_simulation(e)]
        self.campaign_planners = sorted({p for e in self.planning for p in self.database.planners_of(e.id)})
        self._rows, self._best = {}, {}

    def optimum(self, exp):
        return optimum(exp)

    def best_found(self, exp):
        """best_found(), computed once per experiment."""
        if exp.id not in self._best:
            self._best[exp.id] = best_found(self.database, exp)
        return self._best[exp.id]

    def length(self, run):
        return run_length(self.database, run)

    def table_rows(self, exp):
        """table_rows() of a planning experiment, computed once."""
        if exp.id not in self._rows:
            self._rows[exp.id] = table_rows(self.database, exp)
        return self._rows[exp.id]

    def world_file(self, exp):
        """The experiment's world file (relative names resolved against world_dir); None when not recorded."""
        world_file = dbmod.experiment_value(exp, "world_file")
        if world_file and self.world_dir and not os.path.isabs(str(world_file)):
            world_file = os.path.join(self.world_dir, str(world_file))
        return world_file
