# SPDX-License-Identifier: BSD-3-Clause
"""The "Moving worlds" part of the report: simulation experiments of mhplan bench (one experiment per
scenario, one "planner" sim:NAME per controller, one row per run with makespan, flowtime, collisions, ...).

Runs that did not bring every robot to its goal (status other than exact, or crashed) have no finished
makespan or traversal time: their flowtime, makespan and traversal times are lower bounds. The medians here
treat them as +infinity (censored: worse than any finished run), so a controller whose median run did not
finish has no finite median; the box plots show finished runs only and count the others.
"""

import math

import numpy as np

from . import db as dbmod
from . import stats

SIM_PREFIX = "sim:"
# The controller pair of [MAPF]: the classic distributed APF (baseline) and the adaptive APF.
BASELINE, ADAPTIVE = "dapf", "aapf"
# (run column, label) of the reduction table.
REDUCTION_METRICS = [("mean_traversal_time", "mean traversal time"), ("makespan", "makespan")]


def is_simulation(exp):
    """True for an experiment written from a simulation entry of a campaign."""
    kind = exp.params.get("kind")
    if kind is not None:
        return str(kind) == "simulation"
    return exp.params.get("scenario") is not None


def controller_name(planner):
    return planner[len(SIM_PREFIX):] if planner.startswith(SIM_PREFIX) else planner


def references(exp):
    """The paper's figures recorded with the scenario: {key: value} from the reference_* columns."""
    out = {}
    for k, v in exp.params.items():
        if k.startswith("reference_"):
            f = dbmod.to_float(v)
            if f is not None:
                out[k[len("reference_"):]] = f
    return out


def _int(run, column):
    v = dbmod.run_value(run, column)
    return int(round(v)) if v is not None else 0


def finished(run):
    """Every robot reached its goals (and the run did not crash)."""
    return run.outcome == "exact"


def censored_values(runs, column):
    """The column's value for finished runs, +inf for the others (see the module's note)."""
    out = []
    for r in runs:
        v = dbmod.run_value(r, column) if finished(r) else None
        out.append(v if v is not None else math.inf)
    return out


def censored_median(values):
    if not values:
        return None
    return float(np.median(np.array(sorted(values), dtype=float)))


def controller_rows(database, exp):
    """Per controller of a simulation experiment: outcomes, collisions, stuck robots, medians."""
    rows = []
    for planner in database.planners_of(exp.id):
        runs = database.runs_of(exp.id, planner)
        n = len(runs)
        done = sum(1 for r in runs if finished(r))
        crashed = sum(1 for r in runs if r.outcome == "crashed")
        valid = [r for r in runs if r.outcome != "crashed"]
        min_dist = [dbmod.run_value(r, "min_robot_distance") for r in valid]
        min_clear = [dbmod.run_value(r, "min_obstacle_clearance") for r in valid]
        rows.append(
            {
                "controller": controller_name(planner),
                "planner": planner,
                "runs": n,
                "done": done,
                "crashed": crashed,
                "success": 100.0 * done / n if n else None,
                "collisions": sum(_int(r, "collisions") for r in valid),
                "runs_with_collisions": sum(1 for r in valid if _int(r, "collisions") > 0),
                "static_collisions": sum(_int(r, "static_collisions") for r in valid),
                "moving_collisions": sum(_int(r, "moving_collisions") for r in valid),
                "robot_collisions": sum(_int(r, "robot_collisions") for r in valid),
                "stuck": sum(_int(r, "robots_stuck") for r in valid),
                "runs_with_stuck": sum(1 for r in valid if _int(r, "robots_stuck") > 0),
                "median_makespan": censored_median(censored_values(runs, "makespan")),
                "median_flowtime": censored_median(censored_values(runs, "flowtime")),
                "median_traversal": censored_median(censored_values(runs, "mean_traversal_time")),
                "min_robot_distance": min([v for v in min_dist if v is not None], default=None),
                "min_obstacle_clearance": min([v for v in min_clear if v is not None], default=None),
                "median_time": stats.median([dbmod.run_value(r, "time") for r in valid]),
                "median_steps_per_second": stats.median([dbmod.run_value(r, "robot_steps_per_second") for r in valid]),
            }
        )
    return rows


def binomial_coverage(n, lo, hi):
    """Exact coverage of the interval [x_(lo), x_(hi)] (0-based order statistics) for the median of n
    samples from a continuous distribution: P(lo + 1 <= K <= hi), K ~ Binomial(n, 1/2)."""
    return sum(math.comb(n, i) for i in range(lo + 1, hi + 1)) / 2.0 ** n


def paired_reductions(base_runs, new_runs, column):
    """Per run index present in both: 100 (1 - new / base), with unfinished runs as +inf (a finished new
    run against an unfinished base run counts +100 %, the reverse -inf; both unfinished: left out)."""
    base = {_int(r, "run_index"): r for r in base_runs}
    new = {_int(r, "run_index"): r for r in new_runs}
    out, both_unfinished = [], 0
    for k in sorted(set(base) & set(new)):
        b = censored_values([base[k]], column)[0]
        a = censored_values([new[k]], column)[0]
        if math.isinf(b) and math.isinf(a):
            both_unfinished += 1
        elif math.isinf(b):
            out.append(100.0)
        elif math.isinf(a):
            out.append(-math.inf)
        elif b > 0:
            out.append(100.0 * (1.0 - a / b))
    return out, both_unfinished


def median_with_ci(values, confidence=0.95):
    """Median, distribution-free CI (order statistics) and its exact coverage; None when empty."""
    if not values:
        return None
    s = sorted(values)
    n = len(s)
    lo, hi = stats.median_ci_indices(n, confidence)
    return {"median": float(np.median(np.array(s, dtype=float))), "lo": s[lo], "hi": s[hi], "n": n,
            "coverage": binomial_coverage(n, lo, hi)}


def verdict(measured, paper):
    """Plain words: how our reduction (median, CI) compares with the paper's figure."""
    if measured is None:
        return "no comparable runs (neither controller finished a pair of runs)"
    med, lo, hi = measured["median"], measured["lo"], measured["hi"]
    if math.isinf(med) or math.isnan(med):
        return "the median pair has an unfinished adaptive run: an increase"
    if med < 0:
        text = "we measure an increase of %.1f %% (the adaptive APF is slower)" % -med
    elif med == 0:
        text = "we measure no change"
    else:
        text = "we measure a reduction of %.1f %%" % med
    if paper is None:
        return text
    if lo <= paper <= hi:
        return text + "; the paper's %g %% lies in our interval" % paper
    if hi < paper:
        return text + ", less than the paper's %g %%" % paper
    return text + ", more than the paper's %g %%" % paper


def is_mapf(exp):
    """A [MAPF] scenario: it carries the paper's traversal-time figure, or its name says so."""
    scenario = str(exp.params.get("scenario") or exp.name)
    return "traversal_time_reduction_percent" in references(exp) or scenario.startswith("mapf")


def reduction_rows(database, exp):
    """For a [MAPF] scenario with both dapf and aapf: per metric, the medians, the reduction of the medians
    and the paired per-run reduction (median, CI) beside the paper's traversal-time figure."""
    planners = {controller_name(p): p for p in database.planners_of(exp.id)}
    if not is_mapf(exp) or BASELINE not in planners or ADAPTIVE not in planners:
        return []
    base_runs = database.runs_of(exp.id, planners[BASELINE])
    new_runs = database.runs_of(exp.id, planners[ADAPTIVE])
    paper = references(exp).get("traversal_time_reduction_percent")
    rows = []
    for column, label in REDUCTION_METRICS:
        mb = censored_median(censored_values(base_runs, column))
        ma = censored_median(censored_values(new_runs, column))
        if mb is not None and ma is not None and math.isfinite(mb) and math.isfinite(ma) and mb > 0:
            of_medians = 100.0 * (1.0 - ma / mb)
        else:
            of_medians = None
        reductions, both = paired_reductions(base_runs, new_runs, column)
        measured = median_with_ci(reductions)
        rows.append(
            {
                "metric": label,
                "column": column,
                "median_dapf": mb,
                "median_aapf": ma,
                "reduction_of_medians": of_medians,
                "paired": measured,
                "pairs_both_unfinished": both,
                # The paper reports traversal time; makespan is shown for context without a paper figure.
                "paper": paper if column == "mean_traversal_time" else None,
                "verdict": verdict(measured, paper if column == "mean_traversal_time" else None),
            }
        )
    return rows


def distinct_starts(database, exp):
    """Number of distinct start perturbations (start_seed) among the runs, or None when not recorded."""
    if "start_seed" not in database.run_columns:
        return None
    jitter = dbmod.to_float(exp.params.get("start_jitter")) or 0.0
    heading = dbmod.to_float(exp.params.get("heading_jitter")) or 0.0
    if jitter == 0.0 and heading == 0.0:
        return 1
    return len({r.values.get("start_seed") for r in database.runs if r.experiment == exp.id})
