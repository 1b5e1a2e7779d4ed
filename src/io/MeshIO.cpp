// SPDX-License-Identifier: BSD-3-Clause
#include "src/io/MeshIO.h"

#include "src/base/World.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace mhplan
{
    namespace
    {
        Eigen::Matrix4d toEigen(const aiMatrix4x4 &m)
        {
            Eigen::Matrix4d out;
            out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
                m.d4;
            return out;
        }

        std::string extensionOf(const std::string &path)
        {
            std::string ext = std::filesystem::path(path).extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            return ext;
        }

        struct Collector
        {
            const aiScene *scene;
            const MeshLimits &limits;
            const std::string &path;
            TriangleMesh &out;

            void visit(const aiNode *node, const Eigen::Matrix4d &parent, unsigned depth)
            {
                if (depth > 1000)
                    throw InputError(path + ": the scene's node tree is deeper than 1000 levels");
                const Eigen::Matrix4d transform = parent * toEigen(node->mTransformation);
                for (unsigned i = 0; i < node->mNumMeshes; ++i)
                {
                    if (node->mMeshes[i] >= scene->mNumMeshes)
                        throw InputError(path + ": a node names a mesh the scene does not have");
                    addMesh(*scene->mMeshes[node->mMeshes[i]], transform);
                }
                for (unsigned c = 0; c < node->mNumChildren; ++c)
                    visit(node->mChildren[c], transform, depth + 1);
            }

            void addMesh(const aiMesh &mesh, const Eigen::Matrix4d &transform)
            {
                std::size_t faces = 0;
                for (unsigned f = 0; f < mesh.mNumFaces; ++f)
                    faces += mesh.mFaces[f].mNumIndices == 3 ? 1 : 0;
                if (faces == 0)
                    return; // points and lines only
                // Each instance adds its vertices again: the limits count what is stored (docs/meshes.md).
                if (out.triangles.size() + faces > limits.maxTriangles)
                    throw InputError(path + ": more than " + std::to_string(limits.maxTriangles) +
                                     " triangles (instances counted each time they are placed)");
                if (out.vertices.size() + mesh.mNumVertices > limits.maxVertices)
                    throw InputError(path + ": more than " + std::to_string(limits.maxVertices) +
                                     " vertices");
                const auto base = static_cast<std::uint32_t>(out.vertices.size());
                for (unsigned v = 0; v < mesh.mNumVertices; ++v)
                {
                    const aiVector3D &p = mesh.mVertices[v];
                    const Eigen::Vector4d w = transform * Eigen::Vector4d(p.x, p.y, p.z, 1.0);
                    out.vertices.emplace_back(w.x(), w.y(), w.z());
                }
                for (unsigned f = 0; f < mesh.mNumFaces; ++f)
                {
                    const aiFace &face = mesh.mFaces[f];
                    if (face.mNumIndices != 3)
                        continue;
                    std::array<std::uint32_t, 3> t{};
                    for (int k = 0; k < 3; ++k)
                    {
                        if (face.mIndices[k] >= mesh.mNumVertices)
                            throw InputError(path + ": a face names a vertex its mesh does not have");
                        t[k] = base + face.mIndices[k];
                    }
                    out.triangles.push_back(t);
                }
            }
        };
    } // namespace

    TriangleMesh readMesh(const std::string &path, const MeshLimits &limits)
    {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            throw InputError(path + ": no such mesh file");
        const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
        if (ec)
            throw InputError(path + ": cannot read the mesh file (" + ec.message() + ")");
        if (bytes > limits.maxFileBytes)
            throw InputError(path + ": the mesh file has " + std::to_string(bytes) +
                             " bytes, more than the " + std::to_string(limits.maxFileBytes) + " accepted");
        Assimp::Importer importer;
        // Points and lines are dropped; polygons become triangles; identical vertices are shared.
        importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        const aiScene *scene = importer.ReadFile(
            path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
        if (scene == nullptr)
            throw InputError(path + ": cannot read the mesh (" + std::string(importer.GetErrorString()) +
                             ")");
        if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr)
            throw InputError(path + ": the mesh file holds no complete scene");
        TriangleMesh mesh;
        mesh.source = path;
        // COLLADA as OMPL.app reads it (docs/meshes.md, "Up axis and units"): assimp's scene as it stands,
        // the root turned so that the file's up axis is +y (OMPL.app composes every node's transform from
        // the root), but without the scale of COLLADA's <unit meter=...>, which assimp multiplies into the
        // root and OMPL.app's problem files do not expect (a robot file in inches beside an environment
        // file without a unit). The root is that uniform scale times a rotation: its determinant's cube
        // root is the scale.
        Eigen::Matrix4d root = Eigen::Matrix4d::Identity();
        const std::string ext = extensionOf(path);
        if (ext == ".dae" || ext == ".zae")
        {
            const Eigen::Matrix3d turn = toEigen(scene->mRootNode->mTransformation).topLeftCorner<3, 3>();
            const double unit = std::cbrt(std::abs(turn.determinant()));
            if (std::isfinite(unit) && unit > 0.0)
                root.topLeftCorner<3, 3>() /= unit;
        }
        Collector{scene, limits, path, mesh}.visit(scene->mRootNode, root, 0);
        checkAndCleanMesh(mesh);
        return mesh;
    }
} // namespace mhplan
