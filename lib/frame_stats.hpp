#pragma once
/// \file
/// One row of stats.csv.

#include <filesystem>
#include <vector>

#include "lib/atomic_file.hpp"

namespace tissu {

struct FrameStats {
  int frame = 0;
  int frame_count = 0;  ///< frames of the run, for progress
  double time = 0.0;    ///< simulated time (s)
  int particles = 0;
  int springs = 0;
  int faces = 0;
  int pinned = 0;
  double total_mass = 0.0;        ///< (kg)
  double kinetic_energy = 0.0;    ///< (J)
  double potential_energy = 0.0;  ///< elastic + gravitational (J)
  double step_ms = 0.0;           ///< wall time of the frame's solver steps (ms)
  int unconverged_steps = 0;      ///< steps that missed their integrator's tolerance
  int splits = 0;    ///< edges bisected by adaptive refinement after this frame, and around crack
                     ///< tips during it
  int merges = 0;    ///< particles removed by adaptive coarsening after this frame (bisections
                     ///< undone, or collapses of anisotropic remeshing)
  int contacts = 0;  ///< particle-obstacle contacts resolved in the frame's last step
  int self_contacts =
      0;  ///< pairs pushed apart or stopped by self-collision, over the frame's steps
  double collision_ms = 0.0;  ///< wall time of self-collision over the frame's steps (ms)
  int tears = 0;              ///< edges torn (by strain or a cut) during the frame
  int pieces = 0;             ///< connected pieces of cloth at the end of the frame
  int boundary_edges = 0;     ///< edges with a face on one side only, tears included
  /// |force the pins exert on the cloth| (N), solver/pin_reaction.hpp: at rest, the weight they
  /// carry
  double pin_force = 0.0;
  /// the largest engineering strain l / l0 - 1 of a structural spring (dimensionless; -1 when
  /// there is none)
  double max_stretch = 0.0;
  /// the integrator's iterations over the frame's steps (solver/step.hpp last_step_iterations():
  /// CG, PD, Newton or L-BFGS iterations; 0 for the explicit integrators)
  int solver_iterations = 0;
  /// structural springs the strain limit shortened, over the frame's steps (each step's first
  /// sweep; solver/strain_limit.hpp); 0 without `simulation.strain_limit`
  int strain_limited = 0;
  /// OpenMP threads the frame's steps ran on (0 for frame 0, which has none): what the program's
  /// thread choice gave the frame (apps: lib/thread_count.hpp)
  int threads = 0;
  int flips = 0;  ///< edges flipped by anisotropic remeshing after this frame
};

/// A column of stats.csv and its value in a row (integers exactly, as doubles).
struct StatsColumn {
  const char* name;
  double value;
};

/// The columns of stats.csv, in order, with `row`'s values (docs/scenario.md, "Statistics").
std::vector<StatsColumn> stats_columns(const FrameStats& row);

/// Writes stats.csv: a header line, then one line per frame, each handed to the operating system
/// as it is written (AppendFile), so that the file always ends with a whole row: a killed process
/// loses no row it wrote, a full disk none but the one it refused.
class StatsCsv {
 public:
  /// Creates `file` with its header line. Throws FileWriteError if it cannot be written.
  explicit StatsCsv(const std::filesystem::path& file);
  /// Appends `row`. Throws FileWriteError if the disk refuses it, std::runtime_error naming the
  /// file, the frame and the column if a value is not finite (a row of inf or NaN is never
  /// written: the driver stops a diverging run before it records the frame).
  void write(const FrameStats& row);

 private:
  AppendFile m_file;
};

}  // namespace tissu
