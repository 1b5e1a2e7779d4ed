#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Fuzz target report_db: the report's database reader (analysis/mhplan_analysis/db.py, load()) on damaged
and hostile databases. Starting from small OMPL-schema databases, each input is either the file's bytes
mutated (bytes flipped, runs overwritten, the file cut short) or its rows and schema mutated through SQL
(values of the wrong type, NULLs, huge and non-finite numbers, text with control characters, columns and
tables dropped). The reader must either return or refuse with ValueError or sqlite3.Error, which the report
turns into one line naming the file; any other exception is a finding: its input is kept in ARTIFACTS and
the script exits with 1. Deterministic in its seed (scripts/fuzz.sh report_db SECONDS runs it).

usage: fuzz_report_db.py SECONDS [SEED] [ARTIFACTS_DIR]"""

import os
import random
import shutil
import sqlite3
import sys
import tempfile
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "analysis"))

from mhplan_analysis import db as dbmod  # noqa: E402

SCHEMA = [
    "CREATE TABLE experiments (id INTEGER PRIMARY KEY, name VARCHAR(512), totaltime REAL, timelimit REAL, "
    "memorylimit REAL, runcount INTEGER, version VARCHAR(128), hostname VARCHAR(1024), cpuinfo TEXT, "
    "date DATETIME, seed INTEGER, setup TEXT, world TEXT, world_file TEXT, exact_optimum REAL, query TEXT)",
    "CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY, name VARCHAR(512), settings TEXT)",
    "CREATE TABLE enums (name VARCHAR(512), value INTEGER, description TEXT, PRIMARY KEY (name, value))",
    "CREATE TABLE runs (id INTEGER PRIMARY KEY, experimentid INTEGER, plannerid INTEGER, time REAL, "
    "memory REAL, status ENUM, solved BOOLEAN, path_length REAL, run_index INTEGER, run_seed INTEGER)",
    "CREATE TABLE progress (runid INTEGER, time REAL, best_cost REAL, PRIMARY KEY (runid, time))",
    "CREATE TABLE improvements (runid INTEGER, time REAL, cost REAL, source TEXT)",
    "CREATE TABLE paths (runid INTEGER PRIMARY KEY, points TEXT)",
]
STATUS = ["Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type", "Timeout",
          "Approximate solution", "Exact solution", "Crash", "Abort"]
WEIRD = [None, "", "x", "nan", "inf", "-inf", 1e308, -1e308, float("nan"), 2 ** 62, -1, 0, "7", "geometric_",
         "a\nb\x00c\x1b[0m", "\u00e9\u4e2d", b"\xff\xfe", 3.5, "Exact solution"]


def seed_database(path, rng):
    conn = sqlite3.connect(path)
    for statement in SCHEMA:
        conn.execute(statement)
    conn.executemany("INSERT INTO enums VALUES ('status', ?, ?)", list(enumerate(STATUS)))
    for e in range(1, rng.randint(1, 3) + 1):
        conn.execute("INSERT INTO experiments (id, name, world, exact_optimum, query) VALUES (?, ?, ?, ?, ?)",
                     (e, "w%d-default" % e, "w%d" % e, 10.0 + e, "default"))
    for p in range(1, 3):
        conn.execute("INSERT INTO plannerConfigs VALUES (?, ?, '{}')", (p, "geometric_P%d" % p))
    run = 0
    for e in range(1, 3):
        for p in range(1, 3):
            for k in range(rng.randint(1, 4)):
                run += 1
                conn.execute("INSERT INTO runs VALUES (?, ?, ?, ?, 1.5, ?, ?, ?, ?, ?)",
                             (run, e, p, rng.random(), rng.choice([4, 5, 6, 7]), rng.randint(0, 1),
                              10 + rng.random(), k, rng.randint(1, 2 ** 32 - 1)))
                for t in range(rng.randint(0, 3)):
                    conn.execute("INSERT INTO progress VALUES (?, ?, ?)", (run, 0.01 * t, 20 - t))
                    conn.execute("INSERT INTO improvements VALUES (?, ?, ?, 'callback')", (run, 0.01 * t, 20 - t))
                conn.execute("INSERT INTO paths VALUES (?, '0 0;1 1;')", (run,))
    conn.commit()
    conn.close()


def mutate_sql(path, rng):
    conn = sqlite3.connect(path)
    try:
        for _ in range(rng.randint(1, 4)):
            choice = rng.random()
            table = rng.choice(["experiments", "plannerConfigs", "runs", "progress", "improvements", "enums"])
            cols = [r[1] for r in conn.execute("PRAGMA table_info(%s)" % table)]
            if not cols:
                continue
            if choice < 0.6:
                col = rng.choice(cols)
                conn.execute("UPDATE %s SET \"%s\" = ? WHERE rowid IN (SELECT rowid FROM %s ORDER BY random() LIMIT 2)"
                             % (table, col, table), (rng.choice(WEIRD),))
            elif choice < 0.75:
                conn.execute("ALTER TABLE %s DROP COLUMN \"%s\"" % (table, rng.choice(cols)))
            elif choice < 0.85:
                conn.execute("DROP TABLE %s" % table)
            else:
                conn.execute("INSERT INTO %s (\"%s\") VALUES (?)" % (table, rng.choice(cols)), (rng.choice(WEIRD),))
        conn.commit()
    except sqlite3.Error:
        pass  # a mutation SQLite refuses: the input is what is left
    finally:
        conn.close()


def mutate_bytes(path, rng):
    with open(path, "rb") as f:
        data = bytearray(f.read())
    kind = rng.random()
    if kind < 0.4:
        for _ in range(rng.randint(1, 16)):
            data[rng.randrange(len(data))] = rng.randrange(256)
    elif kind < 0.7:
        at = rng.randrange(len(data))
        data[at:at + rng.randint(1, 512)] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 512)))
    else:
        data = data[:rng.randrange(len(data))]
    with open(path, "wb") as f:
        f.write(bytes(data))


def main(argv):
    seconds = float(argv[1]) if len(argv) > 1 else 10.0
    seed = int(argv[2]) if len(argv) > 2 else 1
    artifacts = argv[3] if len(argv) > 3 else os.path.join(tempfile.gettempdir(), "mhplan-fuzz-report-db")
    rng = random.Random(seed)
    work = tempfile.mkdtemp(prefix="mhplan_fuzz_report_db_")
    executions = 0
    end = time.monotonic() + seconds
    try:
        while time.monotonic() < end:
            path = os.path.join(work, "input.db")
            for suffix in ("", "-journal"):
                if os.path.exists(path + suffix):
                    os.remove(path + suffix)
            seed_database(path, rng)
            if rng.random() < 0.5:
                mutate_sql(path, rng)
            if rng.random() < 0.5:
                mutate_bytes(path, rng)
            executions += 1
            try:
                dbmod.load(path)
            except (ValueError, sqlite3.Error):
                pass
            except Exception:  # noqa: BLE001 - anything else is a finding
                os.makedirs(artifacts, exist_ok=True)
                kept = os.path.join(artifacts, "crash-%d-%d.db" % (seed, executions))
                shutil.copy(path, kept)
                traceback.print_exc()
                print("report_db: finding after %d executions, input kept in %s" % (executions, kept), file=sys.stderr)
                return 1
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("report_db: %d executions, no finding" % executions)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
