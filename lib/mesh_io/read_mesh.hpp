#pragma once
/// \file
/// Reading a cloth mesh from a file (OBJ, PLY, glTF/GLB, STL, OFF) through assimp.

#include <filesystem>

#include "topology/indexed_mesh.hpp"

namespace tissu {

/// Reads the polygon mesh in `file` and checks it with validate_indexed_mesh.
///
/// All meshes of the file's scene are merged into one, with their node transforms applied.
/// Only positions are kept: vertices at exactly the same position are joined, so a cloth is not
/// cut at UV or normal seams, nor between the groups or objects of one file. Points and lines
/// are ignored, and so are vertices no face uses; triangles and quads are kept as they are (never
/// triangulated). Vertices keep the importer's order: the file's order for PLY and OFF, the
/// order the faces first use them for OBJ.
///
/// Throws MeshError whose message starts with the file path: when the file is missing or
/// unreadable, when the importer fails or reports indices out of range, or when the mesh fails
/// validate_indexed_mesh. Not safe to call concurrently with other uses of assimp's logger.
IndexedMesh read_mesh(const std::filesystem::path& file);

/// Reads `file` as read_mesh does, but without validate_indexed_mesh: for obstacles, which may be
/// triangle soups (non-manifold, several parts, polygons of any size). Throws MeshError starting
/// with the file path when the file cannot be read or the importer fails.
IndexedMesh read_polygons(const std::filesystem::path& file);

}  // namespace tissu
