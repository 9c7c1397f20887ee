#pragma once
/// \file
/// The OSMesa backend of OffscreenContext (Mesa < 25.1).

#include <memory>

#include "lib/render/gl_context.hpp"

namespace tissu {

/// A current OSMesa OpenGL 3.3 core context drawing into memory; see create_offscreen_context.
std::unique_ptr<OffscreenContext> create_osmesa_context(int width, int height);

}  // namespace tissu
