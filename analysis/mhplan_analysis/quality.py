"""Time to quality: per run, the time of the first solution and the first time the solution was within 10 %,
1 % and 0.1 % of the experiment's exact optimum, read from mhplan's improvements table (every improvement
of the solution, timed when it happened; benchmarks/Improvements.h). Databases without that table fall back
to the progress samples ('best cost', a sampling interval late at most) and the final exact path.

A run that never gets there is censored: its time counts as +infinity (worse than any run that got there),
never dropped. Medians are sample medians of all runs with the censored ones at +infinity, so the median is
"not reached" (+infinity) when more than half of the runs are censored (for an even count: half or more,
since the median averages the two middle runs). Confidence intervals are distribution-free: order statistics
chosen from the binomial(n, 1/2) quantiles, with their exact coverage (simulations.median_with_ci)."""

import math

from . import db as dbmod
from .simulations import median_with_ci

# (key, tolerance, label): None is the first solution.
LEVELS = [("first", None, "first solution"), ("t10", 0.10, "within 10 %"), ("t1", 0.01, "within 1 %"),
          ("t01", 0.001, "within 0.1 %")]


def _length(database, run):
    for col in ("path_length", "solution_length"):
        if col in database.run_columns:
            return dbmod.run_value(run, col)
    return None


def gap(database, run, optimum):
    """The run's optimality gap in percent (column optimality_gap, else from its path length and the optimum);
    None when the run has no exact solution or nothing can tell."""
    if run.outcome != "exact":
        return None
    g = dbmod.run_value(run, "optimality_gap")
    if g is None and optimum:
        length = _length(database, run)
        g = None if length is None else 100.0 * (length - optimum) / optimum
    return g


def time_to(database, run, optimum, tol):
    """Seconds from the start of solve() until the run's solution first cost at most optimum * (1 + tol)
    (tol None: any exact solution); None when it never did (censored) or nothing can tell."""
    if tol is not None and not optimum:
        return None
    target = math.inf if tol is None else optimum * (1.0 + tol)
    rows = database.improvements.get(run.id) if database.improvements is not None else None
    if database.improvements is not None:
        # The table is authoritative: no rows means no exact solution was ever reported.
        for t, c, _ in rows or []:
            if t is not None and c is not None and c <= target:
                return t
        return None
    samples = database.progress.get(run.id)
    if samples and "best_cost" in database.progress_columns:
        for t, values in samples:
            c = dbmod.to_float(values.get("best_cost"))
            if c is not None and t is not None and c <= target:
                return t
    if run.outcome == "exact":
        length = _length(database, run)
        if length is not None and length <= target:
            return dbmod.run_value(run, "time")
    return None


def censored_times(database, runs, optimum, tol):
    """time_to for every run, +inf where it never got there."""
    out = []
    for r in runs:
        t = time_to(database, r, optimum, tol)
        out.append(math.inf if t is None else t)
    return out


def summary(database, runs, optimum, tol, confidence=0.95):
    """Median time (censored), its CI and coverage, n and how many runs got there; None without runs or
    (for a tolerance) without an optimum."""
    if not runs or (tol is not None and not optimum):
        return None
    values = censored_times(database, runs, optimum, tol)
    out = median_with_ci(values, confidence)
    out["reached"] = sum(1 for v in values if math.isfinite(v))
    return out


def median_time(database, runs, optimum, tol):
    """The censored median alone (+inf: not reached; None: nothing to tell)."""
    s = summary(database, runs, optimum, tol)
    return None if s is None else s["median"]


def fmt(s, digits=3):
    """'median [lo, hi] (k/n)' with 'not reached' and an open upper bound for censored values."""
    if s is None:
        return "&ndash;"

    def f(v):
        return "&infin;" if math.isinf(v) else ("%." + str(digits) + "f") % v

    med = "not reached" if math.isinf(s["median"]) else f(s["median"])
    return "%s [%s, %s] (%d/%d)" % (med, f(s["lo"]), f(s["hi"]), s["reached"], s["n"])


def rows(database, exp, optimum):
    """Per planner of one experiment: summary() for every level of LEVELS."""
    out = []
    for planner in database.planners_of(exp.id):
        runs = database.runs_of(exp.id, planner)
        out.append({"planner": planner, **{key: summary(database, runs, optimum, tol) for key, tol, _ in LEVELS}})
    return out
