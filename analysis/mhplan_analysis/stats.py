# SPDX-License-Identifier: BSD-3-Clause
"""Small statistics used by the report (numpy only)."""

import math

import numpy as np


def median(values):
    v = [x for x in values if x is not None]
    return float(np.median(v)) if v else None


def mean(values):
    v = [x for x in values if x is not None]
    return float(np.mean(v)) if v else None


def std(values):
    """Sample standard deviation (ddof = 1, as MATLAB's std in the papers' tables); None below 2 values."""
    v = [x for x in values if x is not None]
    return float(np.std(v, ddof=1)) if len(v) >= 2 else None


def percentile(values, q):
    """The q-th percentile (0..100) of \\p values, linear between the order statistics (numpy's default);
    +inf values (censored: unsolved runs) sort last, and a percentile that needs one is +inf. None without
    values."""
    v = sorted(x for x in values if x is not None)
    if not v:
        return None
    pos = (len(v) - 1) * q / 100.0
    lo, hi = int(math.floor(pos)), int(math.ceil(pos))
    if hi == lo or math.isinf(v[hi]):
        return v[hi]
    return v[lo] + (v[hi] - v[lo]) * (pos - lo)


def median_ci_indices(n, confidence=0.95):
    """Order-statistic indices (0-based, inclusive) of a distribution-free confidence interval for the
    median of n samples: the binomial(n, 1/2) quantiles (normal approximation, clamped)."""
    if n <= 0:
        return None
    z = 1.959963984540054 if abs(confidence - 0.95) < 1e-12 else abs(_normal_ppf((1 - confidence) / 2))
    lo = int(math.floor(n / 2.0 - z * math.sqrt(n) / 2.0))
    hi = int(math.ceil(1 + n / 2.0 + z * math.sqrt(n) / 2.0)) - 1
    return max(lo, 0), min(hi, n - 1)


def _normal_ppf(p):
    # Acklam-style rational approximation is overkill here; bisection on erf is exact enough.
    lo, hi = -10.0, 10.0
    for _ in range(200):
        mid = (lo + hi) / 2
        if 0.5 * (1 + math.erf(mid / math.sqrt(2))) < p:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def step_series(samples, grid):
    """Best cost so far at each grid time from (time, cost) samples (NaN before the first finite cost)."""
    out = np.full(len(grid), np.nan)
    pts = sorted((t, c) for t, c in samples if t is not None and c is not None and math.isfinite(c))
    best, k = math.inf, 0
    for i, g in enumerate(grid):
        while k < len(pts) and pts[k][0] <= g:
            best = min(best, pts[k][1])
            k += 1
        if math.isfinite(best):
            out[i] = best
    return out


def median_band(matrix, confidence=0.95):
    """Column-wise median and CI band over runs (rows); a column's statistics are reported only when more
    than half of the runs have a value there (so the median is defined), else NaN."""
    runs, cols = matrix.shape
    med = np.full(cols, np.nan)
    lo = np.full(cols, np.nan)
    hi = np.full(cols, np.nan)
    for j in range(cols):
        col = matrix[:, j]
        # A run without a solution yet counts as +infinity: it is worse than any cost.
        col = np.where(np.isnan(col), np.inf, col)
        if np.sum(np.isfinite(col)) * 2 <= runs:
            continue
        s = np.sort(col)
        med[j] = np.median(s)
        a, b = median_ci_indices(runs, confidence)
        lo[j] = s[a]
        hi[j] = s[b] if np.isfinite(s[b]) else np.nan
    return med, lo, hi
