# SPDX-License-Identifier: BSD-3-Clause
"""Report section: what the campaign recorded about the machine's load while the planners planned (and the
gaps in the data found on reading: no saved paths, no CPU times)."""

from .data import load_summary


def load_text(summary):
    """One sentence (HTML) stating data.load_summary()."""
    parts = []
    if summary["share"] is not None:
        parts.append("the planners had %.0f %% of a core while they planned (CPU time over wall time of "
                     "solve(), %d runs)" % (100.0 * summary["share"], summary["runs"]))
    if summary["load_min"] is not None:
        load = ("%.2f" % summary["load_min"] if summary["load_min"] == summary["load_max"]
                else "%.2f to %.2f" % (summary["load_min"], summary["load_max"]))
        cores = " on %s core(s) available" % "/".join(str(c) for c in summary["cores"]) if summary["cores"] else ""
        parts.append("the system's 1-minute load average at the experiments' ends was %s%s" % (load, cores))
    if not parts:
        return None
    return "Machine load recorded by the campaign: " + "; ".join(parts) + "."


def render(data, ctx):
    if not data.paths and data.planning:
        ctx.notes.append("The database has no saved paths: no path figures.")
    if not data.planning:
        return []
    out = []
    load = load_summary(data.database, data.planning)
    sentence = load_text(load)
    if sentence:
        out.append("<p class='load'>%s</p>" % sentence)
    else:
        ctx.notes.append("The database records neither CPU times nor the machine's load (an older campaign): "
                         "whether the planners had their cores is unknown.")
    if load["share"] is not None and load["share"] < 0.8:
        ctx.notes.append("The planners had only %.0f %% of a core while they planned (other load on the cores): "
                         "time-limited planners did that much less work (campaign time_limit_kind: cpu bounds "
                         "CPU time instead)." % (100.0 * load["share"]))
    return out
