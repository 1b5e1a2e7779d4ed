# SPDX-License-Identifier: BSD-3-Clause
"""mhplan's analysis: reads OMPL benchmark databases written by `mhplan bench` and draws the report."""
