#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""mhplan report DB -o DIR: write DIR/index.html with figures and tables from a benchmark database.
Runs with Debian's /usr/bin/python3 (matplotlib, numpy, yaml)."""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mhplan_analysis.report import write_report  # noqa: E402


def main(argv=None):
    parser = argparse.ArgumentParser(prog="mhplan report", description=__doc__)
    parser.add_argument("database", help="SQLite database written by mhplan bench / ompl_benchmark_statistics")
    parser.add_argument("-o", "--output", default="report", help="output directory (default: report)")
    parser.add_argument("--worlds", default=None, help="directory that relative world_file paths are relative to")
    args = parser.parse_args(argv)
    if not os.path.isfile(args.database):
        print("mhplan report: error: no such database file '%s'" % args.database, file=sys.stderr)
        return 1
    try:
        index = write_report(args.database, args.output, args.worlds)
    except ValueError as e:
        print("mhplan report: error: %s" % e, file=sys.stderr)
        return 1
    print(index)
    return 0


if __name__ == "__main__":
    sys.exit(main())
