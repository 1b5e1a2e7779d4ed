# SPDX-License-Identifier: BSD-3-Clause
"""The "Validity set-ups" part of the report (docs/setups.md): which set-up every planning experiment ran with
(exact: mhplan's exact checker and motion validator; app: a plain point checker and OMPL's
DiscreteMotionValidator at a resolution, as a user's OMPL program), and per set-up and planner: the stored
paths that fail the independent dense check, the median gap, and the state and motion checks per run and per
improvement of the solution (columns state_checks, motion_checks, improvements)."""

import html

from . import db as dbmod
from . import stats


def setup_of(exp):
    """("exact", None) or ("app", resolution) of an experiment; databases from before set-ups are exact."""
    kind = dbmod.experiment_value(exp, "validity_setup")
    kind = str(kind) if kind not in (None, "") else "exact"
    return kind, dbmod.to_float(dbmod.experiment_value(exp, "validity_resolution"))


def label(exp):
    """How the report names an experiment's set-up."""
    kind, resolution = setup_of(exp)
    if kind == "app":
        return "app (point checker, DiscreteMotionValidator at resolution %g)" % resolution if resolution else "app"
    return "exact"


def rows(database, exps):
    """One row per (set-up, planner): set-up label, planner, runs, exact runs, paths checked, paths failing the
    dense check, exact runs failing it, median gap (exact, collision-free runs), median state and motion
    checks per run, median state and motion checks per improvement (runs with at least one improvement)."""
    groups = {}
    for exp in exps:
        for planner in database.planners_of(exp.id):
            groups.setdefault((label(exp), planner), []).extend((exp, r) for r in database.runs_of(exp.id, planner))
    out = []
    for (setup, planner) in sorted(groups, key=lambda k: (k[0] != "exact", k[0], k[1])):
        members = groups[(setup, planner)]
        checked = failing = exact = exact_failing = 0
        gaps, state, motion, state_per, motion_per = [], [], [], [], []
        for exp, r in members:
            free = dbmod.run_value(r, "collision_free")
            if free is not None:
                checked += 1
                failing += free == 0
            if r.outcome == "exact":
                exact += 1
                exact_failing += free == 0
                gap = dbmod.run_value(r, "optimality_gap")
                if gap is not None and free == 1:
                    gaps.append(gap)
            s = dbmod.run_value(r, "state_checks")
            m = dbmod.run_value(r, "motion_checks")
            improvements = dbmod.run_value(r, "improvements")
            if s is not None:
                state.append(s)
            if m is not None:
                motion.append(m)
            if improvements:
                if s is not None:
                    state_per.append(s / improvements)
                if m is not None:
                    motion_per.append(m / improvements)
        out.append((setup, planner, len(members), exact, checked, failing, exact_failing, stats.median(gaps),
                    stats.median(state), stats.median(motion), stats.median(state_per), stats.median(motion_per)))
    return out


def section(database, exps, table, fmt):
    """HTML of the set-ups part (a list of strings); empty without planning experiments."""
    if not exps:
        return []
    counts = {}
    for exp in exps:
        counts.setdefault(label(exp), []).append(exp.name)
    parts = ["<h2>Validity set-ups</h2>"]
    said = "; ".join("%s: %d experiment%s" % (html.escape(k), len(v), "" if len(v) == 1 else "s")
                     for k, v in sorted(counts.items(), key=lambda kv: kv[0] != "exact"))
    parts.append("<p class='setups'>Set-ups (docs/setups.md): %s. Experiments of the app set-up carry the suffix "
                 "<code>-app</code> in their names everywhere in this report. Every stored path is checked "
                 "independently (points along it at most min(r/4, diagonal/2000) apart, each valid by the "
                 "exact model), whatever the set-up the planner ran with.</p>" % said)

    def count(v):
        return "-" if v is None else "%.0f" % v

    parts.append(table(
        ["set-up", "planner", "runs", "exact", "paths checked", "paths failing the dense check",
         "exact runs failing it", "median gap", "state checks / run", "motion checks / run",
         "state checks / improvement", "motion checks / improvement"],
        [(html.escape(s), html.escape(p), n, ex, ch, fa, exfa, fmt(gap, 3, "%"), count(sc), count(mc), count(sp),
          count(mp))
         for (s, p, n, ex, ch, fa, exfa, gap, sc, mc, sp, mp) in rows(database, exps)]))
    return parts


def render(data, ctx):
    """Report section (docs/report.md): the set-ups of the planning experiments."""
    from . import page
    return section(data.database, data.planning, page.table, page.fmt)
