#pragma once
/// \file
/// The text of a scenario file, read without blocking and within a size bound.

#include <filesystem>
#include <string>

namespace tissu {

/// The whole text of `file`. Only a regular file is opened (its type is checked with stat()
/// first, so a FIFO cannot block the open, nor a device be read without end), and only one of
/// at most max_scenario_bytes. Throws ScenarioError "FILE: what is wrong" otherwise, or when it
/// cannot be opened or read. `name` is the file as messages print it.
std::string read_scenario_text(const std::filesystem::path& file, const std::string& name);

}  // namespace tissu
