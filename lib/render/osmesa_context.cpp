/// \file
/// The OSMesa backend of OffscreenContext: Mesa's software rasteriser (llvmpipe) rendering into
/// memory. Every GL function is looked up with OSMesaGetProcAddress: gl* symbols bound at link time
/// would go to a glvnd libGL linked before libOSMesa, and the image would stay black. OSMesa's rows
/// are bottom-up, like glReadPixels': read_pixels flips them.

#include <GL/osmesa.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/render/osmesa_context.hpp"

namespace tissu {

namespace {

using ReadPixels = void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
using PixelStorei = void (*)(GLenum, GLint);
using Finish = void (*)();
using BindFramebuffer = void (*)(GLenum, GLuint);

class OsMesaContext final : public OffscreenContext {
 public:
  OsMesaContext(int width, int height)
      : m_width(width), m_height(height), m_buffer(4 * static_cast<std::size_t>(width) * height) {
    // clang-format off
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    // clang-format on
    m_context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!m_context)
      throw std::runtime_error(
          "render: OSMesa could not create an OpenGL 3.3 core profile context (is Mesa's "
          "libOSMesa with llvmpipe installed?)");
    try {
      make_current();
      m_read_pixels = reinterpret_cast<ReadPixels>(OSMesaGetProcAddress("glReadPixels"));
      m_pixel_store = reinterpret_cast<PixelStorei>(OSMesaGetProcAddress("glPixelStorei"));
      m_finish = reinterpret_cast<Finish>(OSMesaGetProcAddress("glFinish"));
      m_bind_framebuffer =
          reinterpret_cast<BindFramebuffer>(OSMesaGetProcAddress("glBindFramebuffer"));
      if (!m_read_pixels || !m_pixel_store || !m_finish || !m_bind_framebuffer)
        throw std::runtime_error("render: OSMesa does not provide glReadPixels");
    } catch (...) {
      OSMesaDestroyContext(m_context);
      throw;
    }
  }

  ~OsMesaContext() override { OSMesaDestroyContext(m_context); }

  void make_current() override {
    if (!OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, m_width, m_height))
      throw std::runtime_error("render: OSMesaMakeCurrent failed for a " + std::to_string(m_width) +
                               "x" + std::to_string(m_height) + " image");
  }

  GlProc proc_address(const char* name) override { return OSMesaGetProcAddress(name); }

  unsigned framebuffer() const override { return 0; }

  Image read_pixels() override {
    m_finish();
    Image image{m_width, m_height, std::vector<std::uint8_t>(3u * m_width * m_height)};
    std::vector<std::uint8_t> bottom_up(image.rgb.size());
    m_bind_framebuffer(GL_READ_FRAMEBUFFER, 0);
    m_pixel_store(GL_PACK_ALIGNMENT, 1);
    m_read_pixels(0, 0, m_width, m_height, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
    const std::size_t row = 3u * m_width;
    for (int y = 0; y < m_height; ++y)
      std::copy_n(bottom_up.data() + row * (m_height - 1 - y), row, image.rgb.data() + row * y);
    return image;
  }

  int width() const override { return m_width; }
  int height() const override { return m_height; }

 private:
  int m_width;
  int m_height;
  std::vector<std::uint8_t> m_buffer;  ///< the RGBA surface OSMesa draws into, bottom row first
  OSMesaContext m_context = nullptr;
  ReadPixels m_read_pixels = nullptr;
  PixelStorei m_pixel_store = nullptr;
  Finish m_finish = nullptr;
  BindFramebuffer m_bind_framebuffer = nullptr;
};

}  // namespace

std::unique_ptr<OffscreenContext> create_osmesa_context(int width, int height) {
  return std::make_unique<OsMesaContext>(width, height);
}

}  // namespace tissu
