# SPDX-License-Identifier: BSD-3-Clause
"""Report section: the simulation experiments ("Moving worlds", simulations.py): the [MAPF] traversal-time
reduction beside the paper's figures, then per scenario box plots of makespan and flowtime and a table of
outcomes per controller."""

import html

from . import db as dbmod
from . import simulations
from .page import box_figure, fmt, fmt_ci, fmt_median, slug, table


def box_plots(database, exp, outdir, name):
    """Makespan and flowtime per controller over the finished runs; unfinished runs counted in the labels."""
    planners = database.planners_of(exp.id)
    if not planners:
        return None
    panels = []
    for column, label in (("makespan", "makespan [s]"), ("flowtime", "flowtime [s]")):
        data, names = [], []
        for p in planners:
            runs = database.runs_of(exp.id, p)
            vals = [dbmod.run_value(r, column) for r in runs if simulations.finished(r)]
            data.append([v for v in vals if v is not None])
            unfinished = len(runs) - len(data[-1])
            names.append(simulations.controller_name(p) + ("\n%d of %d not finished" % (unfinished, len(runs)) if unfinished else ""))
        panels.append((data, names, label + " (finished runs)", None))
    return box_figure(panels, exp.name, outdir, "sim_box_%s.png" % name, 4.2, 30)


def render(data, ctx):
    """HTML of the simulation experiments: the [MAPF] traversal-time reduction beside the paper's figures,
    then per scenario box plots of makespan and flowtime and a table of outcomes per controller."""
    database, exps = data.database, data.moving
    if not exps:
        return []
    out = ["<h2>Moving worlds (simulations)</h2>"]
    out.append(
        "<p>One experiment per scenario, one row per controller and run (<code>mhplan bench</code> simulation "
        "entries). A run is <i>finished</i> when every robot reached its goals; the medians below count an "
        "unfinished or crashed run as +&infin; (its times are only lower bounds), so a median shows "
        "'unfinished' when more than half of the runs did not finish. Intervals are distribution-free 95 % "
        "confidence intervals of the median (order statistics; their exact coverage is given, lower for few "
        "runs).</p>"
    )
    reductions = [(e, simulations.reduction_rows(database, e)) for e in exps]
    reductions = [(e, rows) for e, rows in reductions if rows]
    if reductions:
        out.append("<h3>[MAPF] traversal-time reduction: adaptive APF (aapf) against the classic distributed APF (dapf)</h3>")
        out.append(
            "<p>Reduction = 100 (1 &minus; aapf / dapf). <i>Paired</i>: run k of both controllers starts from the "
            "same perturbed configuration (same <code>start_seed</code>); the per-pair reductions' median and "
            "interval. A pair where only dapf did not finish counts +100 %, only aapf &minus;&infin;; pairs where "
            "neither finished are left out. The paper (seed 002) reports 35 % (2 robots) and 50 % (15 robots) "
            "less traversal time; its map and tasks are not recoverable, ours are documented in the scenario "
            "files.</p>"
        )
        rows = []
        for exp, rr in reductions:
            robots = exp.params.get("robot_count")
            for r in rr:
                extra = " (%d pairs: neither finished)" % r["pairs_both_unfinished"] if r["pairs_both_unfinished"] else ""
                rows.append(
                    (
                        html.escape(str(exp.params.get("scenario") or exp.name)),
                        robots if robots is not None else "&ndash;",
                        r["metric"],
                        fmt_median(r["median_dapf"]),
                        fmt_median(r["median_aapf"]),
                        fmt(r["reduction_of_medians"], 1, " %"),
                        fmt_ci(r["paired"]) + extra,
                        "%g %%" % r["paper"] if r["paper"] is not None else "&ndash;",
                        html.escape(r["verdict"]),
                    )
                )
            starts = simulations.distinct_starts(database, exp)
            if starts == 1:
                ctx.notes.append(
                    "%s: every run starts from the same configuration (no start_jitter): deterministic controllers "
                    "repeat one run, so the interval says nothing about variability." % exp.name
                )
        out.append(table(["scenario", "robots", "metric", "median dapf [s]", "median aapf [s]", "reduction of medians", "paired reduction: median [95% CI]", "paper", "in plain words"], rows))

    for exp in exps:
        out.append("<h3>%s</h3>" % html.escape(exp.name))
        desc = []
        for key in ("robot_count", "moving_obstacle_count", "obstacle_count"):
            if exp.params.get(key) is not None:
                desc.append("%s %s" % (key.replace("_", " "), exp.params.get(key)))
        jitter = dbmod.to_float(exp.params.get("start_jitter"))
        if jitter:
            desc.append("starts perturbed by up to %g m" % jitter)
        refs = simulations.references(exp)
        if refs:
            desc.append("paper's figures: " + ", ".join("%s = %g" % (k, v) for k, v in sorted(refs.items())))
        if desc:
            out.append("<p>%s</p>" % html.escape("; ".join(desc)))
        if "paper_time_s" in refs:
            out.append(
                "<p class='note'>The paper's time (%g s) may be a computing time rather than the robot's travel time; "
                "compare with the median traversal time column with that in mind.</p>" % refs["paper_time_s"]
            )
        box = box_plots(database, exp, ctx.outdir, slug(exp.name))
        if box:
            out.append("<img src='%s' alt='makespan and flowtime'>" % box)
        rows = simulations.controller_rows(database, exp)
        if not rows:
            ctx.notes.append("%s: no runs." % exp.name)
            continue
        out.append(
            table(
                ["controller", "runs", "all robots done", "crashed", "collisions (runs with)", "static / moving / robot", "robots stuck (runs with)", "median makespan [s]", "median flowtime [s]", "median traversal [s]", "min robot distance [m]", "min obstacle clearance [m]", "median wall time [s]", "robot-steps/s (median)"],
                [
                    (
                        html.escape(r["controller"]),
                        r["runs"],
                        "%d (%.0f%%)" % (r["done"], r["success"] if r["success"] is not None else 0.0),
                        r["crashed"],
                        "%d (%d)" % (r["collisions"], r["runs_with_collisions"]),
                        "%d / %d / %d" % (r["static_collisions"], r["moving_collisions"], r["robot_collisions"]),
                        "%d (%d)" % (r["stuck"], r["runs_with_stuck"]),
                        fmt_median(r["median_makespan"]),
                        fmt_median(r["median_flowtime"]),
                        fmt_median(r["median_traversal"]),
                        fmt(r["min_robot_distance"], 3),
                        fmt(r["min_obstacle_clearance"], 3),
                        fmt(r["median_time"], 4),
                        fmt(r["median_steps_per_second"], 0),
                    )
                    for r in rows
                ],
            )
        )
    return out

