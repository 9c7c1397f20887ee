// Time to a given accuracy: how long one time step of each solver takes to come within a relative
// error of the fully converged backward Euler step, and each solver's error against its wall time
// as its iteration count grows (issue 7). Scenes, each a 1 m sheet of 0.2 kg/m^2 lying flat with
// its two corners at y = 1 m pinned (Liu et al. 2013's sheet), released from rest:
//   sheet81     81 x 81 particles, h = 1/30 s (the scene);
//   sheet81_h300  the same at h = 1/300 s, the demos' step;
//   sheet128    128 x 128 particles, h = 1/30 s;
//   adaptive    41 x 41 particles refined to 1/160 m edges around two points and cut from the
//               middle of its free edge, h = 1/30 s; each step is timed from a fresh workspace,
//               so that building the system, colouring and factorising are included (the cost of
//               the first step after a topology change).
// The reference minimises backward Euler's incremental potential by Newton's method to round-off:
// for springs without damping, PD's fixed point is that minimiser (Liu et al. 2013), and the
// implicit Euler integrator is its first Newton step (Baraff & Witkin 1998).
// error = |x - x_ref| / |x_ref - x_start| over all particles (dimensionless).
// Why the first step from rest: once the sheet has swung and folded, compressed springs make the
// incremental potential non-convex, and Newton's minimiser and PD's iterates stay about 10 % apart
// (docs/benchmarks.md), so there is no single converged step to measure against.
//
// Benchmarks: to_1e-3/<scene>/<solver> times the step at the smallest iteration count (or
// largest CG tolerance) reaching the target error; to_implicit_euler_error/<scene>/<solver> the
// same for the error of implicit Euler at its default CG tolerance; curve/<scene>/<solver>/<knob>
// the error-time curve, plotted by scripts/plot_pd_accuracy.sh. Results: docs/benchmarks.md.

#include <benchmark/benchmark.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "solver/forces/spring_block_matrix.hpp"
#include "solver/forces/spring_force.hpp"
#include "solver/step.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/compile.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/grid_mesh.hpp"
#include "topology/refine.hpp"
#include "topology/tear.hpp"

namespace tissu {
namespace {

constexpr double target_error = 1e-3;
constexpr int max_iterations = 2048;

SpringSettings undamped_cloth_springs() {
  SpringSettings s;
  s.structural = {true, 1000.0, 0.0};
  s.bending = {true, 4.0, 0.0};
  return s;
}

struct Scene {
  std::string name;
  double time_step_s = 1.0 / 30.0;
  bool fresh_workspace = false;  ///< time each step with a new workspace (system rebuilt)
  SpringModel model;
  State start;
  Eigen::VectorXd reference_x;  ///< 3#P the converged step (m)
  double reference_displacement_m = 0.0;
};

/// What is compared: an integrator, a PD global solver, and the knob that buys accuracy
/// (PD iterations, or implicit Euler's CG tolerance).
struct Method {
  std::string name;
  Integrator integrator = Integrator::projective_dynamics;
  PdGlobalSolver global_solver = PdGlobalSolver::direct;
  bool knob_is_tolerance() const { return integrator == Integrator::implicit_euler; }
};

std::vector<Method> methods() {
  std::vector<Method> all;
  for (const PdGlobalSolver solver :
       {PdGlobalSolver::direct, PdGlobalSolver::jacobi, PdGlobalSolver::chebyshev,
        PdGlobalSolver::gauss_seidel, PdGlobalSolver::colored_gauss_seidel}) {
    all.push_back(
        {std::string("pd_") + to_string(solver), Integrator::projective_dynamics, solver});
  }
  all.push_back({"implicit_euler", Integrator::implicit_euler, PdGlobalSolver::direct});
  return all;
}

SolverParams params_for(const Method& method, double knob, double time_step_s) {
  SolverParams params;
  params.time_step = time_step_s;
  params.integrator = method.integrator;
  params.pd.global_solver = method.global_solver;
  if (method.knob_is_tolerance()) {
    params.implicit.cg_tolerance = knob;
    params.implicit.cg_max_iterations = 100000;
  } else {
    params.pd.iterations = static_cast<int>(knob);
  }
  return params;
}

/// A 1 m square of (cells + 1)^2 particles, 0.2 kg/m^2, lying flat at z = 0, its two corners
/// at y = 1 m pinned.
void build_sheet(int cells, ClothComplex& lcc) {
  GridOptions grid;
  grid.cells_u = grid.cells_v = cells;
  grid.u_axis = Eigen::Vector3d::UnitX();
  grid.v_axis = Eigen::Vector3d::UnitY();
  build_cloth_complex(make_grid_mesh(grid), 0.2, undamped_cloth_springs(), lcc);
  PinSelector corners;
  corners.kind = PinSelector::Kind::corners;
  corners.corners = {Corner::top_left, Corner::top_right};
  apply_pins(lcc, {corners}, ClothFrame{grid.u_axis, grid.v_axis});
}

/// Backward Euler's incremental potential for springs (Liu et al. 2013, eq. 7; Martin et al. 2011):
///   E(x) = 1/(2 h^2) sum_i m_i |x_i - y_i|^2 + sum_s k_s/2 (|x_i - x_j| - l_s)^2   (J),
/// y = x_n + h v_n + h^2 g; its minimiser is the backward Euler step.
double incremental_potential_j(const SpringModel& model, double time_step_s,
                               const Eigen::VectorXd& y, const Eigen::VectorXd& x) {
  double energy = 0.0;
  for (int p = 0; p < model.particle_count(); ++p) {
    energy += 0.5 * model.mass[p] / (time_step_s * time_step_s) *
              (x.segment<3>(3 * p) - y.segment<3>(3 * p)).squaredNorm();
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    energy +=
        spring_energy(x.segment<3>(3 * model.springs(s, 0)), x.segment<3>(3 * model.springs(s, 1)),
                      model.stiffness[s], model.rest_length[s]);
  }
  return energy;
}

/// The converged backward Euler step from `start`: minimises the incremental potential over the
/// free particles by Newton's method from PD's first iterates, with the exact Hessian
/// M/h^2 - df/dx shifted by lambda I (Levenberg-Marquardt; lambda starts from a quarter of the last
/// one and doubles until the matrix is positive definite, so it vanishes near a minimum and Newton
/// converges quadratically) and a backtracking line search, to round-off. Pinned particles move at
/// their velocity, as in every integrator. Returns the positions (m).
Eigen::VectorXd backward_euler_step(const SpringModel& model, double h, const State& start) {
  const int particles = model.particle_count();
  const Eigen::Vector3d gravity = Environment().gravity;
  Eigen::VectorXd y = start.x + h * start.v;
  for (int p = 0; p < particles; ++p) {
    if (model.inverse_mass[p] != 0.0) y.segment<3>(3 * p) += h * h * gravity;
  }
  SolverParams first_iterates;
  first_iterates.time_step = h;
  first_iterates.integrator = Integrator::projective_dynamics;
  first_iterates.pd.iterations = 20;
  State state = start;
  step(model, first_iterates, state);
  Eigen::VectorXd x = state.x;

  SpringBlockPattern pattern;
  update_spring_block_pattern(model, pattern);
  std::vector<Eigen::Matrix3d> blocks(model.spring_count());
  const Eigen::VectorXd inertia = model.mass / (h * h);
  Eigen::SparseMatrix<double> hessian;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  bool pattern_analyzed = false;
  double energy = incremental_potential_j(model, h, y, x);
  double shift = 0.0;  // lambda (kg/s^2)
  Eigen::VectorXd gradient(3 * particles);
  for (int newton = 0; newton < 500; ++newton) {
    for (int p = 0; p < particles; ++p) {
      gradient.segment<3>(3 * p) = inertia[p] * (x.segment<3>(3 * p) - y.segment<3>(3 * p));
    }
    for (int s = 0; s < model.spring_count(); ++s) {
      const int i = model.springs(s, 0), j = model.springs(s, 1);
      const Eigen::Vector3d f = spring_force(x.segment<3>(3 * i), x.segment<3>(3 * j),
                                             model.stiffness[s], model.rest_length[s]);
      gradient.segment<3>(3 * i) -= f;
      gradient.segment<3>(3 * j) += f;
      blocks[s] = -spring_force_jacobian(x.segment<3>(3 * i), x.segment<3>(3 * j),
                                         model.stiffness[s], model.rest_length[s]);
    }
    for (int p = 0; p < particles; ++p) {
      if (model.inverse_mass[p] == 0.0) gradient.segment<3>(3 * p).setZero();
    }
    for (double lambda = shift / 4.0;; lambda = std::max(2.0 * lambda, 1e-3 * inertia.maxCoeff())) {
      assemble_spring_block_matrix(model, pattern, blocks, (inertia.array() + lambda).matrix(),
                                   true, hessian);
      if (!pattern_analyzed) ldlt.analyzePattern(hessian);  // the pattern never changes
      pattern_analyzed = true;
      ldlt.factorize(hessian);
      if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 0.0) {
        shift = lambda;
        break;
      }
    }
    const Eigen::VectorXd direction = ldlt.solve(-gradient);
    const double slope = gradient.dot(direction);
    double alpha = 1.0;
    double trial = incremental_potential_j(model, h, y, x + direction);
    while (trial > energy + 1e-4 * alpha * slope && alpha > 1e-12) {
      alpha *= 0.5;
      trial = incremental_potential_j(model, h, y, x + alpha * direction);
    }
    x += alpha * direction;
    energy = trial;
    // converged when Newton's step has shrunk to round-off and the residual force is negligible
    // (a shallow buckling mode can stall the line search a little above round-off)
    if (gradient.norm() <= 1e-6 && alpha * direction.norm() <= 1e-13 * (x - start.x).norm()) {
      return x;
    }
  }
  throw std::runtime_error("Newton's method did not converge for the reference step");
}

void converge_reference(Scene& scene) {
  std::fprintf(stderr, "%s: converging the reference step...\n", scene.name.c_str());
  scene.reference_x = backward_euler_step(scene.model, scene.time_step_s, scene.start);
  scene.reference_displacement_m = (scene.reference_x - scene.start.x).norm();
}

Scene sheet_scene(const std::string& name, int particles_per_side, double time_step_s) {
  ClothComplex lcc;
  build_sheet(particles_per_side - 1, lcc);
  CompiledCloth cloth = compile(lcc);
  Scene scene;
  scene.name = name;
  scene.time_step_s = time_step_s;
  scene.model = std::move(cloth.model);
  scene.start = std::move(cloth.state);
  converge_reference(scene);
  return scene;
}

/// 41 x 41 particles, refined down to 1/160 m edges around (0.3, 0.7) and (0.5, 0.5), then cut
/// along x = 0.5 from the free edge to the centre.
Scene adaptive_torn_scene() {
  ClothComplex lcc;
  build_sheet(40, lcc);
  for (const Eigen::Vector3d& centre :
       {Eigen::Vector3d(0.3, 0.7, 0.0), Eigen::Vector3d(0.5, 0.5, 0.0)}) {
    for (int ring = 0; ring < 4; ++ring) {
      refine_around_vertex(lcc, nearest_vertex(lcc, centre), 1.0 / 160.0, 100000,
                           undamped_cloth_springs());
    }
  }
  cut_along(lcc, {Eigen::Vector3d(0.5, 0.0, 0.0), Eigen::Vector3d(0.5, 0.5, 0.0)},
            undamped_cloth_springs());
  CompiledCloth cloth = compile(lcc);
  Scene scene;
  scene.name = "adaptive";
  scene.fresh_workspace = true;
  scene.model = std::move(cloth.model);
  scene.start = std::move(cloth.state);
  converge_reference(scene);
  return scene;
}

double step_error(const Scene& scene, const SolverParams& params) {
  State state = scene.start;
  step(scene.model, params, state);
  if (!state.x.allFinite()) return INFINITY;
  return (state.x - scene.reference_x).norm() / scene.reference_displacement_m;
}

/// Iteration counts 1, 2, 3, 4, 6, 8, 11, ... (about sqrt 2 apart), or CG tolerances 1e-1 ...
/// 1e-10; a curve stops once it is 100 times below the target.
std::vector<double> knobs(const Method& method) {
  std::vector<double> values;
  if (method.knob_is_tolerance()) {
    for (int e = 1; e <= 10; ++e) values.push_back(std::pow(10.0, -e));
    return values;
  }
  for (double n = 1.0; n <= max_iterations; n = std::max(n + 1.0, std::round(n * std::sqrt(2.0)))) {
    values.push_back(n);
  }
  return values;
}

/// A solver's error at each of its knobs (see knobs()).
struct ErrorCurve {
  std::vector<double> knobs;
  std::vector<double> errors;
};

ErrorCurve error_curve(const Scene& scene, const Method& method) {
  ErrorCurve curve;
  for (const double knob : knobs(method)) {
    curve.knobs.push_back(knob);
    curve.errors.push_back(step_error(scene, params_for(method, knob, scene.time_step_s)));
    if (curve.errors.back() < 0.01 * target_error) break;
  }
  return curve;
}

/// The cheapest knob reaching `target`: the smallest iteration count (bisection between the
/// curve's points, the error decreasing with iterations) or the largest tolerance on the curve.
std::optional<double> cheapest_knob(const Scene& scene, const Method& method,
                                    const ErrorCurve& curve, double target) {
  std::size_t k = 0;
  while (k < curve.errors.size() && !(curve.errors[k] <= target)) ++k;
  if (k == curve.errors.size()) return std::nullopt;
  if (method.knob_is_tolerance() || k == 0) return curve.knobs[k];
  int low = static_cast<int>(curve.knobs[k - 1]);  // above the target
  int high = static_cast<int>(curve.knobs[k]);     // at or below it
  while (high - low > 1) {
    const int middle = (low + high) / 2;
    if (step_error(scene, params_for(method, middle, scene.time_step_s)) <= target) {
      high = middle;
    } else {
      low = middle;
    }
  }
  return high;
}

void BM_Step(benchmark::State& bench, const Scene* scene, SolverParams params, double error) {
  StepWorkspace workspace;
  State state = scene->start;
  step(scene->model, params, state, workspace);  // untimed: buffers sized, system built
  for (auto _ : bench) {
    bench.PauseTiming();
    state = scene->start;
    if (scene->fresh_workspace) workspace = StepWorkspace();
    bench.ResumeTiming();
    step(scene->model, params, state, workspace);
    benchmark::DoNotOptimize(state.x.data());
  }
  bench.counters["error"] = error;
  bench.counters["particles"] = scene->model.particle_count();
  bench.counters["pd_iterations"] = params.pd.iterations;
  bench.counters["cg_tolerance"] = params.implicit.cg_tolerance;
}

void register_step(const std::string& name, const Scene& scene, const SolverParams& params,
                   double error) {
  benchmark::RegisterBenchmark(name.c_str(), BM_Step, &scene, params, error)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

/// Registers <prefix>/<scene>/<solver>, the step at the cheapest knob reaching `target`, or says
/// on stderr that none does.
void register_cheapest(const std::string& prefix, const Scene& scene, const Method& method,
                       const ErrorCurve& curve, double target) {
  const std::string name = prefix + "/" + scene.name + "/" + method.name;
  const std::optional<double> knob = cheapest_knob(scene, method, curve, target);
  if (!knob) {
    std::fprintf(stderr, "%s: no %s up to %g reaches %.3g (best %.3g)\n", name.c_str(),
                 method.knob_is_tolerance() ? "CG tolerance" : "iteration count",
                 curve.knobs.back(), target,
                 *std::min_element(curve.errors.begin(), curve.errors.end()));
    return;
  }
  const SolverParams params = params_for(method, *knob, scene.time_step_s);
  register_step(name, scene, params, step_error(scene, params));
}

/// The scene's benchmarks: every solver's error curve, its cheapest step to the target error, and
/// its cheapest step to the error of implicit Euler at its default CG tolerance.
void register_scene(const Scene& scene) {
  std::fprintf(stderr, "%s: %d particles, error curves of each solver...\n", scene.name.c_str(),
               scene.model.particle_count());
  const Method implicit_euler = methods().back();
  const double implicit_euler_error = step_error(
      scene, params_for(implicit_euler, ImplicitOptions().cg_tolerance, scene.time_step_s));
  for (const Method& method : methods()) {
    const ErrorCurve curve = error_curve(scene, method);
    for (std::size_t k = 0; k < curve.knobs.size(); ++k) {
      char knob[32];
      std::snprintf(knob, sizeof knob, "%g", curve.knobs[k]);
      register_step("curve/" + scene.name + "/" + method.name + "/" + knob, scene,
                    params_for(method, curve.knobs[k], scene.time_step_s), curve.errors[k]);
    }
    register_cheapest("to_1e-3", scene, method, curve, target_error);
    if (method.knob_is_tolerance()) {
      register_step("to_implicit_euler_error/" + scene.name + "/" + method.name, scene,
                    params_for(method, ImplicitOptions().cg_tolerance, scene.time_step_s),
                    implicit_euler_error);
    } else {
      register_cheapest("to_implicit_euler_error", scene, method, curve, implicit_euler_error);
    }
  }
}

}  // namespace
}  // namespace tissu

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  // scenes live until the benchmarks have run; each is set up (reference, curves) first
  static std::vector<tissu::Scene> scenes;
  scenes.reserve(4);
  scenes.push_back(tissu::sheet_scene("sheet81", 81, 1.0 / 30.0));
  scenes.push_back(tissu::sheet_scene("sheet81_h300", 81, 1.0 / 300.0));
  scenes.push_back(tissu::sheet_scene("sheet128", 128, 1.0 / 30.0));
  scenes.push_back(tissu::adaptive_torn_scene());
  for (const tissu::Scene& scene : scenes) tissu::register_scene(scene);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
