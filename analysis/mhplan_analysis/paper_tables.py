# SPDX-License-Identifier: BSD-3-Clause
"""The report's sections that set our runs beside the seed papers' numbers (docs/algorithms.md section 9):
[LRSMA] Table 3 both ways (fitness S of every run, lengths of the exact runs) and [BFO]'s best lengths."""

import html

from . import db as dbmod
from . import papers, stats, worlds
from .page import fmt, table


def _world_name(exp):
    w = dbmod.experiment_value(exp, "world", "world_name")
    if w:
        return str(w)
    return exp.name.split("/")[0]


def _experiment_world(data, exp):
    """The experiment's world (worlds.World) or None when its file cannot be read."""
    world_file = data.world_file(exp)
    try:
        return worlds.load_world(str(world_file)) if world_file else None
    except (OSError, ValueError):
        return None


def fitness_rows(database, exp, paths, world):
    """Per planner: [LRSMA]'s fitness S of every run's reported path (papers.lrsma_fitness), over all runs
    that reported a path: {planner: (count, min, mean, std)}."""
    out = {}
    if world is None:
        return out
    for planner in database.planners_of(exp.id):
        values = []
        for r in database.runs_of(exp.id, planner):
            pts = paths.get(r.id)
            v = papers.lrsma_fitness(pts, world.circles, world.bounds, r.outcome == "exact") if pts else None
            if v is not None:
                values.append(v)
        out[planner] = (len(values), min(values) if values else None, stats.mean(values), stats.std(values))
    return out


def render(data, ctx):
    """Report section: [LRSMA] Table 3 and [BFO]: our runs (data.table_rows per experiment) with the papers'
    numbers beside, printed as the papers print them."""
    database, planning, paths = data.database, data.planning, data.paths
    parts = []
    lrsma_exps = [(papers.LRSMA_WORLDS[_world_name(e)], e) for e in planning if _world_name(e) in papers.LRSMA_WORLDS]
    if lrsma_exps:
        parts.append("<h2>[LRSMA] Table 3 layout (our runs; the paper's numbers beside)</h2>")
        parts.append("<p class='note'>%s</p>" % html.escape(papers.LRSMA_NOTE))
        for scenario, exp in sorted(lrsma_exps, key=lambda se: se[0]):
            fit = fitness_rows(database, exp, paths, _experiment_world(data, exp))
            ours = {}
            for r in data.table_rows(exp):
                n, fmin, fmean, fstd = fit.get(r["planner"], (0, None, None, None))
                ours[r["planner"]] = (
                    "%s (ours)" % html.escape(r["planner"]),
                    "%d / %d" % (r["counts"]["exact"], r["runs"]),
                    fmt(fmin, 2), fmt(fmean, 2), fmt(fstd, 2),
                    fmt(r["min"], 2), fmt(r["mean"], 2), fmt(r["std"], 2),
                    fmt(r["best_time"], 4), fmt(r["mean_time"], 4),
                )
            # Table 3's five rows in the paper's order, each of ours (run under identical conditions in the
            # campaign) directly above the paper's; then our other planners.
            rows = []
            for alg, (mn, me, sd, bt, mt) in papers.LRSMA_TABLE3[scenario].items():
                if alg in ours:
                    rows.append(ours.pop(alg))
                rows.append(("%s (paper)" % alg, "100 runs", "%.2f" % mn, "%.2f" % me, "%.2f" % sd, "&ndash;", "&ndash;", "&ndash;", "%.2f" % bt, "%.2f" % mt))
            rows.extend(ours.values())
            parts.append("<h3>Scenario %d: %s</h3>" % (scenario, html.escape(exp.name)))
            parts.append(
                table(
                    ["algorithm", "exact / runs", "all runs: S min", "S mean", "S std", "exact runs: length min", "length mean", "length std", "time of best run [s]", "mean time [s]"],
                    rows,
                )
            )
    bfo_exps = [e for e in planning if _world_name(e) in papers.BFO_REPORTED]
    if bfo_exps:
        parts.append("<h2>[BFO] best path lengths (our runs; the paper's numbers beside)</h2>")
        parts.append("<p class='note'>%s</p>" % html.escape(papers.BFO_NOTE))
        for exp in bfo_exps:
            rows = []
            for r in data.table_rows(exp):
                times = [dbmod.run_value(x, "time") for x in database.runs_of(exp.id, r["planner"])]
                times = [t for t in times if t is not None]
                rows.append(("%s (ours)" % html.escape(r["planner"]), fmt(r["min"], 4), fmt(r["best_time"], 4), fmt(min(times) if times else None, 4)))
            rows += [("%s (paper)" % html.escape(n), l, "&ndash;", t if t else "&ndash;") for n, l, t in papers.BFO_REPORTED[_world_name(exp)]]
            parts.append("<h3>%s</h3>" % html.escape(exp.name))
            parts.append(table(["algorithm", "best length", "time of the best-length run [s]", "time of the fastest run [s]"], rows))
    return parts
