#pragma once
// What every fuzz target checks on a refused input: the message a user would see is one clear
// line, never a library's raw text. A violation aborts, which libFuzzer (and the corpus replay
// in ctest) reports as a crash with the input that caused it.

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace tissu::fuzz {

/// Aborts unless `message` is one non-empty line starting with `prefix` (the file's path) and free
/// of the raw texts of the libraries underneath (nlohmann-json's "[json.exception", std::stoul's
/// bare "stoul").
inline void require_clear_message(std::string_view message, std::string_view prefix) {
  const bool clear = !message.empty() && message.find('\n') == std::string_view::npos &&
                     message.substr(0, prefix.size()) == prefix &&
                     message.find("[json.exception") == std::string_view::npos &&
                     message != "stoul" && message != "stod" && message != "stoi";
  if (!clear) {
    std::fprintf(stderr, "fuzz: unclear message: \"%.*s\"\n", static_cast<int>(message.size()),
                 message.data());
    std::abort();
  }
}

}  // namespace tissu::fuzz
