#include "lib/mesh_io/write_mesh.hpp"

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <memory>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

/// A one-mesh scene holding `mesh`: one default material and a root node referencing the mesh.
/// The aiScene destructor frees every part, so each part is attached as soon as it is created.
std::unique_ptr<aiScene> make_scene(const IndexedMesh& mesh) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode();
  scene->mRootNode->mMeshes = new unsigned[1]{0};
  scene->mRootNode->mNumMeshes = 1;

  scene->mMaterials = new aiMaterial* [1] {};
  scene->mNumMaterials = 1;
  scene->mMaterials[0] = new aiMaterial();

  scene->mMeshes = new aiMesh* [1] {};
  scene->mNumMeshes = 1;
  scene->mMeshes[0] = new aiMesh();
  aiMesh& out = *scene->mMeshes[0];
  out.mMaterialIndex = 0;

  out.mVertices = new aiVector3D[mesh.vertices.size()];
  out.mNumVertices = static_cast<unsigned>(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    out.mVertices[v] = aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()),
                                  static_cast<ai_real>(p.z()));
  }

  out.mFaces = new aiFace[mesh.faces.size()];
  out.mNumFaces = static_cast<unsigned>(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    aiFace& target = out.mFaces[f];
    target.mIndices = new unsigned[face.size()];
    target.mNumIndices = static_cast<unsigned>(face.size());
    for (std::size_t i = 0; i < face.size(); ++i) {
      target.mIndices[i] = static_cast<unsigned>(face[i]);
    }
    out.mPrimitiveTypes |= face.size() == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
  }
  return scene;
}

}  // namespace

MeshFormat mesh_format_from_string(std::string_view name) {
  if (name == "obj") {
    return MeshFormat::obj;
  }
  if (name == "ply") {
    return MeshFormat::ply;
  }
  throw std::invalid_argument("unknown mesh format \"" + std::string(name) +
                              "\": expected \"obj\" or \"ply\"");
}

const char* extension(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return "obj";
    case MeshFormat::ply:
      return "ply";
  }
  return "";
}

void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh, MeshFormat format) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int v : mesh.faces[f]) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
        throw std::runtime_error(file.string() + ": cannot write mesh: face " + std::to_string(f) +
                                 " refers to vertex " + std::to_string(v) + ", but the mesh has " +
                                 std::to_string(mesh.vertices.size()) + " vertices");
      }
    }
  }
  const std::unique_ptr<aiScene> scene = make_scene(mesh);
  // "objnomtl" writes no .mtl file next to the .obj; "plyb" is binary little-endian PLY
  const char* exporter_id = format == MeshFormat::obj ? "objnomtl" : "plyb";
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), exporter_id, file.string()) != aiReturn_SUCCESS) {
    throw std::runtime_error(file.string() + ": cannot write mesh: " + exporter.GetErrorString());
  }
}

}  // namespace tissu
