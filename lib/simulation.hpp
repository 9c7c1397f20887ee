#pragma once
/// \file
/// Runs a scenario: builds the cloth, steps it frame by frame, writes meshes and statistics.
/// CGAL-free.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/frame_stats.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/shape_distance.hpp"
#include "lib/stop_request.hpp"

namespace tissu {

struct RunOptions {
  /// created if missing once the cloth is built (a refused mesh or pin leaves it untouched); the
  /// files an earlier run left in it are removed first (lib/run_folder.hpp), then scenario.json
  /// is written (Scenario::resolved_json)
  std::filesystem::path output_dir = "out";
  /// called once the folder is this run's: earlier outputs removed, before scenario.json
  std::function<void()> on_folder_taken;
  std::optional<int> frames;  ///< overrides the scenario's frame count
  /// called with one line when files of an earlier run were removed, and before each setup stage
  /// of a large cloth (lib/cloth_setup.hpp: reading a mesh file of
  /// 16 MiB or more; building and compiling a cloth of 100,000 faces or more) with one line
  /// saying what it does, e.g. "compiling the solver's model: 1000000 particles"
  std::function<void(const std::string&)> on_setup;
  std::function<void(const FrameStats&)> on_frame;  ///< called after each frame, e.g. progress
  std::function<void(int, int)> on_image;  ///< called with (done, total) after each rendered image
  /// called once, at the first frame with an unconverged step, with a one-line explanation
  std::function<void(const std::string&)> on_warning;
  /// when set, called with the frame number and the cloth's surface after each frame, frame 0 too
  std::function<void(int, const MaterialSurface&)> on_surface;
  /// checked before every solver step and every image: once requested, the run ends with the last
  /// whole frame (the frame in progress is dropped, nothing of it written), renders nothing more,
  /// and returns with stopped = true
  StopRequest stop;
};

struct RunResult {
  int frames_done = 0;  ///< frames completed after frame 0
  bool ok = true;
  std::string failure;        ///< when !ok: the frame, the cause and where the last good state is
  int unconverged_steps = 0;  ///< steps that missed their solver's tolerance, in all frames
  int images = 0;             ///< PNG frames rendered
  std::string video_warning;  ///< set when a video was asked for and not made
  bool stopped = false;       ///< ended early because options.stop was requested
};

/// The cloth a scenario builds, as `tissu check` reports it.
struct ClothSummary {
  int particles = 0;
  int faces = 0;
  int springs = 0;
  int pinned = 0;
  double total_mass_kg = 0.0;
};

/// Builds and compiles the cloth of `scenario` as a run would, without stepping it or writing
/// anything: bad meshes or pins throw MeshError or PinError, as run_scenario does.
ClothSummary check_scenario(const Scenario& scenario);

/// Runs `scenario`. Bad meshes or pins throw (MeshError, PinError) before the first step; a solver
/// failure stops the run with ok = false after writing the last good state. Each frame writes its
/// mesh (when due), then its stats.csv row, each whole or not at all (lib/atomic_file.hpp): a
/// frame is recorded when its row is in stats.csv, and every row's mesh is complete then. A file
/// the disk refuses throws FileWriteError naming it, ending the run. When rendering is on,
/// the frames are kept in memory and rendered after the run (a failed one too), so that the
/// default camera frames the whole run. Runs on the calling thread's OpenMP thread count: the
/// library sets no process state, so Scenario::threads is for the program to apply (the tissu
/// apps call omp_set_num_threads with it); results do not depend on it.
RunResult run_scenario(const Scenario& scenario, const RunOptions& options);

/// One frame of a cloth as arrays, in particle order (row k is vertex k of the frame's mesh):
/// what frames.h5 holds (lib/frame_arrays.hpp).
struct FrameArrays {
  int frame = 0;
  double time_s = 0.0;
  Eigen::VectorXd positions_m;          ///< 3n, xyz interleaved
  Eigen::VectorXd velocities_m_per_s;   ///< 3n
  std::vector<Eigen::Vector3d> rest_m;  ///< n material coordinates
  Eigen::VectorXd masses_kg;            ///< n lumped masses
  std::vector<std::vector<int>> faces;  ///< triangles or quads, vertex ids
  std::vector<std::uint8_t> pinned;     ///< n flags
};

/// A step that diverged; the message is run_scenario's (the frame, the step, the cause).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A scenario's cloth stepped one frame at a time, writing nothing: the same steps, pin handles,
/// tearing and adaptation as run_scenario (which writes and renders what this leaves to its
/// caller), for programs that drive tissu themselves, such as the Python module. CGAL stays in
/// the implementation.
class Simulation {
 public:
  /// Builds and compiles the cloth of `scenario`: throws MeshError or PinError as run_scenario.
  explicit Simulation(Scenario scenario);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Advances one frame (scenario.substeps steps). A step that diverges throws SimulationError,
  /// and the cloth is then left in its state before that step.
  void step_frame();
  int frame() const;
  /// The cloth's particles now (refinement and tearing change them).
  int particle_count() const;
  const Scenario& scenario() const;
  /// The cloth now.
  FrameArrays arrays() const;

 private:
  struct Run;
  std::unique_ptr<Run> m_run;
};

}  // namespace tissu
