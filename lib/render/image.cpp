#include "lib/render/image.hpp"

#include <stdexcept>
#include <string>

// the one place stb_image_write's implementation is compiled; static so that it cannot clash with
// another copy (libstb) linked into the same program
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace tissu {

void write_png(const std::filesystem::path& file, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3u * static_cast<std::size_t>(image.width) * image.height)
    throw std::invalid_argument("write_png: image of " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " pixels holds " +
                                std::to_string(image.rgb.size()) + " bytes");
  const int ok =
      stbi_write_png(file.c_str(), image.width, image.height, 3, image.rgb.data(), 3 * image.width);
  if (!ok) throw std::runtime_error(file.string() + ": cannot write PNG image");
}

}  // namespace tissu
