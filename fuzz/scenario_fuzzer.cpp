// Fuzz target: scenario text, parsed and validated as `tissu run` does. It may succeed or throw
// with one clear line naming the scenario file; anything else (a crash, a hang, an unclear
// message) is a bug. Mesh files the text names resolve into a folder that does not exist.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "fuzz/fuzz_checks.hpp"
#include "lib/scenario/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string file = "/nonexistent/tissu_fuzz/scenario.json";
  try {
    tissu::parse_scenario(std::string(reinterpret_cast<const char*>(data), size), file);
  } catch (const std::exception& e) {
    tissu::fuzz::require_clear_message(e.what(), file + ": ");
  }
  return 0;
}
