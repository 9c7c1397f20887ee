#pragma once
/// \file
/// Cheap checks tissu makes on a mesh file before any importer reads it: that it is a regular
/// file of a bounded size, and that the element counts a PLY, OFF, binary STL or GLB header
/// declares fit in the file's size. Importers trust those counts and allocate for them, so a
/// damaged or hostile header is refused here with a clear message instead of costing gigabytes.

#include <cstdint>
#include <filesystem>

namespace tissu {

/// Throws MeshError "<file>: cannot read mesh: <why>" if `file` does not exist, is not a
/// regular file (a directory, FIFO, device or socket: opening a FIFO would block), is empty, is
/// larger than `max_bytes`, or has a header whose counts cannot fit in its size. Never opens
/// anything but a regular file. Returns the file's size (bytes).
std::uintmax_t check_mesh_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

}  // namespace tissu
