#pragma once
/// \file
/// Writing a mesh to an OBJ or PLY file through assimp, e.g. one file per simulated frame.

#include <filesystem>
#include <string_view>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// File formats write_mesh can produce.
enum class MeshFormat {
  obj,  ///< Wavefront OBJ, text, without a material library
  ply,  ///< Stanford PLY, binary little-endian
};

/// The format named `name` ("obj" or "ply"). Throws std::invalid_argument naming the accepted
/// values otherwise.
MeshFormat mesh_format_from_string(std::string_view name);

/// The file name extension of `format`, without the dot: "obj" or "ply".
const char* extension(MeshFormat format);

/// Writes the vertices and faces (3 or 4 vertex ids each, kept as they are) of `mesh` to `file`,
/// overwriting it. Positions are written in single precision. Throws std::runtime_error naming
/// the file if it cannot be written.
void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh, MeshFormat format);

}  // namespace tissu
