#pragma once
/// \file
/// PC2 point caches. tissu writes the cloth's positions, frame by frame, for animation tools:
/// Blender's Mesh Cache modifier, Houdini and Maya play it on the frame-0 mesh, whose vertex k is
/// particle k; only for a cloth whose particles stay the same through the run (no refinement, no
/// tearing). tissu reads an animated obstacle's (a body's) vertex positions from one.
/// The format (Blender's io_pc2 and MeshCache modifier, little-endian): a 32-byte header
///   char signature[12] = "POINTCACHE2\0"; int32 version = 1; int32 points;
///   float32 start_frame; float32 sample_rate (frames between samples); int32 samples;
/// then, per sample, `points` positions x y z as float32 (m). CGAL-free.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "lib/atomic_file.hpp"

namespace tissu {

class PointCacheFile {
 public:
  /// Creates `file` with a header of `points` points and no sample yet. Throws FileWriteError.
  PointCacheFile(const std::filesystem::path& file, int points);
  /// Appends one sample, `x` (3 × points values, m, xyz interleaved), then counts it in the header:
  /// a killed run leaves a cache whose count is at most the samples it holds, which readers play.
  /// Throws FileWriteError (the file then keeps its earlier samples), std::invalid_argument if
  /// `x` does not hold the header's point count.
  void append(const Eigen::VectorXd& x);
  int samples() const { return m_samples; }

 private:
  AppendFile m_file;
  int m_points;
  int m_samples = 0;
};

/// A PC2 file that cannot be read; the message names the file and what is wrong.
class PointCacheError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a PC2 file holds.
struct PointCache {
  double start_frame = 0.0;
  double sample_rate = 1.0;                           ///< frames between samples
  std::vector<std::vector<Eigen::Vector3d>> samples;  ///< per sample, `points` positions (m)
};

/// Reads `file`, written by PointCacheFile or by another tool (Blender's exporter). Bytes after the
/// header's sample count are ignored (a cache still being written). Throws PointCacheError, naming
/// the file, when it cannot be opened, has no "POINTCACHE2" header of version 1, no point or no
/// sample, a sample rate that is not positive and finite, fewer bytes than its header counts, or
/// a non-finite coordinate (naming the sample and the point, from 0), or more than `max_bytes`
/// (checked before reading: the file is untrusted, and read whole).
PointCache read_point_cache(const std::filesystem::path& file,
                            std::uintmax_t max_bytes = std::uintmax_t{1} << 30);

}  // namespace tissu
