#pragma once
/// \file
/// frames.h5: the run's arrays for analysis and learned simulators, one HDF5 group per frame, so
/// that a cloth whose particles change (adaptive refinement, tearing) is stored as it is. Layout
/// (SI; docs/scenario.md "Arrays for Python" gives a reader):
///   /                attributes format = "tissu frames 1", frame_rate_hz, fixed_particles (0|1)
///   /frames/NNNNN    attributes frame (int), time_s; datasets
///     positions        (n, 3) float64, m
///     velocities       (n, 3) float64, m/s
///     rest_positions   (n, 3) float64, m: material coordinates, which refinement interpolates
///     masses           (n,)   float64, kg: lumped particle masses (they sum to the cloth's mass)
///     triangles        (t, 3) int32, vertex ids; a quad is split along its first diagonal
///     pinned           (n,)   uint8, 1 for a pinned particle
/// Row k of the per-particle arrays is vertex k of the frame's mesh file. Each frame is flushed
/// once written: a killed run leaves the frames before it readable. CGAL-free and HDF5-free.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace tissu {

/// One frame's arrays, in particle order.
struct ArrayFrame {
  int frame = 0;
  double time_s = 0.0;
  const Eigen::VectorXd* positions_m = nullptr;          ///< 3n, xyz interleaved
  const Eigen::VectorXd* velocities_m_per_s = nullptr;   ///< 3n
  const std::vector<Eigen::Vector3d>* rest_m = nullptr;  ///< n material coordinates
  const Eigen::VectorXd* masses_kg = nullptr;            ///< n
  const std::vector<std::vector<int>>* faces = nullptr;  ///< triangles or quads, vertex ids
  const std::vector<std::uint8_t>* pinned = nullptr;     ///< n flags
};

class FrameArraysFile {
 public:
  /// Creates (or truncates) `file`. Throws FileWriteError.
  FrameArraysFile(const std::filesystem::path& file, double frame_rate_hz, bool fixed_particles);
  ~FrameArraysFile();
  FrameArraysFile(const FrameArraysFile&) = delete;
  FrameArraysFile& operator=(const FrameArraysFile&) = delete;

  /// Writes /frames/NNNNN and flushes the file. Throws FileWriteError, std::invalid_argument when
  /// the arrays disagree in size or a face is neither a triangle nor a quad.
  void append(const ArrayFrame& frame);

 private:
  /// Writes /frames/`name` (rest: 3n m, triangles: 3t vertex ids).
  void write_group(const char* name, const ArrayFrame& frame, const std::vector<double>& rest,
                   const std::vector<std::int32_t>& triangles);

  std::filesystem::path m_file;
  std::int64_t m_file_id = -1;    ///< hid_t
  std::int64_t m_frames_id = -1;  ///< the /frames group
};

}  // namespace tissu
