# SPDX-License-Identifier: BSD-3-Clause
"""The worlds the report draws, as the mhplan program exports them (`mhplan worlds FILE --json`, field names in
docs/cli.md): the loader that plans is the only parser of world files, so every format it reads (YAML
geometry, inline grids, MovingAI .map, PGM) is drawn the same way. The program is $MHPLAN_BIN (set by
`mhplan report`), else `mhplan` on PATH."""

import json
import math
import os
import shutil
import subprocess


class World:
    def __init__(self, name, bounds, radius=0.0):
        self.name = name
        self.bounds = bounds  # (xmin, xmax, ymin, ymax)
        self.radius = radius
        self.circles = []  # (cx, cy, r)
        self.polygons = []  # [(x, y), ...]
        self.grid = None  # list of rows, top row first, True = blocked
        self.cell_size = 1.0
        self.origin = (0.0, 0.0)
        self.queries = {}  # name -> ((sx, sy), (gx, gy)), in the world file's order
        self.query_yaws = {}  # name -> (start yaw, goal yaw): SE(2)-based worlds only
        self.space = "r2"  # r2, se2, dubins or reeds_shepp (docs/spaces.md)
        self.robot_polygon = []  # [(x, y), ...] in the robot's frame; [] for a disc robot


def mhplan_binary():
    """The mhplan program: $MHPLAN_BIN, else `mhplan` on PATH; None when there is none."""
    env = os.environ.get("MHPLAN_BIN")
    if env:
        return env if os.access(env, os.X_OK) else None
    return shutil.which("mhplan")


def from_json(doc):
    """A World from one element of `mhplan worlds --json`'s "worlds" array."""
    b = doc["bounds"]
    w = World(doc["name"], (b["xmin"], b["xmax"], b["ymin"], b["ymax"]), doc.get("robot_radius", 0.0))
    w.circles = [(c["center"][0], c["center"][1], c["radius"]) for c in doc.get("circles", [])]
    w.polygons = [[tuple(v) for v in p["vertices"]] for p in doc.get("polygons", [])]
    g = doc.get("grid")
    if g:
        w.grid = [[c == "@" for c in row] for row in g["rows"]]
        w.cell_size = g["cell_size"]
        w.origin = tuple(g["origin"])
    for q in doc.get("queries", []):
        w.queries[q["name"]] = (tuple(q["start"]), tuple(q["goal"]))
        if "start_yaw" in q and "goal_yaw" in q:
            w.query_yaws[q["name"]] = (q["start_yaw"], q["goal_yaw"])
    w.space = doc.get("space") or "r2"
    w.robot_polygon = [tuple(v) for v in (doc.get("robot_polygon") or [])]
    return w


def load_world(path):
    """The World of file \\e path, exported by the mhplan program; raises OSError when there is no program and
    ValueError with the program's message when it refuses the file."""
    binary = mhplan_binary()
    if not binary:
        raise OSError("no mhplan program to read worlds (set MHPLAN_BIN or put mhplan on PATH)")
    proc = subprocess.run([binary, "worlds", path, "--json"], capture_output=True, text=True)
    if proc.returncode != 0:
        # The program's message may quote the file (a key, a value): a report never shows file contents.
        raise ValueError("mhplan worlds refused the file (exit code %d; run 'mhplan worlds FILE' to see why)" % proc.returncode)
    return from_json(json.loads(proc.stdout)["worlds"][0])


def parse_query_poses(text):
    """The experiment's query from its 'query_points' property: "(sx,sy)->(gx,gy)", or in an SE(2)-based
    world "(sx,sy,syaw)->(gx,gy,gyaw)"; (start, goal) as tuples of 2 or 3 numbers, None when unreadable."""
    try:
        a, b = str(text).split("->")
        start = tuple(float(v) for v in a.strip().strip("()").split(","))
        goal = tuple(float(v) for v in b.strip().strip("()").split(","))
    except (ValueError, AttributeError):
        return None
    return (start, goal) if len(start) == len(goal) and len(start) in (2, 3) else None


def parse_query_points(text):
    """The experiment's query's positions ((sx, sy), (gx, gy)) from its 'query_points' property; None when
    unreadable."""
    q = parse_query_poses(text)
    return (q[0][:2], q[1][:2]) if q else None


def place(polygon, pose):
    """The robot-frame \\p polygon placed at pose (x, y, yaw): its world-frame vertices."""
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    return [(x + c * vx - s * vy, y + s * vx + c * vy) for vx, vy in polygon]


def densify(poses, step):
    """Poses (x, y, yaw) between consecutive ones of \\p poses at most \\p step metres apart: linear in x and
    y, the shorter way round in yaw (OMPL's SE(2) interpolation; for the cars' stored curves, sampled every
    eighth of the turning radius, a close approximation)."""
    out = []
    for a, b in zip(poses, poses[1:]):
        d = math.hypot(b[0] - a[0], b[1] - a[1])
        turn = math.remainder(b[2] - a[2], 2.0 * math.pi)
        n = max(1, int(math.ceil(d / step)), int(math.ceil(abs(turn) / (math.pi / 12.0))))
        for k in range(n):
            f = k / n
            out.append((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * turn))
    if poses:
        out.append(tuple(poses[-1]))
    return out


def footprint_poses(poses, reach, count=40):
    """Where to draw the robot along a path of poses (x, y, yaw): the first and last, one every
    max(1.5 reach, length / count) metres of travel, and wherever the heading turned by 30 degrees since the
    last one drawn (so a turn in a doorway shows); the same rule as `mhplan plan --svg` (docs/cli.md)."""
    if not poses:
        return []
    dense = densify([tuple(p) for p in poses], max(reach / 4.0, 1e-3))
    travel = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(dense, dense[1:]))
    spacing = max(1.5 * reach, travel / count)
    chosen, since = [dense[0]], 0.0
    for i in range(1, len(dense)):
        since += math.hypot(dense[i][0] - dense[i - 1][0], dense[i][1] - dense[i - 1][1])
        turned = abs(math.remainder(dense[i][2] - chosen[-1][2], 2.0 * math.pi)) >= math.pi / 6.0
        if since >= spacing or turned or i == len(dense) - 1:
            chosen.append(dense[i])
            since = 0.0
    return chosen


def draw_world(ax, world):
    """Draw bounds and obstacles on a matplotlib axis (equal aspect, y up)."""
    from matplotlib.patches import Circle, Polygon, Rectangle

    xmin, xmax, ymin, ymax = world.bounds
    ax.add_patch(Rectangle((xmin, ymin), xmax - xmin, ymax - ymin, fill=False, edgecolor="black", linewidth=1))
    if world.grid is not None:
        import numpy as np

        img = np.array(world.grid, dtype=float)
        ax.imshow(img, cmap="Greys", vmin=0, vmax=1.4, extent=(xmin, xmax, ymin, ymax), origin="upper", interpolation="nearest")
    for cx, cy, r in world.circles:
        ax.add_patch(Circle((cx, cy), r, facecolor="#9a9a9a", edgecolor="#444444", linewidth=0.6))
    for poly in world.polygons:
        ax.add_patch(Polygon(poly, closed=True, facecolor="#9a9a9a", edgecolor="#444444", linewidth=0.6))
    ax.set_xlim(xmin, xmax)
    ax.set_ylim(ymin, ymax)
    ax.set_aspect("equal")
