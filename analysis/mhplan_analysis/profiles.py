# SPDX-License-Identifier: BSD-3-Clause
"""Performance profiles over a campaign's problems (Dolan and More 2002): with c[p][s] the cost of planner p
on problem s (+inf when it did not solve it), r[p][s] = c[p][s] / min_q c[q][s], and
rho_p(tau) = share of problems with r[p][s] <= tau. rho_p(1) is the share of problems where p is (one of) the
best, rho_p(large tau) the share it solves at all. A problem nobody solved counts against everyone. Beside it,
the share of runs within tau % of the exact optimum (gap <= tau), over all runs of all problems."""

import math


def ratios(costs):
    """costs: planner -> list of per-problem costs (same problem order; +inf = unsolved). Returns
    planner -> list of ratios to the best planner of each problem (+inf when unsolved)."""
    planners = list(costs)
    if not planners:
        return {}
    problems = len(costs[planners[0]])
    out = {p: [] for p in planners}
    for s in range(problems):
        best = min(costs[p][s] for p in planners)
        for p in planners:
            c = costs[p][s]
            if not math.isfinite(c) or not math.isfinite(best):
                out[p].append(math.inf)
            elif best <= 0.0:
                out[p].append(1.0 if c <= 0.0 else math.inf)
            else:
                out[p].append(c / best)
    return out


def profile(costs, taus):
    """planner -> [rho_p(tau) for tau in taus]."""
    r = ratios(costs)
    out = {}
    for p, values in r.items():
        values = sorted(values)
        n = len(values)
        curve = []
        k = 0
        for tau in sorted(taus):
            while k < n and values[k] <= tau:
                k += 1
            curve.append(k / n if n else 0.0)
        # Back to the caller's tau order.
        by_tau = dict(zip(sorted(taus), curve))
        out[p] = [by_tau[t] for t in taus]
    return out


def within_gap(gaps, taus):
    """gaps: planner -> list of run gaps in % (+inf or None for a run without an exact path). Returns
    planner -> [share of runs with gap <= tau for tau in taus]."""
    out = {}
    for p, values in gaps.items():
        v = [math.inf if g is None else g for g in values]
        out[p] = [sum(1 for g in v if g <= tau) / len(v) if v else 0.0 for tau in taus]
    return out
