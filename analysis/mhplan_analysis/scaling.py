"""The "Scaling" part of the report: for every world family of the scaling suite (benchmarks/scaling.yaml;
worlds named KIND_SIZE_sSEED by mhplan's generators, a disc robot making its own family), the success rate,
the median optimality gap and the median time to within 1 % of the optimum against the world's size
(obstacles, or cells for grids), one line per planner, log axes, with confidence bands.

Per (family, size, planner) all runs of all queries of the worlds of that size are pooled. The gap of a run
without an exact solution and the time of a run that never got within 1 % count as +infinity (censored, see
quality.py); medians and their bands are the distribution-free order-statistic intervals of
simulations.median_with_ci (a band ends where its bound is censored). The success band is the Wilson score
interval of the exact-solution rate."""

import html
import math
import re

import numpy as np

from . import db as dbmod
from . import page, quality
from .page import plt
from .simulations import median_with_ci

FAMILY_RE = re.compile(r"^(circles|rectangles|polygons|maze|grid)_(\d+)_s\d+$")
GRID_KINDS = ("maze", "grid")


def family_of(exp):
    """(family label, kind, size) of a scaling-suite experiment, or None for other worlds."""
    name = str(dbmod.experiment_value(exp, "world") or "")
    m = FAMILY_RE.match(name)
    if not m:
        return None
    kind = m.group(1)
    radius = dbmod.to_float(dbmod.experiment_value(exp, "robot_radius")) or 0.0
    if kind in GRID_KINDS:
        cells = dbmod.to_float(dbmod.experiment_value(exp, "grid_cells"))
        size = int(cells) if cells else int(m.group(2)) ** 2
    else:
        count = dbmod.to_float(dbmod.experiment_value(exp, "obstacle_count"))
        size = int(count) if count is not None else int(m.group(2))
    label = kind + (" (disc robot, r = %g m)" % radius if radius > 0 else "")
    return label, kind, size


def wilson(k, n, z=1.959963984540054):
    """Wilson score interval of a proportion k/n (as fractions)."""
    if n == 0:
        return None
    p = k / n
    den = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / den
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / den
    return max(0.0, centre - half), min(1.0, centre + half)


def _optimum(exp):
    return dbmod.to_float(dbmod.experiment_value(exp, "exact_optimum"))


def cell(database, exps, planner):
    """The pooled statistics of one planner over the experiments of one (family, size)."""
    runs, gaps, times = 0, [], []
    exact = 0
    for exp in exps:
        opt = _optimum(exp)
        rs = database.runs_of(exp.id, planner)
        runs += len(rs)
        for r in rs:
            exact += 1 if r.outcome == "exact" else 0
            g = quality.gap(database, r, opt)
            gaps.append(g if g is not None else math.inf)
        times += quality.censored_times(database, rs, opt, 0.01)
    if runs == 0:
        return None
    return {"runs": runs, "exact": exact, "success": exact / runs, "success_ci": wilson(exact, runs),
            "gap": median_with_ci(gaps), "t1": median_with_ci(times)}


def scaling_table(database, exps):
    """{family: {"kind": kind, "sizes": [size, ...], "planners": {planner: {size: cell}}}} over the
    scaling-suite experiments of \\p exps (others are ignored)."""
    groups = {}
    for exp in exps:
        f = family_of(exp)
        if f is None:
            continue
        label, kind, size = f
        g = groups.setdefault(label, {"kind": kind, "exps": {}})
        g["exps"].setdefault(size, []).append(exp)
    out = {}
    for label, g in sorted(groups.items()):
        sizes = sorted(g["exps"])
        planners = []
        for size in sizes:
            for exp in g["exps"][size]:
                for p in database.planners_of(exp.id):
                    if p not in planners:
                        planners.append(p)
        table = {p: {} for p in planners}
        for p in planners:
            for size in sizes:
                c = cell(database, g["exps"][size], p)
                if c is not None:
                    table[p][size] = c
        out[label] = {"kind": g["kind"], "sizes": sizes, "planners": table}
    return out


def _finite(v):
    return v if v is not None and math.isfinite(v) else np.nan


def figure(label, fam, outdir, colors):
    """Three panels against size: success rate, median gap, median time to within 1 %."""
    sizes = fam["sizes"]
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    for planner, by_size in fam["planners"].items():
        xs = [s for s in sizes if s in by_size]
        if not xs:
            continue
        color = colors.get(planner)
        cells = [by_size[s] for s in xs]
        succ = [100.0 * c["success"] for c in cells]
        lo = [100.0 * c["success_ci"][0] for c in cells]
        hi = [100.0 * c["success_ci"][1] for c in cells]
        axes[0].plot(xs, succ, marker="o", color=color, label=planner)
        axes[0].fill_between(xs, lo, hi, color=color, alpha=0.05)
        for ax, key in ((axes[1], "gap"), (axes[2], "t1")):
            med = [_finite(c[key]["median"]) if c[key] else np.nan for c in cells]
            blo = [_finite(c[key]["lo"]) if c[key] else np.nan for c in cells]
            bhi = [_finite(c[key]["hi"]) if c[key] else np.nan for c in cells]
            if key == "gap":  # a gap of 0 cannot be drawn on a log axis
                med = [max(v, 1e-4) if not np.isnan(v) else v for v in med]
                blo = [max(v, 1e-4) if not np.isnan(v) else v for v in blo]
                bhi = [max(v, 1e-4) if not np.isnan(v) else v for v in bhi]
            ax.plot(xs, med, marker="o", color=color, label=planner)
            ax.fill_between(xs, blo, bhi, color=color, alpha=0.12)
    unit = "cells" if fam["kind"] in GRID_KINDS else "obstacles"
    titles = ["success rate [%] (exact solutions)", "median optimality gap [%]", "median time to within 1 % [s]"]
    for ax, title in zip(axes, titles):
        ax.set_xscale("log")
        ax.set_xlabel("world size [%s]" % unit)
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylim(-3, 103)
    for ax in axes[1:]:
        if any(line.get_ydata().size and np.any(np.isfinite(line.get_ydata())) for line in ax.get_lines()):
            ax.set_yscale("log")
    axes[2].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.suptitle("Scaling: %s" % label, fontsize=11)
    fig.tight_layout()
    slug = "".join(c if c.isalnum() else "_" for c in label)
    return page.save(fig, outdir, "scaling_%s.png" % slug, dpi=100)


def _fmt_median(m, digits):
    if m is None:
        return "&ndash;"
    if math.isinf(m["median"]):
        return "not reached"
    return ("%." + str(digits) + "f") % m["median"]


def render(data, ctx):
    """Report section: Scaling (empty when no experiment belongs to a scaling family)."""
    database, outdir, colors, notes = data.database, ctx.outdir, ctx.colors, ctx.notes
    table = scaling_table(database, data.planning)
    if not table:
        return []
    parts = ["<h2>Scaling</h2>",
             "<p>Per world family and size, all runs of all queries pooled. Success: exact solutions (band: "
             "Wilson 95 % interval). Gap and time to within 1 %%: medians with unsolved or never-within-1 %% runs "
             "at +&infin; (bands: distribution-free 95 %% intervals of the median; 'not reached' when the median is "
             "censored). Cells: success %% / median gap %% / median time to within 1 %% [s].</p>"]
    for label, fam in table.items():
        parts.append("<h3>%s</h3>" % html.escape(label))
        parts.append("<img src='%s' alt='scaling %s'>" % (figure(label, fam, outdir, colors), html.escape(label)))
        unit = "cells" if fam["kind"] in GRID_KINDS else "obstacles"
        head = ["planner"] + ["%d %s" % (s, unit) for s in fam["sizes"]]
        rows = []
        for planner, by_size in fam["planners"].items():
            row = [html.escape(planner)]
            for s in fam["sizes"]:
                c = by_size.get(s)
                row.append("&ndash;" if c is None else "%.0f / %s / %s" % (100.0 * c["success"],
                                                                           _fmt_median(c["gap"], 2),
                                                                           _fmt_median(c["t1"], 3)))
            rows.append(row)
        parts.append(page.table(head, rows))
    if database.improvements is None:
        notes.append("Scaling: times to within 1 % come from progress samples (no improvements table).")
    return parts
