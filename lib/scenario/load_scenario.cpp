#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>

#include "lib/scenario/parse_strict_json.hpp"
#include "lib/scenario/printable_text.hpp"
#include "lib/scenario/read_cloth.hpp"
#include "lib/scenario/read_collisions.hpp"
#include "lib/scenario/read_render.hpp"
#include "lib/scenario/read_scenario_text.hpp"
#include "lib/scenario/read_tearing.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "solver/step.hpp"

namespace tissu {
namespace {

/// An array index written in a --set path: digits only, below `size`.
std::optional<std::size_t> array_index(const std::string& key, std::size_t size) {
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
  if (key.empty() || error != std::errc() || end != key.data() + key.size() || index >= size) {
    return std::nullopt;  // not a number, beyond size_t (99999999999999999999), or too large
  }
  return index;
}

/// Applies "a.b.c=value" to `root`; value is JSON if it parses, else a string. The assignment
/// must be UTF-8 (a scenario's text is); its path and value together nest at most
/// max_json_depth levels.
void apply_override(nlohmann::json& root, const std::string& assignment, const std::string& file) {
  const std::string shown = "--set " + printable_text(assignment);
  if (const std::size_t bad = invalid_utf8_offset(assignment); bad != std::string::npos) {
    throw ScenarioError(file + ": " + shown + ": byte " + std::to_string(bad) +
                        " is not UTF-8 text; expected key.path=value in UTF-8");
  }
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw ScenarioError(file + ": " + shown + ": expected key.path=value");
  }
  const std::string path = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  std::vector<std::string> keys;
  for (std::size_t begin = 0;;) {
    const std::size_t dot = std::min(path.find('.', begin), path.size());
    keys.push_back(path.substr(begin, dot - begin));
    if (keys.back().empty()) throw ScenarioError(file + ": " + shown + ": empty key in path");
    if (keys.size() > static_cast<std::size_t>(max_json_depth)) {
      throw ScenarioError(file + ": " + shown + ": a key path of more than " +
                          std::to_string(max_json_depth) +
                          " keys (the nesting limit of a scenario; a scenario needs about 6)");
    }
    if (dot == path.size()) break;
    begin = dot + 1;
  }
  StrictJsonResult parsed =
      parse_strict_json(text, file, printable_text(path), static_cast<int>(keys.size()));
  nlohmann::json value =
      parsed.syntax_error.empty() ? std::move(parsed.value) : nlohmann::json(text);

  nlohmann::json* node = &root;
  std::string walked;
  for (const std::string& key : keys) {
    if (node->is_array()) {
      const std::optional<std::size_t> index = array_index(key, node->size());
      if (!index) {
        throw ScenarioError(file + ": " + shown + ": '" + printable_text(walked) +
                            "' is an array; expected an index below " +
                            std::to_string(node->size()));
      }
      node = &(*node)[*index];
    } else if (node->is_object() || node->is_null()) {
      node = &(*node)[key];
    } else {
      throw ScenarioError(file + ": " + shown + ": '" + printable_text(walked) +
                          "' is not an object");
    }
    walked += (walked.empty() ? "" : ".") + key;
  }
  *node = std::move(value);
}

/// The scenario's "name", else the file's stem: a plain file name, since it names the output
/// folder out/<name> and the files <name>.mp4 and <name>.gif in it.
std::string read_name(JsonObjectReader& top, const std::filesystem::path& file) {
  const bool given = top.has("name");
  const std::string name = given ? top.string("name") : file.stem().string();
  std::string wrong;
  if (name.empty()) {
    wrong = "it is empty";
  } else if (name == "." || name == "..") {
    wrong = "\"" + name + "\" names a folder";
  } else if (name.find('/') != std::string::npos) {
    wrong = "it holds a '/'";
  } else if (name.size() > max_name_bytes) {
    wrong = "it has " + std::to_string(name.size()) + " bytes, more than the " +
            std::to_string(max_name_bytes) + " a name may have";
  } else if (invalid_utf8_offset(name) != std::string::npos ||
             std::any_of(name.begin(), name.end(),
                         [](unsigned char c) { return c < 0x20 || c == 0x7F; })) {
    wrong = "it holds control characters or bytes that are not UTF-8";
  }
  if (wrong.empty()) return name;
  const std::string expected = "a plain file name (no '/', not \".\" or \"..\", at most " +
                               std::to_string(max_name_bytes) +
                               " bytes), as it names the output folder out/<name>";
  if (given) top.fail("name", expected + "; " + wrong);
  throw ScenarioError(top.file() + ": name: missing, and the file's stem \"" +
                      printable_text(name) + "\" is not " + expected + "; give a \"name\"");
}

/// One of `values`, named in the scenario by to_string(value).
template <class Enum>
Enum read_named(JsonObjectReader& section, std::string_view key, Enum fallback,
                const std::vector<Enum>& values) {
  std::vector<std::string> names;
  for (Enum value : values) names.push_back(to_string(value));
  const std::string name = section.choice_or(key, to_string(fallback), names);
  return values[std::find(names.begin(), names.end(), name) - names.begin()];
}

/// The "pd" object of "simulation": Projective Dynamics' global solver and iterations.
ProjectiveDynamicsOptions read_pd(JsonObjectReader pd) {
  ProjectiveDynamicsOptions o;
  o.global_solver =
      read_named(pd, "global_solver", o.global_solver,
                 {PdGlobalSolver::direct, PdGlobalSolver::jacobi, PdGlobalSolver::chebyshev,
                  PdGlobalSolver::gauss_seidel, PdGlobalSolver::colored_gauss_seidel,
                  PdGlobalSolver::block_gauss_seidel});
  o.iterations = pd.integer_or("iterations", o.iterations, 1, 100000);
  o.linear_iterations = pd.integer_or("linear_iterations", o.linear_iterations, 1, 100000);
  o.tolerance = pd.number_or("tolerance", o.tolerance, between(0.0, 1.0, ""));
  o.chebyshev_spectral_radius = pd.number_or("chebyshev_spectral_radius",
                                             o.chebyshev_spectral_radius, between(0.0, 0.9999, ""));
  o.chebyshev_relaxation = pd.number_or("chebyshev_relaxation", o.chebyshev_relaxation,
                                        {0.0, 1.0, true, "a number in (0, 1]"});
  o.chebyshev_delay = pd.integer_or("chebyshev_delay", o.chebyshev_delay, 0, 100000);
  o.max_estimated_error =
      pd.number_or("max_estimated_error", o.max_estimated_error, non_negative(""));
  pd.finish();
  return o;
}

/// The "newton" object of "simulation": when a Newton step stops.
NewtonOptions read_newton(JsonObjectReader newton) {
  NewtonOptions o;
  o.tolerance = newton.number_or("tolerance", o.tolerance, {0.0, 1.0, true, "a number in (0, 1]"});
  o.max_iterations = newton.integer_or("max_iterations", o.max_iterations, 1, 100000);
  o.cg_max_iterations = newton.integer_or("cg_max_iterations", o.cg_max_iterations, 1, 1000000);
  o.gradient_reduction =
      newton.number_or("gradient_reduction", o.gradient_reduction, between(0.0, 1.0, ""));
  o.preconditioner = read_named(newton, "preconditioner", o.preconditioner,
                                {NewtonPreconditioner::multigrid, NewtonPreconditioner::pd_matrix});
  newton.finish();
  return o;
}

/// The "quasi_newton" object of "simulation": when an L-BFGS step stops, and its memory.
QuasiNewtonOptions read_quasi_newton(JsonObjectReader quasi_newton) {
  QuasiNewtonOptions o;
  o.tolerance =
      quasi_newton.number_or("tolerance", o.tolerance, {0.0, 1.0, true, "a number in (0, 1]"});
  o.max_iterations = quasi_newton.integer_or("max_iterations", o.max_iterations, 1, 100000);
  o.history = quasi_newton.integer_or("history", o.history, 0, 1000);
  o.gradient_reduction =
      quasi_newton.number_or("gradient_reduction", o.gradient_reduction, between(0.0, 1.0, ""));
  o.newton_fallback = quasi_newton.boolean_or("newton_fallback", o.newton_fallback);
  o.initial_hessian =
      read_named(quasi_newton, "initial_hessian", o.initial_hessian,
                 {QuasiNewtonInitialHessian::pd_matrix, QuasiNewtonInitialHessian::pd_multigrid});
  quasi_newton.finish();
  return o;
}

// the loosest quasi-Newton tolerance that follows the converged motion with a V-cycle as the
// initial Hessian and no gradient_reduction (docs/benchmarks.md, "quasi-Newton's initial Hessian
// by multigrid")
constexpr double pd_multigrid_tolerance = 1e-3;

void read_simulation(JsonObjectReader simulation, Scenario& s) {
  // implicit Euler was the default until 2026-12-06: its keys without a named integrator were
  // probably written for it, and now set nothing
  if (!simulation.has("integrator")) {
    for (const char* key : {"cg_tolerance", "cg_max_iterations"}) {
      if (simulation.has(key)) {
        s.notes.push_back(simulation.file() + ": " + simulation.key_path(key) +
                          ": read by \"implicit_euler\" only, and this scenario names no "
                          "simulation.integrator: it runs the default, \"quasi_newton\" (before "
                          "2026-12-06 \"implicit_euler\"); name \"implicit_euler\" to use it");
      }
    }
  }
  s.solver.integrator = read_named(
      simulation, "integrator", Integrator::quasi_newton,
      {Integrator::symplectic_euler, Integrator::position_verlet, Integrator::implicit_euler,
       Integrator::projective_dynamics, Integrator::newton, Integrator::quasi_newton});
  s.frames = simulation.integer("frames", 1, max_frames);
  s.frame_rate = simulation.number_or(
      "frame_rate", 30.0, between(min_frame_rate_hz, max_frame_rate_hz, " (frames per second)"));
  if (simulation.has("substeps") && simulation.has("time_step")) {
    simulation.fail("time_step", "either \"substeps\" or \"time_step\", not both");
  }
  if (simulation.has("time_step")) {
    const double h = simulation.number("time_step", positive(" (s)"));
    const double steps = 1.0 / (s.frame_rate * h);
    // bounded before the cast: 1e-300 would give 3e298 steps, and an int cannot hold them
    if (!(steps <= max_substeps + 0.5)) {
      std::ostringstream expected;
      expected << "a time step of at least " << 1.0 / (s.frame_rate * max_substeps)
               << " s: at most " << max_substeps << " steps per frame of 1/" << s.frame_rate
               << " s";
      simulation.fail("time_step", expected.str());
    }
    if (std::abs(steps - std::round(steps)) > 1e-6 * steps || std::round(steps) < 1) {
      simulation.fail("time_step", "a time step that divides the frame duration 1/frame_rate");
    }
    s.substeps = static_cast<int>(std::round(steps));
  } else {
    s.substeps = simulation.integer_or("substeps", 10, 1, max_substeps);
  }
  s.solver.time_step = 1.0 / (s.frame_rate * s.substeps);
  s.solver.implicit.cg_tolerance =
      simulation.number_or("cg_tolerance", s.solver.implicit.cg_tolerance, between(1e-16, 1, ""));
  s.solver.implicit.cg_max_iterations =
      simulation.integer_or("cg_max_iterations", s.solver.implicit.cg_max_iterations, 1, 1'000'000);
  s.solver.obstacle_penalty =
      simulation.number_or("obstacle_penalty", s.solver.obstacle_penalty, non_negative(""));
  const bool friction_in_step_set = simulation.has("friction_in_step");
  s.solver.friction_in_step = simulation.boolean_or("friction_in_step", s.solver.friction_in_step);
  const bool minimiser =
      s.solver.integrator == Integrator::newton || s.solver.integrator == Integrator::quasi_newton;
  if (friction_in_step_set && s.solver.friction_in_step &&
      !(minimiser && s.solver.obstacle_penalty > 0.0)) {
    s.notes.push_back(simulation.file() + ": " + simulation.key_path("friction_in_step") +
                      ": acts only with simulation.obstacle_penalty > 0 and the newton or "
                      "quasi_newton integrator; here friction acts after each step only");
  }
  s.solver.strain_limit = simulation.number_or("strain_limit", s.solver.strain_limit,
                                               between(0.0, 10.0, " (0: none; 0.1: 10 %)"));
  s.threads = simulation.integer_or("threads", 0, 0, 1024);
  s.solver.pd = read_pd(simulation.optional_object("pd"));
  s.solver.newton = read_newton(simulation.optional_object("newton"));
  s.solver.quasi_newton = read_quasi_newton(simulation.optional_object("quasi_newton"));
  if (s.solver.quasi_newton.initial_hessian == QuasiNewtonInitialHessian::pd_multigrid &&
      s.solver.quasi_newton.tolerance > pd_multigrid_tolerance &&
      s.solver.quasi_newton.gradient_reduction == 0.0) {
    s.notes.push_back(simulation.file() + ": " + simulation.key_path("quasi_newton") +
                      ".initial_hessian: \"pd_multigrid\" stops steps early at tolerances above "
                      "0.001 (the stiff hanging sheet hung 0.7 m short of its converged motion at "
                      "0.01); set simulation.quasi_newton.gradient_reduction to 0.1, or "
                      "tolerance to 0.001");
  }
  simulation.finish();
}

void read_environment(JsonObjectReader environment, Environment& e) {
  e.gravity = environment.vector3_or("gravity", e.gravity);
  e.air_damping = environment.number_or("air_damping", e.air_damping, non_negative(" (1/s)"));
  if (environment.has("wind")) {
    JsonObjectReader wind = environment.object("wind");
    e.wind.velocity = wind.vector3_or("velocity", e.wind.velocity);
    e.wind.gust_amplitude = wind.number_or("gust_amplitude", 0.0, between(0.0, 10.0, ""));
    e.wind.gust_frequency = wind.number_or("gust_frequency", 0.0, non_negative(" (Hz)"));
    e.wind.air_density =
        wind.number_or("air_density", e.wind.air_density, non_negative(" (kg/m^3)"));
    e.wind.drag_coefficient =
        wind.number_or("drag_coefficient", e.wind.drag_coefficient, non_negative(""));
    wind.finish();
  }
  environment.finish();
}

AdaptiveSettings read_adaptive(JsonObjectReader adaptive, double frame_rate_hz) {
  AdaptiveSettings a;
  RefinementOptions& r = a.refinement;
  a.enabled = adaptive.boolean_or("enabled", true);
  a.every = adaptive.integer_or("every", a.every, 1, std::numeric_limits<int>::max());
  r.strain_threshold = adaptive.number_or("strain", r.strain_threshold, non_negative(""));
  r.curvature_threshold_rad =
      adaptive.number_or("curvature", r.curvature_threshold_rad, between(0.0, M_PI, " (rad)"));
  r.min_edge_length_m =
      adaptive.number_or("min_edge_length", r.min_edge_length_m, positive(" (m)"));
  r.max_edge_length_m = adaptive.number_or("max_edge_length", 0.0, non_negative(" (m)"));
  r.max_particles = adaptive.integer_or("max_particles", r.max_particles, 3, max_cloth_particles);
  const double interval_s = a.every / frame_rate_hz;  // between two adaptation passes
  r.lookahead_s = adaptive.number_or("lookahead", interval_s, between(0.0, 10.0, " (s)"));
  r.obstacle_proximity = adaptive.boolean_or("obstacles", r.obstacle_proximity);
  const double coarsen_after_s =
      adaptive.number_or("coarsen_after", 0.1, between(0.0, 1e6, " (s)"));
  r.coarsen_after_passes =
      static_cast<int>(std::clamp(std::ceil(coarsen_after_s / interval_s - 1e-9), 1.0, 1e9));
  a.hysteresis =
      adaptive.number_or("hysteresis", a.hysteresis, {0.0, 0.999, false, "a number in [0, 1)"});
  r.anisotropic = adaptive.boolean_or("anisotropic", r.anisotropic);
  r.max_aspect_ratio =
      adaptive.number_or("max_aspect_ratio", r.max_aspect_ratio, between(1.0, 100.0, ""));
  if (a.enabled && r.strain_threshold == 0.0 && r.curvature_threshold_rad == 0.0 &&
      r.max_edge_length_m == 0.0) {
    adaptive.fail("strain",
                  "a positive \"strain\", \"curvature\" or \"max_edge_length\" when adaptive");
  }
  adaptive.finish();
  return a;
}

/// The "output" object; `fixed_particles` says whether the particles stay the same through the
/// run (no refinement, no tearing), which a point cache needs.
void read_output(JsonObjectReader output, OutputOptions& o, bool fixed_particles) {
  o.write_meshes = output.boolean_or("meshes", o.write_meshes);
  o.mesh_format = mesh_format_from_string(output.choice_or("mesh_format", "obj", {"obj", "ply"}));
  o.mesh_every = output.integer_or("mesh_every", 1, 1, std::numeric_limits<int>::max());
  o.glb = output.boolean_or("glb", o.glb);
  o.viewer = output.boolean_or("viewer", o.viewer);
  o.point_cache = output.boolean_or("point_cache", fixed_particles);
  o.arrays = output.boolean_or("arrays", o.arrays);
  if (o.point_cache && !fixed_particles) {
    output.fail("point_cache",
                "false with adaptive refinement or tearing, which change the particles: a PC2 "
                "cache holds one fixed set of points (the frame meshes carry such runs)");
  }
  output.finish();
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::filesystem::path& file,
                        const std::vector<std::string>& overrides) {
  const std::string name = printable_text(file.string());
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw ScenarioError(name + ": the file is empty; expected a JSON object {...}");
  }
  if (text.size() > max_scenario_bytes) {
    throw ScenarioError(name + ": " + std::to_string(text.size()) +
                        " bytes of text, more than the " + std::to_string(max_scenario_bytes) +
                        " (16 MiB) a scenario may have");
  }
  StrictJsonResult parsed = parse_strict_json(text, name);
  if (!parsed.syntax_error.empty()) {
    throw ScenarioError(name + ": invalid JSON: " + parsed.syntax_error);
  }
  nlohmann::json root = std::move(parsed.value);
  for (const std::string& assignment : overrides) apply_override(root, assignment, name);

  Scenario s;
  s.file = file;
  nlohmann::json resolved = root;  // the readers add the defaults they fall back on
  JsonObjectReader top = object_reader(root, name, "", &resolved);
  s.name = read_name(top, file);
  top.resolve("name", s.name);
  // a section left out is switched off: read as {"enabled": false}, which fills its defaults in
  static const nlohmann::json switched_off = {{"enabled", false}};
  read_cloth(top.object("cloth"), s);
  s.pins = read_pins(top);
  read_environment(top.optional_object("environment"), s.solver.environment);
  read_simulation(top.object("simulation"), s);
  s.solver.obstacles = read_obstacles(top, s.notes);
  s.solver.self_collision =
      read_self_collision(top.optional_object("self_collision", switched_off));
  s.adaptive = read_adaptive(top.optional_object("adaptive", switched_off), s.frame_rate);
  s.springs.bending_follows_hinge_shape = s.adaptive.enabled && s.adaptive.refinement.anisotropic;
  s.tearing = read_tearing(top.optional_object("tearing", switched_off));
  if (s.tearing.enabled && s.tearing.options.strain_threshold > 0.0 &&
      s.solver.strain_limit > 0.0) {
    std::ostringstream message;
    message << name << ": simulation.strain_limit: expected 0 (none) when tearing by strain, "
            << "which the limit would hold back, got " << s.solver.strain_limit;
    throw ScenarioError(message.str());
  }
  if (s.springs.material && s.solver.integrator == Integrator::projective_dynamics &&
      s.springs.material->formulation == StiffnessFormulation::delingette2008) {
    throw ScenarioError(name +
                        ": simulation.integrator: expected \"implicit_euler\", "
                        "\"symplectic_euler\" or \"position_verlet\" with formulation "
                        "\"delingette2008\", whose couplings between the edges of a triangle "
                        "Projective Dynamics cannot project, got \"projective_dynamics\"");
  }
  if (s.springs.material && s.refines_cloth() &&
      !formulation_defines(s.springs.material->formulation, 3)) {
    throw ScenarioError(name +
                        ": cloth.material.formulation: expected a formulation defined on "
                        "triangles, as refinement (adaptive, or around crack tips) cuts the cloth "
                        "into triangles, got \"" +
                        std::string(to_string(s.springs.material->formulation)) +
                        "\", defined on rectangles");
  }
  read_output(top.optional_object("output"), s.output, !s.refines_cloth() && !s.tearing.enabled);
  s.render = read_render(top.optional_object("render", switched_off));
  top.finish();
  // replace: a string set by --set may hold bytes that are not UTF-8
  s.resolved_json = resolved.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  return s;
}

Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<std::string>& overrides) {
  return parse_scenario(read_scenario_text(file, printable_text(file.string())), file, overrides);
}

}  // namespace tissu
