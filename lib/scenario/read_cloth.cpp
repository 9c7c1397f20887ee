#include "lib/scenario/read_cloth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "lib/scenario/read_motion.hpp"
#include "lib/scenario/scenario_limits.hpp"

namespace tissu {
namespace {

GridOptions read_grid(JsonObjectReader grid) {
  GridOptions o;
  const std::vector<double> size =
      grid.numbers("size", 2, between(min_grid_side_m, max_grid_side_m, " (m)"));
  o.width = size[0];
  o.height = size[1];
  const std::vector<int> resolution = grid.integers("resolution", 1);
  if (resolution.size() != 2) grid.fail("resolution", "two cell counts [along u, along v]");
  o.cells_u = resolution[0];
  o.cells_v = resolution[1];
  // bounded before building: [65536, 65536] would ask for 4.3e9 particles and their springs
  const long long particles = (o.cells_u + 1LL) * (o.cells_v + 1LL);
  if (particles > max_cloth_particles) {
    grid.fail("resolution", "cell counts [u, v] giving at most " +
                                std::to_string(max_cloth_particles) +
                                " particles (u + 1) (v + 1), the cloth size limit (these give " +
                                std::to_string(particles) + ")");
  }
  o.cells = grid.choice_or("cells", "triangles", {"triangles", "quads"}) == "quads"
                ? GridCells::quads
                : GridCells::triangles;
  const std::string diagonal =
      grid.choice_or("diagonal", "alternating", {"forward", "backward", "alternating"});
  o.diagonal = diagonal == "forward"    ? DiagonalPattern::forward
               : diagonal == "backward" ? DiagonalPattern::backward
                                        : DiagonalPattern::alternating;
  if (grid.has("pleats")) {
    JsonObjectReader pleats = grid.object("pleats");
    o.pleats = pleats.integer("count", 1, std::max(1, o.cells_u / 2));
    o.gathered_width = pleats.number(
        "gathered_width", {0.0, o.width * (1.0 - 1e-6), true, "a width (m) in (0, size[0])"});
    pleats.finish();
  }
  o.origin = grid.vector3_or("origin", o.origin);
  o.u_axis = grid.direction_or("u_axis", o.u_axis);
  o.v_axis = grid.direction_or("v_axis", o.v_axis);
  if (std::abs(o.u_axis.dot(o.v_axis)) > 1e-9)
    grid.fail("v_axis", "a direction orthogonal to u_axis");
  grid.finish();
  return o;
}

ClothFrame read_frame(JsonObjectReader& section) {
  ClothFrame frame;
  frame.u_axis = section.direction_or("u_axis", frame.u_axis);
  frame.v_axis = section.direction_or("v_axis", frame.v_axis);
  return frame;
}

/// A kind's settings. With a material the stiffness comes from it: the kind is on unless
/// switched off, and a "stiffness" key is refused.
SpringKindSettings read_spring_kind(JsonObjectReader& springs, std::string_view kind,
                                    bool from_material) {
  SpringKindSettings out;
  out.enabled = from_material;
  if (!springs.has(kind)) return out;
  JsonObjectReader section = springs.object(kind);
  out.enabled = section.boolean_or("enabled", true);
  if (from_material) {
    if (section.has("stiffness")) {
      section.fail("stiffness",
                   "no stiffness: with \"material\" it comes from E, nu and thickness");
    }
  } else {
    out.stiffness = section.number("stiffness", positive(" (N/m)"));
  }
  out.damping = section.number_or("damping", 0.0, non_negative(" (N s/m)"));
  section.finish();
  return out;
}

std::vector<std::string> formulation_names() {
  std::vector<std::string> names;
  for (int f = 0; f < stiffness_formulation_count; ++f) {
    names.emplace_back(to_string(static_cast<StiffnessFormulation>(f)));
  }
  return names;
}

Material read_material(JsonObjectReader material, const std::optional<GridOptions>& grid) {
  Material m;
  m.youngs_modulus_pa = material.number("E", positive(" (Young's modulus, Pa)"));
  m.thickness_m = material.number("thickness", positive(" (m)"));
  m.density_kg_per_m3 = material.number("density", positive(" (kg/m^3)"));
  m.formulation = *stiffness_formulation_from_string(
      material.choice_or("formulation", "delingette2008", formulation_names()));
  m.poisson_ratio = material.number("nu", NumberRule{});
  const PoissonRange range = supported_poisson_ratios(m.formulation);
  if (!range.contains(m.poisson_ratio)) {
    material.fail("nu", std::string("a Poisson ratio ") + (range.min == range.max ? "of " : "in ") +
                            describe(range) + " for formulation \"" +
                            std::string(to_string(m.formulation)) +
                            "\": " + std::string(supported_range_reason(m.formulation)));
  }
  if (grid && !formulation_defines(m.formulation, grid->cells == GridCells::quads ? 4 : 3)) {
    material.fail("formulation",
                  std::string("a formulation defined on the grid's ") +
                      (grid->cells == GridCells::quads ? "quads" : "triangles") +
                      " (cloth.grid.cells): \"" + std::string(to_string(m.formulation)) +
                      "\" is defined on " +
                      (grid->cells == GridCells::quads ? "triangles" : "rectangles"));
  }
  material.finish();
  return m;
}

Side read_side(JsonObjectReader& pin) {
  const std::string side = pin.choice("side", {"left", "right", "bottom", "top"});
  return side == "left"     ? Side::left
         : side == "right"  ? Side::right
         : side == "bottom" ? Side::bottom
                            : Side::top;
}

std::vector<Corner> read_corners(JsonObjectReader& pin) {
  const std::vector<std::string> names = {"bottom_left", "bottom_right", "top_left", "top_right"};
  std::vector<Corner> corners;
  for (const ArrayElement& element : pin.array("corners")) {
    const nlohmann::json& name = *element.value;
    const auto it = name.is_string()
                        ? std::find(names.begin(), names.end(), name.get<std::string>())
                        : names.end();
    if (it == names.end()) {
      throw ScenarioError(pin.file() + ": " + element.path +
                          ": expected one of \"bottom_left\", \"bottom_right\", \"top_left\", "
                          "\"top_right\", got " +
                          name.dump());
    }
    corners.push_back(static_cast<Corner>(it - names.begin()));
  }
  if (corners.empty()) pin.fail("corners", "at least one corner");
  return corners;
}

PinSelector read_pin(JsonObjectReader pin) {
  PinSelector s;
  const int kinds = pin.has("side") + pin.has("corners") + pin.has("indices") + pin.has("box");
  if (kinds != 1) {
    throw ScenarioError(pin.file() + ": " + pin.path() +
                        ": expected exactly one of \"side\", \"corners\", \"indices\", \"box\"");
  }
  if (pin.has("side")) {
    s.kind = PinSelector::Kind::side;
    s.side = read_side(pin);
    s.every = pin.integer_or("every", 1, 1, std::numeric_limits<int>::max());
  } else if (pin.has("corners")) {
    s.kind = PinSelector::Kind::corners;
    s.corners = read_corners(pin);
  } else if (pin.has("indices")) {
    s.kind = PinSelector::Kind::indices;
    s.indices = pin.integers("indices", 0);
  } else {
    s.kind = PinSelector::Kind::box;
    s.box = pin.box("box");
  }
  if (pin.has("motion")) {
    if (pin.has("velocity")) {
      pin.fail("velocity", "no \"velocity\" beside \"motion\" (give it as motion.velocity)");
    }
    s.motion = read_motion(pin.object("motion"), std::nullopt);
  } else {
    s.motion.drift_m_per_s = pin.vector3_or("velocity", Eigen::Vector3d::Zero());
  }
  s.attach_at_s = pin.number_or("attach_at", 0.0, non_negative(" (s)"));
  if (pin.has("release_at")) {
    s.release_at_s =
        pin.number("release_at", {s.attach_at_s, std::numeric_limits<double>::infinity(), true,
                                  "a time (s) after attach_at"});
  }
  pin.finish();
  return s;
}

}  // namespace

void read_cloth(JsonObjectReader cloth, Scenario& scenario) {
  if (cloth.has("grid") == cloth.has("mesh")) {
    cloth.fail("grid", "exactly one of \"grid\" and \"mesh\" in \"cloth\"");
  }
  if (cloth.has("grid")) {
    scenario.cloth.grid = read_grid(cloth.object("grid"));
    scenario.cloth.frame = {scenario.cloth.grid->u_axis, scenario.cloth.grid->v_axis};
  } else {
    JsonObjectReader mesh = cloth.object("mesh");
    const std::filesystem::path file = mesh.string("file");
    if (file.empty()) mesh.fail("file", "the path of a mesh file, not an empty string");
    scenario.cloth.mesh_file = file.is_absolute() ? file : scenario.file.parent_path() / file;
    // absolute, so that the resolved scenario runs from any folder
    mesh.resolve("file", std::filesystem::absolute(scenario.cloth.mesh_file).string());
    scenario.cloth.frame = read_frame(mesh);
    mesh.finish();
  }
  const bool from_material = cloth.has("material");
  if (from_material) {
    if (cloth.has("density")) {
      cloth.fail("density",
                 "no \"density\" beside \"material\": give the material's density (kg/m^3) in "
                 "\"material\"");
    }
    scenario.springs.material = read_material(cloth.object("material"), scenario.cloth.grid);
    scenario.areal_density = scenario.springs.material->areal_density_kg_per_m2();
  } else {
    scenario.areal_density = cloth.number("density", positive(" (kg/m^2)"));
  }
  // with a material, "springs" only switches kinds off or sets their damping
  JsonObjectReader springs =
      from_material ? cloth.optional_object("springs") : cloth.object("springs");
  scenario.springs.structural = read_spring_kind(springs, "structural", from_material);
  scenario.springs.shear = read_spring_kind(springs, "shear", from_material);
  scenario.springs.bending = read_spring_kind(springs, "bending", from_material);
  if (!scenario.springs.structural.enabled) {
    springs.fail("structural",
                 "structural springs: a cloth without them has no in-plane stiffness");
  }
  springs.finish();
  cloth.finish();
}

std::vector<PinSelector> read_pins(JsonObjectReader& top) {
  std::vector<PinSelector> pins;
  if (!top.has("pins")) return pins;
  for (const ArrayElement& element : top.array("pins")) {
    pins.push_back(read_pin(object_reader(element, top.file())));
  }
  return pins;
}

}  // namespace tissu
