// Bending at every level of refinement (topology/spring_assignment.cpp, bending_level_factor): a
// sheet refined in one half is the same cloth as the uniform fine sheet, so both drape over a
// cylinder to the same shape; with the same spring stiffness at both levels (tissu before the
// rule) the coarse half is 16 times too stiff and hangs differently. A sheet remeshed
// anisotropically into thin cells drapes like the uniform fine sheet too.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "lib/cloth_setup.hpp"
#include "lib/scenario/scenario.hpp"
#include "lib/shape_distance.hpp"
#include "solver/step.hpp"
#include "topology/compile.hpp"
#include "topology/current_mesh.hpp"
#include "topology/refine.hpp"
#include "topology/remesh.hpp"
#include "topology/retriangulation.hpp"
#include "topology/spring_assignment.hpp"

namespace tissu {
namespace {

/// A 0.6 m x 0.4 m sheet lying level just above a cylinder of radius 0.1 m along y, whose top is
/// at z = 0.3 m, on cells of 0.6 / cells m; bending springs of `bending` N/m on those cells.
std::string sheet_over_cylinder(int cells, double bending_n_per_m) {
  const std::string k = std::to_string(bending_n_per_m);
  return R"({
  "cloth": { "grid": { "size": [0.6, 0.4], "resolution": [)" +
         std::to_string(cells) + ", " + std::to_string(cells * 2 / 3) + R"(],
                       "origin": [-0.3, -0.2, 0.306], "u_axis": [1, 0, 0], "v_axis": [0, 1, 0] },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 1000, "damping": 0.5 },
                          "bending": { "stiffness": )" +
         k + R"(, "damping": 0 } } },
  "environment": { "air_damping": 0.5 },
  "obstacles": [ { "type": "capsule", "from": [0, -1, 0.2], "to": [0, 1, 0.2], "radius": 0.1,
                   "static_friction": 0.8, "kinetic_friction": 0.6 } ],
  "simulation": { "integrator": "implicit_euler", "frames": 45, "substeps": 10 }
})";
}

// on the 2.5 cm cells: stiff enough for bending to shape the drape (the uniform 5 cm sheet with
// the same springs ends 15 mm from the fine one on average, with 1/16 of them 2.3 mm)
constexpr double fine_bending_n_per_m = 200.0;

enum class Rule { scaled, unscaled };

/// `lcc`, built from `scenario`, stepped for the scenario's frames; its shape then.
MaterialSurface drape(const Scenario& scenario, ClothComplex& lcc) {
  CompiledCloth cloth = compile(lcc);
  StepWorkspace workspace;
  for (int k = 0; k < scenario.frames * scenario.substeps; ++k) {
    EXPECT_NE(step(cloth.model, scenario.solver, cloth.state, workspace), StepStatus::non_finite);
  }
  write_back(cloth, cloth.state, lcc);
  return {current_mesh(lcc), rest_positions(lcc)};
}

/// The sheet on 5 cm cells with its right half (rest x > 0) bisected twice into 2.5 cm cells,
/// draped for 1.5 s. Rule::scaled: the scenario gives the 5 cm cells 1/16 of the fine cells'
/// bending stiffness, and each bisection quadruples it. Rule::unscaled, as tissu did before the
/// rule: every bending spring has the fine cells' stiffness, at both levels (every face made its
/// own input face after refining).
MaterialSurface half_refined_drape(Rule rule) {
  const double coarse_n_per_m =
      rule == Rule::scaled ? fine_bending_n_per_m / 16.0 : fine_bending_n_per_m;
  const Scenario scenario =
      parse_scenario(sheet_over_cylinder(12, coarse_n_per_m), "half_refined.json");
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  for (bool split = true; split;) {
    split = false;
    std::vector<Vertex_handle> right;
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      if (v->info().rest_position.x() > 1e-9) right.push_back(v);
    }
    // edges of 4 cm or more are split: down to the 2.5 cm legs (3.5 cm diagonals) of the fine grid
    for (Vertex_handle v : right)
      split |= refine_around_vertex(lcc, v, 0.02, 100000, scenario.springs) > 0;
  }
  if (rule == Rule::unscaled) {
    for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
      f->info().input_area = f->info().rest_area;
    }
    assign_springs(lcc, scenario.springs);
  }
  return drape(scenario, lcc);
}

MaterialSurface uniform_fine_drape() {
  const Scenario scenario =
      parse_scenario(sheet_over_cylinder(24, fine_bending_n_per_m), "uniform_fine.json");
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  return drape(scenario, lcc);
}

/// The sheet on 10 cm cells, remeshed anisotropically (topology/remesh.hpp) as if wrapped round
/// the cylinder (each point's rest x becomes an arc of the cylinder), into cells 2.5 cm across the
/// fold and up to 10 cm along it, then laid flat again and draped for 1.5 s. The scenario gives
/// the 10 cm cells 1/256 of the fine cells' bending stiffness (four bisections); refined hinges
/// scale by their area and shape, as with adaptive.anisotropic.
MaterialSurface remeshed_drape(int& particles) {
  Scenario scenario =
      parse_scenario(sheet_over_cylinder(6, fine_bending_n_per_m / 256.0), "remeshed.json");
  scenario.springs.bending_follows_hinge_shape = true;
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  const double radius_m = 0.106, axis_z_m = 0.2;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Point3& r = v->info().rest_position;
    const double angle_rad = r.x() / radius_m;
    v->point() =
        Point3(radius_m * std::sin(angle_rad), r.y(), axis_z_m + radius_m * std::cos(angle_rad));
  }
  RefinementOptions options;
  options.anisotropic = true;
  options.curvature_threshold_rad = 0.025 / radius_m;  // 2.5 cm edges across the fold
  options.min_edge_length_m = 0.02;
  for (int pass = 0; pass < 20; ++pass) {
    const RemeshReport r = remesh(lcc, options, 0.0, scenario.springs);
    if (r.splits + r.flips == 0) break;
  }
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    v->point() = v->info().rest_position;
  }
  particles = static_cast<int>(lcc.vertex_attributes().size());
  return drape(scenario, lcc);
}

TEST(BendingLevels, ASheetRefinedInOneHalfDrapesOverACylinderLikeTheUniformFineSheet) {
  const MaterialSurface fine = uniform_fine_drape();
  const double size_m = std::hypot(0.6, 0.4);
  const ShapeDistance scaled = material_point_distance(half_refined_drape(Rule::scaled), fine);
  const ShapeDistance unscaled = material_point_distance(half_refined_drape(Rule::unscaled), fine);
  // the sheet has draped: its sides hang well below the cylinder's top
  double lowest_z = 1.0;
  for (const Eigen::Vector3d& x : fine.current.vertices) lowest_z = std::min(lowest_z, x.z());
  EXPECT_LT(lowest_z, 0.25);
  EXPECT_LT(scaled.mean_m, 0.01 * size_m) << "with the scaling rule";
  EXPECT_GT(unscaled.mean_m, 2.0 * scaled.mean_m) << "without it, " << unscaled.mean_m << " m";
}

// The cloth of thin remeshed cells (membrane, masses and bending together) drapes as the fine
// one does. This does not tell the bending rules apart: at this stiffness a sheet without
// bending ends within 0.2 % of the fine one too (docs/benchmarks.md, "the bending rule, tried
// against shapes").
TEST(BendingLevels, ASheetRemeshedIntoThinCellsDrapesOverACylinderLikeTheUniformFineSheet) {
  const MaterialSurface fine = uniform_fine_drape();
  int particles = 0;
  const MaterialSurface remeshed = remeshed_drape(particles);
  EXPECT_LT(particles, static_cast<int>(fine.current.vertices.size()) / 2);
  // thin cells: the grid's right isosceles halves have quality 0.87, a right triangle of legs in
  // the ratio 2.6 (longest edge^2 / area = 6) sqrt(3) / 3, one of legs 2.5 and 10 cm 0.41; the
  // thinnest here 0.19
  std::vector<RestTriangle> cells;
  for (const std::vector<int>& f : remeshed.current.faces) {
    cells.push_back({remeshed.rest_m[f[0]], remeshed.rest_m[f[1]], remeshed.rest_m[f[2]]});
  }
  EXPECT_LT(lowest_quality(cells), std::sqrt(3.0) / 3.0);
  const double size_m = std::hypot(0.6, 0.4);
  EXPECT_LT(material_point_distance(remeshed, fine).mean_m, 0.01 * size_m);
}

}  // namespace
}  // namespace tissu
