#pragma once
/// \file
/// An 8-bit RGB image in memory, and writing it to PNG.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tissu {

struct Image {
  int width = 0;                  ///< pixels
  int height = 0;                 ///< pixels
  std::vector<std::uint8_t> rgb;  ///< width*height*3 bytes: row-major, top row first, R G B

  /// The 3 bytes of pixel (x, y), y counted from the top row.
  const std::uint8_t* pixel(int x, int y) const { return rgb.data() + 3 * (y * width + x); }
};

/// Writes `image` to `file` as an 8-bit RGB PNG, overwriting it, whole or not at all (through a
/// temporary file, lib/atomic_file.hpp). Throws std::invalid_argument if the image's size and data
/// disagree, FileWriteError (a std::runtime_error) naming the file if it cannot be written.
void write_png(const std::filesystem::path& file, const Image& image);

}  // namespace tissu
