// Output files are complete or absent: a write the disk refuses (here a file size limit, which
// fails writes with EFBIG as a full disk fails them with ENOSPC) throws an error naming the file
// and leaves no half-written file, no temporary, and an append-only file at its last whole record.

#include "lib/atomic_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/file_size_limit.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path test_dir() {
  return test::fresh_dir_for_this_test("atomic_file");
}

std::string contents_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The names of the entries of `dir`, hidden ones too.
std::vector<std::string> entries_of(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(WriteFileAtomically, WritesTheContentsAndLeavesNothingElse) {
  const fs::path dir = test_dir();
  const std::string bytes("mesh\0bytes\n", 11);
  write_file_atomically(dir / "frame_00000.obj", bytes, "mesh");
  EXPECT_EQ(contents_of(dir / "frame_00000.obj"), bytes);
  write_file_atomically(dir / "frame_00000.obj", "shorter", "mesh");  // replaced, not overwritten
  EXPECT_EQ(contents_of(dir / "frame_00000.obj"), "shorter");
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{"frame_00000.obj"});
}

TEST(WriteFileAtomically, ARefusedWriteThrowsNamingTheFileAndKeepsTheOldOneWhole) {
  const fs::path dir = test_dir();
  write_file_atomically(dir / "frame_00001.obj", "the previous run's frame\n", "mesh");
  const std::string big(64 * 1024, 'v');
  try {
    const test::FileSizeLimit limit(16 * 1024);
    write_file_atomically(dir / "frame_00001.obj", big, "mesh");
    FAIL() << "a 64 KiB file was written under a 16 KiB limit";
  } catch (const FileWriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir / "frame_00001.obj").string() +
                                    ": cannot write mesh: " + std::strerror(EFBIG)));
    EXPECT_EQ(e.file(), dir / "frame_00001.obj");
  }
  EXPECT_EQ(contents_of(dir / "frame_00001.obj"), "the previous run's frame\n");
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{"frame_00001.obj"});  // no temporary

  try {  // a new file: absent after the failure
    const test::FileSizeLimit limit(16 * 1024);
    write_file_atomically(dir / "frame_00002.obj", big, "mesh");
    FAIL() << "a 64 KiB file was written under a 16 KiB limit";
  } catch (const FileWriteError&) {
  }
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{"frame_00001.obj"});
}

TEST(WriteFileAtomically, AMissingFolderIsAnErrorNamingTheFile) {
  const fs::path file = test_dir() / "no_such_folder" / "frame_00000.ply";
  EXPECT_THAT([&] { write_file_atomically(file, "x", "mesh"); },
              ::testing::ThrowsMessage<FileWriteError>(
                  HasSubstr(file.string() + ": cannot write mesh: " + std::strerror(ENOENT))));
}

TEST(TemporaryPathBeside, IsAFreshHiddenNameInTheSameFolder) {
  const fs::path a = temporary_path_beside("out/curtain/frame_00003.obj");
  const fs::path b = temporary_path_beside("out/curtain/frame_00003.obj");
  EXPECT_EQ(a.parent_path(), "out/curtain");
  EXPECT_THAT(a.filename().string(), ::testing::StartsWith(".frame_00003.obj.tmp"));
  EXPECT_NE(a, b);
}

TEST(PendingFile, AppearsOnCommitAndIsRemovedOtherwise) {
  const fs::path dir = test_dir();
  {
    PendingFile video(dir / "run.mp4", "mp4 video");
    std::ofstream(video.temporary()) << "half a video";  // a program that failed or was stopped
  }
  EXPECT_TRUE(entries_of(dir).empty());
  {
    PendingFile video(dir / "run.mp4", "mp4 video");
    std::ofstream(video.temporary()) << "a video";
    video.commit();
  }
  EXPECT_EQ(contents_of(dir / "run.mp4"), "a video");
  EXPECT_EQ(entries_of(dir), std::vector<std::string>{"run.mp4"});
  PendingFile never_written(dir / "run.gif", "gif video");
  EXPECT_THROW(never_written.commit(), FileWriteError);
  EXPECT_FALSE(fs::exists(dir / "run.gif"));
}

TEST(AppendFile, EndsWithItsLastWholeRecordWhenTheDiskRefusesOne) {
  const fs::path file = test_dir() / "stats.csv";
  AppendFile csv(file, "statistics");
  const std::string row = std::string(299, '7') + "\n";  // 300 bytes
  int written = 0;
  try {
    const test::FileSizeLimit limit(1000);  // room for 3 rows and a third of the 4th
    for (; written < 10; ++written) csv.append(row);
    FAIL() << "10 rows of 300 bytes were written under a 1000-byte limit";
  } catch (const FileWriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string() + ": cannot write statistics: "));
  }
  EXPECT_EQ(written, 3);
  EXPECT_EQ(fs::file_size(file), 900u);
  csv.append(row);  // room again: the file goes on from its last whole row
  EXPECT_EQ(contents_of(file), row + row + row + row);
}

TEST(AppendFile, ReplacesAnOlderFileAndWritesThroughAtOnce) {
  const fs::path file = test_dir() / "stats.csv";
  std::ofstream(file) << "an older run's rows\n";
  AppendFile csv(file, "statistics");
  EXPECT_EQ(fs::file_size(file), 0u);
  csv.append("frame,time\n");
  EXPECT_EQ(contents_of(file), "frame,time\n");  // in the file before the object is gone
}

}  // namespace
}  // namespace tissu
