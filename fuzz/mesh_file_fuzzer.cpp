// Fuzz target: one mesh file format (TISSU_FUZZ_EXTENSION, e.g. ".ply"), read as a cloth mesh and
// as an obstacle mesh. Reading may succeed or throw MeshError with one clear line naming the
// file; anything else (a crash, a hang, another exception, an unclear message) is a bug. assimp
// runs in a child process (lib/mesh_io/sandboxed_call.hpp), so this checks that its failures
// reach tissu's caller as errors, and fuzzes tissu's own OBJ reader, header checks and mesh
// validation in process.

#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz/fuzz_checks.hpp"
#include "lib/mesh_io/read_mesh.hpp"

namespace {

/// A file of this process under the temp dir, with the format's extension.
const std::filesystem::path& input_file() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("tissu_fuzz_" + std::to_string(getpid()) + TISSU_FUZZ_EXTENSION);
  return file;
}

void read_as(bool cloth, const tissu::MeshImportLimits& limits) {
  try {
    if (cloth) {
      tissu::read_numbered_mesh(input_file(), limits);
    } else {
      tissu::read_polygons(input_file(), limits);
    }
  } catch (const tissu::MeshError& e) {
    tissu::fuzz::require_clear_message(e.what(), input_file().string() + ": ");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(input_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  tissu::MeshImportLimits limits;
  limits.importer = tissu::SandboxLimits{std::chrono::milliseconds(3000), std::size_t{1} << 30};
  read_as(true, limits);
  read_as(false, limits);
  return 0;
}
