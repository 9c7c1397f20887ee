#pragma once
/// \file
/// The headless renderer: draws a RenderScene seen by a Camera into an Image, offscreen.

#include <memory>

#include "lib/render/camera.hpp"
#include "lib/render/image.hpp"
#include "lib/render/render_options.hpp"
#include "lib/render/render_scene.hpp"

namespace tissu {

/// Owns an offscreen OpenGL context of the options' image size and the GPU objects drawn with it.
/// Draws the cloth with smooth (area-weighted) vertex normals and two-sided lighting from two
/// lights fixed to the camera (upper left key, right fill), the back side in its own colour; or
/// coloured by face strain. Draws the scene's obstacles with the same lights in the obstacle
/// colour (smooth on curved surfaces, flat on each side of sharp edges, no wireframe). Optionally
/// overlays the polygon edges (a quad shows as a quad), marks pinned particles, and draws a
/// ground plane that fades into the background. Not thread-safe; one renderer per thread.
class Renderer {
 public:
  /// Validates `options` (std::invalid_argument) and creates the context (std::runtime_error).
  explicit Renderer(const RenderOptions& options);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  /// The image of `scene` seen by `camera`, options().width x options().height pixels. Throws
  /// std::invalid_argument for an invalid camera or scene, std::runtime_error on an OpenGL error.
  Image render(const RenderScene& scene, const Camera& camera);

  const RenderOptions& options() const;

 private:
  struct State;
  std::unique_ptr<State> m_state;
};

}  // namespace tissu
