#include "lib/render/gl_functions.hpp"

#include <stdexcept>
#include <string>

namespace tissu {

GlFunctions load_gl_functions(OffscreenContext& context) {
  GlFunctions gl;
#define TISSU_GL_LOAD(type, name)                                     \
  gl.name = reinterpret_cast<type>(context.proc_address("gl" #name)); \
  if (!gl.name) throw std::runtime_error("render: the OpenGL context does not provide gl" #name);
  TISSU_GL_FUNCTIONS(TISSU_GL_LOAD)
#undef TISSU_GL_LOAD
  return gl;
}

}  // namespace tissu
