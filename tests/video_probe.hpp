#pragma once
// Reading videos back in tests, through ffprobe (installed with ffmpeg by the set-up script).

#include <cstdio>
#include <filesystem>
#include <string>

namespace tissu::test {

/// The number of video frames ffprobe counts in `video`, -1 if it cannot tell.
inline int video_frame_count(const std::filesystem::path& video) {
  const std::string command =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
      "-of csv=p=0 '" +
      video.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  int count = -1;
  if (std::fscanf(pipe, "%d", &count) != 1) count = -1;
  pclose(pipe);
  return count;
}

}  // namespace tissu::test
