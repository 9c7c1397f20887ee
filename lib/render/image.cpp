#include "lib/render/image.hpp"

#include <stdexcept>
#include <string>

// the one place stb_image_write's implementation is compiled; static so that it cannot clash with
// another copy (libstb) linked into the same program
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

#include "lib/atomic_file.hpp"

namespace tissu {
namespace {

/// stb's output callback: appends the bytes to the std::string `context`.
void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3u * static_cast<std::size_t>(image.width) * image.height)
    throw std::invalid_argument("write_png: image of " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " pixels holds " +
                                std::to_string(image.rgb.size()) + " bytes");
  // encoded in memory, then written whole or not at all (lib/atomic_file.hpp): stbi_write_png
  // itself does not report a failed write, and would leave a truncated image on a full disk
  std::string png;
  const int ok = stbi_write_png_to_func(append_bytes, &png, image.width, image.height, 3,
                                        image.rgb.data(), 3 * image.width);
  if (!ok) throw std::runtime_error(file.string() + ": cannot encode PNG image");
  write_file_atomically(file, png, "PNG image");
}

}  // namespace tissu
