#pragma once
/// \file
/// JSON text parsed as strictly as a scenario needs: one value and nothing after it, no key twice
/// in an object, no number beyond a double's range, nesting bounded by max_json_depth.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace tissu {

struct StrictJsonResult {
  nlohmann::json value;      ///< the parsed value, when syntax_error is empty
  std::string syntax_error;  ///< "parse error at line L, column C: ..." when the text is not JSON
};

/// Parses `text` (comments allowed) into a tree. The value stands at key path `base_path` of
/// `file` ("" for the whole file), `base_depth` levels deep; both name the place in messages.
/// Text that is not JSON gives a syntax error in the result. JSON that breaks a rule throws
/// ScenarioError "FILE: KEY.PATH: what is wrong" on one printable line: a NUL byte anywhere (the
/// parser would take it for the end of the text), a key repeated in an object, a number out of
/// a double's range (1e999), arrays and objects nested more than max_json_depth levels.
StrictJsonResult parse_strict_json(std::string_view text, const std::string& file,
                                   const std::string& base_path = "", int base_depth = 0);

}  // namespace tissu
