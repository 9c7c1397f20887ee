// Fuzz target: scenario text, parsed and validated as `tissu run` does. It may succeed or throw
// one of tissu's errors (ScenarioError, or MeshError and PinError for what the scenario names)
// with one line naming the scenario file; anything else (a crash, a hang, another exception, a
// message of several lines or without the file) is a bug. Mesh files the text names resolve into
// a folder that does not exist.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_checks.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "topology/indexed_mesh.hpp"
#include "topology/pin_selection.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = "/nonexistent/tissu_fuzz/scenario.json";
  try {
    tissu::parse_scenario(std::string(reinterpret_cast<const char*>(data), size), file);
  } catch (const tissu::ScenarioError& e) {
    tissu::fuzz::require_clear_message(e.what(), file + ": ");
  } catch (const tissu::MeshError& e) {
    tissu::fuzz::require_clear_message(e.what(), file + ": ");
  } catch (const tissu::PinError& e) {
    tissu::fuzz::require_clear_message(e.what(), file + ": ");
  }
  return 0;
}
