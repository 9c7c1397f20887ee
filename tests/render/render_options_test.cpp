#include "lib/render/render_options.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace tissu {
namespace {

using ::testing::HasSubstr;

std::string options_error(const RenderOptions& options) {
  try {
    validate_render_options(options);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateRenderOptions, AcceptsTheDefaults) {
  EXPECT_EQ(options_error(RenderOptions{}), "");
}

TEST(ValidateRenderOptions, RejectsOddSizes) {
  RenderOptions options;
  options.width = 641;
  EXPECT_THAT(options_error(options),
              HasSubstr("render: image width must be even (video encoders need it), got 641"));
  options.width = 640;
  options.height = 481;
  EXPECT_THAT(options_error(options),
              HasSubstr("render: image height must be even (video encoders need it), got 481"));
}

TEST(ValidateRenderOptions, RejectsTinyAndHugeSizes) {
  RenderOptions options;
  options.width = 0;
  EXPECT_THAT(options_error(options), HasSubstr("image width must be at least 2 pixels, got 0"));
  options.width = 20000;
  EXPECT_THAT(options_error(options), HasSubstr("at most 16384 pixels, got 20000"));
}

TEST(ValidateRenderOptions, RejectsColoursOutsideZeroToOne) {
  RenderOptions options;
  options.back_color = {0.5f, 1.5f, 0.0f};
  EXPECT_THAT(options_error(options),
              HasSubstr("render: back colour components must be in [0, 1], got 1.5"));
  options = RenderOptions{};
  options.obstacle_color = {-0.1f, 0.5f, 0.5f};
  EXPECT_THAT(options_error(options),
              HasSubstr("render: obstacle colour components must be in [0, 1], got -0.1"));
}

TEST(ValidateRenderOptions, RejectsANonPositiveStrainRangeAndBadSampleCounts) {
  RenderOptions options;
  options.strain_range = 0.0;
  EXPECT_THAT(options_error(options), HasSubstr("strain range must be positive, got 0"));
  options = RenderOptions{};
  options.samples = 0;
  EXPECT_THAT(options_error(options), HasSubstr("samples must be in [1, 16], got 0"));
}

}  // namespace
}  // namespace tissu
