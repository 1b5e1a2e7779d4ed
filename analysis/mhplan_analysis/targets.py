# SPDX-License-Identifier: BSD-3-Clause
"""Issue 31's targets (benchmarks/README.md, "Issue 31's targets"): per validity set-up (setups.py) and
planner, over every planning experiment with an exact optimum: exact runs / runs, the optimality gap at the
50th, 75th and 90th percentile, the runs that got within 1 % of the optimum and their median time to get
there, the median time to within 1 % over all runs, the median time of the first solution, and the runs whose
path fails the independent dense check. Under the table, per set-up, the targets themselves: every memetic
run exact; the best memetic planner's 90th-percentile gap and median time to within 1 % at or below the best
OMPL planner's; in the app set-up, its first solution and time to within 1 % no slower than Informed RRT*'s.

Conventions are the Scaling section's and quality.py's: a run without an exact solution has gap +infinity
(so a percentile needing one is infinite), times come from the improvements table (exact times; the progress
samples without it), a run that never got there is censored at +infinity and counts in the all-runs medians.
The gap is the planner's own path against the exact optimum, whether or not the dense check passes (its
failures have their own column). The last two columns count a run whose returned path fails the dense check as
never within 1 % (its improvements ran through an obstacle the validator did not see: with OMPL's discrete
validator a planner can look fast to within 1 % by cutting corners), and the app set-up has that target too.

Also a command: PYTHONPATH=analysis /usr/bin/python3 -m mhplan_analysis.targets DB prints the table and the
targets as Markdown."""

import argparse
import html
import math
import sys

from . import db as dbmod
from . import quality, setups, simulations, stats
from .data import optimum

# OMPL's anytime (asymptotically near-optimal) planners, as src/registry/Registry.cpp marks them.
OMPL_ANYTIME = ("LBTRRT", "RRTstar", "InformedRRTstar", "SORRTstar", "RRTsharp", "RRTXstatic", "SST", "PRM",
                "PRMstar", "LazyPRM", "LazyPRMstar", "SPARS", "SPARStwo", "BITstar", "ABITstar", "AITstar",
                "CForest")
REFERENCE = "InformedRRTstar"  # the app set-up's reference for the first solution and time to within 1 %

HEAD = ["set-up", "planner", "exact / runs", "gap p50 [%]", "gap p75 [%]", "gap p90 [%]", "within 1 %",
        "their median t(1 %) [s]", "median t(1 %), all runs [s]", "median first solution [s]",
        "paths failing the dense check", "within 1 %, clean path", "median t(1 %), clean paths, all runs [s]"]


def is_memetic(planner):
    return planner.endswith("-MEM")


def is_ompl(planner):
    return planner in OMPL_ANYTIME


def experiments(database, exps=None):
    """The planning experiments with an exact optimum (of \\p exps, default every one of the database)."""
    exps = database.experiments if exps is None else exps
    return [e for e in exps if not simulations.is_simulation(e) and optimum(e)]


def setup_name(exp):
    """The set-up as the table names it: "exact", or "app R" (R the DiscreteMotionValidator's resolution)."""
    kind, resolution = setups.setup_of(exp)
    return "%s %g" % (kind, resolution) if kind == "app" and resolution else kind


def row(database, members):
    """The statistics of one (set-up, planner) over its (experiment, run) pairs."""
    gaps, t1, first, clean = [], [], [], []
    exact = failing = 0
    for exp, r in members:
        opt = optimum(exp)
        exact += r.outcome == "exact"
        failing += dbmod.run_value(r, "collision_free") == 0
        g = quality.gap(database, r, opt)
        gaps.append(math.inf if g is None else g)
        t = quality.time_to(database, r, opt, 0.01)
        t1.append(math.inf if t is None else t)
        clean.append(math.inf if t is None or dbmod.run_value(r, "collision_free") == 0 else t)
        f = quality.time_to(database, r, opt, None)
        first.append(math.inf if f is None else f)
    reached = [t for t in t1 if math.isfinite(t)]
    return {"runs": len(members), "exact": exact, "p50": stats.percentile(gaps, 50),
            "p75": stats.percentile(gaps, 75), "p90": stats.percentile(gaps, 90), "within": len(reached),
            "t1_reached": stats.median(reached), "t1": stats.percentile(t1, 50), "first": stats.percentile(first, 50),
            "dense_failures": failing, "within_clean": sum(math.isfinite(t) for t in clean),
            "t1_clean": stats.percentile(clean, 50)}


def rows(database, exps=None):
    """[(set-up name, planner, row)] for the experiments with an optimum, the exact set-up first, planners in
    the database's order."""
    groups = {}
    for exp in experiments(database, exps):
        label = setup_name(exp)
        for planner in database.planners_of(exp.id):
            groups.setdefault((label, planner), []).extend((exp, r) for r in database.runs_of(exp.id, planner))
    order = {p: i for i, p in enumerate(database.planners)}
    keys = sorted(groups, key=lambda k: (k[0] != "exact", k[0], order.get(k[1], len(order)), k[1]))
    return [(s, p, row(database, groups[(s, p)])) for s, p in keys]


def _min(candidates, key):
    """(planner, row) of the smallest value of \\p key among \\p candidates (None when there is none)."""
    best = None
    for p, r in candidates:
        v = r[key]
        if v is not None and (best is None or v < best[1][key]):
            best = (p, r)
    return best


def verdicts(table):
    """Per set-up: issue 31's targets as (set-up name, [(target, measured, met)]), met True, False or None
    (undecided: both sides infinite). The best memetic planner is the one with the lowest 90th-percentile gap
    (then 75th, 50th, median time to within 1 %), compared with the lowest of OMPL's planners in each measure."""
    out = []
    for label in dict.fromkeys(s for s, _, _ in table):
        mine = [(p, r) for s, p, r in table if s == label]
        memetic = [(p, r) for p, r in mine if is_memetic(p)]
        ompl = [(p, r) for p, r in mine if is_ompl(p)]
        lines = []
        if memetic:
            missing = ["%s %d/%d" % (p, r["exact"], r["runs"]) for p, r in memetic if r["exact"] < r["runs"]]
            lines.append(("every memetic run exact", "; ".join(missing) if missing else "all exact", not missing))
            dense = ["%s %d" % (p, r["dense_failures"]) for p, r in memetic if r["dense_failures"]]
            lines.append(("no memetic path fails the dense check", "; ".join(dense) if dense else "none fails",
                          not dense))
        best = min(memetic, key=lambda pr: (pr[1]["p90"], pr[1]["p75"], pr[1]["p50"], pr[1]["t1"]), default=None)
        if best and ompl:
            for key, what in (("p90", "90th-percentile gap"), ("t1", "median time to within 1 % (all runs)")):
                b = _min(ompl, key)
                unit = " %" if key == "p90" else " s"
                measured = "%s %s vs %s %s" % (best[0], _plain(best[1][key], unit), b[0], _plain(b[1][key], unit))
                lines.append(("best memetic's %s at or below the best OMPL planner's" % what, measured,
                              _at_most(best[1][key], b[1][key])))
        reference = dict(ompl).get(REFERENCE)
        if best and reference and label != "exact":
            for key, what in (("first", "median first solution"), ("t1", "median time to within 1 % (all runs)"),
                              ("t1_clean", "median time to within 1 % with a path passing the dense check "
                                           "(all runs)")):
                measured = "%s %s vs %s %s" % (best[0], _plain(best[1][key], " s"), REFERENCE,
                                               _plain(reference[key], " s"))
                lines.append(("best memetic's %s no slower than %s's" % (what, REFERENCE), measured,
                              _at_most(best[1][key], reference[key])))
        if lines:
            out.append((label, lines))
    return out


def _at_most(a, b):
    """a <= b; None (undecided) when both are infinite: neither got there in enough runs to tell."""
    return None if math.isinf(a) and math.isinf(b) else a <= b


def verdict(met):
    return "undecided: both inf" if met is None else ("met" if met else "not met")


def _plain(v, unit="", digits=3):
    if v is None:
        return "-"
    if math.isinf(v):
        return "inf"
    return ("%." + str(digits) + "f") % v + unit


def cells(label, planner, r):
    """A row of HEAD as text (+infinity written inf, nothing to tell -)."""
    return [label, planner, "%d/%d" % (r["exact"], r["runs"]), _plain(r["p50"]), _plain(r["p75"]), _plain(r["p90"]),
            "%d/%d" % (r["within"], r["runs"]), _plain(r["t1_reached"]), _plain(r["t1"]), _plain(r["first"]),
            "%d" % r["dense_failures"], "%d/%d" % (r["within_clean"], r["runs"]), _plain(r["t1_clean"])]


def markdown(database, exps=None):
    """The table and the targets as Markdown ("" without experiments with an optimum)."""
    table = rows(database, exps)
    if not table:
        return ""
    lines = ["| " + " | ".join(HEAD) + " |", "|" + "---|" * len(HEAD)]
    lines += ["| " + " | ".join(cells(s, p, r)) + " |" for s, p, r in table]
    lines.append("")
    lines.append(NOTE % len(experiments(database, exps)))
    for label, checks in verdicts(table):
        lines.append("")
        lines.append("Targets, %s:" % label)
        lines += ["- %s: %s (%s)" % (what, measured, verdict(met)) for what, measured, met in checks]
    return "\n".join(lines) + "\n"


NOTE = ("%d experiments with an exact optimum. Set-ups (docs/setups.md): exact = mhplan's exact checker and motion "
        "validator; app R = a point checker and OMPL's DiscreteMotionValidator at resolution R. Gap: %% above the "
        "exact optimum, a run without an exact solution at inf. Times from the start of solve() (improvements "
        "table); 'all runs' medians count a run that never got there as inf.")


def render(data, ctx):
    """Report section (docs/report.md): issue 31's targets, when some planning experiment has an optimum."""
    from . import page
    table = rows(data.database, data.planning)
    if not table:
        return []
    parts = ["<h2>Targets (issue 31)</h2>",
             "<p>Per validity set-up and planner (benchmarks/README.md, \"Issue 31's targets\"). %s The same "
             "table as Markdown: <code>PYTHONPATH=analysis /usr/bin/python3 -m mhplan_analysis.targets "
             "DB</code>.</p>" % html.escape(NOTE % len(experiments(data.database, data.planning))),
             page.table(HEAD, [[html.escape(c) for c in cells(s, p, r)] for s, p, r in table])]
    for label, checks in verdicts(table):
        parts.append("<p>Targets, %s:</p><ul>%s</ul>" % (html.escape(label), "".join(
            "<li>%s: %s (<b>%s</b>)</li>" % (html.escape(w), html.escape(m), verdict(ok))
            for w, m, ok in checks)))
    if data.database.improvements is None:
        ctx.notes.append("Targets: times come from progress samples (no improvements table).")
    return parts


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m mhplan_analysis.targets",
                                     description="Print issue 31's targets table of a benchmark database as "
                                                 "Markdown (benchmarks/README.md, \"Issue 31's targets\").")
    parser.add_argument("database", help="SQLite database written by mhplan bench")
    args = parser.parse_args(argv)
    try:
        database = dbmod.load(args.database)
    except Exception as e:  # a missing file, not a database, not a benchmark database
        print("targets: error: cannot read '%s': %s" % (args.database, e), file=sys.stderr)
        return 1
    text = markdown(database)
    if not text:
        print("targets: error: '%s' has no planning experiment with an exact optimum" % args.database,
              file=sys.stderr)
        return 1
    sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
