// The bounds of lib/scenario/scenario_limits.hpp, as parse_scenario applies them: every hostile
// value is refused with one line naming the file, the key and the bound (issue 18).

#include "lib/scenario/scenario_limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/scenario/printable_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "tests/lib/scenario_errors.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string with(const std::string& assignment) {
  return test::scenario_error_of(test::minimal_scenario, {assignment});
}

TEST(ScenarioLimits, TheTimeStepIsBoundedBeforeItBecomesAStepCount) {
  // 1e-300 s once gave 3e298 steps per frame cast to int: the run went on with the time at 0
  EXPECT_EQ(with("simulation.time_step=1e-300"),
            "dir/s.json: simulation.time_step: expected a time step of at least 3.33333e-08 s: "
            "at most 1000000 steps per frame of 1/30 s, got 1e-300");
  EXPECT_THAT(with("simulation.time_step=5e-324"),
              HasSubstr("simulation.time_step: expected a time step of at least"));
  const Scenario finest = parse_scenario(test::minimal_scenario, "dir/s.json",
                                         {"simulation.frame_rate=1", "simulation.time_step=1e-6"});
  EXPECT_EQ(finest.substeps, max_substeps);
  EXPECT_EQ(
      parse_scenario(test::minimal_scenario, "s.json", {"simulation.substeps=1000000"}).substeps,
      max_substeps);
  EXPECT_THAT(with("simulation.substeps=1000001"),
              HasSubstr("simulation.substeps: expected an integer from 1 to 1000000"));
}

TEST(ScenarioLimits, TheFrameRateKeepsTheTimeStepANormalNumber) {
  EXPECT_EQ(with("simulation.frame_rate=1e-300"),
            "dir/s.json: simulation.frame_rate: expected a number between 0.001 and 1e+06 "
            "(frames per second), got 1e-300");
  EXPECT_THAT(with("simulation.frame_rate=1e7"), HasSubstr("simulation.frame_rate: expected"));
  EXPECT_EQ(with("simulation.frame_rate=0.001"), "no error");
  EXPECT_EQ(with("simulation.frame_rate=1000000"), "no error");
}

TEST(ScenarioLimits, AGridHasAtMostAMillionParticles) {
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "s.json", {"cloth.grid.resolution=[999,999]"})
                .cloth.grid->cells_u,
            999);
  EXPECT_EQ(with("cloth.grid.resolution=[1000,999]"),
            "dir/s.json: cloth.grid.resolution: expected cell counts [u, v] giving at most 1000000 "
            "particles (u + 1) (v + 1), the cloth size limit (these give 1001000), got [1000,999]");
  // once bad_alloc, with no file or key
  EXPECT_THAT(with("cloth.grid.resolution=[65536,65536]"), HasSubstr("(these give 4295098369)"));
  EXPECT_THAT(with("cloth.grid.resolution=[100000,100000]"),
              HasSubstr("cloth.grid.resolution: expected cell counts"));
  EXPECT_THAT(with("cloth.grid.resolution=[2147483647,2147483647]"),
              HasSubstr("(these give 4611686018427387904)"));
}

TEST(ScenarioLimits, AGridSideIsBetweenAMicrometreAndAThousandKilometres) {
  // 1e200 m once gave "area inf is below inf"
  EXPECT_EQ(with("cloth.grid.size=[1e200,1e200]"),
            "dir/s.json: cloth.grid.size: expected an array of 2 numbers, each a number between "
            "1e-06 and 1e+06 (m), got [1e+200,1e+200]");
  EXPECT_THAT(with("cloth.grid.size=[1e-200,1]"), HasSubstr("cloth.grid.size: expected"));
  EXPECT_EQ(with("cloth.grid.size=[1e6,1e-6]"), "no error");
}

TEST(ScenarioLimits, IntegersBeyondSixtyFourBitsAreRefusedNotWrapped) {
  EXPECT_EQ(with("simulation.frames=18446744073709551615"),
            "dir/s.json: simulation.frames: expected an integer from 1 to 10000000, got "
            "18446744073709551615");
  EXPECT_THAT(with("simulation.frames=9223372036854775808"),
              HasSubstr("simulation.frames: expected an integer"));
  EXPECT_THAT(with("simulation.frames=-9223372036854775808"),
              HasSubstr("simulation.frames: expected an integer"));
  EXPECT_THAT(with("simulation.frames=10000001"), HasSubstr("simulation.frames: expected"));
  EXPECT_THAT(with(R"(pins=[{"indices": [0, 18446744073709551615]}])"),
              HasSubstr("pins[0].indices: expected a non-empty array of integers >= 0"));
  EXPECT_THAT(with("cloth.grid.resolution=[4,4294967300]"),
              HasSubstr("cloth.grid.resolution: expected a non-empty array of integers >= 1"));
}

TEST(ScenarioLimits, ARenderedImageHasBoundedSamples) {
  EXPECT_EQ(with(R"(render={"width": 16384, "height": 16384, "samples": 16})"),
            "dir/s.json: render.samples: expected at most 134217728 samples per image, width x "
            "height x samples (the render memory limit), not 16384 x 16384 x 16 = 4294967296, "
            "got 16");
  EXPECT_THAT(with(R"(render={"width": 16384, "height": 16384, "samples": 1})"),
              HasSubstr("render.width: expected at most 134217728 samples per image"));
  EXPECT_EQ(with(R"(render={"width": 3840, "height": 2160, "samples": 16})"), "no error");
}

TEST(ScenarioLimits, AdaptiveRefinementStopsAtAMillionParticles) {
  EXPECT_THAT(with(R"(adaptive={"strain": 0.1, "max_particles": 10000000})"),
              HasSubstr("adaptive.max_particles: expected an integer from 3 to 1000000"));
}

TEST(ScenarioLimits, TheNameIsAPlainFileName) {
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json", {"name=my-run_2"}).name,
            "my-run_2");
  // absolute, or climbing out of out/: each once wrote outside the output folder
  EXPECT_EQ(with("name=/tmp/x"),
            "dir/s.json: name: expected a plain file name (no '/', not \".\" or \"..\", at most "
            "200 bytes), as it names the output folder out/<name>; it holds a '/', got \"/tmp/x\"");
  EXPECT_THAT(with("name=../.."), HasSubstr("name: expected a plain file name"));
  EXPECT_THAT(with("name=.."), HasSubstr("\"..\" names a folder"));
  EXPECT_THAT(with("name=."), HasSubstr("\".\" names a folder"));
  EXPECT_THAT(with(R"(name="")"), HasSubstr("it is empty"));
  EXPECT_THAT(with("name=" + std::string(201, 'n')), HasSubstr("it has 201 bytes"));
  EXPECT_THAT(with(R"(name="a\nb")"), HasSubstr("control characters"));
  EXPECT_THAT(with("name=3"), HasSubstr("name: expected a string"));
  // the default, the file's stem, obeys the same rule
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/run.v2.json").name, "run.v2");
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario, {}, "dir/...json"),
              HasSubstr("dir/...json: name: missing, and the file's stem \"..\" is not a plain "
                        "file name"));
}

TEST(ScenarioLimits, MeshPathsAreNotEmpty) {
  EXPECT_EQ(with(R"(cloth={"mesh": {"file": ""}, "density": 0.2,
                          "springs": {"structural": {"stiffness": 1}}})"),
            "dir/s.json: cloth.mesh.file: expected the path of a mesh file, not an empty string, "
            "got \"\"");
  EXPECT_THAT(with(R"(obstacles=[{"type": "mesh", "file": ""}])"),
              HasSubstr("obstacles[0].file: expected the path of a mesh file, not an empty"));
  EXPECT_THAT(with(R"(obstacles=[{"type": "mesh", "file": "m.obj", "scale": 1e300}])"),
              HasSubstr("obstacles[0].scale: expected a number between 1e-06 and 1e+06, got"));
}

TEST(ScenarioLimits, TheTextIsOneJsonValueWithoutRepeatedKeys) {
  EXPECT_EQ(test::scenario_error_of(""),
            "dir/s.json: the file is empty; expected a JSON object {...}");
  EXPECT_EQ(test::scenario_error_of(" \n\t "),
            "dir/s.json: the file is empty; expected a JSON object {...}");
  // just after the closing brace, on the minimal scenario's 9th line
  EXPECT_THAT(test::scenario_error_of(std::string(test::minimal_scenario) + std::string("\0", 1)),
              HasSubstr("dir/s.json: invalid JSON: a NUL byte at line 9, column 2"));
  EXPECT_THAT(test::scenario_error_of(std::string(test::minimal_scenario) + " 1"),
              HasSubstr("expected end of input"));
  EXPECT_THAT(test::scenario_error_of(R"({"cloth": {"density": -1, "density": 0.2}})"),
              HasSubstr("dir/s.json: cloth.density: duplicate key"));
  EXPECT_THAT(test::scenario_error_of(R"({"cloth": {"grid": {"size": [1, 1e999]}}})"),
              HasSubstr("dir/s.json: cloth.grid.size[1]: the number 1e999 is beyond the range"));
  EXPECT_THAT(test::scenario_error_of("{\"cloth\": " + std::string(100000, '[') + "}"),
              HasSubstr("dir/s.json: cloth[0][0]"));
}

TEST(ScenarioLimits, OverridesAreCheckedLikeTheFile) {
  // once "stoul"
  EXPECT_EQ(
      test::scenario_error_of(test::minimal_scenario, {"pins=[]", "pins.99999999999999999999=1"}),
      "dir/s.json: --set pins.99999999999999999999=1: 'pins' is an array; expected an index "
      "below 0");
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario,
                                      {"pins=[{\"side\": \"top\"}]", "pins.-1.every=1"}),
              HasSubstr("'pins' is an array; expected an index below 1"));
  // once a raw type error from nlohmann
  EXPECT_EQ(with("name=\xFF"),
            "dir/s.json: --set name=\\xFF: byte 5 is not UTF-8 text; expected key.path=value in "
            "UTF-8");
  EXPECT_THAT(with("na\xC3me=1"), HasSubstr("--set na\\xC3me=1: byte 2 is not UTF-8 text"));
  EXPECT_THAT(with("simulation.frames=1e999"),
              HasSubstr("dir/s.json: simulation.frames: the number 1e999 is beyond the range"));
  EXPECT_THAT(with(R"(cloth.springs={"structural": {"stiffness": 1, "stiffness": 2}})"),
              HasSubstr("dir/s.json: cloth.springs.structural.stiffness: duplicate key"));
  // once a stack overflow, at 60,000 levels
  EXPECT_THAT(with("cloth=" + std::string(60000, '[') + std::string(60000, ']')),
              HasSubstr("dir/s.json: cloth[0][0][0]"));
  std::string path;
  for (int k = 0; k < 60000; ++k) path += "a.";
  EXPECT_THAT(with(path + "a=1"), HasSubstr(": a key path of more than 64 keys"));
  // 64 keys put a value inside 64 objects, the limit; an array there is a 65th level
  path.clear();
  for (int k = 1; k < max_json_depth; ++k) path += "a.";
  EXPECT_THAT(with(path + "a=1"), HasSubstr("dir/s.json: a: unknown key"));
  EXPECT_THAT(with(path + "a=[1]"), HasSubstr(": arrays and objects nested more than 64 levels"));
  EXPECT_THAT(with(path + "a.a=1"), HasSubstr(": a key path of more than 64 keys"));
  // text that is not JSON is still a string
  EXPECT_EQ(parse_scenario(test::minimal_scenario, "dir/s.json", {"name=[not json"}).name,
            "[not json");
}

TEST(ScenarioLimits, EveryMessageIsOnePrintableLine) {
  const std::vector<std::vector<std::string>> hostile = {{"out\nput=1"},
                                                         {"name=a\nb"},
                                                         {"simulation.frames=1\n2"},
                                                         {"\x01=1"},
                                                         {"cloth.densit\xC3\xA9=1"},
                                                         {"x=" + std::string(100000, 'x')},
                                                         {std::string(100000, 'k') + "=1"},
                                                         {"simulation.integrator=\"\\u0000\""}};
  for (const std::vector<std::string>& overrides : hostile) {
    const std::string message = test::scenario_error_of(test::minimal_scenario, overrides);
    EXPECT_THAT(message, Not(HasSubstr("\n"))) << message;
    EXPECT_EQ(invalid_utf8_offset(message), std::string::npos) << message;
    EXPECT_LT(message.size(), 1000u) << message;
    EXPECT_NE(message, "no error") << overrides[0];
  }
}

}  // namespace
}  // namespace tissu
