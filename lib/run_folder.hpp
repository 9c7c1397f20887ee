#pragma once
/// \file
/// The run folder before a run: what an earlier run left there goes, so that the folder holds one
/// run only (its frames, its stats.csv, its images) and `tissu render` or a reader of the arrays
/// never mixes two. Only files tissu writes are removed, by name; anything else stays. CGAL-free.

#include <filesystem>
#include <string>

namespace tissu {

/// Whether `name`, a file name in a run folder, is one tissu writes there whatever the scenario:
/// stats.csv, scenario.json, run.json, frames.pc2, frames.h5,
/// frame_NNNNN.obj|.ply|.png|.glb,
/// last_good_frame_*.obj|.ply, and the temporaries of those (".<name>.tmp<pid>_<n>",
/// lib/atomic_file.hpp).
bool is_run_output_name(const std::string& name);

/// Removes from `dir` (when it exists) the files of an earlier run: every regular file that
/// is_run_output_name() accepts, and the videos <stem>.mp4 and <stem>.gif for `video_stem` and for
/// the "name" in the scenario.json an earlier run left, and viewer/index.html, tissu_viewer.js and
/// frames.js (the folder too, once empty). Returns how many files it removed; throws
/// std::filesystem::filesystem_error naming the file it could not remove.
int remove_earlier_run(const std::filesystem::path& dir, const std::string& video_stem);

/// Writes `dir`/scenario.json: `resolved_json` (Scenario::resolved_json) with simulation.frames
/// set to `frames`, the count actually run (the command line may override it). Throws
/// FileWriteError.
void write_resolved_scenario(const std::filesystem::path& dir, const std::string& resolved_json,
                             int frames);

}  // namespace tissu
