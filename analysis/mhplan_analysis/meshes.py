# SPDX-License-Identifier: BSD-3-Clause
"""The report's pictures of OMPL.app problems ({cfg: FILE} campaign entries, docs/omplapp.md "Pictures"): the
meshes as the mhplan program reads them (`mhplan worlds PROBLEM.cfg --json`: the loader that plans is the only
reader of mesh files, as for worlds in worlds.py), drawn with each planner's best and median exact path.
SE(2) problems are drawn from above with the robot's footprint (its triangles projected) at poses along each
best path; SE(3) problems as three orthographic projections (top x-y, front x-z, side y-z) with the robot at
a few poses along each best path."""

import json
import math
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from . import db as dbmod  # noqa: E402
from . import worlds  # noqa: E402

# Projections of SE(3) problems: (title, horizontal axis, vertical axis) of the x, y, z coordinates.
VIEWS = (("top (x-y)", 0, 1), ("front (x-z)", 0, 2), ("side (y-z)", 1, 2))
# Beyond this many environment triangles a projection draws every k-th (the figure says so).
MAX_DRAWN_TRIANGLES = 60000


def load_problem(path):
    """The problem of .cfg file \\p path as `mhplan worlds FILE --json` exports it: name, space (se2, se3),
    volume, start, goal, environment and robot (vertices, triangles; the robot centred on its origin). Raises
    OSError without a program, ValueError when it refuses the file."""
    binary = worlds.mhplan_binary()
    if not binary:
        raise OSError("no mhplan program to read meshes (set MHPLAN_BIN or put mhplan on PATH)")
    proc = subprocess.run([binary, "worlds", path, "--json"], capture_output=True, text=True)
    if proc.returncode != 0:
        raise ValueError("mhplan worlds refused the problem file (exit code %d; run 'mhplan worlds FILE')" % proc.returncode)
    doc = json.loads(proc.stdout)["problems"][0]
    for part in ("environment", "robot"):
        doc[part]["vertices"] = np.array(doc[part]["vertices"], dtype=float).reshape(-1, 3)
        doc[part]["triangles"] = np.array(doc[part]["triangles"], dtype=int).reshape(-1, 3)
    return doc


def rotation(q):
    """The rotation matrix of quaternion (w, x, y, z)."""
    w, x, y, z = q
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def placed(mesh, pose):
    """The mesh's triangles (n x 3 x 3) at \\p pose: (x, y, yaw) in SE(2), (x, y, z, qw, qx, qy, qz) in SE(3)."""
    if len(mesh["triangles"]) == 0:
        return np.zeros((0, 3, 3))  # a point robot (docs/worlds3d.md)
    if len(pose) == 3:
        c, s = math.cos(pose[2]), math.sin(pose[2])
        r, t = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]), np.array([pose[0], pose[1], 0.0])
    else:
        r, t = rotation(pose[3:7]), np.array(pose[0:3])
    return (mesh["vertices"] @ r.T + t)[mesh["triangles"]]


def _draw_triangles(ax, tris, h, v, **style):
    """Triangles (n x 3 x 3) projected onto coordinates h, v; returns the step k when only every k-th is drawn."""
    k = max(1, int(math.ceil(len(tris) / MAX_DRAWN_TRIANGLES)))
    ax.add_collection(PolyCollection(tris[::k][:, :, [h, v]], **style))
    return k


def _pose(pose_doc, se3):
    p, q = pose_doc["position"], pose_doc["orientation"]
    if se3:
        return tuple(p) + tuple(q)
    return (p[0], p[1], 2.0 * math.atan2(q[3], q[0]))  # a rotation about +z


def _se3_poses(path, count=6):
    """About \\p count poses of an SE(3) path, evenly spread over its waypoints (the first and last included)."""
    if len(path) <= count:
        return list(path)
    idx = sorted(set(int(round(i * (len(path) - 1) / (count - 1))) for i in range(count)))
    return [path[i] for i in idx]


def _best_and_median(database, exp, paths):
    """Per planner with exact saved paths: (planner, best length, best path, median path)."""
    out = []
    for p in database.planners_of(exp.id):
        exact = []
        for r in database.runs_of(exp.id, p):
            length = dbmod.run_value(r, "path_length")
            if r.outcome == "exact" and length is not None and r.id in paths:
                exact.append((length, r.id))
        exact.sort()
        if exact:
            out.append((p, exact[0][0], paths[exact[0][1]], paths[exact[len(exact) // 2][1]]))
    return out


def path_figure(database, exp, paths, world_file, outdir, colors, owner=None):
    """The problem with each planner's best (solid) and median (dashed) exact path, saved as
    paths_EXPERIMENT.png in \\p outdir; returns (file name or None, a note or None). \\p owner (the report's
    path_figure) gets .footprints: how many best paths show the robot."""
    if owner is not None:
        owner.footprints = 0
    if not world_file or not os.path.exists(str(world_file)):
        return None, "problem file %s not found" % (world_file or "(not recorded)")
    try:
        prob = load_problem(str(world_file))
    except (OSError, ValueError, KeyError) as e:
        return None, "cannot draw %s: %s" % (world_file, e)
    se3 = prob["space"] in ("se3", "r3")  # R^3 (3D YAML worlds): poses with the identity rotation
    env, robot = prob["environment"], prob["robot"]
    env_tris = env["vertices"][env["triangles"]]
    vmin, vmax = prob["volume"]["min"], prob["volume"]["max"]
    views = VIEWS if se3 else VIEWS[:1]
    fig, axes = plt.subplots(1, len(views), figsize=(5.2 * len(views) + 2.0, 5.2), squeeze=False)
    axes = axes[0]
    thinned = 1
    for ax, (title, h, v) in zip(axes, views):
        thinned = _draw_triangles(ax, env_tris, h, v, facecolor="#9a9a9a", edgecolor="#444444", linewidth=0.3, alpha=0.6, zorder=1)
        ax.add_patch(matplotlib.patches.Rectangle((vmin[h], vmin[v]), vmax[h] - vmin[h], vmax[v] - vmin[v], fill=False, edgecolor="black", linewidth=1))
        ax.set_xlim(vmin[h], vmax[h])
        ax.set_ylim(vmin[v], vmax[v])
        ax.set_aspect("equal")
        ax.set_xlabel("xyz"[h])
        ax.set_ylabel("xyz"[v])
        if se3:
            ax.set_title(title, fontsize=9)
    footprints = 0
    drawn = 0
    for planner, best_len, best, median in _best_and_median(database, exp, paths):
        same = median is best
        if prob["space"] == "r3":
            best, median = ([tuple(s) + (1.0, 0.0, 0.0, 0.0) if len(s) == 3 else s for s in p] for p in (best, median))
        dim = 7 if se3 else 3
        if any(len(s) != dim for s in best):
            continue  # not poses of this problem's space
        color = colors.get(planner, "#d62728")
        poses = (_se3_poses(best) if se3 else
                 worlds.footprint_poses(best, max(prob["robot_reach"], 1e-6)))
        for ax, (_, h, v) in zip(axes, views):
            ax.plot([s[h] for s in best], [s[v] for s in best], color=color, linewidth=1.8, zorder=4,
                    label="%s best %.3f" % (planner, best_len) if ax is axes[-1] else None)
            if not same:
                ax.plot([s[h] for s in median], [s[v] for s in median], color=color, linewidth=1.0, linestyle="--", alpha=0.8, zorder=4)
            for pose in poses:
                _draw_triangles(ax, placed(robot, pose), h, v, facecolor=color, edgecolor=color, linewidth=0.4, alpha=0.12, zorder=3)
        footprints += 1
        drawn += 1
    for pose_doc, color in ((prob["start"], "#2ca02c"), (prob["goal"], "#1f77b4")):
        pose = _pose(pose_doc, se3)
        for ax, (_, h, v) in zip(axes, views):
            _draw_triangles(ax, placed(robot, pose), h, v, facecolor=color, edgecolor=color, linewidth=0.5, alpha=0.35, zorder=5)
    what = "orthographic projections" if se3 else "seen from above"
    label = {"se2": "SE(2)", "se3": "SE(3)", "r3": "R^3", "dubins": "Dubins car", "reeds_shepp": "Reeds-Shepp car"}.get(prob["space"], prob["space"])
    title = "%s (%s, %s): best (solid) and median (dashed) paths" % (exp.name, label, what)
    if footprints:
        title += "; the robot at six poses along each best path" if se3 else "; the robot along each best path"
    if thinned > 1:
        title += "; every %d-th environment triangle drawn" % thinned
    fig.suptitle(title, fontsize=10)
    if drawn:
        axes[-1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5), frameon=False)
    fig.tight_layout()
    slug = "".join(c if c.isalnum() or c in "-_" else "_" for c in exp.name)
    path = os.path.join(outdir, "paths_%s.png" % slug)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    if owner is not None:
        # The report's paragraph on footprints states the 2D rule (1.5 reaches, 30 degrees): SE(2) only; an
        # SE(3) figure says in its title that it shows the robot at six poses.
        owner.footprints = 0 if se3 else footprints
    return os.path.basename(path), None if drawn else "no saved exact paths"
