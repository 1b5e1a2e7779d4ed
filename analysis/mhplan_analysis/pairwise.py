# SPDX-License-Identifier: BSD-3-Clause
"""Pairwise comparison of planners on one problem, as the planning literature reports it: the two-sided
Mann-Whitney U test (exact null distribution without ties and up to MAX_EXACT runs per side, else the normal
approximation with tie and continuity correction), Holm's step-down correction over all pairs of a problem,
and the Vargha-Delaney A12 effect size. Censored values (a run that never reached the quality) are +inf: they
rank behind every finite value and tie with each other, which is what a rank test needs.

Conventions (docs/cli.md does not cover these; the report states them): for samples x and y,
U = #(x_i > y_j) + 0.5 #(x_i = y_j) and A12(x, y) = U / (n_x n_y) = P(X > Y) + 0.5 P(X = Y). For costs (gap,
time) lower is better, so "row better than column" is A12(column, row)."""

import math

MAX_EXACT = 50


def u_statistic(x, y):
    """U of x against y: pairs with x_i > y_j, ties counted one half (by ranks, O((n+m) log(n+m)))."""
    pooled = sorted([(v, 0) for v in x] + [(v, 1) for v in y], key=lambda t: t[0])
    ranks = [0.0] * len(pooled)
    i = 0
    while i < len(pooled):
        j = i
        while j + 1 < len(pooled) and pooled[j + 1][0] == pooled[i][0]:
            j += 1
        for k in range(i, j + 1):
            ranks[k] = 0.5 * (i + j) + 1.0
        i = j + 1
    rx = sum(r for r, (_, side) in zip(ranks, pooled) if side == 0)
    n = len(x)
    return rx - n * (n + 1) / 2.0


def a12(x, y):
    """Vargha-Delaney A12 = P(X > Y) + 0.5 P(X = Y); None for an empty sample."""
    if not x or not y:
        return None
    return u_statistic(x, y) / (len(x) * len(y))


def _exact_counts(n, m):
    """Number of arrangements giving U = 0..n m under the null (no ties): the coefficients of the Gaussian
    binomial [n + m choose n]_q = prod_{i=1..n} (1 - q^(m+i)) / (1 - q^i), in exact integers."""
    size = n * m + 1
    poly = [0] * size
    poly[0] = 1
    for i in range(1, n + 1):
        # Multiply by (1 - q^(m+i)), then divide by (1 - q^i) (a running sum with stride i).
        k = m + i
        for d in range(size - 1, k - 1, -1):
            poly[d] -= poly[d - k]
        for d in range(i, size):
            poly[d] += poly[d - i]
    return poly


def _normal_sf(z):
    return 0.5 * math.erfc(z / math.sqrt(2.0))


def mann_whitney(x, y):
    """Two-sided Mann-Whitney U test of x against y: {"u", "p", "method"} ("exact" or "normal"); None for an
    empty sample."""
    n, m = len(x), len(y)
    if n == 0 or m == 0:
        return None
    u = u_statistic(x, y)
    pooled = list(x) + list(y)
    ties = len(set(pooled)) != len(pooled)
    if not ties and max(n, m) <= MAX_EXACT:
        counts = _exact_counts(n, m)
        total = sum(counts)
        k = int(round(u))
        low = sum(counts[: k + 1])
        high = sum(counts[k:])
        return {"u": u, "p": min(1.0, 2.0 * min(low, high) / total), "method": "exact"}
    total = n + m
    tie_sum = 0
    values = sorted(pooled)
    i = 0
    while i < total:
        j = i
        while j + 1 < total and values[j + 1] == values[i]:
            j += 1
        t = j - i + 1
        tie_sum += t ** 3 - t
        i = j + 1
    mu = n * m / 2.0
    var = n * m / 12.0 * ((total + 1) - tie_sum / (total * (total - 1)))
    if var <= 0.0:
        return {"u": u, "p": 1.0, "method": "normal"}
    z = (max(u, n * m - u) - mu - 0.5) / math.sqrt(var)
    return {"u": u, "p": min(1.0, 2.0 * _normal_sf(z)), "method": "normal"}


def holm(pvalues):
    """Holm's step-down adjusted p-values, in the order given (None stays None)."""
    idx = [i for i, p in enumerate(pvalues) if p is not None]
    order = sorted(idx, key=lambda i: pvalues[i])
    m = len(order)
    out = list(pvalues)
    running = 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (m - rank) * pvalues[i]))
        out[i] = running
    return out


def matrix(samples, alpha=0.05):
    """All pairs of planners of one problem. samples: planner -> list of costs (lower is better, +inf
    censored). Returns {(a, b): {"better": A12 that a beats b, "p", "p_holm", "significant", "method"}} for
    every ordered pair a != b with data, Holm-corrected over the unordered pairs."""
    names = [p for p in samples if samples[p]]
    pairs = [(a, b) for i, a in enumerate(names) for b in names[i + 1 :]]
    tests = [mann_whitney(samples[a], samples[b]) for a, b in pairs]
    adjusted = holm([t["p"] for t in tests])
    out = {}
    for (a, b), t, padj in zip(pairs, tests, adjusted):
        for row, col in ((a, b), (b, a)):
            out[(row, col)] = {
                "better": a12(samples[col], samples[row]),
                "p": t["p"],
                "p_holm": padj,
                "significant": padj < alpha,
                "method": t["method"],
            }
    return out
