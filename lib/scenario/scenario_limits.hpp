#pragma once
/// \file
/// Bounds on what a scenario may ask for, so that a hostile or mistaken file gets a one-line
/// error at load time instead of a crash, a hang or an allocation storm during the run. Each is
/// named in the message that refuses it and listed in docs/scenario.md, "Limits".

#include <cstddef>

namespace tissu {

/// Largest scenario file (bytes). The biggest shipped scenario is a few KiB, and the pins of every
/// vertex of a million-particle mesh about 8 MiB. The text is read whole, and its JSON tree takes
/// up to ~35 times the text's size: 16 MiB of "{}," measured 0.56 GiB and 4 s (docs/scenario.md).
inline constexpr std::size_t max_scenario_bytes = std::size_t{16} << 20;  // 16 MiB

/// Deepest nesting of arrays and objects in a scenario (the file, or a --set value at its key
/// path). A scenario uses 6 levels; nlohmann's dump() and the tree's copies recurse per level.
inline constexpr int max_json_depth = 64;

/// Frames a run may simulate after frame 0 (simulation.frames, --frames).
inline constexpr int max_frames = 10'000'000;

/// Solver steps per frame (simulation.substeps, or 1 / (frame_rate time_step)).
inline constexpr int max_substeps = 1'000'000;

/// Accepted frame rates (Hz): the time step 1 / (frame_rate substeps) stays a normal double.
inline constexpr double min_frame_rate_hz = 1e-3;
inline constexpr double max_frame_rate_hz = 1e6;

/// Particles of a grid cloth, (cells_u + 1) (cells_v + 1), and of an adaptive cloth
/// (adaptive.max_particles): about 2 million triangles, a few GiB of complex and springs.
inline constexpr int max_cloth_particles = 1'000'000;

/// Side of a grid cloth (m): both bounds keep a cell's area, (size / cells)^2, a normal double
/// measured against the 1e-12 relative tolerance of the mesh checks.
inline constexpr double min_grid_side_m = 1e-6;
inline constexpr double max_grid_side_m = 1e6;

/// Scale of an obstacle mesh (obstacles[i].scale), for the same reason.
inline constexpr double min_obstacle_scale = 1e-6;
inline constexpr double max_obstacle_scale = 1e6;

/// Samples of one rendered image: max_render_samples, in lib/render/render_options.hpp.

/// Longest scenario "name" (bytes): it names out/<name> and <name>.mp4, and a file name may
/// have 255 bytes on Linux.
inline constexpr std::size_t max_name_bytes = 200;

}  // namespace tissu
