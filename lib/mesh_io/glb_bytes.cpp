// The glTF binary of a frame, through assimp's glTF 2 exporter: tissu builds the scene (one mesh,
// one double-sided material) and assimp writes the container, accessors and buffer.
#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <Eigen/Geometry>
#include <array>
#include <stdexcept>

#include "lib/mesh_io/mesh_encoding.hpp"

namespace tissu {
namespace {

/// tissu's z-up world in glTF's y-up frame (glTF 2.0 spec, 3.4 "Coordinate System and Units"):
/// (x, y, z) -> (x, z, -y), a rotation, so orientation and lengths (m) are kept.
aiVector3D y_up(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.z()), static_cast<float>(-p.y())};
}

/// Area-weighted vertex normals of `mesh`'s triangles (unit, y-up; zero for an unused vertex).
std::vector<Eigen::Vector3d> vertex_normals(const IndexedMesh& mesh,
                                            const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Eigen::Vector3d> normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    // twice the triangle's area along its normal: larger triangles weigh more
    const Eigen::Vector3d n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    for (int v : t) normals[v] += n;
  }
  for (Eigen::Vector3d& n : normals) {
    if (n.norm() > 0.0) n.normalize();
  }
  return normals;
}

}  // namespace

std::string glb_bytes(const IndexedMesh& mesh, const std::vector<Eigen::Vector3d>* texture_uvw) {
  std::vector<std::array<int, 3>> triangles;  // a quad split along its first diagonal
  for (const std::vector<int>& face : mesh.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      triangles.push_back({face[0], face[k], face[k + 1]});
  }
  const std::vector<Eigen::Vector3d> normals = vertex_normals(mesh, triangles);

  // aiScene's destructor deletes what its pointers own: everything below is new-allocated
  aiScene scene;
  scene.mRootNode = new aiNode("cloth");
  scene.mRootNode->mNumMeshes = 1;
  scene.mRootNode->mMeshes = new unsigned[1]{0};
  scene.mNumMaterials = 1;
  scene.mMaterials = new aiMaterial* [1] { new aiMaterial };
  const int two_sided = 1;  // cloth is seen from both sides
  scene.mMaterials[0]->AddProperty(&two_sided, 1, AI_MATKEY_TWOSIDED);
  scene.mNumMeshes = 1;
  scene.mMeshes = new aiMesh* [1] { new aiMesh };
  aiMesh& out = *scene.mMeshes[0];
  out.mMaterialIndex = 0;
  out.mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out.mNumVertices = static_cast<unsigned>(mesh.vertices.size());
  out.mVertices = new aiVector3D[out.mNumVertices];
  out.mNormals = new aiVector3D[out.mNumVertices];
  for (unsigned v = 0; v < out.mNumVertices; ++v) {
    out.mVertices[v] = y_up(mesh.vertices[v]);
    out.mNormals[v] = y_up(normals[v]);
  }
  if (texture_uvw != nullptr) {
    out.mNumUVComponents[0] = 2;
    out.mTextureCoords[0] = new aiVector3D[out.mNumVertices];
    for (unsigned v = 0; v < out.mNumVertices; ++v) {
      out.mTextureCoords[0][v] = aiVector3D(static_cast<float>((*texture_uvw)[v].x()),
                                            static_cast<float>((*texture_uvw)[v].y()), 0.0f);
    }
  }
  out.mNumFaces = static_cast<unsigned>(triangles.size());
  out.mFaces = new aiFace[out.mNumFaces];
  for (unsigned f = 0; f < out.mNumFaces; ++f) {
    out.mFaces[f].mNumIndices = 3;
    out.mFaces[f].mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) out.mFaces[f].mIndices[k] = static_cast<unsigned>(triangles[f][k]);
  }

  Assimp::Exporter exporter;
  const aiExportDataBlob* blob = exporter.ExportToBlob(&scene, "glb2");
  if (blob == nullptr)
    throw std::runtime_error(std::string("assimp's glTF exporter: ") + exporter.GetErrorString());
  return std::string(static_cast<const char*>(blob->data), blob->size);
}

}  // namespace tissu
