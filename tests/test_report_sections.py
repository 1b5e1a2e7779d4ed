#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The report's section interface (docs/report.md, docs/conventions.md "Adding a report section"): a new
section is one module with render(data, ctx) and one line in report.SECTIONS. The test adds such a module
(written to a temporary folder that joins the package) and finds its part of the page in the registered place,
its note under "Gaps in the data", and the data it was given read from the database."""

import os
import sqlite3
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "analysis"))

import mhplan_analysis  # noqa: E402
from mhplan_analysis import report  # noqa: E402

EXTRA = '''
import html


def render(data, ctx):
    """One line per planning experiment: its name and how many runs it has."""
    ctx.notes.append("extra section: a note")
    rows = [(html.escape(e.name), len(data.database.runs_of(e.id))) for e in data.planning]
    return ["<h2>Extra section</h2>", ctx_table(rows)]


def ctx_table(rows):
    from mhplan_analysis.page import table
    return table(["experiment", "runs"], rows)
'''


def make_db(path):
    """Two planners, three runs each, on one experiment: OMPL's tables and the columns the report reads."""
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE experiments (id INTEGER PRIMARY KEY, name TEXT, exact_optimum REAL)")
    conn.execute("CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY, name TEXT)")
    conn.execute("CREATE TABLE runs (id INTEGER PRIMARY KEY, experimentid INTEGER, plannerid INTEGER, "
                 "status INTEGER, time REAL, path_length REAL)")
    conn.execute("INSERT INTO experiments VALUES (1, 'w-default', 10.0)")
    conn.executemany("INSERT INTO plannerConfigs VALUES (?, ?)", [(1, "geometric_A"), (2, "geometric_B")])
    for i in range(6):
        conn.execute("INSERT INTO runs VALUES (?, 1, ?, 6, ?, ?)", (i + 1, 1 + i % 2, 0.1 * (i + 1), 10.5 + i))
    conn.commit()
    conn.close()


class Sections(unittest.TestCase):
    def test_every_registered_section_has_the_interface(self):
        for name, module in zip(report.SECTIONS, report.sections()):
            self.assertTrue(callable(getattr(module, "render", None)), name)

    def test_a_new_section_is_one_module_and_one_line(self):
        with tempfile.TemporaryDirectory() as tmp:
            package = os.path.join(tmp, "pkg")
            os.makedirs(package)
            with open(os.path.join(package, "extra_section_test.py"), "w") as f:
                f.write(EXTRA)
            mhplan_analysis.__path__.append(package)  # the new module, as if written into the package
            saved = list(report.SECTIONS)
            try:
                report.SECTIONS.insert(report.SECTIONS.index("problems"), "extra_section_test")  # its line
                db = os.path.join(tmp, "t.db")
                make_db(db)
                with open(report.write_report(db, os.path.join(tmp, "out"))) as f:
                    text = f.read()
            finally:
                report.SECTIONS[:] = saved
                mhplan_analysis.__path__.remove(package)
            self.assertIn("<h2>Extra section</h2>", text)
            self.assertIn("<tr><td>w-default</td><td>6</td></tr>", text)
            # In the registered place: after the ranking, before the per-problem part.
            self.assertLess(text.index("Ranking per problem"), text.index("Extra section"))
            self.assertLess(text.index("Extra section"), text.index("<h2>w-default</h2>"))
            gaps = text[text.index("Gaps in the data"):]
            self.assertIn("<li>extra section: a note</li>", gaps[:gaps.index("</ul>")])
            # Without its line the section is not on the page.
            with open(report.write_report(db, os.path.join(tmp, "out2"))) as f:
                self.assertNotIn("Extra section", f.read())


if __name__ == "__main__":
    unittest.main()
