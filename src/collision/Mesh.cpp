// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/Mesh.h"

#include "src/base/World.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <cmath>
#include <limits>

namespace mhplan
{
    namespace
    {
        template <typename F> void forUsedVertices(const TriangleMesh &m, F &&f)
        {
            std::vector<char> used(m.vertices.size(), 0);
            for (const auto &t : m.triangles)
                for (const std::uint32_t i : t)
                    used[i] = 1;
            for (std::size_t i = 0; i < m.vertices.size(); ++i)
                if (used[i] != 0)
                    f(m.vertices[i]);
        }
    } // namespace

    Eigen::AlignedBox3d TriangleMesh::box() const
    {
        Eigen::AlignedBox3d b; // empty
        forUsedVertices(*this, [&](const Eigen::Vector3d &v) { b.extend(v); });
        return b;
    }

    Eigen::Vector3d TriangleMesh::vertexCentroid() const
    {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        std::size_t n = 0;
        forUsedVertices(*this,
                        [&](const Eigen::Vector3d &v)
                        {
                            sum += v;
                            ++n;
                        });
        return n == 0 ? sum : Eigen::Vector3d(sum / static_cast<double>(n));
    }

    double TriangleMesh::reachFrom(const Eigen::Vector3d &p) const
    {
        double r = 0.0;
        forUsedVertices(*this, [&](const Eigen::Vector3d &v) { r = std::max(r, (v - p).norm()); });
        return r;
    }

    TriangleMesh TriangleMesh::translated(const Eigen::Vector3d &shift) const
    {
        TriangleMesh out = *this;
        for (auto &v : out.vertices)
            v += shift;
        return out;
    }

    std::size_t checkAndCleanMesh(TriangleMesh &mesh)
    {
        const std::string where = "mesh '" + mesh.source + "'";
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
            if (!mesh.vertices[i].allFinite())
                throw InputError(where + ": vertex " + std::to_string(i) + " is not finite");
        std::vector<std::array<std::uint32_t, 3>> kept;
        kept.reserve(mesh.triangles.size());
        double extent = 0.0;
        for (const auto &v : mesh.vertices)
            extent = std::max(extent, v.cwiseAbs().maxCoeff());
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        {
            const auto &t = mesh.triangles[i];
            for (const std::uint32_t k : t)
                if (k >= mesh.vertices.size())
                    throw InputError(where + ": triangle " + std::to_string(i) + " names vertex " +
                                     std::to_string(k) + " of " + std::to_string(mesh.vertices.size()));
            const Eigen::Vector3d n =
                (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
            // Twice the area, against the square of the scene's size: below rounding, the triangle is a
            // segment or a point (docs/meshes.md).
            const double scale = std::max(1.0, extent);
            if (n.norm() > 1e-12 * scale * scale)
                kept.push_back(t);
        }
        const std::size_t dropped = mesh.triangles.size() - kept.size();
        if (kept.empty())
            throw InputError(where + (mesh.triangles.empty()
                                          ? ": no triangles (an empty mesh, or points and lines only)"
                                          : ": every triangle is degenerate (zero area)"));
        mesh.triangles = std::move(kept);
        return dropped;
    }

    struct MeshShape::Impl
    {
        std::shared_ptr<fcl::CollisionGeometryd> model;
    };

    MeshShape::MeshShape() : impl_(std::make_unique<Impl>()) {}

    std::unique_ptr<MeshShape> MeshShape::box(const Eigen::Vector3d &size)
    {
        if (!size.allFinite() || !(size.minCoeff() > 0.0))
            throw InputError("a box needs three finite edge lengths > 0");
        std::unique_ptr<MeshShape> s(new MeshShape());
        s->impl_->model = std::make_shared<fcl::Boxd>(size);
        s->impl_->model->computeLocalAABB();
        return s;
    }

    std::unique_ptr<MeshShape> MeshShape::sphere(double radius)
    {
        if (!std::isfinite(radius) || !(radius >= 0.0))
            throw InputError("a sphere needs a finite radius >= 0");
        std::unique_ptr<MeshShape> s(new MeshShape());
        s->impl_->model = std::make_shared<fcl::Sphered>(radius);
        s->impl_->model->computeLocalAABB();
        return s;
    }

    MeshShape::MeshShape(const TriangleMesh &mesh) : impl_(std::make_unique<Impl>())
    {
        if (mesh.triangles.empty())
            throw InputError("mesh '" + mesh.source + "': no triangles");
        std::vector<fcl::Vector3d> points(mesh.vertices.begin(), mesh.vertices.end());
        std::vector<fcl::Triangle> triangles;
        triangles.reserve(mesh.triangles.size());
        for (const auto &t : mesh.triangles)
            triangles.emplace_back(t[0], t[1], t[2]);
        const auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
        if (bvh->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size())) !=
                fcl::BVH_OK ||
            bvh->addSubModel(points, triangles) != fcl::BVH_OK || bvh->endModel() != fcl::BVH_OK)
            throw InputError("mesh '" + mesh.source + "': FCL cannot build its bounding-volume hierarchy");
        bvh->computeLocalAABB();
        impl_->model = bvh;
        triangles_ = mesh.triangles.size();
    }

    MeshShape::~MeshShape() = default;

    bool MeshShape::collides(const Eigen::Isometry3d &a, const MeshShape &other,
                             const Eigen::Isometry3d &b) const
    {
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        fcl::collide(impl_->model.get(), a, other.impl_->model.get(), b, request, result);
        return result.isCollision();
    }

    double MeshShape::distance(const Eigen::Isometry3d &a, const MeshShape &other,
                               const Eigen::Isometry3d &b) const
    {
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        const double d = fcl::distance(impl_->model.get(), a, other.impl_->model.get(), b, request, result);
        return std::isfinite(d) ? d : -1.0;
    }
} // namespace mhplan
