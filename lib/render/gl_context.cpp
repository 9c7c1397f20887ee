#include "lib/render/gl_context.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "lib/render/osmesa_context.hpp"

namespace tissu {

OffscreenContext::~OffscreenContext() = default;

std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument("render: context size must be positive, got " +
                                std::to_string(width) + "x" + std::to_string(height));
  // llvmpipe reads this once, when the first context of the process is made; the 0 keeps a value
  // the user set
  setenv("LP_NUM_THREADS", "2", 0);
  return create_osmesa_context(width, height);
}

}  // namespace tissu
