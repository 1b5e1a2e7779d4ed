# SPDX-License-Identifier: BSD-3-Clause
"""The report's shared HTML and figure helpers: tables, number formats, the page's style, planner colours,
figure files and the one box-plot figure (planning attributes and simulation makespans alike). Every section
module (docs/report.md) uses these, none defines its own."""

import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CSS = """body{font-family:sans-serif;max-width:1200px;margin:2em auto;color:#222}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#f0f0f0}td:first-child,th:first-child{text-align:left}img{max-width:100%;border:1px solid #eee}
.note{background:#fff8e0;border-left:4px solid #e0b000;padding:0.4em 0.8em}h2{border-bottom:1px solid #ddd}"""


def table(headers, rows):
    """An HTML table: \\p headers and \\p rows are HTML already (escape text before)."""
    out = ["<table><tr>" + "".join("<th>%s</th>" % h for h in headers) + "</tr>"]
    for r in rows:
        out.append("<tr>" + "".join("<td>%s</td>" % c for c in r) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def fmt(v, digits=3, suffix=""):
    """A number with \\p digits decimals; '&ndash;' for None, 'never' for infinity."""
    if v is None:
        return "&ndash;"
    if isinstance(v, float) and math.isinf(v):
        return "never"
    return ("%." + str(digits) + "f%s") % (v, suffix)


def fmt_ci(measured, digits=1):
    """'median % [lo, hi] (n, coverage)' of simulations.median_with_ci, with signed infinities."""
    if measured is None:
        return "&ndash;"

    def f(v):
        if math.isinf(v):
            return "+&infin;" if v > 0 else "&minus;&infin;"
        return ("%." + str(digits) + "f") % v

    return "%s %% [%s, %s] (n = %d, coverage %.0f %%)" % (f(measured["median"]), f(measured["lo"]), f(measured["hi"]), measured["n"], 100.0 * measured["coverage"])


def fmt_median(v, digits=2):
    """A censored median: 'unfinished' when more than half of the runs did not finish."""
    if v is None:
        return "&ndash;"
    if math.isinf(v):
        return "unfinished"
    return ("%." + str(digits) + "f") % v


def slug(text):
    """\\p text as a file-name part."""
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in text)


def planner_colors(planners):
    """Distinct colours: tab10, then Dark2 and Set1 (never two shades of one hue side by side)."""
    palette = list(plt.get_cmap("tab10").colors) + list(plt.get_cmap("Dark2").colors) + list(plt.get_cmap("Set1").colors)
    return {p: palette[i % len(palette)] for i, p in enumerate(planners)}


def save(fig, outdir, name, dpi=110):
    """Save \\p fig as outdir/name (tight), close it and return the file name the page links."""
    path = os.path.join(outdir, name)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    return os.path.basename(path)


def box_figure(panels, title, outdir, name, panel_width, rotation, finish=None):
    """The one box-plot figure of the report: panels side by side, one box per name, saved as outdir/name.
    \p panels: list of (data, names, label, decorate) with data one list of values per name (an empty list
    draws no box) and decorate None or decorate(ax, data), which sets the panel's scale and reference lines;
    finish(axes), when given, runs after every panel is drawn. Returns the file name."""
    fig, axes = plt.subplots(1, len(panels), figsize=(panel_width * len(panels) + 1.0, 4.6), squeeze=False)
    for ax, (data, names, label, decorate) in zip(axes[0], panels):
        ax.boxplot([d if d else [np.nan] for d in data], vert=True, widths=0.6, showfliers=True)
        ax.set_xticks(range(1, len(names) + 1))
        ax.set_xticklabels(names, rotation=rotation, ha="right", fontsize=8)
        ax.set_title(label, fontsize=10)
        if decorate:
            decorate(ax, data)
        ax.grid(axis="y", alpha=0.3)
    if finish:
        finish(axes[0])
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    return save(fig, outdir, name)
