#pragma once
/// \file
/// A NumberedMesh as bytes and back, so that a mesh imported in a child process
/// (sandboxed_call.hpp) can be handed to its parent. Internal to lib/mesh_io: the layout (native
/// byte order, sizes before contents) is for one machine's processes, not a file format.

#include <string>

#include "lib/mesh_io/read_mesh.hpp"

namespace tissu {

/// The bytes of `mesh`: every field of NumberedMesh.
std::string numbered_mesh_bytes(const NumberedMesh& mesh);

/// The mesh whose numbered_mesh_bytes are `bytes`. Throws std::runtime_error if they are
/// truncated or their sizes do not add up (never reads out of bounds).
NumberedMesh numbered_mesh_from_bytes(const std::string& bytes);

}  // namespace tissu
