#pragma once
/// \file
/// An offscreen OpenGL 3.3 core context behind one small interface, so that the renderer does not
/// depend on how the context is made. The one backend today is OSMesa (software, llvmpipe). Mesa
/// dropped OSMesa in 25.1: an EGL backend (EGL_MESA_platform_surfaceless + an FBO) can implement
/// this interface and be chosen in create_offscreen_context without touching the renderer.

#include <memory>

#include "lib/render/image.hpp"

namespace tissu {

/// An OpenGL entry point as returned by a context's loader; cast to the function's type.
using GlProc = void (*)();

class OffscreenContext {
 public:
  virtual ~OffscreenContext();
  OffscreenContext() = default;
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// Makes this context current on the calling thread.
  virtual void make_current() = 0;
  /// The address of OpenGL function `name` (e.g. "glDrawArrays"), or nullptr if unknown.
  virtual GlProc proc_address(const char* name) = 0;
  /// The framebuffer object the final image is drawn into (0: the context's own surface).
  virtual unsigned framebuffer() const = 0;
  /// Finishes drawing and reads framebuffer() into an image, top row first. Current context only.
  virtual Image read_pixels() = 0;
  virtual int width() const = 0;   ///< pixels
  virtual int height() const = 0;  ///< pixels
};

/// A current OpenGL 3.3 core context with an RGBA8 + 24-bit depth surface of width x height pixels.
/// Before the first context of the process it sets LP_NUM_THREADS=2 (llvmpipe's rasteriser
/// threads) unless the environment already sets it, so that llvmpipe does not start one thread per
/// core next to the solver's OpenMP threads; set LP_NUM_THREADS yourself to choose (0 rasterises on
/// the calling thread). Throws std::runtime_error if no context can be made.
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height);

}  // namespace tissu
