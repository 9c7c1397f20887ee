#pragma once
/// \file
/// The "render" section of a scenario.

#include "lib/scenario/json_reader.hpp"
#include "lib/scenario/scenario.hpp"

namespace tissu {

/// Reads "render"; the camera and the image size are checked as the renderer requires.
RenderSettings read_render(JsonObjectReader render);

}  // namespace tissu
