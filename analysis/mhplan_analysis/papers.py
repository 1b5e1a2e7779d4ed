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

# [BFO] Abbas & Ali 2016: best path lengths reported (start/goal assumed (0,0) -> (10,10)).
BFO_REPORTED = {
    "bfo_case1": [("ATBFO", 14.5346, None)],
    "bfo_case1_moved": [("ATBFO", 14.5412, None)],
    "bfo_case2": [
        ("ATBFO (C = 0.1)", 14.4797, 8.27),
        ("ATBFO (C = 0.05)", 14.7852, 11.63),
        ("NBCA (cited)", 14.40351, 62.14),
        ("GA (cited)", 14.40982, 34.70),
    ],
}
BFO_NOTE = (
    "The paper gives no start and goal; we assume (0,0) to (10,10) in [0,10]^2. Under that query the exact "
    "optimum of case 2 is 14.4198, so the NBCA and GA figures it cites (below the optimum) must come from "
    "another query or scaling."
)
