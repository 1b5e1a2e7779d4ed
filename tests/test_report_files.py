#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 26: the report opens exactly the database file it is given, whatever characters its name holds
('#', '?', '%' would otherwise be read as parts of SQLite's file: URI), and never shows a file's contents in
its messages (an error of `mhplan worlds` may quote the file)."""

import os
import sqlite3
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "analysis"))

from mhplan_analysis import db as dbmod  # noqa: E402
from mhplan_analysis import report, worlds  # noqa: E402


def make_db(path, marker):
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE marker (name TEXT)")
    conn.execute("INSERT INTO marker VALUES (?)", (marker,))
    conn.commit()
    conn.close()


class DatabaseNames(unittest.TestCase):
    def test_every_name_opens_that_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            # Decoys: what "file:run#1.db" and "file:a?b.db" would name as URIs.
            make_db(os.path.join(tmp, "run"), "decoy")
            make_db(os.path.join(tmp, "a"), "decoy")
            for name in ["run#1.db", "a?b.db", "50%.db", "100%25.db", "sp ace.db", "q'uote.db"]:
                path = os.path.join(tmp, name)
                make_db(path, name)
                before = sorted(os.listdir(tmp))
                conn = dbmod.connect_readonly(path)
                try:
                    self.assertEqual(conn.execute("SELECT name FROM marker").fetchone()[0], name)
                finally:
                    conn.close()
                self.assertEqual(sorted(os.listdir(tmp)), before, "a stray file was created for %s" % name)
                # The report's path reader goes through the same opening.
                self.assertEqual(report.load_paths(path), {})

    def test_read_only(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "x#y.db")
            make_db(path, "x")
            conn = dbmod.connect_readonly(path)
            with self.assertRaises(sqlite3.OperationalError):
                conn.execute("INSERT INTO marker VALUES ('no')")
            conn.close()


class DamagedDatabases(unittest.TestCase):
    """Findings of the report_db fuzz target (tests/fuzz/fuzz_report_db.py): refused with ValueError (one line
    naming the file in the report), never a traceback."""

    def make(self, tmp, statements):
        path = os.path.join(tmp, "d.db")
        if os.path.exists(path):
            os.remove(path)
        conn = sqlite3.connect(path)
        for st in statements:
            conn.execute(st)
        conn.commit()
        conn.close()
        return path

    def test_missing_columns_and_odd_values(self):
        base = ["CREATE TABLE experiments (id INTEGER PRIMARY KEY, name TEXT)",
                "CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY, name TEXT)",
                "INSERT INTO experiments VALUES (1, 'w-default')"]
        with tempfile.TemporaryDirectory() as tmp:
            path = self.make(tmp, base + ["CREATE TABLE runs (id INTEGER PRIMARY KEY, plannerid INTEGER)",
                                          "INSERT INTO runs VALUES (1, 1)"])
            with self.assertRaises(ValueError) as caught:
                dbmod.load(path)
            self.assertIn("experimentid", str(caught.exception))
            # A planner name stored as a blob, a status stored as text: read, not a crash.
            path = self.make(tmp, base + ["CREATE TABLE runs (id INTEGER PRIMARY KEY, experimentid INTEGER, "
                                          "plannerid INTEGER, status TEXT)",
                                          "INSERT INTO plannerConfigs VALUES (1, X'ff00')",
                                          "INSERT INTO runs VALUES (1, 1, 1, 'x')"])
            database = dbmod.load(path)
            self.assertEqual(len(database.runs), 1)


class NoFileContents(unittest.TestCase):
    def setUp(self):
        if not worlds.mhplan_binary():
            self.skipTest("no mhplan program (set MHPLAN_BIN)")

    def test_a_refused_world_is_not_quoted(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "secret.yaml")
            with open(path, "w") as f:
                f.write("bounds: [0, 10, 0, 10]\nTOPSECRET_KEY_4711: hunter2\npassword: TOPSECRET_VALUE_4712\n")
            with self.assertRaises(ValueError) as caught:
                worlds.load_world(path)
            message = str(caught.exception)
            self.assertNotIn("TOPSECRET", message)
            self.assertIn("mhplan worlds refused the file", message)


if __name__ == "__main__":
    unittest.main()
