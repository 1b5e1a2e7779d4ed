# SPDX-License-Identifier: BSD-3-Clause
"""The report's planning figures: per experiment the box plots of the run attributes, the convergence of the
best cost and the paths drawn in the world; over the campaign the success bars. Each draws with the shared
helpers of page.py and returns the file name the page links (docs/report.md)."""

import math
import os

import numpy as np

from . import data as datamod
from . import db as dbmod
from . import meshes, stats, worlds
from .page import box_figure, plt, save, slug

OUTCOME_COLORS = {"exact": "#2ca02c", "approximate": "#ff7f0e", "failed": "#9e9e9e", "crashed": "#d62728"}


def box_plots(database, exp, outdir):
    """One figure per experiment: a box plot per available attribute (Planner Arena style); returns (file
    name, labels of the attributes without values)."""
    present = [(k, datamod.column(database, c), label) for k, c, label in datamod.ATTRIBUTES]
    present = [(k, c, label) for k, c, label in present if c]
    planners = database.planners_of(exp.id)
    if not present or not planners:
        return None, []
    best = datamod.best_found(database, exp)
    opt = datamod.optimum(exp)
    panels, missing = [], []
    for key, col, label in present:
        data = []
        for p in planners:
            runs = database.runs_of(exp.id, p)
            # Quality attributes over exact runs only; time over all runs.
            chosen = runs if key in ("time", "cpu_time") else [r for r in runs if r.outcome == "exact"]
            vals = [dbmod.run_value(r, col) for r in chosen]
            if key == "gap" and best:
                vals = datamod.best_found_gaps(database, exp, p, chosen)
            data.append([v for v in vals if v is not None])
        if key == "gap" and best:
            label = "gap to best found [%] (no exact optimum)"
        if not any(data):
            missing.append(label)
        panels.append((data, planners, label, _decorate(key, opt, best)))

    def same_time_scale(axes):
        # Wall and CPU time side by side on one scale: a CPU box below its wall box is time the planner
        # waited for a core.
        timed = [ax for ax, (key, _, _) in zip(axes, present) if key in ("time", "cpu_time")]
        if len(timed) == 2:
            lo = min(a.get_ylim()[0] for a in timed)
            hi = max(a.get_ylim()[1] for a in timed)
            for a in timed:
                a.set_ylim(lo, hi)

    name = box_figure(panels, exp.name, outdir, "box_%s.png" % slug(exp.name), 3.2, 60, same_time_scale)
    return name, missing


def _decorate(key, opt, best):
    """The scale and reference line of one attribute's panel."""

    def decorate(ax, data):
        attribute_scale(ax, key, [v for d in data for v in d])
        if key == "length" and opt:
            ax.axhline(opt, color="#1f77b4", linestyle="--", linewidth=1, label="exact optimum")
            ax.legend(fontsize=7, loc="upper right")
        elif key == "length" and best:
            ax.axhline(best, color="#1f77b4", linestyle=":", linewidth=1, label="best found")
            ax.legend(fontsize=7, loc="upper right")

    return decorate


def attribute_scale(ax, key, values):
    """The value axis of one box plot: time on a log scale; smoothness (never negative, heavy-tailed: one
    sharp turn dominates) on a symmetric log scale from 0, so no negative tick appears even when every path
    is straight (all values 0)."""
    if key in ("time", "cpu_time"):
        ax.set_yscale("log")
    elif key == "smoothness":
        finite = [v for v in values if v is not None and math.isfinite(v)]
        top = max(finite) if finite else 0.0
        if top <= 1.0:
            ax.set_ylim(0.0, 1.05)  # linear: a symmetric log axis up to 1 would have no tick at all
        else:
            ax.set_yscale("symlog", linthresh=1.0)
            ax.set_ylim(0.0, top * 1.3)


def success_bars(database, outdir, exps=None):
    """Stacked bars per experiment and planner: exact, approximate, failed, crashed (share of runs)."""
    exps = database.experiments if exps is None else exps
    if not exps:
        return None
    fig, axes = plt.subplots(len(exps), 1, figsize=(10, 1.9 * len(exps) + 1.2), squeeze=False)
    for ax, exp in zip(axes[:, 0], exps):
        planners = database.planners_of(exp.id)
        left = np.zeros(len(planners))
        for outcome in dbmod.OUTCOMES:
            share = []
            for p in planners:
                runs = database.runs_of(exp.id, p)
                share.append(100.0 * sum(1 for r in runs if r.outcome == outcome) / max(len(runs), 1))
            ax.barh(range(len(planners)), share, left=left, color=OUTCOME_COLORS[outcome], label=outcome, height=0.7)
            left += np.array(share)
        ax.set_yticks(range(len(planners)))
        ax.set_yticklabels(planners, fontsize=7)
        ax.invert_yaxis()
        ax.set_xlim(0, 100)
        ax.set_title(exp.name, fontsize=9, loc="left")
    axes[-1, 0].set_xlabel("share of runs [%]")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="upper center", ncol=4, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / (1.9 * len(exps) + 1.2)))
    return save(fig, outdir, "success.png")


def convergence_samples(database, exp, planner):
    """(samples, source) of one planner's runs: runid -> [(time, cost), ...]. From mhplan's improvements table
    when the database has one (every improvement at the exact time it happened, benchmarks/Improvements.h),
    else from OMPL's progress samples ('best cost', a sampling interval late at most)."""
    runs = database.runs_of(exp.id, planner)
    if database.improvements is not None:
        return {r.id: [(t, c) for t, c, _ in database.improvements.get(r.id, [])] for r in runs}, "improvements"
    if "best_cost" not in database.progress_columns:
        return {}, None
    return {r.id: [(t, dbmod.to_float(v.get("best_cost"))) for t, v in database.progress.get(r.id, [])] for r in runs}, "progress"


def convergence_series(database, exp, planner, tmax):
    """The planner's best cost over time: (times, median, lo, hi, source), a step function that holds each
    value from its time to the next (draw with steps-post). The times are exactly the recorded improvements'
    times of all its runs (the median of step functions changes only there), plus tmax; a run without a
    solution yet counts as +inf (stats.median_band). None when no run recorded a cost."""
    samples, source = convergence_samples(database, exp, planner)
    finite = [(t, c) for s in samples.values() for t, c in s if t is not None and c is not None and math.isfinite(c)]
    if not finite:
        return None
    times = sorted({max(t, 1e-6) for t, _ in finite} | {max(tmax, max(t for t, _ in finite))})
    grid = np.array(times)
    runs = database.runs_of(exp.id, planner)
    matrix = np.array([stats.step_series([(max(t, 1e-6), c) for t, c in samples[r.id] if t is not None], grid) for r in runs])
    med, lo, hi = stats.median_band(matrix)
    if np.all(np.isnan(med)):
        return None
    return grid, med, lo, hi, source


def convergence_figure(database, exp, colors):
    """The convergence figure (a matplotlib figure; None when nothing was recorded): per planner the median
    best cost (95 % CI band) over a log time axis, from the recorded improvements. With a reference (the
    exact optimum, else the best cost found in the campaign) the y axis is the gap to it in % on a symmetric
    log scale, so lines that converge stay apart; the reference (gap 0) is a thin grey line drawn beneath
    every planner's line, and the planners' lines get thinner in drawing order, so a line on top of another
    leaves the one beneath visible as its outline."""
    tmax = max((dbmod.to_float(exp.params.get("timelimit")) or 1.0), 1e-3)
    series = {}
    for p in database.planners_of(exp.id):
        s = convergence_series(database, exp, p, tmax)
        if s is not None:
            series[p] = s
    if not series:
        return None
    opt = datamod.optimum(exp)
    best = None if opt else datamod.best_found(database, exp)
    ref = opt or best
    fig, ax = plt.subplots(figsize=(8, 5))
    n = len(series)
    lowest, highest = 0.0, 0.0
    for i, (p, (grid, med, lo, hi, _)) in enumerate(series.items()):
        if ref:
            med, lo, hi = (100.0 * (v - ref) / ref for v in (med, lo, hi))
            lowest = min(lowest, float(np.nanmin(med)))
            highest = max(highest, float(np.nanmax(med)))
        width = 3.2 - 2.0 * i / max(n - 1, 1)
        ax.plot(grid, med, color=colors[p], label=p, linewidth=width, drawstyle="steps-post", zorder=3 + i / n)
        ax.fill_between(grid, lo, np.where(np.isnan(hi), med, hi), color=colors[p], alpha=0.15, linewidth=0, step="post", zorder=2)
    if ref:
        label = ("exact optimum %.4f" % opt) if opt else ("best found %.4f (no exact optimum)" % best)
        ax.axhline(0.0, color="#555555", linestyle="--", linewidth=0.8, label=label, zorder=1, gid="reference")
        ax.set_yscale("symlog", linthresh=0.1)
        # Room above the highest median (a line along the frame would be hidden by it).
        ax.set_ylim(min(lowest * 1.2, 0.0) if lowest < 0 else 0.0, max(highest * 2.0, 1.0))
        ax.set_ylabel("gap to the %s [%%] (median, 95%% CI)" % ("exact optimum" if opt else "best found"))
    else:
        ax.set_ylabel("best cost (median, 95% CI)")
    ax.set_xscale("log")
    ax.set_xlim(min(float(s[0][0]) for s in series.values()), max(float(s[0][-1]) for s in series.values()))
    ax.set_xlabel("time [s] (every recorded improvement)" if any(s[4] == "improvements" for s in series.values())
                  else "time [s] (progress samples)")
    ax.set_title(exp.name)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=9, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
    fig.tight_layout()
    return fig


def convergence_plot(database, exp, outdir, colors):
    """convergence_figure saved as convergence_EXPERIMENT.png; its file name, None without data."""
    fig = convergence_figure(database, exp, colors)
    if fig is None:
        return None
    return save(fig, outdir, "convergence_%s.png" % slug(exp.name))


def experiment_query(exp, world):
    """Start and goal of the experiment's own query: its recorded points (query_points), else its query name
    in the world, else the world's only query; None when none of these tells (never another query's)."""
    q = worlds.parse_query_points(dbmod.experiment_value(exp, "query_points"))
    if q:
        return q
    name = dbmod.experiment_value(exp, "query")
    if name is not None and str(name) in world.queries:
        return world.queries[str(name)]
    if name is None and len(world.queries) == 1:
        return next(iter(world.queries.values()))
    return None


def experiment_yaws(exp, world):
    """(start yaw, goal yaw) of the experiment's query in an SE(2)-based world: from its recorded
    query_points, else from the world's query of that name; None when neither tells."""
    q = worlds.parse_query_poses(dbmod.experiment_value(exp, "query_points"))
    if q and len(q[0]) == 3:
        return q[0][2], q[1][2]
    name = dbmod.experiment_value(exp, "query")
    if name is not None and str(name) in world.query_yaws:
        return world.query_yaws[str(name)]
    if name is None and len(world.query_yaws) == 1:
        return next(iter(world.query_yaws.values()))
    return None


def _reach(world):
    return max(math.hypot(x, y) for x, y in world.robot_polygon)


def _footprint(ax, world, pose, color, gid, alpha=0.12):
    """The robot's polygon at pose (x, y, yaw), filled translucent with an outline, beneath the paths."""
    from matplotlib.patches import Polygon

    ax.add_patch(Polygon(worlds.place(world.robot_polygon, pose), closed=True, facecolor=color, alpha=alpha,
                         edgecolor=color, linewidth=0.8, zorder=3, gid=gid))


def path_figure(database, exp, paths, world_file, outdir, colors):
    """The world with each planner's best and median exact path."""
    if dbmod.experiment_value(exp, "world_type") in ("omplapp", "world3d"):  # meshes.py: OMPL.app problems, 3D worlds
        return meshes.path_figure(database, exp, paths, world_file, outdir, colors, path_figure)
    if not world_file or not os.path.exists(world_file):
        return None, "world file %s not found" % (world_file or "(not recorded)")
    try:
        world = worlds.load_world(world_file)
    except (OSError, ValueError, KeyError) as e:
        return None, "cannot draw %s: %s" % (world_file, e)
    query_unknown = None
    footprints = 0
    fig, ax = plt.subplots(figsize=(8.5, 7))
    worlds.draw_world(ax, world)
    drawn = 0
    for p in database.planners_of(exp.id):
        exact = [(r, datamod.run_length(database, r)) for r in database.runs_of(exp.id, p) if r.outcome == "exact"]
        exact = sorted([(l, r) for r, l in exact if l is not None and r.id in paths], key=lambda lr: lr[0])
        if not exact:
            continue
        best = exact[0][1]
        med = exact[len(exact) // 2][1]
        xs, ys = [v[0] for v in paths[best.id]], [v[1] for v in paths[best.id]]
        ax.plot(xs, ys, color=colors[p], linewidth=1.8, label="%s best %.3f" % (p, exact[0][0]), zorder=4)
        if med.id != best.id:
            xs, ys = [v[0] for v in paths[med.id]], [v[1] for v in paths[med.id]]
            ax.plot(xs, ys, color=colors[p], linewidth=1.0, linestyle="--", alpha=0.8, zorder=4)
        # A polygon robot (SE(2)-based worlds, paths stored with headings): its footprint along the best
        # path, so one sees where it turned.
        if world.robot_polygon and all(len(v) == 3 for v in paths[best.id]):
            for pose in worlds.footprint_poses(paths[best.id], _reach(world)):
                _footprint(ax, world, pose, colors[p], "footprint")
            footprints += 1
        drawn += 1
    q = experiment_query(exp, world)
    if q:
        ax.plot(*q[0], "o", color="#2ca02c", markersize=8, clip_on=False, zorder=5)
        ax.plot(*q[1], "*", color="#1f77b4", markersize=13, clip_on=False, zorder=5)
        yaws = experiment_yaws(exp, world)
        if world.robot_polygon and yaws:
            _footprint(ax, world, q[0] + (yaws[0],), "#2ca02c", "footprint-start", 0.3)
            _footprint(ax, world, q[1] + (yaws[1],), "#1f77b4", "footprint-goal", 0.3)
    else:
        query_unknown = "no start and goal markers (the experiment's query is not recorded)"
    title = "%s: best (solid) and median (dashed) paths" % exp.name
    if footprints:
        title += "; the robot along each best path"
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
    fig.tight_layout()
    name = save(fig, outdir, "paths_%s.png" % slug(exp.name))
    path_figure.footprints = footprints  # how many best paths show the robot (the page says so)
    return name, query_unknown if drawn else "no saved exact paths"

