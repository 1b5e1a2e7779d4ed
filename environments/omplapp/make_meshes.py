#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the small meshes of mhplan's OMPL.app-style problems (environments/omplapp/README.md): boxes as
triangles, in OBJ, ASCII STL, ASCII PLY and COLLADA. Run from anywhere; the files land beside this script."""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def box(lo, hi):
    """The 8 corners and 12 outward triangles of an axis-aligned box."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    f = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
         (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    return v, f


def merge(boxes):
    verts, faces = [], []
    for v, f in boxes:
        base = len(verts)
        verts += v
        faces += [(a + base, b + base, c + base) for a, b, c in f]
    return verts, faces


def write_obj(name, mesh, comment):
    v, f = mesh
    with open(os.path.join(HERE, name), "w") as out:
        out.write("# " + comment + "\n")
        for p in v:
            out.write("v %g %g %g\n" % p)
        for a, b, c in f:
            out.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def write_stl(name, mesh):
    v, f = mesh
    with open(os.path.join(HERE, name), "w") as out:
        out.write("solid mhplan\n")
        for tri in f:
            out.write(" facet normal 0 0 0\n  outer loop\n")
            for i in tri:
                out.write("   vertex %g %g %g\n" % v[i])
            out.write("  endloop\n endfacet\n")
        out.write("endsolid mhplan\n")


def write_ply(name, mesh):
    v, f = mesh
    with open(os.path.join(HERE, name), "w") as out:
        out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                  "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                  % (len(v), len(f)))
        for p in v:
            out.write("%g %g %g\n" % p)
        for a, b, c in f:
            out.write("3 %d %d %d\n" % (a, b, c))


def dae_geometry(gid, mesh):
    v, f = mesh
    pos = " ".join("%g %g %g" % p for p in v)
    idx = " ".join("%d %d %d" % t for t in f)
    return ('<geometry id="%s"><mesh><source id="%s-pos"><float_array id="%s-arr" count="%d">%s</float_array>'
            '<technique_common><accessor source="#%s-arr" count="%d" stride="3"><param name="X" type="float"/>'
            '<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>'
            '<vertices id="%s-vtx"><input semantic="POSITION" source="#%s-pos"/></vertices>'
            '<triangles count="%d"><input semantic="VERTEX" source="#%s-vtx" offset="0"/><p>%s</p></triangles>'
            '</mesh></geometry>\n' % (gid, gid, gid, 3 * len(v), pos, gid, len(v), gid, gid, len(f), gid, idx))


def write_dae(name, up, geometries, scene):
    with open(os.path.join(HERE, name), "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                  '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">\n'
                  '<asset><contributor><authoring_tool>mhplan make_meshes.py</authoring_tool></contributor>'
                  '<up_axis>%s</up_axis></asset>\n<library_geometries>\n' % up)
        for gid, mesh in geometries:
            out.write(dae_geometry(gid, mesh))
        out.write('</library_geometries>\n<library_visual_scenes><visual_scene id="scene">\n%s'
                  '</visual_scene></library_visual_scenes>\n'
                  '<scene><instance_visual_scene url="#scene"/></scene>\n</COLLADA>\n' % scene)


# 2D bug trap (SE(2)): walls 2 high (z in [-1, 1]) around a pocket open at the top, gap 1.2 wide.
bugtrap = merge([box((-4, -4, -1), (-3, 4, 1)), box((3, -4, -1), (4, 4, 1)), box((-4, -4, -1), (4, -3, 1)),
                 box((-4, 3, -1), (-0.6, 4, 1)), box((0.6, 3, -1), (4, 4, 1))])
write_obj("bugtrap_env.obj", bugtrap, "mhplan 2D bug trap: a pocket in [-4, 4]^2 open by 1.2 at the top")
# Its robot: a 1.0 x 0.4 bar, written as COLLADA the way SketchUp writes it (Z_UP, a node with a matrix). Read
# as OMPL.app reads COLLADA (docs/meshes.md), Z_UP turns (x, y, z) to (x, z, -y): the bar's cross-section is
# 0.4 x 0.4 about the axis, so it is the same bar either way.
bar = box((0, 0, -0.2), (1.0, 0.4, 0.2))
write_dae("bar_robot.dae", "Z_UP", [("bar", bar)],
          '<node name="SketchUp"><node name="instance_0"><matrix>1 0 0 -0.5 0 1 0 -0.2 0 0 1 0 0 0 0 1</matrix>'
          '<instance_geometry url="#bar"/></node></node>\n')

# 3D narrow passage (SE(3)): a wall at x in [-0.25, 0.25] across y, z in [-4, 4] with a 1.0 x 1.0 window.
wall = merge([box((-0.25, -4, -4), (0.25, -0.5, 4)), box((-0.25, 0.5, -4), (0.25, 4, 4)),
              box((-0.25, -0.5, -4), (0.25, 0.5, -0.5)), box((-0.25, -0.5, 0.5), (0.25, 0.5, 4))])
write_stl("passage_env.stl", wall)
# Its robot: a 1.6 x 0.5 x 0.5 rod, longer than the window is wide: it must pass end first.
write_ply("rod_robot.ply", box((-0.8, -0.25, -0.25), (0.8, 0.25, 0.25)))

# COLLADA with nested transforms, two instances of one geometry and a non-default up axis (X_UP): the unit
# cube placed (after turning X_UP to +y, as assimp and OMPL.app do) at two known places; tests/test_meshes.cpp
# checks the vertices.
cube = box((0, 0, 0), (1, 1, 1))
write_dae("nested_xup.dae", "X_UP", [("cube", cube)],
          '<node name="outer"><translate>10 0 0</translate>'
          '<node name="inner"><rotate>0 0 1 90</rotate><scale>2 2 2</scale><instance_geometry url="#cube"/>'
          '</node><node name="second"><translate>0 5 0</translate><instance_geometry url="#cube"/></node></node>\n')
