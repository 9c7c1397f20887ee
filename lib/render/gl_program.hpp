#pragma once
/// \file
/// Compiling and linking a GLSL program.

#include "lib/render/gl_functions.hpp"

namespace tissu {

/// A linked program of `vertex_source` and `fragment_source`. Throws std::runtime_error with the
/// GLSL compiler's or linker's log, naming `name`, if either fails.
GLuint build_program(const GlFunctions& gl, const char* name, const char* vertex_source,
                     const char* fragment_source);

}  // namespace tissu
