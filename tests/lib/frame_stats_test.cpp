// stats.csv always ends with a whole row: a row the disk refuses is not left half written, and a
// row holding inf or NaN is refused before anything of it is written.

#include "lib/frame_stats.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests/file_size_limit.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

FrameStats row(int frame) {
  FrameStats r;
  r.frame = frame;
  r.time = frame / 30.0;
  r.particles = 25;
  r.total_mass = 0.2;
  r.kinetic_energy = 1e-3 * frame;
  return r;
}

TEST(StatsCsv, WritesAHeaderThenOneWholeRowPerFrame) {
  const fs::path file = test::fresh_dir_for_this_test("stats_csv") / "stats.csv";
  StatsCsv stats(file);
  for (int f = 0; f < 3; ++f) stats.write(row(f));
  const std::vector<std::string> lines = lines_of(file);  // read while the writer is alive
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_THAT(lines[0], ::testing::StartsWith("frame,time,particles,"));
  const auto commas = static_cast<std::ptrdiff_t>(stats_columns(FrameStats{}).size() - 1);
  EXPECT_EQ(commas, 24);  // 25 columns, flips the last
  for (const std::string& line : lines)
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), commas);
  EXPECT_THAT(lines[3], ::testing::StartsWith("2,0.0666"));
}

TEST(StatsCsv, ARowOfInfinityIsRefusedNamingTheFrameAndColumn) {
  const fs::path file = test::fresh_dir_for_this_test("stats_csv") / "stats.csv";
  StatsCsv stats(file);
  stats.write(row(0));
  FrameStats blown = row(1);
  blown.kinetic_energy = std::numeric_limits<double>::infinity();
  EXPECT_THAT([&] { stats.write(blown); },
              ::testing::ThrowsMessage<std::runtime_error>(
                  HasSubstr("stats.csv: frame 1: kinetic_energy is inf, not a finite number")));
  blown = row(1);
  blown.potential_energy = std::nan("");
  EXPECT_THROW(stats.write(blown), std::runtime_error);
  EXPECT_EQ(lines_of(file).size(), 2u);  // the header and frame 0
}

TEST(StatsCsv, ARowTheDiskRefusesIsNotLeftHalfWritten) {
  const fs::path file = test::fresh_dir_for_this_test("stats_csv") / "stats.csv";
  StatsCsv stats(file);
  int written = 0;
  try {
    const test::FileSizeLimit limit(2000);
    for (; written < 100; ++written) stats.write(row(written));
    FAIL() << "100 rows fitted in 2000 bytes";
  } catch (const FileWriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string() + ": cannot write statistics: "));
  }
  const std::vector<std::string> lines = lines_of(file);
  EXPECT_EQ(lines.size(), 1u + written);
  EXPECT_EQ(std::count(lines.back().begin(), lines.back().end(), ','),
            static_cast<std::ptrdiff_t>(stats_columns(FrameStats{}).size() - 1));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str().back(), '\n');
}

}  // namespace
}  // namespace tissu
