#include "lib/render/video.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/atomic_file.hpp"
#include "lib/render/image.hpp"
#include "tests/file_size_limit.hpp"
#include "tests/test_temp_dir.hpp"
#include "tests/video_probe.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

/// A fresh directory for the running test.
fs::path test_dir() {
  return test::fresh_dir_for_this_test("video");
}

/// Writes `count` 64 x 48 frames of a square moving right into `dir`, numbered 0, every,
/// 2 every, ...; returns their paths.
std::vector<fs::path> write_frames(const fs::path& dir, int count, int every = 1) {
  std::vector<fs::path> files;
  for (int frame = 0; frame < count; ++frame) {
    Image image{64, 48, std::vector<std::uint8_t>(64 * 48 * 3, 230)};
    for (int y = 16; y < 32; ++y)
      for (int x = 4 * frame; x < 4 * frame + 16; ++x) {
        std::uint8_t* p = image.rgb.data() + 3 * (y * 64 + x);
        p[0] = 200, p[1] = 40, p[2] = 30;
      }
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame * every);
    files.push_back(dir / name);
    write_png(files.back(), image);
  }
  return files;
}

/// Sets PATH for the lifetime of the object, then restores it.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) {
    if (const char* old = std::getenv("PATH")) m_old = old;
    setenv("PATH", path.c_str(), 1);
  }
  ~ScopedPath() {
    if (m_old)
      setenv("PATH", m_old->c_str(), 1);
    else
      unsetenv("PATH");
  }

 private:
  std::optional<std::string> m_old;
};

bool ffmpeg_installed() {
  return std::system("command -v ffmpeg > /dev/null 2>&1") == 0;
}

TEST(EncodeVideo, MakesAnMp4AndAGifFromTenFrames) {
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = test_dir();
  const VideoResult result =
      encode_video(write_frames(dir, 10), 10.0, dir / "clip.mp4", dir / "clip.gif");
  EXPECT_TRUE(result.made) << result.warning;
  EXPECT_EQ(result.warning, "");
  ASSERT_TRUE(fs::exists(dir / "clip.mp4"));
  ASSERT_TRUE(fs::exists(dir / "clip.gif"));
  EXPECT_GT(fs::file_size(dir / "clip.mp4"), 500u);
  EXPECT_GT(fs::file_size(dir / "clip.gif"), 500u);
}

TEST(EncodeVideo, WarnsWithoutThrowingWhenFfmpegIsNotOnThePath) {
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 2);
  fs::create_directories(dir / "empty_bin");
  VideoResult result;
  {
    const ScopedPath path((dir / "empty_bin").string());
    EXPECT_NO_THROW(result = encode_video(frames, 25.0, dir / "clip.mp4", dir / "clip.gif"));
  }
  EXPECT_FALSE(result.made);
  EXPECT_THAT(result.warning,
              HasSubstr("ffmpeg not found on PATH: no video made; frames are in " + dir.string()));
  EXPECT_FALSE(fs::exists(dir / "clip.mp4"));
}

TEST(EncodeVideo, WarnsWhenThereAreNoFrames) {
  const fs::path dir = test_dir();
  const VideoResult result = encode_video({}, 25.0, dir / "clip.mp4", dir / "clip.gif");
  EXPECT_FALSE(result.made);
  EXPECT_FALSE(result.warning.empty());
  const VideoResult missing =
      encode_video({dir / "frame_00000.png"}, 25.0, dir / "clip.mp4", dir / "clip.gif");
  EXPECT_FALSE(missing.made);
  EXPECT_THAT(missing.warning, HasSubstr("frame_00000.png is not a file"));
}

TEST(EncodeVideo, EncodesImagesNumberedWithGapsAndOnlyThose) {
  // every 5th frame rendered (frame_00000, frame_00005, ...) beside a stray image of an older run
  if (!ffmpeg_installed() || std::system("command -v ffprobe > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ffmpeg or ffprobe is not installed";
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 6, 5);
  fs::create_directories(dir / "older");
  write_frames(dir / "older", 1);
  fs::copy_file(dir / "older" / "frame_00000.png", dir / "frame_00001.png");
  const VideoResult result = encode_video(frames, 10.0, dir / "clip.mp4", "");
  ASSERT_TRUE(result.made) << result.warning;
  EXPECT_EQ(test::video_frame_count(dir / "clip.mp4"), 6);
}

TEST(EncodeVideo, ReportsTheErrorOutputOfAFailingFfmpeg) {
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 3);
  // ffmpeg cannot create a file in a folder that does not exist
  const VideoResult result = encode_video(frames, 25.0, dir / "missing" / "clip.mp4", "");
  EXPECT_FALSE(result.made);
  EXPECT_THAT(result.warning, HasSubstr("ffmpeg failed to make the MP4"));
  EXPECT_THAT(result.warning, HasSubstr("exit status"));
}

/// The names in `dir` other than the images write_frames() put there.
std::vector<std::string> non_frames_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) != 0) names.push_back(name);
  }
  return names;
}

TEST(EncodeVideo, AVideoThatCannotTakeItsPlaceIsAWarningAndLeavesNoTemporary) {
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 3);
  fs::create_directories(dir / "taken.mp4");  // a folder cannot be replaced by a file
  const VideoResult result = encode_video(frames, 25.0, dir / "taken.mp4", "");
  EXPECT_FALSE(result.made);
  EXPECT_THAT(result.warning, HasSubstr("taken.mp4: cannot write mp4 video: "));
  EXPECT_EQ(non_frames_in(dir), std::vector<std::string>{"taken.mp4"});
}

TEST(EncodeVideo, AVideoTheDiskRefusesIsAnErrorNamingItAndLeavesNothing) {
  // a file size limit fails ffmpeg's writes with EFBIG, as a full disk fails them with ENOSPC
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 12);
  try {
    const test::FileSizeLimit limit(1024);  // ffmpeg inherits it, and SIGXFSZ ignored
    encode_video(frames, 10.0, dir / "clip.mp4", dir / "clip.gif");
    FAIL() << "a video was made under a 1 KiB file size limit";
  } catch (const FileWriteError& e) {
    EXPECT_THAT(e.what(), HasSubstr((dir / "clip.mp4").string() +
                                    ": cannot write mp4 video: " + std::strerror(EFBIG)));
  }
  EXPECT_TRUE(non_frames_in(dir).empty());
}

TEST(EncodeVideo, AStopRequestEndsFfmpegAndMakesNothing) {
  if (!ffmpeg_installed()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = test_dir();
  const std::vector<fs::path> frames = write_frames(dir, 12);
  const volatile std::sig_atomic_t stop_signal = SIGTERM;  // already requested
  const VideoResult result =
      encode_video(frames, 10.0, dir / "clip.mp4", dir / "clip.gif", StopRequest{&stop_signal});
  EXPECT_TRUE(result.stopped);
  EXPECT_FALSE(result.made);
  EXPECT_TRUE(non_frames_in(dir).empty());
}

TEST(EncodeVideo, RejectsANonPositiveFrameRate) {
  EXPECT_THROW(encode_video({"a.png"}, 0.0, "a.mp4", "a.gif"), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
