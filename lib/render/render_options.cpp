#include "lib/render/render_options.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

template <typename T>
std::string to_text(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void check_size(const char* name, int pixels) {
  if (pixels < 2)
    throw std::invalid_argument(std::string("render: image ") + name +
                                " must be at least 2 pixels, got " + to_text(pixels));
  if (pixels > 16384)
    throw std::invalid_argument(std::string("render: image ") + name +
                                " must be at most 16384 pixels, got " + to_text(pixels));
  if (pixels % 2 != 0)
    throw std::invalid_argument(std::string("render: image ") + name +
                                " must be even (video encoders need it), got " + to_text(pixels));
}

void check_color(const char* name, const Eigen::Vector3f& color) {
  for (int i = 0; i < 3; ++i) {
    if (!(color[i] >= 0.0f && color[i] <= 1.0f))
      throw std::invalid_argument(std::string("render: ") + name +
                                  " components must be in [0, 1], got " + to_text(color[i]));
  }
}

void check_range(const char* name, double value, double low, double high) {
  if (!(value >= low && value <= high))
    throw std::invalid_argument(std::string("render: ") + name + " must be in [" + to_text(low) +
                                ", " + to_text(high) + "], got " + to_text(value));
}

}  // namespace

void validate_render_options(const RenderOptions& options) {
  check_size("width", options.width);
  check_size("height", options.height);
  check_range("samples", options.samples, 1, 16);
  const long long samples = 1LL * options.width * options.height * options.samples;
  if (samples > max_render_samples)
    throw std::invalid_argument("render: an image of " + to_text(options.width) + " x " +
                                to_text(options.height) + " pixels at " + to_text(options.samples) +
                                " samples has " + to_text(samples) + " samples, more than the " +
                                to_text(max_render_samples) +
                                " an image may have (width x height x samples)");
  if (!(options.strain_range > 0.0) || !std::isfinite(options.strain_range))
    throw std::invalid_argument("render: strain range must be positive, got " +
                                to_text(options.strain_range));
  check_color("front colour", options.front_color);
  check_color("back colour", options.back_color);
  check_color("background colour", options.background_color);
  check_color("wireframe colour", options.wireframe_color);
  check_color("pin colour", options.pin_color);
  check_color("ground colour", options.ground_color);
  check_color("obstacle colour", options.obstacle_color);
  check_range("wireframe width (pixels)", options.wireframe_width_px, 1.0, 16.0);
  check_range("wireframe opacity", options.wireframe_opacity, 0.0, 1.0);
  check_range("pin size (pixels)", options.pin_size_px, 1.0, 64.0);
}

}  // namespace tissu
