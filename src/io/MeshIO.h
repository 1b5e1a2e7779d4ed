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
        points and lines dropped, and, for COLLADA, the file's up axis turned to +z (a Z_UP file, as SketchUp
        writes it, keeps its coordinates; Y_UP, COLLADA's default, and X_UP are rotated so that their up axis
        becomes +z). Refuses (InputError naming the file) a missing or unreadable file, one larger than
        limits.maxFileBytes, a scene with more triangles or vertices than the limits, a mesh without
        triangles of positive area, and non-finite coordinates. */
    TriangleMesh readMesh(const std::string &path, const MeshLimits &limits = {});
} // namespace mhplan

#endif
