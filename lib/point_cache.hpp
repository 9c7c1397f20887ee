#pragma once
/// \file
/// A PC2 point cache of the cloth's positions, frame by frame, for animation tools: Blender's Mesh
/// Cache modifier, Houdini and Maya play it on the frame-0 mesh, whose vertex k is particle k.
/// Only for a cloth whose particles stay the same through the run (no refinement, no tearing).
/// The format (Blender's io_pc2 and MeshCache modifier, little-endian): a 32-byte header
///   char signature[12] = "POINTCACHE2\0"; int32 version = 1; int32 points;
///   float32 start_frame; float32 sample_rate (frames between samples); int32 samples;
/// then, per sample, `points` positions x y z as float32 (m). CGAL-free.

#include <Eigen/Core>
#include <filesystem>

#include "lib/atomic_file.hpp"

namespace tissu {

class PointCacheFile {
 public:
  /// Creates `file` with a header of `points` points and no sample yet. Throws FileWriteError.
  PointCacheFile(const std::filesystem::path& file, int points);
  /// Appends one sample, `x` (3 × points values, m, xyz interleaved), then counts it in the header: a
  /// killed run leaves a cache whose count is at most the samples it holds, which readers play.
  /// Throws FileWriteError (the file then keeps its earlier samples), std::invalid_argument if
  /// `x` does not hold the header's point count.
  void append(const Eigen::VectorXd& x);
  int samples() const { return m_samples; }

 private:
  AppendFile m_file;
  int m_points;
  int m_samples = 0;
};

}  // namespace tissu
