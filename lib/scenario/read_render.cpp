#include "lib/scenario/read_render.hpp"

namespace tissu {
namespace {

int read_even_pixels(JsonObjectReader& render, std::string_view key, int fallback) {
  const int pixels = render.integer_or(key, fallback, 2, 16384);
  if (pixels % 2 != 0) render.fail(key, "an even number of pixels (video encoders need it)");
  return pixels;
}

Camera read_camera(JsonObjectReader camera) {
  Camera c;
  c.position = camera.vector3("position");
  c.target = camera.vector3("target");
  c.up = camera.vector3_or("up", c.up);
  c.fov_y_deg = camera.number_or(
      "fov", c.fov_y_deg, {0.0, 179.0, true, "a vertical field of view in (0, 179] degrees"});
  camera.finish();
  try {
    validate_camera(c);
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(camera.file() + ": " + camera.path() + ": " + e.what());
  }
  return c;
}

}  // namespace

RenderSettings read_render(JsonObjectReader render) {
  RenderSettings r;
  RenderOptions& o = r.options;
  r.enabled = render.boolean_or("enabled", true);
  o.width = read_even_pixels(render, "width", o.width);
  o.height = read_even_pixels(render, "height", o.height);
  o.samples = render.integer_or("samples", o.samples, 1, 16);
  if (const long long samples = 1LL * o.width * o.height * o.samples;
      samples > max_render_samples) {
    // named here with the key the user can lower; validate_render_options checks it again
    render.fail(o.samples > 1 ? "samples" : "width",
                "at most " + std::to_string(max_render_samples) +
                    " samples per image, width x height x samples (the render memory limit), not " +
                    std::to_string(o.width) + " x " + std::to_string(o.height) + " x " +
                    std::to_string(o.samples) + " = " + std::to_string(samples));
  }
  o.wireframe = render.boolean_or("wireframe", o.wireframe);
  const std::string mode =
      render.choice_or("color_mode", "shaded", {"shaded", "strain", "level", "sizing"});
  o.color_mode = mode == "strain"   ? ColorMode::strain
                 : mode == "level"  ? ColorMode::level
                 : mode == "sizing" ? ColorMode::sizing_term
                                    : ColorMode::shaded;
  o.strain_range = render.number_or("strain_range", o.strain_range, positive(""));
  o.show_pins = render.boolean_or("show_pins", o.show_pins);
  r.every = render.integer_or("every", 1, 1, std::numeric_limits<int>::max());
  r.video = render.boolean_or("video", r.video);
  if (render.has("camera")) r.camera = read_camera(render.object("camera"));
  render.finish();
  try {
    validate_render_options(o);
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(render.file() + ": " + render.path() + ": " + e.what());
  }
  return r;
}

}  // namespace tissu
