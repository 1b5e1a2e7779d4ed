# SPDX-License-Identifier: BSD-3-Clause
"""One HTML report from an mhplan/OMPL benchmark database: box plots, success bars, convergence, paths,
the papers' tables and a ranking per problem. Every number in a table is computed here from the database
(see tables(); the tests recompute them with SQL)."""

import html
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import db as dbmod  # noqa: E402
from . import comparisons, meshes, movingai, paper_tables, papers, quality, scaling, simulations, stats, worlds  # noqa: E402

# (key, candidate run columns in order of preference, axis label). The first column present is used.
ATTRIBUTES = [
    ("time", ["time"], "wall time [s]"),
    ("cpu_time", ["cpu_time"], "CPU time [s]"),
    ("length", ["path_length", "solution_length"], "path length [m]"),
    ("gap", ["optimality_gap"], "optimality gap [%]"),
    ("clearance", ["min_clearance", "solution_clearance"], "minimum clearance [m]"),
    ("smoothness", ["smoothness", "solution_smoothness"], "smoothness"),
]
OUTCOME_COLORS = {"exact": "#2ca02c", "approximate": "#ff7f0e", "failed": "#9e9e9e", "crashed": "#d62728"}


def _column(database, candidates):
    for c in candidates:
        if c in database.run_columns:
            return c
    return None


def _optimum(exp):
    return dbmod.to_float(dbmod.experiment_value(exp, "exact_optimum", "optimum", "optimum_length"))


SPACES_WITHOUT_OPTIMUM = ("se2", "dubins", "reeds_shepp")


def _space(exp):
    """The experiment's state space when it is an SE(2)-based one (docs/spaces.md), else None."""
    space = dbmod.experiment_value(exp, "space")
    return space if space in SPACES_WITHOUT_OPTIMUM else None


def _valid_exact_lengths(database, exp, planner=None):
    """(length, run) of the exact runs whose path passed the independent check (collision_free not 0)."""
    out = []
    for p in [planner] if planner else database.planners_of(exp.id):
        for r in database.runs_of(exp.id, p):
            if r.outcome != "exact" or dbmod.run_value(r, "collision_free") == 0:
                continue
            length = _run_length(database, r)
            if length is not None:
                out.append((length, r))
    return out


def _best_found(database, exp):
    """SE(2)-based experiments have no exact optimum: their gaps are measured to the best cost any planner
    found in the campaign on that problem (exact, collision-free runs). None for every other experiment."""
    if not _space(exp) or _optimum(exp):
        return None
    lengths = [l for l, _ in _valid_exact_lengths(database, exp)]
    return min(lengths) if lengths else None


def _best_found_gaps(database, exp, planner, chosen=None):
    best = _best_found(database, exp)
    if not best:
        return []
    ids = None if chosen is None else {r.id for r in chosen}
    return [100.0 * (l - best) / best for l, r in _valid_exact_lengths(database, exp, planner) if ids is None or r.id in ids]


def _slug(text):
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in text)


def _planner_colors(planners):
    """Distinct colours: tab10, then Dark2 and Set1 (never two shades of one hue side by side)."""
    palette = list(plt.get_cmap("tab10").colors) + list(plt.get_cmap("Dark2").colors) + list(plt.get_cmap("Set1").colors)
    return {p: palette[i % len(palette)] for i, p in enumerate(planners)}


def _run_length(database, run):
    col = _column(database, ["path_length", "solution_length"])
    return dbmod.run_value(run, col) if col else None


# ---------------------------------------------------------------------------------------------- tables
def table_rows(database, exp):
    """Per planner of one experiment: runs, outcome counts, length min/mean/std/median, time of the best run,
    mean time, median gap, median time to within 1% of the optimum (quality.summary: every improvement, censored
    runs at +inf, with its CI). Lengths only over exact runs."""
    opt = _optimum(exp)
    gap_col = _column(database, ["optimality_gap"])
    rows = []
    for planner in database.planners_of(exp.id):
        runs = database.runs_of(exp.id, planner)
        exact = [r for r in runs if r.outcome == "exact"]
        lengths = [(_run_length(database, r), r) for r in exact]
        lengths = [(l, r) for l, r in lengths if l is not None]
        times = [dbmod.run_value(r, "time") for r in runs]
        best = min(lengths, key=lambda lr: lr[0]) if lengths else None
        gaps = [dbmod.run_value(r, gap_col) for r in exact] if gap_col else []
        if not gap_col and opt:
            gaps = [100.0 * (l - opt) / opt for l, _ in lengths]
        if _best_found(database, exp):
            gaps = _best_found_gaps(database, exp, planner)
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


def _fmt(v, digits=3, suffix=""):
    if v is None:
        return "&ndash;"
    if isinstance(v, float) and math.isinf(v):
        return "never"
    return ("%." + str(digits) + "f%s") % (v, suffix)


# ---------------------------------------------------------------------------------------------- figures
def box_plots(database, exp, outdir):
    """One figure per experiment: a box plot per available attribute (Planner Arena style)."""
    present = [(k, _column(database, c), label) for k, c, label in ATTRIBUTES]
    present = [(k, c, label) for k, c, label in present if c]
    planners = database.planners_of(exp.id)
    if not present or not planners:
        return None, []
    fig, axes = plt.subplots(1, len(present), figsize=(3.2 * len(present) + 1.0, 4.6), squeeze=False)
    missing = []
    for ax, (key, col, label) in zip(axes[0], present):
        data, names = [], []
        for p in planners:
            runs = database.runs_of(exp.id, p)
            # Quality attributes over exact runs only; time over all runs.
            chosen = runs if key in ("time", "cpu_time") else [r for r in runs if r.outcome == "exact"]
            vals = [dbmod.run_value(r, col) for r in chosen]
            if key == "gap" and _best_found(database, exp):
                vals = _best_found_gaps(database, exp, p, chosen)
            data.append([v for v in vals if v is not None])
            names.append(p)
        if key == "gap" and _best_found(database, exp):
            label = "gap to best found [%] (no exact optimum)"
        if not any(data):
            missing.append(label)
        ax.boxplot([d if d else [np.nan] for d in data], vert=True, widths=0.6, showfliers=True)
        ax.set_xticks(range(1, len(names) + 1))
        ax.set_xticklabels(names, rotation=60, ha="right", fontsize=8)
        ax.set_title(label, fontsize=10)
        attribute_scale(ax, key, [v for d in data for v in d])
        if key == "length" and _optimum(exp):
            ax.axhline(_optimum(exp), color="#1f77b4", linestyle="--", linewidth=1, label="exact optimum")
            ax.legend(fontsize=7, loc="upper right")
        elif key == "length" and _best_found(database, exp):
            ax.axhline(_best_found(database, exp), color="#1f77b4", linestyle=":", linewidth=1, label="best found")
            ax.legend(fontsize=7, loc="upper right")
        ax.grid(axis="y", alpha=0.3)
    # Wall and CPU time side by side on one scale: a CPU box below its wall box is time the planner waited
    # for a core.
    timed = [ax for ax, (key, _, _) in zip(axes[0], present) if key in ("time", "cpu_time")]
    if len(timed) == 2:
        lo = min(a.get_ylim()[0] for a in timed)
        hi = max(a.get_ylim()[1] for a in timed)
        for a in timed:
            a.set_ylim(lo, hi)
    fig.suptitle(exp.name, fontsize=11)
    fig.tight_layout()
    path = os.path.join(outdir, "box_%s.png" % _slug(exp.name))
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return os.path.basename(path), missing


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
    path = os.path.join(outdir, "success.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return os.path.basename(path)


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
    opt = _optimum(exp)
    best = None if opt else _best_found(database, exp)
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
    path = os.path.join(outdir, "convergence_%s.png" % _slug(exp.name))
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return os.path.basename(path)


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
        exact = [(r, _run_length(database, r)) for r in database.runs_of(exp.id, p) if r.outcome == "exact"]
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
    path = os.path.join(outdir, "paths_%s.png" % _slug(exp.name))
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    path_figure.footprints = footprints  # how many best paths show the robot (the page says so)
    return os.path.basename(path), query_unknown if drawn else "no saved exact paths"


def load_paths(database_path):
    """Saved solution paths, runid -> [(x, y), ...], from the database's 'paths' table (runid, points as
    "x y;x y;...") when present; in SE(2)-based worlds [(x, y, yaw), ...] ("x y yaw;...")."""
    import sqlite3

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


# ---------------------------------------------------------------------------------------------- HTML
def _table(headers, rows):
    out = ["<table><tr>" + "".join("<th>%s</th>" % h for h in headers) + "</tr>"]
    for r in rows:
        out.append("<tr>" + "".join("<td>%s</td>" % c for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


CSS = """body{font-family:sans-serif;max-width:1200px;margin:2em auto;color:#222}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#f0f0f0}td:first-child,th:first-child{text-align:left}img{max-width:100%;border:1px solid #eee}
.note{background:#fff8e0;border-left:4px solid #e0b000;padding:0.4em 0.8em}h2{border-bottom:1px solid #ddd}"""


def _fmt_ci(measured, digits=1):
    if measured is None:
        return "&ndash;"

    def f(v):
        if math.isinf(v):
            return "+&infin;" if v > 0 else "&minus;&infin;"
        return ("%." + str(digits) + "f") % v

    return "%s %% [%s, %s] (n = %d, coverage %.0f %%)" % (f(measured["median"]), f(measured["lo"]), f(measured["hi"]), measured["n"], 100.0 * measured["coverage"])


def _fmt_median(v, digits=2):
    """A censored median: 'unfinished' when more than half of the runs did not finish."""
    if v is None:
        return "&ndash;"
    if math.isinf(v):
        return "unfinished"
    return ("%." + str(digits) + "f") % v


def moving_worlds_section(database, exps, outdir, notes):
    """HTML of the simulation experiments: the [MAPF] traversal-time reduction beside the paper's figures,
    then per scenario box plots of makespan and flowtime and a table of outcomes per controller."""
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
                        _fmt_median(r["median_dapf"]),
                        _fmt_median(r["median_aapf"]),
                        _fmt(r["reduction_of_medians"], 1, " %"),
                        _fmt_ci(r["paired"]) + extra,
                        "%g %%" % r["paper"] if r["paper"] is not None else "&ndash;",
                        html.escape(r["verdict"]),
                    )
                )
            starts = simulations.distinct_starts(database, exp)
            if starts == 1:
                notes.append(
                    "%s: every run starts from the same configuration (no start_jitter): deterministic controllers "
                    "repeat one run, so the interval says nothing about variability." % exp.name
                )
        out.append(_table(["scenario", "robots", "metric", "median dapf [s]", "median aapf [s]", "reduction of medians", "paired reduction: median [95% CI]", "paper", "in plain words"], rows))

    for exp in exps:
        slug = _slug(exp.name)
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
        box = simulations.box_plots(database, exp, outdir, slug)
        if box:
            out.append("<img src='%s' alt='makespan and flowtime'>" % box)
        rows = simulations.controller_rows(database, exp)
        if not rows:
            notes.append("%s: no runs." % exp.name)
            continue
        out.append(
            _table(
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
                        _fmt_median(r["median_makespan"]),
                        _fmt_median(r["median_flowtime"]),
                        _fmt_median(r["median_traversal"]),
                        _fmt(r["min_robot_distance"], 3),
                        _fmt(r["min_obstacle_clearance"], 3),
                        _fmt(r["median_time"], 4),
                        _fmt(r["median_steps_per_second"], 0),
                    )
                    for r in rows
                ],
            )
        )
    return out


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


def load_text(summary):
    """One sentence (HTML) stating load_summary()."""
    parts = []
    if summary["share"] is not None:
        parts.append("the planners had %.0f %% of a core while they planned (CPU time over wall time of "
                     "solve(), %d runs)" % (100.0 * summary["share"], summary["runs"]))
    if summary["load_min"] is not None:
        load = ("%.2f" % summary["load_min"] if summary["load_min"] == summary["load_max"]
                else "%.2f to %.2f" % (summary["load_min"], summary["load_max"]))
        cores = " on %s core(s) available" % "/".join(str(c) for c in summary["cores"]) if summary["cores"] else ""
        parts.append("the system's 1-minute load average at the experiments' ends was %s%s" % (load, cores))
    if not parts:
        return None
    return "Machine load recorded by the campaign: " + "; ".join(parts) + "."


def write_report(database_path, outdir, world_dir=None):
    """Write index.html and its figures into outdir; returns the index path."""
    os.makedirs(outdir, exist_ok=True)
    database = dbmod.load(database_path)
    paths = load_paths(database_path)
    colors = _planner_colors(database.planners)
    notes = list(database.notes)
    parts = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>mhplan report</title><style>%s</style></head><body>" % CSS]
    parts.append("<h1>mhplan benchmark report</h1>")
    parts.append("<p>Database <code>%s</code>: %d experiments, %d planners, %d runs.</p>" % (html.escape(database_path), len(database.experiments), len(database.planners), len(database.runs)))
    # Planning experiments (worlds x queries) and simulation experiments (scenarios x controllers).
    planning = [e for e in database.experiments if not simulations.is_simulation(e)]
    moving = [e for e in database.experiments if simulations.is_simulation(e)]
    if not paths and planning:
        notes.append("The database has no saved paths: no path figures.")
    if planning:
        load = load_summary(database, planning)
        sentence = load_text(load)
        if sentence:
            parts.append("<p class='load'>%s</p>" % sentence)
        else:
            notes.append("The database records neither CPU times nor the machine's load (an older campaign): "
                         "whether the planners had their cores is unknown.")
        if load["share"] is not None and load["share"] < 0.8:
            notes.append("The planners had only %.0f %% of a core while they planned (other load on the cores): "
                         "time-limited planners did that much less work (campaign time_limit_kind: cpu bounds "
                         "CPU time instead)." % (100.0 * load["share"]))

    # Ranking and success first: what a reader wants.
    if planning:
        parts.append("<h2>Success</h2>")
        sb = success_bars(database, outdir, planning)
        if sb:
            parts.append("<img src='%s' alt='success rates'>" % sb)

    per_exp_tables = {}
    for exp in planning:
        per_exp_tables[exp.id] = table_rows(database, exp)

    if planning:
        parts.append("<h2>Ranking per problem</h2>")
    campaign_planners = sorted({p for e in planning for p in database.planners_of(e.id)})
    for exp in planning:
        rows = sorted(per_exp_tables[exp.id], key=lambda r: (-r["counts"]["exact"] / max(r["runs"], 1), r["median_gap"] if r["median_gap"] is not None else math.inf))
        opt = _optimum(exp)
        best = _best_found(database, exp)
        if best:
            reference = "none in space %s; gaps are to the best found cost %s (the best exact, collision-free path any planner of the campaign found)" % (html.escape(_space(exp)), _fmt(best, 4))
        else:
            reference = _fmt(opt, 4) if opt else "not recorded (no gaps)"
        parts.append("<h3>%s</h3><p>exact optimum: %s</p>" % (html.escape(exp.name), reference))
        # A campaign with skip_inapplicable: the planners of the campaign not run on this problem.
        not_run = [p for p in campaign_planners if p not in database.planners_of(exp.id)]
        if not_run:
            parts.append("<p class='skipped'>Not run here (the planner cannot run on this world's state space; "
                         "skipped by the campaign's skip_inapplicable, not a failure): %s.</p>" % ", ".join(html.escape(p) for p in not_run))
        parts.append(
            _table(
                ["planner", "success rate", "median gap to best found" if best else "median gap", "median time to within 1% [s] [95% CI] (reached/runs)", "runs"],
                [
                    (
                        html.escape(r["planner"]),
                        "%.0f%%" % (100.0 * r["counts"]["exact"] / max(r["runs"], 1)),
                        _fmt(r["median_gap"], 2, "%"),
                        quality.fmt(r["t1"], 4),
                        r["runs"],
                    )
                    for r in rows
                ],
            )
        )

    if planning:
        parts.extend(comparisons.campaign_section(database, planning, _optimum, outdir, colors))

    # The papers' tables.
    parts.extend(paper_tables.paper_tables(database, planning, per_exp_tables, paths, world_dir, _table, _fmt))

    if planning:
        parts.extend(scaling.scaling_section(database, planning, outdir, colors, notes, _table))

    if planning:
        parts.extend(movingai.section(database, planning, lambda r: _run_length(database, r), _table, _fmt))

    if moving:
        parts.extend(moving_worlds_section(database, moving, outdir, notes))

    # Per problem: figures and the full table.
    for exp in planning:
        parts.append("<h2>%s</h2>" % html.escape(exp.name))
        sentence = load_text(load_summary(database, [exp]))
        if sentence:
            parts.append("<p class='load'>%s</p>" % sentence.replace("by the campaign", "for this problem"))
        box, missing = box_plots(database, exp, outdir)
        if box:
            parts.append("<img src='%s' alt='box plots'>" % box)
        for m in missing:
            notes.append("%s: no values for %s (no exact runs or no such column)." % (exp.name, m))
        conv = convergence_plot(database, exp, outdir, colors)
        if conv:
            parts.append("<img src='%s' alt='convergence'>" % conv)
        else:
            notes.append("%s: no convergence plot (no planner recorded an improvement or 'best cost' progress)." % exp.name)
        world_file = dbmod.experiment_value(exp, "world_file")
        if world_file and world_dir and not os.path.isabs(str(world_file)):
            world_file = os.path.join(world_dir, str(world_file))
        if paths:
            pf, why = path_figure(database, exp, paths, world_file, outdir, colors)
            if pf:
                shown = getattr(path_figure, "footprints", 0)
                parts.append("<img class='paths' src='%s' alt='paths' data-footprints='%d'>" % (pf, shown))
                if shown:
                    parts.append("<p class='footprints'>The robot's footprint is drawn along each planner's best "
                                 "path (at start, goal, every 1.5 robot reaches of travel and every 30&deg; of "
                                 "turn), green at the start, blue at the goal.</p>")
            if why:
                notes.append("%s: %s." % (exp.name, why))
        rows = per_exp_tables[exp.id]
        parts.append(
            _table(
                ["planner", "runs", "exact", "approx.", "failed", "crashed", "length min", "length median", "length mean", "length std", "mean time [s]"],
                [
                    (html.escape(r["planner"]), r["runs"], r["counts"]["exact"], r["counts"]["approximate"], r["counts"]["failed"], r["counts"]["crashed"], _fmt(r["min"], 4), _fmt(r["median"], 4), _fmt(r["mean"], 4), _fmt(r["std"], 4), _fmt(r["mean_time"], 4))
                    for r in rows
                ],
            )
        )
        parts.extend(comparisons.problem_section(database, exp, _optimum(exp)))
        parts.append("<p>Time to quality [s]: median [95%% CI] (runs that got there / runs); a run that never got "
                     "there counts as +&infin;%s.</p>" % ("" if database.improvements is not None else
                                                         " (no improvements table: from the progress samples)"))
        parts.append(
            _table(
                ["planner"] + [label for _, _, label in quality.LEVELS],
                [(html.escape(q["planner"]),) + tuple(quality.fmt(q[key], 4) for key, _, _ in quality.LEVELS)
                 for q in quality.rows(database, exp, _optimum(exp))],
            )
        )
    if notes:
        parts.insert(3, "<h2>Gaps in the data</h2><ul>" + "".join("<li>%s</li>" % html.escape(n) for n in notes) + "</ul>")
    parts.append("</body></html>")
    index = os.path.join(outdir, "index.html")
    with open(index, "w") as f:
        f.write("\n".join(parts))
    return index
