# SPDX-License-Identifier: BSD-3-Clause
"""Just enough of mhplan's world files to draw them: YAML worlds (circles, rectangles, polygons, inline grid
rows, .map grid files) and bare MovingAI .map files. The C++ loader (src/io/WorldIO.cpp) is the reference and
validates; this one only draws files that already passed it."""

import math
import os

import yaml


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
        self.queries = {}  # name -> ((sx, sy), (gx, gy))


def _read_map(path):
    with open(path) as f:
        lines = [l.rstrip("\r\n") for l in f]
    i = next(k for k, l in enumerate(lines) if l.strip() == "map")
    height = int(next(l.split()[1] for l in lines[:i] if l.startswith("height")))
    return [[c in "@OTW" for c in row] for row in lines[i + 1 : i + 1 + height]]


def _rectangle(spec):
    if "min" in spec:
        (x0, y0), (x1, y1) = spec["min"], spec["max"]
        return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    (cx, cy), (w, h) = spec["center"], spec["size"]
    a = math.radians(spec.get("angle", 0.0))
    c, s = math.cos(a), math.sin(a)
    return [(cx + c * x - s * y, cy + s * x + c * y) for x, y in ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))]


def load_world(path):
    """A World from a .yaml/.yml or .map file; raises OSError/ValueError on files it cannot read."""
    if path.endswith(".map"):
        rows = _read_map(path)
        w = World(os.path.splitext(os.path.basename(path))[0], (0.0, len(rows[0]), 0.0, len(rows)))
        w.grid = rows
        return w
    with open(path) as f:
        doc = yaml.safe_load(f)
    radius = float((doc.get("robot") or {}).get("radius", 0.0))
    name = doc.get("name", os.path.basename(path))
    if "grid" in doc:
        g = doc["grid"]
        if "rows" in g:
            rows = [[c in "@OTW" for c in r] for r in g["rows"]]
        elif str(g.get("file", "")).endswith(".map"):
            rows = _read_map(os.path.join(os.path.dirname(path), g["file"]))
        else:
            raise ValueError("%s: only .map and inline grids can be drawn" % path)
        cs = float(g.get("cell_size", 1.0))
        ox, oy = g.get("origin", [0.0, 0.0])
        w = World(name, (ox, ox + cs * len(rows[0]), oy, oy + cs * len(rows)), radius)
        w.grid, w.cell_size, w.origin = rows, cs, (ox, oy)
    else:
        b = doc["bounds"]
        bounds = (b["xmin"], b["xmax"], b["ymin"], b["ymax"]) if isinstance(b, dict) else tuple(b)
        w = World(name, tuple(float(v) for v in bounds), radius)
        for item in doc.get("obstacles") or []:
            (kind, spec), = item.items()
            if kind == "circle":
                w.circles.append((spec["center"][0], spec["center"][1], spec["radius"]))
            elif kind == "rectangle":
                w.polygons.append(_rectangle(spec))
            elif kind == "polygon":
                w.polygons.append([tuple(p) for p in spec["points"]])
    for i, q in enumerate(doc.get("queries") or []):
        w.queries[q.get("name", "default" if i == 0 else "q%d" % i)] = (tuple(q["start"]), tuple(q["goal"]))
    return w


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
