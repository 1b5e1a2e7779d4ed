#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes tests/data/astar_random.map and astar_random.scen: a random 48 x 32 MovingAI octile map and a scenario
of 80 problems whose optimal lengths come from a plain Dijkstra written here (independent of mhplan's A*).
MovingAI rules: 8-connected, straight moves cost 1, diagonal moves sqrt 2 and need both side cells free.
Coordinates: x = column, y = row from the top line. Deterministic (fixed seed). Run from any directory."""
import heapq
import math
import os
import random

WIDTH, HEIGHT, DENSITY, PROBLEMS, SEED = 48, 32, 0.3, 80, 2024
HERE = os.path.dirname(os.path.abspath(__file__))
rng = random.Random(SEED)

rows = [["@" if rng.random() < DENSITY else "." for _ in range(WIDTH)] for _ in range(HEIGHT)]
# A long wall with one gap and a diagonal staircase of blocked cells (corner cutting must be refused).
for y in range(4, HEIGHT - 4):
    rows[y][20] = "@" if y != HEIGHT // 2 else "."
for k in range(10):
    rows[2 + k][30 + k] = "@"


def free(x, y):
    return 0 <= x < WIDTH and 0 <= y < HEIGHT and rows[y][x] == "."


def dijkstra(sx, sy):
    dist = {(sx, sy): 0.0}
    heap = [(0.0, sx, sy)]
    done = set()
    while heap:
        d, x, y = heapq.heappop(heap)
        if (x, y) in done:
            continue
        done.add((x, y))
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                if dx == 0 and dy == 0:
                    continue
                nx, ny = x + dx, y + dy
                if not free(nx, ny):
                    continue
                if dx != 0 and dy != 0 and not (free(x + dx, y) and free(x, y + dy)):
                    continue
                nd = d + (math.sqrt(2.0) if dx != 0 and dy != 0 else 1.0)
                if nd < dist.get((nx, ny), math.inf):
                    dist[(nx, ny)] = nd
                    heapq.heappush(heap, (nd, nx, ny))
    return dist


cells = [(x, y) for y in range(HEIGHT) for x in range(WIDTH) if free(x, y)]
problems = []
while len(problems) < PROBLEMS:
    s = rng.choice(cells)
    dist = dijkstra(*s)
    reachable = sorted(c for c in dist if c != s)
    if not reachable:
        continue
    g = rng.choice(reachable)
    problems.append((int(dist[g] // 4), s, g, dist[g]))
problems.sort(key=lambda p: p[0])

with open(os.path.join(HERE, "astar_random.map"), "w") as f:
    f.write("type octile\nheight %d\nwidth %d\nmap\n" % (HEIGHT, WIDTH))
    for r in rows:
        f.write("".join(r) + "\n")
with open(os.path.join(HERE, "astar_random.scen"), "w") as f:
    f.write("version 1\n")
    for bucket, (sx, sy), (gx, gy), d in problems:
        f.write("%d\tastar_random.map\t%d\t%d\t%d\t%d\t%d\t%d\t%.8f\n" % (bucket, WIDTH, HEIGHT, sx, sy, gx, gy, d))
