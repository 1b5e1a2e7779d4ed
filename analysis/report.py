#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""mhplan report DB -o DIR: write DIR/index.html with figures and tables from a benchmark database.
Runs with Debian's /usr/bin/python3 (matplotlib, numpy); worlds are drawn from `mhplan worlds FILE --json`
($MHPLAN_BIN, set by mhplan report, else mhplan on PATH)."""

import argparse
import os
import sqlite3
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mhplan_analysis.report import write_report  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(prog="mhplan report", description=__doc__)
    parser.add_argument("database", help="SQLite database written by mhplan bench / ompl_benchmark_statistics")
    parser.add_argument("-o", "--output", default="report", help="output directory (default: report)")
    parser.add_argument("--worlds", default=None, help="directory that relative world_file paths are relative to")
    args = parser.parse_args(argv)
    def fail(message):
        print("mhplan report: error: %s" % message, file=sys.stderr)
        return 1

    if not os.path.isfile(args.database):
        return fail("no such database file '%s'" % args.database)
    with open(args.database, "rb") as f:
        if f.read(16) != b"SQLite format 3\x00":
            return fail("'%s' is not an SQLite database (written by mhplan bench)" % args.database)
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        return fail("the output '%s' exists and is not a directory" % args.output)
    try:
        index = write_report(args.database, args.output, args.worlds)
    except ValueError as e:
        return fail(e)
    except sqlite3.Error as e:
        return fail("cannot read the database '%s': %s" % (args.database, e))
    except OSError as e:
        return fail("cannot write '%s': %s" % (e.filename or args.output, e.strerror or e))
    print(index)
    return 0


if __name__ == "__main__":
    sys.exit(main())
