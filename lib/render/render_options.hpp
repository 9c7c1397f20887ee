#pragma once
/// \file
/// How the renderer draws a frame: image size, colours, overlays. Colours are RGB in [0, 1],
/// written as they appear on screen (no gamma conversion).

#include <Eigen/Core>

namespace tissu {

/// What the cloth's surface colour shows.
enum class ColorMode {
  shaded,  ///< front_color on the front side (counter-clockwise faces), back_color behind
  strain,  ///< per-face strain on a blue-white-red diverging map, both sides
  level,   ///< per-face refinement level, one colour per level (light input faces, darker finer)
  sizing_term,  ///< per face, which term of the sizing field holds it fine, one colour per term
};

struct RenderOptions {
  int width = 1280;        ///< image width (pixels), even and >= 2 (video encoders need even sizes)
  int height = 720;        ///< image height (pixels), even and >= 2
  int samples = 4;         ///< multisample anti-aliasing samples per pixel, 1 to 16 (1 = off)
  bool wireframe = false;  ///< draws the polygon edges (quads as quads) on the cloth
  ColorMode color_mode = ColorMode::shaded;  ///< surface colouring
  /// Strain mapped to the ends of the strain colour map: -strain_range is full blue, 0 white,
  /// +strain_range full red; values beyond are clamped. Must be > 0.
  double strain_range = 0.1;
  bool show_pins = true;    ///< marks pinned particles with small squares
  bool show_ground = true;  ///< draws the scene's ground plane, when it has one
  Eigen::Vector3f front_color{0.80f, 0.22f, 0.18f};       ///< front side: warm red
  Eigen::Vector3f back_color{0.42f, 0.50f, 0.62f};        ///< back side: blue-grey
  Eigen::Vector3f background_color{0.96f, 0.96f, 0.97f};  ///< clear colour: near white
  Eigen::Vector3f wireframe_color{0.10f, 0.08f, 0.08f};   ///< edge lines: near black
  Eigen::Vector3f pin_color{0.08f, 0.08f, 0.10f};         ///< pin squares: near black
  Eigen::Vector3f ground_color{0.80f, 0.80f, 0.78f};      ///< ground plane: light grey
  Eigen::Vector3f obstacle_color{0.66f, 0.70f, 0.76f};    ///< obstacles: light grey-blue
  float wireframe_width_px = 1.0f;                        ///< edge line width (pixels), in [1, 16]
  float wireframe_opacity = 0.6f;  ///< edge lines blended over the surface: 0 invisible, 1 opaque
  float pin_size_px = 6.0f;        ///< pin square side (pixels), in [1, 64]
};

/// Most samples one image may have, width x height x samples: the multisample colour and depth
/// buffers take 8 bytes per sample (1 GiB at the bound), and the single-sample buffers, the
/// read-back and the PNG encoder as much again per pixel. 3840 x 2160 at 16 samples fits;
/// 16384 x 16384 at 16 samples (34 GiB) does not.
inline constexpr long long max_render_samples = 134'217'728;  // 2^27

/// Throws std::invalid_argument, with a message starting "render: " that names the field and the
/// value, when a size is odd, below 2 or above 16384, samples is outside [1, 16], width x height x
/// samples is above max_render_samples, a colour component is outside [0, 1], strain_range is not
/// positive, or a line size, line opacity or pin size is out of range.
void validate_render_options(const RenderOptions& options);

}  // namespace tissu
