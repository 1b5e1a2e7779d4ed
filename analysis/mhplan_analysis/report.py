# SPDX-License-Identifier: BSD-3-Clause
"""One HTML report from an mhplan/OMPL benchmark database, assembled from sections (docs/report.md): the
database is read once into a data.ReportData, then every module named in SECTIONS renders its part of the
page, in that order. Every number in a table is computed from the database (the tests recompute them with
SQL).

A section is a module of this package with render(data, ctx) -> list of HTML strings (empty when the
database has nothing for it). data is the ReportData; ctx gives outdir (where figures go), colors (planner
-> colour, the same in every figure) and notes (append plain-text gaps in the data; the page lists them
under "Gaps in the data"). Tables, formats and figure files come from page.py."""

import html
import importlib
import os

from . import data as datamod
from . import db as dbmod  # noqa: F401 (the tests reach the modules through report)
from . import simulations, stats, worlds  # noqa: F401
from .data import load_paths, load_summary, table_rows  # noqa: F401
from .figures import (attribute_scale, box_plots, convergence_figure, convergence_plot,  # noqa: F401
                      convergence_series, experiment_query, experiment_yaws, path_figure, success_bars)
from .overview import load_text  # noqa: F401
from .page import CSS, plt  # noqa: F401
from .page import planner_colors as _planner_colors

_optimum = datamod.optimum

# The sections in page order: one module name a line. A new section is a new module and one line here.
SECTIONS = [
    "overview",       # the machine's load while the campaign planned
    "ranking",        # success bars, ranking per problem
    "comparisons",    # performance profiles
    "setups",         # validity set-ups (exact, app), dense-check failures, checks per improvement
    "targets",        # issue 31's targets per set-up and planner (experiments with an exact optimum)
    "paper_tables",   # [LRSMA] Table 3, [BFO]
    "scaling",        # the scaling suite's families
    "movingai",       # MovingAI benchmark sets by bucket
    "moving_worlds",  # simulations
    "problems",       # per problem: figures, tables, pairwise tests, times to quality
]


class Context:
    """What a section writes to besides its HTML: the figure directory, the planners' colours, the notes."""

    def __init__(self, outdir, colors, notes):
        self.outdir, self.colors, self.notes = outdir, colors, notes


def sections():
    """The section modules of SECTIONS, imported."""
    return [importlib.import_module("." + name, __package__) for name in SECTIONS]


def write_report(database_path, outdir, world_dir=None):
    """Write index.html and its figures into outdir; returns the index path."""
    os.makedirs(outdir, exist_ok=True)
    data = datamod.ReportData(database_path, world_dir)
    database = data.database
    ctx = Context(outdir, _planner_colors(database.planners), list(database.notes))
    parts = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>mhplan report</title><style>%s</style></head><body>" % CSS]
    parts.append("<h1>mhplan benchmark report</h1>")
    parts.append("<p>Database <code>%s</code>: %d experiments, %d planners, %d runs.</p>" % (html.escape(database_path), len(database.experiments), len(database.planners), len(database.runs)))
    header = len(parts)
    for section in sections():
        parts.extend(section.render(data, ctx))
    if ctx.notes:
        parts.insert(header, "<h2>Gaps in the data</h2><ul>" + "".join("<li>%s</li>" % html.escape(n) for n in ctx.notes) + "</ul>")
    parts.append("</body></html>")
    index = os.path.join(outdir, "index.html")
    with open(index, "w") as f:
        f.write("\n".join(parts))
    return index
