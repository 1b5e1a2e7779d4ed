# SPDX-License-Identifier: BSD-3-Clause
"""Report section: success and ranking first (what a reader wants): the success bars of every planning
experiment, then per problem the planners ranked by success rate and median gap."""

import html
import math

from . import quality
from .data import space
from .figures import success_bars
from .page import fmt, table


def render(data, ctx):
    if not data.planning:
        return []
    out = ["<h2>Success</h2>"]
    sb = success_bars(data.database, ctx.outdir, data.planning)
    if sb:
        out.append("<img src='%s' alt='success rates'>" % sb)
    out.append("<h2>Ranking per problem</h2>")
    for exp in data.planning:
        rows = sorted(data.table_rows(exp), key=lambda r: (-r["counts"]["exact"] / max(r["runs"], 1), r["median_gap"] if r["median_gap"] is not None else math.inf))
        opt = data.optimum(exp)
        best = data.best_found(exp)
        if best:
            reference = "none in space %s; gaps are to the best found cost %s (the best exact, collision-free path any planner of the campaign found)" % (html.escape(space(exp)), fmt(best, 4))
        else:
            reference = fmt(opt, 4) if opt else "not recorded (no gaps)"
        out.append("<h3>%s</h3><p>exact optimum: %s</p>" % (html.escape(exp.name), reference))
        # A campaign with skip_inapplicable: the planners of the campaign not run on this problem.
        here = data.database.planners_of(exp.id)
        not_run = [p for p in data.campaign_planners if p not in here]
        if not_run:
            out.append("<p class='skipped'>Not run here (the planner cannot run on this world's state space; "
                       "skipped by the campaign's skip_inapplicable, not a failure): %s.</p>" % ", ".join(html.escape(p) for p in not_run))
        out.append(
            table(
                ["planner", "success rate", "median gap to best found" if best else "median gap", "median time to within 1% [s] [95% CI] (reached/runs)", "runs"],
                [
                    (
                        html.escape(r["planner"]),
                        "%.0f%%" % (100.0 * r["counts"]["exact"] / max(r["runs"], 1)),
                        fmt(r["median_gap"], 2, "%"),
                        quality.fmt(r["t1"], 4),
                        r["runs"],
                    )
                    for r in rows
                ],
            )
        )
    return out
