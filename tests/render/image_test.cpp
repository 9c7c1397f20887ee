#include "lib/render/image.hpp"
#include "tests/test_temp_dir.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(WritePng, WritesAFileThatReadsBackWithTheSameSizeAndPixels) {
  Image image{6, 4, std::vector<std::uint8_t>(6 * 4 * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i);
  const fs::path file = test::fresh_temp_dir("png") / "tissu_write_png_test.png";
  fs::remove(file);
  write_png(file, image);
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(data, nullptr) << stbi_failure_reason();
  EXPECT_EQ(width, 6);
  EXPECT_EQ(height, 4);
  EXPECT_EQ(channels, 3);
  EXPECT_TRUE(std::equal(image.rgb.begin(), image.rgb.end(), data));
  stbi_image_free(data);
}

TEST(WritePng, NamesTheFileItCannotWrite) {
  const Image image{2, 2, std::vector<std::uint8_t>(12)};
  const fs::path file = fs::path(::testing::TempDir()) / "no_such_dir_tissu" / "frame.png";
  try {
    write_png(file, image);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
  }
}

TEST(WritePng, RejectsAnImageWhoseDataDoesNotMatchItsSize) {
  const Image image{4, 4, std::vector<std::uint8_t>(10)};
  EXPECT_THROW(write_png(fs::path(::testing::TempDir()) / "bad.png", image), std::invalid_argument);
}

TEST(ImagePixel, CountsRowsFromTheTop) {
  Image image{2, 2, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}};
  EXPECT_EQ(image.pixel(1, 0)[0], 1);
  EXPECT_EQ(image.pixel(0, 1)[0], 2);
}

}  // namespace
}  // namespace tissu
