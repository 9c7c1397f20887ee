#pragma once
// What every fuzz target checks on a refused input: the message a user would see is one line
// naming the file. A violation aborts, which libFuzzer (and the corpus replay in ctest) reports
// as a crash with the input that caused it. That the error is one of tissu's own exceptions, not
// a library's (nlohmann-json's, std::stoul's, std::bad_alloc), each target checks by catching only
// those: any other escapes, and libFuzzer reports it. The text is not searched for a library's
// words: it echoes the user's keys and values, which may hold any words (the fuzzer once made
// the key "c[json.exception").

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace tissu::fuzz {

/// Aborts unless `message` is one line starting with `prefix` (the file's path) and saying more.
inline void require_clear_message(std::string_view message, std::string_view prefix) {
  const bool clear = message.size() > prefix.size() &&
                     message.find('\n') == std::string_view::npos &&
                     message.substr(0, prefix.size()) == prefix;
  if (!clear) {
    std::fprintf(stderr, "fuzz: unclear message: \"%.*s\"\n", static_cast<int>(message.size()),
                 message.data());
    std::abort();
  }
}

}  // namespace tissu::fuzz
