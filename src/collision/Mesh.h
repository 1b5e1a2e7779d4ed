// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: triangle meshes (the robots and environments of OMPL.app's problems, docs/meshes.md) and their FCL
   bounding-volume hierarchies. */
#ifndef MHPLAN_MESH_H
#define MHPLAN_MESH_H

#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Triangles over shared vertices, in one frame (the file's, after its node transforms and up
        axis, docs/meshes.md). */
    struct TriangleMesh
    {
        std::vector<Eigen::Vector3d> vertices;
        std::vector<std::array<std::uint32_t, 3>> triangles;
        /** \brief Where it came from (a file name), for messages. */
        std::string source;

        /** \brief The axis-aligned box of the vertices used by triangles ({+inf, -inf} when empty). */
        Eigen::AlignedBox3d box() const;
        /** \brief The mean of the vertices used by triangles (OMPL.app's robot centre). */
        Eigen::Vector3d vertexCentroid() const;
        /** \brief The farthest vertex from \e p. */
        double reachFrom(const Eigen::Vector3d &p) const;
        /** \brief The mesh moved by \e shift (every vertex plus shift). */
        TriangleMesh translated(const Eigen::Vector3d &shift) const;
    };

    /** \brief Limits that keep a mesh file from exhausting memory or time (docs/meshes.md): the file size,
        and the triangles and vertices after triangulation. */
    struct MeshLimits
    {
        std::uint64_t maxFileBytes{256ull << 20};
        std::size_t maxTriangles{4000000};
        std::size_t maxVertices{4000000};
    };

    /** \brief The checks every mesh passes before it is used (throws InputError naming mesh.source):
        finite coordinates, triangle indices in range, at least one triangle of positive area. Triangles of
        zero area (repeated or collinear corners) are dropped; the count is returned. */
    std::size_t checkAndCleanMesh(TriangleMesh &mesh);

    /** \brief A mesh as an FCL bounding-volume hierarchy (OBBRSS, as OMPL.app builds it), placed by rigid
        transforms for collision and distance queries. Immutable once built; queries are safe from several
        threads. */
    class MeshShape
    {
      public:
        explicit MeshShape(const TriangleMesh &mesh);
        /** \brief A solid box of edge lengths \e size centred on its origin (fcl::Box, docs/worlds3d.md): a
            point inside it touches it. */
        static std::unique_ptr<MeshShape> box(const Eigen::Vector3d &size);
        /** \brief A solid ball of radius \e radius >= 0 about its origin (fcl::Sphere; radius 0 is a point).
         */
        static std::unique_ptr<MeshShape> sphere(double radius);
        ~MeshShape();
        MeshShape(const MeshShape &) = delete;
        MeshShape &operator=(const MeshShape &) = delete;

        /** \brief The triangles of a mesh; 0 for a box or a sphere. */
        std::size_t triangleCount() const { return triangles_; }

        /** \brief True when this mesh at \e a and \e other at \e b share a point (FCL's collide). */
        bool collides(const Eigen::Isometry3d &a, const MeshShape &other, const Eigen::Isometry3d &b) const;
        /** \brief FCL's distance between this mesh at \e a and \e other at \e b (exact triangle distances);
            0 or a negative value when they touch or overlap. */
        double distance(const Eigen::Isometry3d &a, const MeshShape &other, const Eigen::Isometry3d &b) const;

      private:
        MeshShape();
        struct Impl;
        std::unique_ptr<Impl> impl_;
        std::size_t triangles_{0};
    };
} // namespace mhplan

#endif
