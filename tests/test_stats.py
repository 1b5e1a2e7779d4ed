#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report's statistics against closed forms and independent computations: Mann-Whitney U and A12 by
brute force over all pairs, the exact p-value by enumerating every split of the pooled sample, the normal
approximation and the exact test against scipy (when Debian's python3-scipy is there), Holm's correction by
hand, and performance profiles against a direct count."""

import itertools
import math
import os
import random
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "analysis"))

from mhplan_analysis import pairwise, profiles  # noqa: E402


def brute_u(x, y):
    return sum(1.0 if a > b else 0.5 if a == b else 0.0 for a in x for b in y)


def brute_exact_p(x, y):
    """Share of all C(n+m, n) splits of the pooled sample whose U is as far from n m / 2 as the observed."""
    pooled = list(x) + list(y)
    n, m = len(x), len(y)
    mu = n * m / 2.0
    observed = abs(brute_u(x, y) - mu)
    extreme = total = 0
    for chosen in itertools.combinations(range(n + m), n):
        xs = [pooled[i] for i in chosen]
        ys = [pooled[i] for i in range(n + m) if i not in chosen]
        total += 1
        extreme += abs(brute_u(xs, ys) - mu) >= observed - 1e-12
    return extreme / total


class MannWhitneyTest(unittest.TestCase):
    def test_closed_forms(self):
        # Completely separated samples: U = 0, A12 = 0, exact two-sided p = 2 / C(6, 3) = 0.1.
        t = pairwise.mann_whitney([1, 2, 3], [4, 5, 6])
        self.assertEqual(t["u"], 0.0)
        self.assertEqual(t["method"], "exact")
        self.assertAlmostEqual(t["p"], 0.1, places=12)
        self.assertEqual(pairwise.a12([1, 2, 3], [4, 5, 6]), 0.0)
        self.assertEqual(pairwise.a12([4, 5, 6], [1, 2, 3]), 1.0)
        # Identical samples: A12 = 0.5, p = 1.
        self.assertEqual(pairwise.a12([1, 1, 1], [1, 1, 1]), 0.5)
        self.assertEqual(pairwise.mann_whitney([2, 2], [2, 2])["p"], 1.0)
        # n = m = 5 separated: p = 2 / 252.
        self.assertAlmostEqual(pairwise.mann_whitney(range(5), range(10, 15))["p"], 2.0 / 252.0, places=12)

    def test_u_and_a12_equal_brute_force_over_all_pairs(self):
        rng = random.Random(5)
        for _ in range(200):
            n, m = rng.randint(1, 12), rng.randint(1, 12)
            # Small integers force ties; some censored runs (+inf) too.
            x = [rng.choice([rng.randint(0, 6), math.inf]) for _ in range(n)]
            y = [rng.choice([rng.randint(0, 6), math.inf]) for _ in range(m)]
            self.assertAlmostEqual(pairwise.u_statistic(x, y), brute_u(x, y), places=9)
            self.assertAlmostEqual(pairwise.a12(x, y), brute_u(x, y) / (n * m), places=12)

    def test_exact_p_equals_enumeration_of_every_split(self):
        rng = random.Random(7)
        for _ in range(40):
            n, m = rng.randint(1, 6), rng.randint(1, 6)
            pooled = rng.sample(range(100), n + m)
            x, y = pooled[:n], pooled[n:]
            t = pairwise.mann_whitney(x, y)
            self.assertEqual(t["method"], "exact")
            self.assertAlmostEqual(t["p"], brute_exact_p(x, y), places=12)

    def test_against_scipy(self):
        try:
            from scipy.stats import mannwhitneyu
        except ImportError:
            self.skipTest("python3-scipy not installed")
        rng = random.Random(11)
        for _ in range(60):
            n, m = rng.randint(2, 30), rng.randint(2, 30)
            x = [rng.gauss(0.0, 1.0) for _ in range(n)]
            y = [rng.gauss(0.4, 1.0) for _ in range(m)]
            t = pairwise.mann_whitney(x, y)
            ref = mannwhitneyu(x, y, alternative="two-sided", method="exact")
            self.assertAlmostEqual(t["u"], ref.statistic, places=9)
            self.assertAlmostEqual(t["p"], ref.pvalue, places=9)
            # With ties (rounded values, censored runs): the normal approximation with tie correction.
            xt = [round(v, 0) if rng.random() < 0.9 else math.inf for v in x]
            yt = [round(v, 0) if rng.random() < 0.9 else math.inf for v in y]
            big = 1e300  # scipy ranks +inf fine too, but keep its input finite
            t = pairwise.mann_whitney(xt, yt)
            ref = mannwhitneyu([min(v, big) for v in xt], [min(v, big) for v in yt], alternative="two-sided",
                               method="asymptotic", use_continuity=True)
            self.assertEqual(t["method"], "normal")
            self.assertAlmostEqual(t["p"], ref.pvalue, places=9)

    def test_holm_by_hand(self):
        # Sorted 0.005, 0.01, 0.03, 0.04 times 4, 3, 2, 1 = 0.02, 0.03, 0.06, 0.04 -> running max.
        self.assertEqual([round(p, 12) for p in pairwise.holm([0.01, 0.04, 0.03, 0.005])], [0.03, 0.06, 0.06, 0.02])
        self.assertEqual(pairwise.holm([0.5, None, 0.9]), [1.0, None, 1.0])
        self.assertEqual(pairwise.holm([]), [])

    def test_matrix(self):
        fast = [1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7]
        slow = [5.0, 5.1, 5.2, 5.3, 5.4, 5.5, 5.6, math.inf]
        same = [5.0, 5.1, 5.2, 5.3, 5.4, 5.5, 5.6, math.inf]
        m = pairwise.matrix({"A": fast, "B": slow, "C": same, "D": []})
        self.assertEqual(m[("A", "B")]["better"], 1.0)
        self.assertEqual(m[("B", "A")]["better"], 0.0)
        self.assertTrue(m[("A", "B")]["significant"])
        self.assertFalse(m[("B", "C")]["significant"])
        self.assertEqual(m[("B", "C")]["better"], 0.5)
        self.assertNotIn(("A", "D"), m)
        # Holm over the three pairs: each adjusted p is at least the raw p.
        for v in m.values():
            self.assertGreaterEqual(v["p_holm"], v["p"])


class ProfileTest(unittest.TestCase):
    def test_closed_form(self):
        # Problem 1: A 1, B 2; problem 2: A 4, B 2; problem 3: A inf, B 3; problem 4: nobody.
        costs = {"A": [1.0, 4.0, math.inf, math.inf], "B": [2.0, 2.0, 3.0, math.inf]}
        self.assertEqual(profiles.ratios(costs), {"A": [1.0, 2.0, math.inf, math.inf], "B": [2.0, 1.0, 1.0, math.inf]})
        taus = [1.0, 1.5, 2.0, 100.0]
        self.assertEqual(profiles.profile(costs, taus), {"A": [0.25, 0.25, 0.5, 0.5], "B": [0.5, 0.5, 0.75, 0.75]})

    def test_against_a_direct_count(self):
        rng = random.Random(3)
        planners = ["P%d" % i for i in range(4)]
        costs = {p: [rng.choice([rng.uniform(0.1, 10.0), math.inf]) for _ in range(25)] for p in planners}
        taus = [1.0 + 0.25 * k for k in range(40)][::-1]  # any order
        prof = profiles.profile(costs, taus)
        for p in planners:
            for tau, rho in zip(taus, prof[p]):
                count = 0
                for s in range(25):
                    best = min(costs[q][s] for q in planners)
                    count += math.isfinite(costs[p][s]) and math.isfinite(best) and costs[p][s] <= tau * best
                self.assertAlmostEqual(rho, count / 25.0, places=12)
            # Non-decreasing in tau.
            ordered = [r for _, r in sorted(zip(taus, prof[p]))]
            self.assertEqual(ordered, sorted(ordered))
        # At tau = 1 every solved problem has at least one best planner.
        solved = sum(1 for s in range(25) if any(math.isfinite(costs[q][s]) for q in planners))
        at_one = sum(prof[p][taus.index(1.0)] for p in planners) * 25
        self.assertGreaterEqual(at_one + 1e-9, solved)

    def test_within_gap(self):
        got = profiles.within_gap({"A": [0.0, 0.5, 2.0, None], "B": []}, [0.0, 1.0, 5.0])
        self.assertEqual(got, {"A": [0.25, 0.5, 0.75], "B": [0.0, 0.0, 0.0]})


if __name__ == "__main__":
    unittest.main()
