# SPDX-License-Identifier: BSD-3-Clause
"""Reading an OMPL benchmark database (as written by ompl_benchmark_statistics) into plain Python data.

The schema is OMPL's: experiments, plannerConfigs, runs (one column per run property, spaces turned into
underscores), progress (runid, time, one column per progress property) and enums. mhplan's campaigns add
experiment parameters (world, optimum, ...) and run properties (optimality gap, clearance, ...); this module
reads whatever is there and the rest of the report says plainly what is missing.
"""

import math
import os
import sqlite3
from dataclasses import dataclass, field

# OMPL 1.5's ompl::base::PlannerStatus::StatusType, used when the database has no enums table entries.
DEFAULT_STATUS = {
    0: "Unknown status",
    1: "Invalid start",
    2: "Invalid goal",
    3: "Unrecognized goal type",
    4: "Timeout",
    5: "Approximate solution",
    6: "Exact solution",
    7: "Crash",
    8: "Abort",
}

# Outcome classes drawn in the success bars.
OUTCOMES = ("exact", "approximate", "failed", "crashed")


def classify_status(description):
    """Map a status description to one of OUTCOMES."""
    d = (description or "").lower()
    if "exact" in d:
        return "exact"
    if "approximate" in d:
        return "approximate"
    if "crash" in d:
        return "crashed"
    return "failed"


@dataclass
class Experiment:
    id: int
    name: str
    params: dict  # every column of the experiments table


@dataclass
class Run:
    id: int
    experiment: int
    planner: str
    values: dict  # every column of the runs table
    outcome: str


@dataclass
class Database:
    path: str
    experiments: list
    planners: list  # planner names in first-seen order
    runs: list
    run_columns: list
    progress_columns: list
    progress: dict = field(default_factory=dict)  # runid -> list of (time, {column: value})
    # runid -> [(time, cost, source), ...] by time: every improvement of the solution (mhplan's table
    # improvements; None when the database has no such table, e.g. older campaigns).
    improvements: dict = None
    notes: list = field(default_factory=list)  # plain-language gaps found while reading

    def _index(self):
        """experiment id -> planner -> runs (in id order, planners in first-seen order), built once from the
        runs read (again only when the list of runs was replaced or grew)."""
        key = (id(self.runs), len(self.runs))
        if getattr(self, "_index_key", None) != key:
            index, every = {}, {}
            for r in self.runs:
                index.setdefault(r.experiment, {}).setdefault(r.planner, []).append(r)
                every.setdefault(r.experiment, []).append(r)
            self._by_experiment, self._all_of, self._index_key = index, every, key
        return self._by_experiment

    def runs_of(self, experiment_id, planner=None):
        by_planner = self._index().get(experiment_id, {})
        if planner is not None:
            return list(by_planner.get(planner, []))
        return list(self._all_of.get(experiment_id, []))

    def planners_of(self, experiment_id):
        return list(self._index().get(experiment_id, {}))


def _columns(cur, table):
    cur.execute("PRAGMA table_info(%s)" % table)
    return [row[1] for row in cur.fetchall()]


def _tables(cur):
    cur.execute("SELECT name FROM sqlite_master WHERE type='table'")
    return {row[0] for row in cur.fetchall()}


def to_float(value):
    """A finite float, or None."""
    if value is None:
        return None
    try:
        f = float(value)
    except (TypeError, ValueError):
        return None
    return f if math.isfinite(f) else None


def connect_readonly(path):
    """Open the SQLite file \\e path read-only, whatever characters its name holds ('#', '?', '%', blanks:
    the name is percent-encoded into SQLite's file: URI, so it never names another file)."""
    from urllib.parse import quote

    return sqlite3.connect("file:%s?mode=ro" % quote(os.path.abspath(path)), uri=True)


def load(path):
    """Read the database at \\p path. Raises ValueError when it is not an OMPL benchmark database."""
    conn = connect_readonly(path)
    try:
        cur = conn.cursor()
        tables = _tables(cur)
        missing = {"experiments", "plannerConfigs", "runs"} - tables
        if missing:
            raise ValueError("%s is not an OMPL benchmark database (missing tables: %s)" % (path, ", ".join(sorted(missing))))
        notes = []
        # Columns the reader relies on (a damaged or hostile database is refused, never a traceback).
        required = {"experiments": ("id", "name"), "plannerConfigs": ("id", "name"),
                    "runs": ("id", "experimentid", "plannerid")}
        if "progress" in tables:
            required["progress"] = ("runid", "time")
        for table, needed in required.items():
            absent = [c for c in needed if c not in _columns(cur, table)]
            if absent:
                raise ValueError("%s is not an OMPL benchmark database (table %s has no column %s)"
                                 % (path, table, ", ".join(absent)))
        exp_cols = _columns(cur, "experiments")
        cur.execute("SELECT * FROM experiments ORDER BY id")
        experiments = [Experiment(row[0], _text(row[exp_cols.index("name")]), dict(zip(exp_cols, row))) for row in cur.fetchall()]

        status_names = dict(DEFAULT_STATUS)
        if "enums" in tables:
            cur.execute("SELECT value, description FROM enums WHERE name = 'status'")
            rows = cur.fetchall()
            if rows:
                status_names = {_int(v): d for v, d in rows}

        cur.execute("SELECT id, name FROM plannerConfigs")
        planner_names = {pid: name for pid, name in cur.fetchall()}
        run_cols = _columns(cur, "runs")
        cur.execute("SELECT * FROM runs ORDER BY id")
        runs, planners = [], []
        for row in cur.fetchall():
            values = dict(zip(run_cols, row))
            name = _text(planner_names.get(values["plannerid"], "planner %s" % values["plannerid"]))
            if name.startswith("geometric_"):
                name = name[len("geometric_"):]
            if name not in planners:
                planners.append(name)
            if "status" in values and values["status"] is not None:
                outcome = classify_status(str(status_names.get(_int(values["status"]), "")))
            else:
                solved = values.get("solved")
                outcome = "exact" if solved in (1, "1", True) else "failed"
            runs.append(Run(values["id"], values["experimentid"], name, values, outcome))
        if "status" not in run_cols:
            notes.append("The runs table has no status column: outcomes are inferred from 'solved'.")

        progress, progress_cols = {}, []
        if "progress" in tables:
            progress_cols = _columns(cur, "progress")
            cur.execute("SELECT * FROM progress ORDER BY runid, time")
            for row in cur.fetchall():
                values = dict(zip(progress_cols, row))
                progress.setdefault(values["runid"], []).append((to_float(values["time"]), values))
        else:
            notes.append("The database has no progress table: no convergence plots.")
        improvements = None
        if "improvements" in tables:
            improvements = {}
            cur.execute("SELECT runid, time, cost, source FROM improvements ORDER BY runid, time, cost DESC")
            for runid, t, c, source in cur.fetchall():
                improvements.setdefault(runid, []).append((to_float(t), to_float(c), source))
        else:
            notes.append("The database has no improvements table: times to quality come from the progress samples "
                         "(a sampling interval late at most).")
        return Database(path, experiments, planners, runs, run_cols, progress_cols, progress, improvements, notes)
    finally:
        conn.close()


def _text(value):
    """A name as text, whatever SQLite held (a blob, a number, NULL)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return "" if value is None else str(value)


def _int(value):
    """An enum value as stored (an integer, or text or a float holding one); None when it is none."""
    try:
        f = float(value)
    except (TypeError, ValueError):
        return None
    return int(f) if math.isfinite(f) and f == int(f) else None


def run_value(run, *names):
    """The first finite float among the run's columns \\p names (None when none is present)."""
    for n in names:
        if n in run.values:
            v = to_float(run.values[n])
            if v is not None:
                return v
    return None


def experiment_value(experiment, *names):
    for n in names:
        if n in experiment.params:
            return experiment.params[n]
    return None
