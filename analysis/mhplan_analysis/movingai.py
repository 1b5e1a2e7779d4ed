# SPDX-License-Identifier: BSD-3-Clause
"""The "MovingAI benchmark sets" part of the report: campaign worlds {map: ..., scen: ...} (one experiment per
selected .scen problem, with its bucket, the .scen optimum and mhplan's octile optimum recorded). Per map and
bucket, per planner: success rate, median length relative to the octile optimum (1 = the 8-connected optimum;
below 1 = shorter, which any-angle and continuous planners can be) and median gap to the any-angle optimum
(exact_optimum)."""

import html

from . import db as dbmod
from . import stats
from .page import fmt, table


def is_movingai(exp):
    """True for an experiment made from a MovingAI .scen problem."""
    return dbmod.to_float(exp.params.get("scen_optimum")) is not None and exp.params.get("scen_bucket") is not None


def bucket_rows(database, exps, length_of):
    """Rows (map, bucket, planner, problems, runs, exact runs, median length / octile optimum, median gap to the
    any-angle optimum in %) over the experiments \\p exps; \\p length_of(run) gives a run's path length (m)."""
    groups = {}
    for exp in exps:
        key = (str(exp.params.get("world")), int(exp.params.get("scen_bucket")))
        groups.setdefault(key, []).append(exp)
    rows = []
    for (world, bucket) in sorted(groups):
        members = groups[(world, bucket)]
        planners = []
        for exp in members:
            for p in database.planners_of(exp.id):
                if p not in planners:
                    planners.append(p)
        for planner in planners:
            runs = exact = 0
            ratios, gaps = [], []
            for exp in members:
                octile = dbmod.to_float(exp.params.get("octile_optimum_m"))
                opt = dbmod.to_float(exp.params.get("exact_optimum"))
                for r in database.runs_of(exp.id, planner):
                    runs += 1
                    if r.outcome != "exact":
                        continue
                    exact += 1
                    length = length_of(r)
                    if length is None:
                        continue
                    if octile:
                        ratios.append(length / octile)
                    if opt:
                        gaps.append(100.0 * (length - opt) / opt)
            rows.append((world, bucket, planner, len(members), runs, exact, stats.median(ratios), stats.median(gaps)))
    return rows


def render(data, ctx):
    """Report section: the MovingAI part (a list of strings); empty without MovingAI experiments."""
    database, length_of = data.database, data.length
    exps = [e for e in data.planning if is_movingai(e)]
    if not exps:
        return []
    out = ["<h2>MovingAI benchmark sets, by bucket</h2>"]
    out.append(
        "<p>One experiment per selected <code>.scen</code> problem; each problem's .scen optimum was checked against "
        "mhplan's octile optimum when the campaign started (both are in the database: <code>scen_optimum</code>, "
        "<code>octile_optimum</code>). Length ratio: path length / octile optimum (median over exact runs); gap: "
        "to the any-angle optimum (<code>exact_optimum</code>).</p>"
    )
    rows = bucket_rows(database, exps, length_of)
    out.append(
        table(
            ["map", "bucket", "planner", "problems", "success", "median length / octile optimum", "median gap to any-angle optimum"],
            [
                (
                    html.escape(w),
                    b,
                    html.escape(p),
                    n,
                    "%d/%d" % (ex, runs),
                    fmt(ratio, 4),
                    fmt(gap, 2, "%"),
                )
                for w, b, p, n, runs, ex, ratio, gap in rows
            ],
        )
    )
    return out
