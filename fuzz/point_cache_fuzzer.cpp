// Fuzz target: a PC2 point cache (an animated mesh obstacle's `animation.point_cache`), read as
// tissu reads an untrusted one. Reading may succeed or throw PointCacheError with one clear line
// naming the file; anything else (a crash, a hang, an allocation beyond the file's size, another
// exception, an unclear message) is a bug.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz/fuzz_checks.hpp"
#include "lib/point_cache.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("tissu_fuzz_" + std::to_string(getpid()) + ".pc2");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    tissu::read_point_cache(file, std::uintmax_t{1} << 20);  // 1 MiB: inputs stay small
  } catch (const tissu::PointCacheError& e) {
    tissu::fuzz::require_clear_message(e.what(), "point cache " + file.string() + ": ");
  }
  return 0;
}
