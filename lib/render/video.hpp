#pragma once
/// \file
/// Encoding a folder of PNG frames into an MP4 and a GIF with the ffmpeg program, when there is
/// one. Video is a bonus: a missing or failing ffmpeg gives a warning, never an exception.

#include <filesystem>
#include <string>
#include <vector>

#include "lib/stop_request.hpp"

namespace tissu {

struct VideoResult {
  bool made = false;     ///< every requested file was written
  std::string warning;   ///< one line saying what was not made and why; empty when made
  bool stopped = false;  ///< a stop was requested while encoding: ffmpeg was ended, nothing made
};

/// Encodes the PNG images `frames`, in that order, shown at `frame_rate` images per second, into
/// `mp4` (H.264, yuv420p, so any player reads it) and `gif` (at most 320 pixels wide, at most 15
/// frames per second, own palette, looping forever), running the first `ffmpeg` found on the PATH
/// with stdin from /dev/null. The images may be named anything (frame_00000.png, frame_00005.png,
/// ... when every 5th frame was rendered): ffmpeg reads them through consecutively numbered links
/// in a temporary folder, removed afterwards, and nothing else in their folder is read. An empty
/// path skips that file. Without ffmpeg, without images, when one is missing, or when ffmpeg
/// fails, returns made = false and a warning (naming the end of ffmpeg's error output when it
/// failed).
///
/// Each video is written whole or not at all: ffmpeg writes a temporary file beside it, renamed
/// over it once ffmpeg has succeeded, removed otherwise (lib/atomic_file.hpp). When `stop` is
/// requested, ffmpeg is ended and nothing more is made (stopped = true). Throws
/// std::invalid_argument for a frame rate that is not positive, and FileWriteError naming the video
/// when ffmpeg's error output says the disk refused its writes (no space left, file size limit,
/// quota; ffmpeg 5.1 exits 0 all the same):
/// a full disk stops a run like any other write, while other ffmpeg failures are warnings.
VideoResult encode_video(const std::vector<std::filesystem::path>& frames, double frame_rate,
                         const std::filesystem::path& mp4, const std::filesystem::path& gif,
                         StopRequest stop = {});

}  // namespace tissu
