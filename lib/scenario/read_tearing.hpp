#pragma once
/// \file
/// The "tearing" section of a scenario.

#include "lib/scenario/json_reader.hpp"
#include "lib/scenario/scenario.hpp"

namespace tissu {

/// Reads "tearing"; enabled unless it says "enabled": false. An enabled section needs a "strain"
/// or at least one cut.
TearingSettings read_tearing(JsonObjectReader tearing);

}  // namespace tissu
