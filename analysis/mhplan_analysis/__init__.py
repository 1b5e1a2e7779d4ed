"""mhplan's analysis: reads OMPL benchmark databases written by `mhplan bench` and draws the report."""
