#include "lib/scenario/parse_strict_json.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string nested_arrays(int levels) {
  return std::string(levels, '[') + std::string(levels, ']');
}

/// The ScenarioError of parsing `text` as file "f.json", its syntax error, or "no error".
std::string problem_of(const std::string& text, const std::string& path = "", int depth = 0) {
  try {
    const StrictJsonResult result = parse_strict_json(text, "f.json", path, depth);
    return result.syntax_error.empty() ? "no error" : "syntax: " + result.syntax_error;
  } catch (const ScenarioError& e) {
    return e.what();
  }
}

TEST(StrictJson, BuildsTheSameTreeAsNlohmann) {
  const std::string text = R"({ // a comment
    "a": [1, -2, 3.5, "x", true, null, {"b": []}], "c": {"d": {}} /* another */ })";
  const StrictJsonResult result = parse_strict_json(text, "f.json");
  ASSERT_EQ(result.syntax_error, "");
  EXPECT_EQ(result.value, nlohmann::json::parse(text, nullptr, true, true));
}

TEST(StrictJson, BoundsTheNestingAtTheLimitExactly) {
  EXPECT_EQ(problem_of(nested_arrays(max_json_depth)), "no error");
  EXPECT_EQ(problem_of("{\"a\": " + nested_arrays(max_json_depth - 1) + "}"), "no error");
  // the object is level 1, "a" level 2: the 64th array is one too many
  std::string path = "a";
  for (int k = 1; k < max_json_depth; ++k) path += "[0]";
  EXPECT_THAT(problem_of("{\"a\": " + nested_arrays(max_json_depth) + "}"),
              HasSubstr("f.json: " + path + ": arrays and objects nested more than 64 levels"));
  const std::string deep = problem_of("{\"a\": [" + nested_arrays(100000) + "]}");
  EXPECT_THAT(deep, HasSubstr("f.json: a[0][0][0]"));
  EXPECT_THAT(deep, HasSubstr(": arrays and objects nested more than 64 levels deep (the limit"));
  EXPECT_THAT(problem_of(nested_arrays(100000)), HasSubstr("f.json: [0][0]"));
}

TEST(StrictJson, CountsTheDepthOfTheKeyPathItStandsAt) {
  EXPECT_EQ(problem_of(nested_arrays(4), "a.b", max_json_depth - 4), "no error");
  EXPECT_THAT(problem_of(nested_arrays(5), "a.b", max_json_depth - 4),
              HasSubstr("f.json: a.b[0][0][0][0]: arrays and objects nested more than"));
}

TEST(StrictJson, RefusesARepeatedKeyNamingIt) {
  EXPECT_THAT(problem_of(R"({"cloth": {"density": -1, "density": 0.2}})"),
              HasSubstr("f.json: cloth.density: duplicate key: it appears twice"));
  EXPECT_THAT(problem_of(R"({"pins": [{"side": "top"}, {"side": "left", "side": "top"}]})"),
              HasSubstr("f.json: pins[1].side: duplicate key"));
  EXPECT_EQ(problem_of(R"([{"a": 1}, {"a": 2}])"), "no error");  // two objects, one key each
}

TEST(StrictJson, RefusesANumberBeyondADoubleNamingItsKey) {
  EXPECT_THAT(problem_of(R"({"simulation": {"time_step": 1e999}})"),
              HasSubstr("f.json: simulation.time_step: the number 1e999 is beyond the range of a "
                        "double (about 1.8e308)"));
  EXPECT_THAT(problem_of(R"({"pins": [{"indices": [0, -1e400]}]})"),
              HasSubstr("f.json: pins[0].indices[1]: the number -1e400"));
  EXPECT_THAT(problem_of("1e999"), HasSubstr("f.json: top level: the number 1e999"));
  EXPECT_THAT(problem_of("1e999", "cloth.density", 2), HasSubstr("f.json: cloth.density: the"));
  // integers beyond 64 bits are doubles, as nlohmann reads them; within range, accepted
  EXPECT_EQ(problem_of("[18446744073709551616, 1e308]"), "no error");
}

TEST(StrictJson, RefusesANulByteAndAnythingAfterTheValue) {
  EXPECT_THAT(problem_of(std::string("{\"a\": 1}\n\0", 10)),
              HasSubstr("f.json: invalid JSON: a NUL byte at line 2, column 1"));
  EXPECT_THAT(problem_of(std::string("{\"a\": \"x\0y\"}", 12)), HasSubstr("a NUL byte at line 1"));
  EXPECT_THAT(problem_of("{\"a\": 1} {\"b\": 2}"), HasSubstr("syntax: parse error at line 1"));
  EXPECT_THAT(problem_of("{\"a\": 1} {\"b\": 2}"), HasSubstr("expected end of input"));
}

TEST(StrictJson, GivesSyntaxErrorsOnOnePrintableLine) {
  const std::string bad_byte = problem_of("{\"a\xFF\": 1}");
  EXPECT_THAT(bad_byte, HasSubstr("syntax: parse error at line 1, column 4"));
  EXPECT_THAT(bad_byte, HasSubstr("\\xFF"));
  EXPECT_THAT(bad_byte, Not(HasSubstr("\xFF")));
  EXPECT_THAT(problem_of("{\n\"a\": \n"), Not(HasSubstr("\n")));
}

TEST(StrictJson, PrintsKeysOnOneLine) {
  const std::string message = problem_of("{\"out\\nput\": 1, \"out\\nput\": 2}");
  EXPECT_THAT(message, HasSubstr("f.json: out\\nput: duplicate key"));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

}  // namespace
}  // namespace tissu
