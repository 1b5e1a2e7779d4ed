# SPDX-License-Identifier: BSD-3-Clause
"""The report's comparisons between planners: per problem a compact matrix of pairwise tests (pairwise.py) on
the gap and on the time to within 1 % of the optimum; per campaign performance profiles (profiles.py) and the
share of runs within tau % of the optimum."""

import html
import math

import numpy as np

from . import db as dbmod
from . import pairwise, profiles, quality
from .page import plt, save


def _valid_exact(database, run):
    """True for an exact run whose path passed the independent check (collision_free not 0)."""
    return run.outcome == "exact" and dbmod.run_value(run, "collision_free") != 0


def best_found(database, exp):
    """The best cost any planner found on the experiment: the shortest exact, collision-free path of the
    campaign; None when no run found one. The reference of the gaps where there is no exact optimum."""
    lengths = [quality._length(database, r) for p in database.planners_of(exp.id) for r in database.runs_of(exp.id, p) if _valid_exact(database, r)]
    lengths = [l for l in lengths if l is not None]
    return min(lengths) if lengths else None


def run_gaps(database, exp, planner, optimum, best=None):
    """Per run of \\e planner: its gap in % when it found an exact path, else +inf (a failed run is worse
    than any path). Without an exact \\e optimum the gap is to \\e best (best_found: the cost relative to
    the best found; a path that is not collision-free counts +inf there)."""
    out = []
    gap_col = "optimality_gap" if "optimality_gap" in database.run_columns else None
    for r in database.runs_of(exp.id, planner):
        g = None
        if r.outcome == "exact":
            if optimum:
                g = dbmod.run_value(r, gap_col) if gap_col else None
                if g is None:
                    length = quality._length(database, r)
                    g = None if length is None else 100.0 * (length - optimum) / optimum
            elif best and _valid_exact(database, r):
                length = quality._length(database, r)
                g = None if length is None else 100.0 * (length - best) / best
        out.append(math.inf if g is None else g)
    return out


def samples(database, exp, optimum):
    """{"gap": planner -> run gaps, "t1": planner -> censored times to within 1 %} (t1 only with an
    optimum). Without an exact optimum "gap" is the cost relative to the best found (best_found); there is
    then no "gap" at all when no run found a path."""
    planners = database.planners_of(exp.id)
    best = None if optimum else best_found(database, exp)
    if not optimum and not best:
        return {}
    out = {"gap": {p: run_gaps(database, exp, p, optimum, best) for p in planners}}
    if optimum:
        out["t1"] = {p: quality.censored_times(database, database.runs_of(exp.id, p), optimum, 0.01) for p in planners}
    return out


def matrix_html(values, alpha=0.05):
    """A planners x planners table: cell (row, column) = A12 that the row beats the column (lower cost
    better), bold with * when Holm-corrected p < alpha."""
    names = [p for p in values if values[p]]
    if len(names) < 2:
        return None
    m = pairwise.matrix(values, alpha)
    rows = ["<table class='pairwise'><tr><th>row beats column</th>" + "".join("<th>%s</th>" % html.escape(n) for n in names) + "</tr>"]
    for a in names:
        cells = []
        for b in names:
            if a == b:
                cells.append("<td>&ndash;</td>")
                continue
            c = m[(a, b)]
            text = "%.2f" % c["better"]
            title = "p = %.3g, Holm p = %.3g (%s)" % (c["p"], c["p_holm"], c["method"])
            cells.append("<td title='%s'>%s</td>" % (title, "<b>%s*</b>" % text if c["significant"] else text))
        rows.append("<tr><td>%s</td>%s</tr>" % (html.escape(a), "".join(cells)))
    rows.append("</table>")
    return "\n".join(rows)


def problem_section(database, exp, optimum):
    """HTML for one problem: the pairwise matrices on the gap and on the time to within 1 %."""
    s = samples(database, exp, optimum)
    out = []
    gap_label = "optimality gap (a run without an exact path counts +&infin;)" if optimum else "cost relative to the best found, in % of the best exact collision-free path any planner found (no exact optimum; a run without such a path counts +&infin;)"
    for key, label in (("gap", gap_label), ("t1", "time to within 1 % of the optimum (never: +&infin;)")):
        if key not in s:
            continue
        table = matrix_html(s[key])
        if table:
            out.append("<p>Pairwise on the %s: A12 that the row planner has the lower value (0.5 = no difference); "
                       "<b>*</b>: two-sided Mann-Whitney U, Holm-corrected over all pairs, p &lt; 0.05.</p>" % label)
            out.append(table)
    return out


TAUS = np.logspace(0, 2, 121)
LEGEND_FONTSIZE = 11
GAP_TAUS = np.concatenate([[0.0], np.logspace(-2, 2, 120)])


def campaign_costs(database, exps, optimum_of):
    """Per planner and problem (experiments where the planner ran): the censored median time to within 1 %
    and the median path length (runs without an exact path at +inf). Problems without an optimum are left
    out of the time profile."""
    planners = sorted({p for e in exps for p in database.planners_of(e.id)})
    times = {p: [] for p in planners}
    lengths = {p: [] for p in planners}
    gaps = {p: [] for p in planners}
    timed = 0
    for e in exps:
        opt = optimum_of(e)
        present = database.planners_of(e.id)
        for p in planners:
            runs = database.runs_of(e.id, p) if p in present else []
            ls = []
            for r in runs:
                length = quality._length(database, r) if r.outcome == "exact" else None
                ls.append(math.inf if length is None else length)
            lengths[p].append(float(np.median(ls)) if ls else math.inf)
            if opt:
                t = quality.censored_times(database, runs, opt, 0.01) if runs else []
                times[p].append(float(np.median(t)) if t else math.inf)
                gaps[p].extend(run_gaps(database, e, p, opt) if runs else [])
        timed += 1 if opt else 0
    return times if timed else None, lengths, gaps


def profile_figure(database, exps, optimum_of, outdir, colors):
    """Three panels: Dolan-More profiles of the time to within 1 % and of the median length, and the share
    of runs within tau % of the optimum. None with fewer than two planners."""
    times, lengths, gaps = campaign_costs(database, exps, optimum_of)
    if len(lengths) < 2:
        return None
    panels = []
    if times:
        panels.append(("time to within 1 % of the optimum", profiles.profile(times, list(TAUS)), TAUS, "factor tau of the best planner's time", True))
    panels.append(("median path length", profiles.profile(lengths, list(TAUS)), TAUS, "factor tau of the best planner's length", True))
    if any(gaps.values()):
        panels.append(("runs within tau % of the optimum", profiles.within_gap(gaps, list(GAP_TAUS)), GAP_TAUS, "gap tau [%]", False))
    fig, axes = plt.subplots(1, len(panels), figsize=(5.0 * len(panels) + 1.5, 4.2), squeeze=False)
    for ax, (title, curves, taus, xlabel, ratio) in zip(axes[0], panels):
        for p, ys in curves.items():
            ax.step(taus, ys, where="post", color=colors.get(p), label=p, linewidth=1.4)
        ax.set_xscale("symlog", linthresh=0.01) if not ratio else ax.set_xscale("log")
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("share of problems" if ratio else "share of runs")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3, which="both")
    # The legend is read beside three panels: the report's body text size, thick colour keys.
    legend = axes[0, -1].legend(fontsize=LEGEND_FONTSIZE, loc="center left", bbox_to_anchor=(1.01, 0.5),
                                frameon=False, handlelength=2.5)
    for line in legend.get_lines():
        line.set_linewidth(3.0)
    fig.tight_layout()
    return save(fig, outdir, "profiles.png")


def render(data, ctx):
    """Report section: the campaign's performance profiles over its planning experiments."""
    exps = data.planning
    if not exps:
        return []
    fig = profile_figure(data.database, exps, data.optimum, ctx.outdir, ctx.colors)
    if not fig:
        return []
    return [
        "<h2>Performance profiles</h2>",
        "<p>Dolan-Mor&eacute; profiles over the %d problems: the share of problems on which a planner's cost is "
        "within a factor &tau; of the best planner's (left: median time to within 1 %% of the optimum, runs "
        "that never got there at +&infin;; middle: median path length, runs without an exact path at "
        "+&infin;). &tau; = 1: the planner is (one of) the best; the curve's end: the share it solves at all. "
        "Right: the share of all runs with a gap of at most &tau; %%. A planner that did not run on a problem counts "
        "as not solving it.</p>" % len(exps),
        "<img src='%s' alt='performance profiles'>" % fig,
    ]
