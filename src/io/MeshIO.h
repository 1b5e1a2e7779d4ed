// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: reading triangle meshes (COLLADA, OBJ, STL, PLY and the other formats assimp reads) into
   mhplan's TriangleMesh (docs/meshes.md). */
#ifndef MHPLAN_MESH_IO_H
#define MHPLAN_MESH_IO_H

#include "src/collision/Mesh.h"

#include <string>

namespace mhplan
{
    /** \brief Read a mesh file through assimp: every mesh of every node, placed by the node's transform
        composed with its ancestors' (so instances and nested transforms count), polygons triangulated,
        points and lines dropped, and, for COLLADA, read as OMPL.app reads it (docs/meshes.md, "Up axis and
        units"): the file's up axis turned to +y as assimp turns it (Z_UP: (x, y, z) at (x, z, -y); X_UP at
        (-y, x, z); Y_UP kept), COLLADA's unit not applied. Refuses (InputError naming the file) a missing or
       unreadable file, one larger than limits.maxFileBytes, a scene with more triangles or vertices than the
       limits, a mesh without triangles of positive area, and non-finite coordinates. */
    TriangleMesh readMesh(const std::string &path, const MeshLimits &limits = {});
} // namespace mhplan

#endif
