#pragma once
// What the scenario tests share: a minimal valid scenario, and the error a text gives.

#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_error.hpp"

namespace tissu::test {

/// A valid scenario with every required key and little else: a 4 x 2 grid, 3 frames.
inline const char* const minimal_scenario = R"({
  // a comment, allowed
  "cloth": {
    "grid": { "size": [1.0, 0.5], "resolution": [4, 2] },
    "density": 0.2,
    "springs": { "structural": { "stiffness": 100 } }
  },
  "simulation": { "frames": 3 }
})";

/// The ScenarioError message `text` (read as `file`, with `overrides` applied) gives, or
/// "no error".
inline std::string scenario_error_of(const std::string& text,
                                     const std::vector<std::string>& overrides = {},
                                     const std::string& file = "dir/s.json") {
  try {
    parse_scenario(text, file, overrides);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

/// The ScenarioError message of the minimal scenario with `key` set to `value` (JSON text), or
/// "no error".
inline std::string minimal_scenario_error(const std::string& key, const std::string& value) {
  return scenario_error_of(minimal_scenario, {key + "=" + value});
}

}  // namespace tissu::test
