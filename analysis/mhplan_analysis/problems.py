# SPDX-License-Identifier: BSD-3-Clause
"""Report section: per planning problem its figures (box plots, convergence, paths in the world), the full
table of outcomes and lengths, the pairwise comparisons and the times to quality."""

import html

from . import comparisons, quality
from .data import load_summary
from .figures import box_plots, convergence_plot, path_figure
from .overview import load_text
from .page import fmt, table


def render(data, ctx):
    database = data.database
    out = []
    for exp in data.planning:
        out.append("<h2>%s</h2>" % html.escape(exp.name))
        sentence = load_text(load_summary(database, [exp]))
        if sentence:
            out.append("<p class='load'>%s</p>" % sentence.replace("by the campaign", "for this problem"))
        box, missing = box_plots(database, exp, ctx.outdir)
        if box:
            out.append("<img src='%s' alt='box plots'>" % box)
        for m in missing:
            ctx.notes.append("%s: no values for %s (no exact runs or no such column)." % (exp.name, m))
        conv = convergence_plot(database, exp, ctx.outdir, ctx.colors)
        if conv:
            out.append("<img src='%s' alt='convergence'>" % conv)
        else:
            ctx.notes.append("%s: no convergence plot (no planner recorded an improvement or 'best cost' progress)." % exp.name)
        if data.paths:
            pf, why = path_figure(database, exp, data.paths, data.world_file(exp), ctx.outdir, ctx.colors)
            if pf:
                shown = getattr(path_figure, "footprints", 0)
                out.append("<img class='paths' src='%s' alt='paths' data-footprints='%d'>" % (pf, shown))
                if shown:
                    out.append("<p class='footprints'>The robot's footprint is drawn along each planner's best "
                               "path (at start, goal, every 1.5 robot reaches of travel and every 30&deg; of "
                               "turn), green at the start, blue at the goal.</p>")
            if why:
                ctx.notes.append("%s: %s." % (exp.name, why))
        out.append(
            table(
                ["planner", "runs", "exact", "approx.", "failed", "crashed", "length min", "length median", "length mean", "length std", "mean time [s]"],
                [
                    (html.escape(r["planner"]), r["runs"], r["counts"]["exact"], r["counts"]["approximate"], r["counts"]["failed"], r["counts"]["crashed"], fmt(r["min"], 4), fmt(r["median"], 4), fmt(r["mean"], 4), fmt(r["std"], 4), fmt(r["mean_time"], 4))
                    for r in data.table_rows(exp)
                ],
            )
        )
        out.extend(comparisons.problem_section(database, exp, data.optimum(exp)))
        out.append("<p>Time to quality [s]: median [95%% CI] (runs that got there / runs); a run that never got "
                   "there counts as +&infin;%s.</p>" % ("" if database.improvements is not None else
                                                       " (no improvements table: from the progress samples)"))
        out.append(
            table(
                ["planner"] + [label for _, _, label in quality.LEVELS],
                [(html.escape(q["planner"]),) + tuple(quality.fmt(q[key], 4) for key, _, _ in quality.LEVELS)
                 for q in quality.rows(database, exp, data.optimum(exp))],
            )
        )
    return out
