# SPDX-License-Identifier: BSD-3-Clause
"""Numbers the seed papers report (docs/algorithms.md section 9), set beside ours in the report."""

# [LRSMA] Zheng et al. 2023, Table 3: per scenario and algorithm, path length (min, mean, std) and planning
# time (best run, mean) in seconds. Their scenarios' coordinates are not published: ours are reconstructions.
LRSMA_TABLE3 = {
    1: {
        "GWO": (29.15, 30.14, 0.71, 2.00, 2.00),
        "WOA": (29.10, 29.92, 0.38, 2.08, 2.07),
        "PSO": (29.37, 30.25, 0.37, 1.73, 1.76),
        "SMA": (29.10, 29.88, 0.62, 2.02, 2.01),
        "LRSMA": (29.11, 29.81, 0.55, 2.16, 2.18),
    },
    2: {
        "GWO": (29.13, 37.23, 12.75, 1.95, 1.97),
        "WOA": (30.51, 33.43, 15.70, 2.08, 2.09),
        "PSO": (31.52, 34.31, 4.50, 1.91, 1.85),
        "SMA": (31.52, 32.50, 1.04, 1.97, 1.97),
        "LRSMA": (29.11, 32.32, 0.91, 2.06, 2.08),
    },
    3: {
        "GWO": (30.03, 42.52, 22.78, 2.80, 2.81),
        "WOA": (29.90, 37.38, 93.64, 3.11, 3.04),
        "PSO": (30.10, 37.61, 9.46, 2.81, 2.68),
        "SMA": (29.90, 35.82, 9.04, 2.97, 2.94),
        "LRSMA": (28.91, 34.58, 4.81, 2.97, 2.98),
    },
}
LRSMA_WORLDS = {"lrsma_scenario1": 1, "lrsma_scenario2": 2, "lrsma_scenario3": 3}

# [BFO] Abbas & Ali 2016: ATBFO's best path lengths (start/goal assumed (0,0) -> (10,10)) and, where the paper
# gives one, the time of its FASTEST run (Figs 10 and 12: a different run from the shortest path's). Numbers are
# kept as the paper prints them (text), so the report shows them at the paper's own precision.
# Case 1 (docs/algorithms.md 9.1, corrected 2026-12-01): the paper contradicts itself (Table 1 lists obstacle 1
# at (2,2); the text moves it "from (3,2) to (2,2)" in the second scenario, where APF fails). So bfo_case1
# (Table 1's (2,2)) is the second scenario, 14.5412, and bfo_case1_moved ((3,2)) the first, 14.5346.
BFO_REPORTED = {
    "bfo_case1": [("ATBFO (scenario 2, obstacle 1 at (2,2))", "14.5412", None)],
    "bfo_case1_moved": [("ATBFO (scenario 1, obstacle 1 at (3,2))", "14.5346", None)],
    "bfo_case2": [
        ("ATBFO (C = 0.1)", "14.4797", "8.27"),
        ("ATBFO (C = 0.05)", "14.7852", "11.63"),
        ("NBCA (cited)", "14.40351", "62.14"),
        ("GA (cited)", "14.40982", "34.70"),
    ],
}
BFO_NOTE = (
    "The paper gives no start and goal; we assume (0,0) to (10,10) in [0,10]^2. Under that query the exact "
    "optimum of case 2 is 14.4198, so the NBCA and GA figures it cites (below the optimum) must come from "
    "another query or scaling. The paper's lengths are ATBFO's (online mode); its times (8.27 s, 11.63 s) are "
    "those of the fastest runs, not of the runs with the shortest paths. Case 1: the paper contradicts itself "
    "(Table 1 puts obstacle 1 at (2,2), the text says the second scenario moves it from (3,2) to (2,2), where "
    "APF fails): bfo_case1 (Table 1's (2,2)) is taken as the second scenario (14.5412), bfo_case1_moved ((3,2)) "
    "as the first (14.5346)."
)

LRSMA_NOTE = (
    "Our scenarios are reconstructions (the paper publishes no coordinates): the paper's numbers are context, "
    "not a like-for-like comparison. The paper's means and standard deviations evidently include runs that "
    "ended in collision, with their penalised fitness (WOA's scenario-3 std 93.64 exceeds its mean 37.38, which "
    "collision-free lengths near 29 cannot give), so ours are given both ways: the fitness S = length + 1000 f2 "
    "([LRSMA]'s, eta2 = 1000) of every run's reported path, and the lengths of the exact (collision-free) runs "
    "only. The paper ran 100 runs per algorithm, every algorithm (SMA too) in its spline framework with m = 3."
)


def lrsma_fitness(points, circles, bounds, exact, samples=100):
    """[LRSMA]'s fitness S = length + 1000 f2 of a reported path (docs/algorithms.md 1.2), as mhplan's planners
    measure it: the interpolation points are the path sampled at `samples` evenly spaced values of the vertex
    parameter t = 0..k (for a spline-decoded path of `samples` vertices these are its vertices);
    f2 = sum over circles (cx, cy, R) of the mean over the points of max(1 - |q - c| / R, 0), plus the mean of
    min(distance outside the bounds, 1); a path that is not exact but has f2 = 0 gets f2 = 1e-3 (a collision
    between samples). None for a path of fewer than 2 points."""
    if not points or len(points) < 2:
        return None
    k = len(points) - 1
    qs = []
    for i in range(samples):
        t = k * i / (samples - 1)
        j = min(int(t), k - 1)
        u = t - j
        (x0, y0), (x1, y1) = points[j][:2], points[j + 1][:2]
        qs.append((x0 + (x1 - x0) * u, y0 + (y1 - y0) * u))
    f2 = 0.0
    for cx, cy, r in circles:
        if r > 0:
            f2 += sum(max(1.0 - ((qx - cx) ** 2 + (qy - cy) ** 2) ** 0.5 / r, 0.0) for qx, qy in qs) / len(qs)
    xmin, xmax, ymin, ymax = bounds
    outside = 0.0
    for qx, qy in qs:
        dx = max(xmin - qx, 0.0, qx - xmax)
        dy = max(ymin - qy, 0.0, qy - ymax)
        outside += min((dx * dx + dy * dy) ** 0.5, 1.0)
    f2 += outside / len(qs)
    if not exact and f2 == 0.0:
        f2 = 1e-3
    length = sum(((points[i + 1][0] - points[i][0]) ** 2 + (points[i + 1][1] - points[i][1]) ** 2) ** 0.5 for i in range(k))
    return length + 1000.0 * f2
