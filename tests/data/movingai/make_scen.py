#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the MovingAI scenario files of tests/data/movingai/ for rooms.map (written by hand): optima from a
plain Dijkstra written here (independent of mhplan), MovingAI rules (8-connected, straight 1, diagonal sqrt 2
with both side cells free; '.' free, '@' and 'T' blocked; x = column, y = row from the top).
  rooms.map.scen        LF line ends, optima in full precision (17 significant digits), buckets 0..2
  rooms_crlf.map.scen   CRLF line ends, optima with 6 significant digits (as MovingAI's own files round)
  rooms_wrong.map.scen  one optimum off by 0.01 (line 4), to be refused
Deterministic; run from any directory."""
import heapq
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(HERE, "rooms.map")) as f:
    lines = f.read().split("\n")
height, width = int(lines[1].split()[1]), int(lines[2].split()[1])
rows = lines[4:4 + height]


def free(x, y):
    return 0 <= x < width and 0 <= y < height and rows[y][x] == "."


def dijkstra(sx, sy, gx, gy):
    dist = {(sx, sy): 0.0}
    heap = [(0.0, sx, sy)]
    while heap:
        d, x, y = heapq.heappop(heap)
        if (x, y) == (gx, gy):
            return d
        if d > dist[(x, y)]:
            continue
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                if (dx, dy) == (0, 0) or not free(x + dx, y + dy):
                    continue
                if dx and dy and not (free(x + dx, y) and free(x, y + dy)):
                    continue
                nd = d + (math.sqrt(2) if dx and dy else 1.0)
                if nd < dist.get((x + dx, y + dy), math.inf):
                    dist[(x + dx, y + dy)] = nd
                    heapq.heappush(heap, (nd, x + dx, y + dy))
    return None


# (start, goal) pairs; buckets by optimum length / 4 as MovingAI does.
PAIRS = [((0, 0), (1, 0)), ((0, 0), (2, 2)), ((3, 2), (5, 4)), ((0, 7), (3, 4)), ((0, 0), (11, 7)),
         ((2, 5), (11, 0)), ((7, 7), (9, 7)), ((5, 0), (5, 7)), ((0, 3), (10, 4)), ((11, 7), (0, 5))]
problems = []
for (sx, sy), (gx, gy) in PAIRS:
    assert free(sx, sy) and free(gx, gy), (sx, sy, gx, gy)
    d = dijkstra(sx, sy, gx, gy)
    assert d is not None
    problems.append((int(d // 4), sx, sy, gx, gy, d))
problems.sort(key=lambda p: (p[0], p[5]))


def write(name, fmt, eol, wrong_line=None):
    out = ["version 1"]
    for i, (b, sx, sy, gx, gy, d) in enumerate(problems):
        value = d + 0.01 if wrong_line == i + 2 else d
        out.append("\t".join([str(b), "rooms.map", str(width), str(height), str(sx), str(sy), str(gx), str(gy),
                              fmt(value)]))
    with open(os.path.join(HERE, name), "w", newline="") as f:
        f.write(eol.join(out) + eol)


write("rooms.map.scen", lambda v: repr(v), "\n")
write("rooms_crlf.map.scen", lambda v: "%.6g" % v, "\r\n")
write("rooms_wrong.map.scen", lambda v: repr(v), "\n", wrong_line=4)
