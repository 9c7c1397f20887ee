#include "lib/simulation.hpp"

#include <omp.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "lib/cloth_setup.hpp"
#include "lib/frame_arrays.hpp"
#include "lib/obstacle_mesh.hpp"
#include "lib/pin_handles.hpp"
#include "lib/point_cache.hpp"
#include "lib/render_frames.hpp"
#include "lib/run_folder.hpp"
#include "lib/tear_step.hpp"
#include "lib/viewer_frames.hpp"
#include "solver/energy.hpp"
#include "solver/pin_reaction.hpp"
#include "solver/speed_limit.hpp"
#include "solver/spring_strain.hpp"
#include "solver/step.hpp"
#include "topology/coarsen.hpp"
#include "topology/compile.hpp"
#include "topology/current_mesh.hpp"
#include "topology/edge_measures.hpp"
#include "topology/refine.hpp"
#include "topology/remesh.hpp"
#include "topology/tear.hpp"

namespace tissu {
namespace {

std::filesystem::path frame_file(const std::filesystem::path& dir, const std::string& stem,
                                 int frame, MeshFormat format) {
  char number[16];
  std::snprintf(number, sizeof number, "%05d", frame);
  return dir / (stem + number + "." + extension(format));
}

/// What the solver steps of one frame did.
struct FrameSteps {
  double wall_ms = 0.0;
  int unconverged = 0;
  int obstacle_contacts = 0;  ///< in the last step
  int self_contacts = 0;
  double collision_ms = 0.0;
  int tears = 0;
  int tip_splits = 0;      ///< edges bisected around crack tips
  int iterations = 0;      ///< the integrator's, over the steps
  int strain_limited = 0;  ///< springs the strain limit shortened, over the steps
  int threads = 0;         ///< OpenMP threads the steps ran on
  bool stopped = false;    ///< a stop was requested before all the frame's steps were made

  void add(StepStatus status, const SolverParams& params, const StepWorkspace& workspace) {
    if (status == StepStatus::not_converged) ++unconverged;
    iterations += last_step_iterations(params, workspace);
    strain_limited += workspace.strain_limited;
    obstacle_contacts = workspace.obstacle_contacts;
    self_contacts += workspace.self_collision.proximities + workspace.self_collision.impacts;
    collision_ms += workspace.self_collision.wall_ms;
  }
};

/// The complex's pieces and boundary edges for stats.csv, counted again only for a newly compiled
/// cloth: every topological edit recompiles it (edit_and_recompile(), which gives the model a new
/// identity), so between two compilations the counts cannot change. Counting walks every dart of
/// the complex: done every frame, it took 2-3 % of a run whose mesh does not change.
class TopologyCounts {
 public:
  void refresh(const CompiledCloth& cloth, const ClothComplex& lcc) {
    if (cloth.model.identity == m_counted_model) return;
    m_counted_model = cloth.model.identity;
    pieces = count_pieces(lcc);
    boundary_edges = count_boundary_edges(lcc);
  }

  int pieces = 0;
  int boundary_edges = 0;

 private:
  std::uint64_t m_counted_model = 0;  // SpringModel::identity; 0: none counted yet
};

FrameStats measure(const CompiledCloth& cloth, const ClothComplex& lcc,
                   const Environment& environment, int frame, int frame_count,
                   const FrameSteps& steps, TopologyCounts& topology) {
  topology.refresh(cloth, lcc);
  const SpringModel& m = cloth.model;
  FrameStats s;
  s.frame = frame;
  s.frame_count = frame_count;
  s.time = cloth.state.time;
  s.particles = m.particle_count();
  s.springs = m.spring_count();
  s.faces = static_cast<int>(lcc.attributes<2>().size());
  s.pinned = static_cast<int>(std::count(m.pinned.begin(), m.pinned.end(), 1));
  s.total_mass = total_mass(m);
  s.kinetic_energy = kinetic_energy(m, cloth.state);
  s.potential_energy = potential_energy(m, environment.gravity, cloth.state);
  s.step_ms = steps.wall_ms;
  s.unconverged_steps = steps.unconverged;
  s.contacts = steps.obstacle_contacts;
  s.self_contacts = steps.self_contacts;
  s.collision_ms = steps.collision_ms;
  s.tears = steps.tears;
  s.pieces = topology.pieces;
  s.boundary_edges = topology.boundary_edges;
  s.pin_force = pin_reaction_force(m, environment, cloth.state).norm();
  s.max_stretch = max_spring_strain(m, cloth.state.x, SpringKind::structural);
  s.solver_iterations = steps.iterations;
  s.strain_limited = steps.strain_limited;
  s.threads = steps.threads;
  return s;
}

/// Appends the frame's arrays (positions and velocities from the solver's state, which the complex
/// was written back from) to frames.h5.
void write_frame_arrays(FrameArraysFile& arrays, int frame, const CompiledCloth& cloth,
                        const ClothComplex& lcc) {
  const std::vector<Eigen::Vector3d> rest_m = rest_positions(lcc);
  const std::vector<std::vector<int>> faces = current_mesh(lcc).faces;
  arrays.append({frame, cloth.state.time, &cloth.state.x, &cloth.state.v, &rest_m,
                 &cloth.model.mass, &faces, &cloth.model.pinned});
}

/// What image of the frame at `time_s` shows: the cloth, and the obstacles where they are then,
/// a +z plane becoming the renderer's ground.
RenderFrame snapshot(const ClothComplex& lcc, const std::vector<Obstacle>& obstacles,
                     double time_s) {
  RenderFrame frame{current_mesh(lcc), {}, face_edge_strain(lcc)};
  frame.face_level = face_refinement_level(lcc);
  frame.face_sizing_term = face_sizing_term(lcc);
  frame.pinned.resize(frame.mesh.vertices.size());
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    frame.pinned[v->info().index_at_last_compile] = v->info().pinned ? 1 : 0;
  }
  for (const Obstacle& obstacle : obstacles) {
    if (obstacle.shape != ObstacleShape::plane)
      frame.obstacles.push_back(obstacle_mesh(obstacle, time_s));
  }
  frame.ground_height_m = ground_height_m(obstacles, time_s);
  return frame;
}

struct Adaptation {
  int splits = 0;
  int merges = 0;
  int flips = 0;  ///< anisotropic remeshing's
};

/// Refines where the sizing field asks for it, then coarsens where the cloth has calmed down; or,
/// with adaptive.anisotropic, one pass of anisotropic remeshing (topology/remesh.hpp).
Adaptation adapt(ClothComplex& lcc, const Scenario& scenario, double time_s) {
  const AdaptiveSettings& adaptive = scenario.adaptive;
  const SizingInputs inputs{&scenario.solver.obstacles, time_s};
  Adaptation changes;
  if (adaptive.refinement.anisotropic) {
    const RemeshReport r =
        remesh(lcc, adaptive.refinement, adaptive.hysteresis, scenario.springs, inputs);
    return {r.splits, r.collapses, r.flips};
  }
  changes.splits = refine(lcc, adaptive.refinement, scenario.springs, inputs).splits;
  if (adaptive.hysteresis > 0.0) {  // on the sizing field refine() computed
    changes.merges =
        coarsen_on_current_sizing(lcc, adaptive.refinement, adaptive.hysteresis, scenario.springs)
            .merges;
  }
  return changes;
}

/// The first step of a run that went wrong: its positions or velocities stopped being finite, or a
/// particle moves faster than the scene can make it (solver/speed_limit.hpp).
struct Divergence {
  int substep = 0;      ///< 1-based, within the frame
  double time_s = 0.0;  ///< at the end of that step
  std::string cause;    ///< what was wrong, in words
};

/// `value` with 3 significant digits, then `unit`.
std::string number_text(double value, const char* unit) {
  char text[48];
  std::snprintf(text, sizeof text, "%.3g%s", value, unit);
  return text;
}

/// What was wrong with the state a step left, if anything: non-finite values, or a free particle
/// over the speed limit.
std::optional<std::string> divergence_cause(StepStatus status, const CompiledCloth& cloth,
                                            const SpeedLimit& limit) {
  if (status == StepStatus::non_finite) return std::string("non-finite positions or velocities");
  const std::optional<Overspeed> over = find_overspeed(limit, cloth.model, cloth.state);
  if (!over) return std::nullopt;
  return "particle " + std::to_string(over->particle) + " moves at " +
         number_text(over->speed_m_per_s, " m/s") + ", over the " +
         number_text(over->limit_m_per_s, " m/s") + " no particle of this scene can reach (" +
         number_text(limit.margin, "") +
         " x what gravity, handles, obstacles, wind and elastic release can give by then)";
}

/// Stage 1 of a frame: the solver's substeps, with tearing after each one (which widens the speed
/// limit by the recoil of the stretch it released). Stops at the first step that diverges
/// (divergence_cause()); `cloth` then holds the state before that step (kept
/// in `before_step`), on the model it was stepped with, while the complex still holds the
/// previous frame's state or that of the last step that tore the cloth in this frame. Stops
/// before a step when `stop` is requested, with steps.stopped set.
std::optional<Divergence> step_frame_of(const Scenario& scenario, ClothComplex& lcc,
                                        CompiledCloth& cloth, StepWorkspace& workspace,
                                        PinHandles& handles, TearStep& tearing, SpeedLimit& limit,
                                        State& before_step, FrameSteps& steps, StopRequest stop) {
  const auto start = std::chrono::steady_clock::now();
  steps.threads = omp_get_max_threads();
  for (int sub = 0; sub < scenario.substeps; ++sub) {
    if (stop.requested()) {
      steps.stopped = true;
      return std::nullopt;
    }
    handles.before_step(lcc, cloth, scenario.solver.time_step);
    before_step = cloth.state;
    const StepStatus status = step(cloth.model, scenario.solver, cloth.state, workspace);
    steps.add(status, scenario.solver, workspace);
    if (auto cause = divergence_cause(status, cloth, limit)) {
      const double time_s = cloth.state.time;
      cloth.state = before_step;
      return Divergence{sub + 1, time_s, std::move(*cause)};
    }
    const TearReport torn = tearing.after_step(lcc, cloth);
    if (torn.tears > 0) widen_for_release(limit, cloth.model, cloth.state);  // the lips recoil
    steps.tears += torn.tears;
    steps.tip_splits += torn.tip_refinements;
  }
  steps.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::nullopt;
}

/// Stage 2 of a frame: writes the stepped state into the complex (which the recording reads) and,
/// on the frames where adaptation is due, refines and coarsens it.
Adaptation adapt_frame(const Scenario& scenario, int frame, ClothComplex& lcc,
                       CompiledCloth& cloth) {
  const bool due = scenario.adaptive.enabled && frame % scenario.adaptive.every == 0;
  Adaptation changes;
  edit_and_recompile(lcc, cloth, [&](ClothComplex& complex) {
    if (!due) return false;
    changes = adapt(complex, scenario, cloth.state.time);
    return changes.splits + changes.merges + changes.flips > 0;
  });
  return changes;
}

/// `kept`: where the state before the step is, e.g. "written to FILE".
std::string divergence_message(const Scenario& scenario, int frame, const Divergence& divergence,
                               const CompiledCloth& last_good, const std::string& kept) {
  const std::string energy = number_text(kinetic_energy(last_good.model, last_good.state), " J");
  return "frame " + std::to_string(frame) + ", step " + std::to_string(divergence.substep) +
         " of " + std::to_string(scenario.substeps) + " (t = " + std::to_string(divergence.time_s) +
         " s): " + divergence.cause + "; the time step " +
         std::to_string(scenario.solver.time_step) +
         " s is likely too large for the stiffness (more substeps or the implicit_euler "
         "integrator help); the state before that step (t = " +
         std::to_string(last_good.state.time) + " s, kinetic energy " + energy + ") " + kept;
}

/// Where the state before the step that diverged goes: last_good_frame_NNNNN.<ext> when it is the
/// previous frame's, last_good_frame_NNNNN_step_SS.<ext> when it is SS steps after frame NNNNN.
std::filesystem::path last_good_file(const std::filesystem::path& dir, int frame, int substep,
                                     MeshFormat format) {
  if (substep == 1) return frame_file(dir, "last_good_frame_", frame - 1, format);
  char stem[48];
  std::snprintf(stem, sizeof stem, "last_good_frame_%05d_step_%02d.", frame - 1, substep - 1);
  return dir / (std::string(stem) + extension(format));
}

/// What to do about steps that missed their tolerance, for the warning of the first such frame.
std::string unconverged_message(const Scenario& scenario, int frame, int unconverged) {
  const SolverParams& solver = scenario.solver;
  std::string what = to_string(solver.integrator);
  std::string advice;
  switch (solver.integrator) {
    case Integrator::projective_dynamics:
      what += std::string(" with the ") + to_string(solver.pd.global_solver) + " global solver";
      advice = solver.pd.global_solver == PdGlobalSolver::direct
                   ? "raise simulation.pd.iterations or substeps"
                   : "its sweeps leave the cloth behind the step (frozen, on stiff cloth): use "
                     "the \"direct\" global solver, more linear_iterations, or more substeps";
      break;
    case Integrator::implicit_euler:
      advice = "raise simulation.cg_max_iterations or substeps";
      break;
    default:
      advice = "raise its max_iterations, or substeps";
      break;
  }
  return "frame " + std::to_string(frame) + ": " + std::to_string(unconverged) + " of " +
         std::to_string(scenario.substeps) + " steps of " + what + " did not converge; " + advice +
         " (docs/scenario.md); stats.csv counts them in unconverged_steps";
}

}  // namespace

ClothSummary check_scenario(const Scenario& scenario) {
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  const CompiledCloth cloth = compile(lcc);
  const SpringModel& m = cloth.model;
  return {m.particle_count(), static_cast<int>(lcc.attributes<2>().size()), m.spring_count(),
          static_cast<int>(std::count(m.pinned.begin(), m.pinned.end(), 1)), total_mass(m)};
}

RunResult run_scenario(const Scenario& scenario, const RunOptions& options) {
  const int frame_count = options.frames.value_or(scenario.frames);
  const OutputOptions& output = scenario.output;
  // the cloth first: a scenario refused for its mesh or pins leaves the folder as it was
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc, options.on_setup);
  std::filesystem::create_directories(options.output_dir);
  if (const int removed = remove_earlier_run(options.output_dir, scenario.name);
      removed > 0 && options.on_setup) {
    options.on_setup("removed " + std::to_string(removed) + " files of an earlier run from " +
                     options.output_dir.string());
  }
  if (options.on_folder_taken) options.on_folder_taken();
  if (!scenario.resolved_json.empty())
    write_resolved_scenario(options.output_dir, scenario.resolved_json, frame_count);

  if (options.on_setup && lcc.attributes<2>().size() >= large_cloth_faces) {
    options.on_setup("compiling the solver's model: " +
                     std::to_string(lcc.vertex_attributes().size()) + " particles");
  }
  CompiledCloth cloth = compile(lcc);
  StatsCsv stats(options.output_dir / "stats.csv");
  std::optional<PointCacheFile> point_cache;
  if (output.point_cache)
    point_cache.emplace(options.output_dir / "frames.pc2", cloth.model.particle_count());
  std::optional<ViewerFramesFile> viewer;
  if (output.viewer) viewer.emplace(options.output_dir / "viewer", scenario.name);
  std::optional<FrameArraysFile> arrays;
  if (output.arrays) {
    arrays.emplace(options.output_dir / "frames.h5", scenario.frame_rate,
                   !scenario.refines_cloth() && !scenario.tearing.enabled);
  }

  const RenderSettings& render = scenario.render;
  std::vector<RenderFrame> to_render;
  auto render_recorded = [&](RunResult& result) {
    if (to_render.empty()) return;
    const RenderedRun rendered =
        render_frames(to_render, render, scenario.frame_rate / render.every, options.output_dir,
                      scenario.name, options.on_image, options.stop);
    result.images = rendered.images;
    result.video_warning = rendered.video_warning;
    result.stopped = result.stopped || rendered.stopped;
  };

  // stage 3 of a frame: meshes, statistics, images and callbacks, all read from the complex.
  // The mesh goes first and the stats row, which records the frame, after it: a run killed
  // between the two (SIGKILL) leaves a mesh without its row, never a row without its mesh.
  TopologyCounts topology;
  auto record = [&](int frame, const FrameSteps& steps, Adaptation changes) {
    FrameStats row =
        measure(cloth, lcc, scenario.solver.environment, frame, frame_count, steps, topology);
    row.splits = changes.splits + steps.tip_splits;
    row.merges = changes.merges;
    row.flips = changes.flips;
    // what the viewer and the renderer show of the frame, taken once for both
    const bool rendered = render.enabled && frame % render.every == 0;
    std::optional<RenderFrame> shown;
    if (viewer || rendered) {
      shown = snapshot(lcc, scenario.solver.obstacles, cloth.state.time);
      shown->frame = frame;
    }
    std::vector<std::filesystem::path> mesh_files;
    auto write_frame_mesh = [&](MeshFormat format) {
      mesh_files.push_back(frame_file(options.output_dir, "frame_", frame, format));
      write_mesh(mesh_files.back(), current_mesh(lcc), {rest_positions(lcc), scenario.cloth.frame},
                 format);
    };
    try {
      if (frame % output.mesh_every == 0 || frame == frame_count) {
        if (output.write_meshes) write_frame_mesh(output.mesh_format);
        if (output.glb) write_frame_mesh(MeshFormat::glb);
      }
      if (point_cache) point_cache->append(cloth.state.x);
      if (arrays) write_frame_arrays(*arrays, frame, cloth, lcc);
      if (viewer) viewer->append(*shown, row);
      stats.write(row);
    } catch (...) {  // the frame is not recorded: its meshes go too, so that the two still agree
      std::error_code ignored;
      for (const std::filesystem::path& file : mesh_files) std::filesystem::remove(file, ignored);
      throw;
    }
    if (rendered) to_render.push_back(std::move(*shown));
    if (options.on_frame) options.on_frame(row);
    if (options.on_surface) options.on_surface(frame, {current_mesh(lcc), rest_positions(lcc)});
  };
  record(0, FrameSteps{}, Adaptation{});

  RunResult result;
  StepWorkspace workspace;
  TearStep tearing(scenario);
  PinHandles handles(scenario.pins);
  SpeedLimit limit = speed_limit_at_start(cloth.model, scenario.solver, cloth.state);
  limit.handle_speed_m_per_s = handles.fastest_speed_m_per_s(cloth.state);
  State before_step;
  for (int frame = 1; frame <= frame_count; ++frame) {
    FrameSteps steps;
    if (const auto divergence = step_frame_of(scenario, lcc, cloth, workspace, handles, tearing,
                                              limit, before_step, steps, options.stop)) {
      write_back(cloth, cloth.state, lcc);  // the state before the step that diverged
      const auto last_good =
          last_good_file(options.output_dir, frame, divergence->substep, output.mesh_format);
      write_mesh(last_good, current_mesh(lcc), {rest_positions(lcc), scenario.cloth.frame},
                 output.mesh_format);
      result.ok = false;
      result.failure = divergence_message(scenario, frame, *divergence, cloth,
                                          "written to " + last_good.string());
      render_recorded(result);
      return result;
    }
    if (steps.stopped) {  // the frame in progress is dropped; nothing is rendered after a stop
      result.stopped = true;
      return result;
    }
    if (steps.unconverged > 0 && result.unconverged_steps == 0 && options.on_warning) {
      options.on_warning(unconverged_message(scenario, frame, steps.unconverged));
    }
    result.unconverged_steps += steps.unconverged;
    const Adaptation changes = adapt_frame(scenario, frame, lcc, cloth);
    record(frame, steps, changes);
    result.frames_done = frame;
  }
  render_recorded(result);
  return result;
}

struct Simulation::Run {
  explicit Run(Scenario s) : scenario(std::move(s)), tearing(scenario), handles(scenario.pins) {
    build_scenario_cloth(scenario, lcc);
    cloth = compile(lcc);
    limit = speed_limit_at_start(cloth.model, scenario.solver, cloth.state);
    limit.handle_speed_m_per_s = handles.fastest_speed_m_per_s(cloth.state);
  }

  Scenario scenario;
  ClothComplex lcc;
  CompiledCloth cloth;
  StepWorkspace workspace;
  TearStep tearing;
  PinHandles handles;
  SpeedLimit limit;
  State before_step;
  int frame = 0;
};

Simulation::Simulation(Scenario scenario) : m_run(std::make_unique<Run>(std::move(scenario))) {}

Simulation::~Simulation() = default;

void Simulation::step_frame() {
  Run& r = *m_run;
  FrameSteps steps;
  if (const auto divergence = step_frame_of(r.scenario, r.lcc, r.cloth, r.workspace, r.handles,
                                            r.tearing, r.limit, r.before_step, steps, {})) {
    write_back(r.cloth, r.cloth.state, r.lcc);  // the state before the step that diverged
    throw SimulationError(
        divergence_message(r.scenario, r.frame + 1, *divergence, r.cloth, "kept (the arrays now)"));
  }
  ++r.frame;
  adapt_frame(r.scenario, r.frame, r.lcc, r.cloth);
}

int Simulation::frame() const {
  return m_run->frame;
}

int Simulation::particle_count() const {
  return m_run->cloth.model.particle_count();
}

const Scenario& Simulation::scenario() const {
  return m_run->scenario;
}

FrameArrays Simulation::arrays() const {
  const Run& r = *m_run;
  return {r.frame,
          r.cloth.state.time,
          r.cloth.state.x,
          r.cloth.state.v,
          rest_positions(r.lcc),
          r.cloth.model.mass,
          current_mesh(r.lcc).faces,
          {r.cloth.model.pinned.begin(), r.cloth.model.pinned.end()}};
}

}  // namespace tissu
