#include "lib/scenario/read_scenario_text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

std::string error_reading(const std::filesystem::path& file) {
  try {
    read_scenario_text(file, file.string());
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ReadScenarioText, ReadsARegularFileWhole) {
  const auto dir = test::fresh_dir_for_this_test("read_scenario_text");
  const std::string text = std::string("{\"a\": 1}\n") + std::string(200000, ' ') + "\n";
  std::ofstream(dir / "s.json") << text;
  EXPECT_EQ(read_scenario_text(dir / "s.json", "s.json"), text);
}

TEST(ReadScenarioText, ReadsAFileOfExactlyTheLimit) {
  const auto dir = test::fresh_dir_for_this_test("read_scenario_text");
  std::ofstream(dir / "s.json") << std::string(max_scenario_bytes, ' ');
  EXPECT_EQ(read_scenario_text(dir / "s.json", "s.json").size(), max_scenario_bytes);
  std::ofstream(dir / "t.json") << std::string(max_scenario_bytes + 1, ' ');
  EXPECT_EQ(error_reading(dir / "t.json"),
            (dir / "t.json").string() +
                ": cannot read the scenario: it has 16777217 bytes, more "
                "than the 16777216 (16 MiB) a scenario file may have");
}

TEST(ReadScenarioText, OpensOnlyRegularFiles) {
  const auto dir = test::fresh_dir_for_this_test("read_scenario_text");
  EXPECT_EQ(error_reading(dir), dir.string() +
                                    ": cannot read the scenario: it is a directory; expected a "
                                    "regular file of JSON text");
  // a FIFO would block open() until a writer comes: refused from its stat(), never opened
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  EXPECT_THAT(error_reading(dir / "fifo.json"), HasSubstr("it is a FIFO (named pipe)"));
  // a device would be read without end
  EXPECT_THAT(error_reading("/dev/zero"),
              HasSubstr("/dev/zero: cannot read the scenario: it is a character device"));
  EXPECT_THAT(error_reading(dir / "none.json"),
              HasSubstr("none.json: cannot open the scenario file: No such file or directory"));
}

TEST(ReadScenarioText, FollowsSymbolicLinksToRegularFiles) {
  const auto dir = test::fresh_dir_for_this_test("read_scenario_text");
  std::ofstream(dir / "s.json") << "{}";
  std::filesystem::create_symlink(dir / "s.json", dir / "link.json");
  EXPECT_EQ(read_scenario_text(dir / "link.json", "link.json"), "{}");
  std::filesystem::create_symlink("/dev/zero", dir / "zero.json");
  EXPECT_THAT(error_reading(dir / "zero.json"), HasSubstr("it is a character device"));
}

}  // namespace
}  // namespace tissu
