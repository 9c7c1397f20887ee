// Springs from a material through the cloth complex: each edge gets the shares of its faces, the
// cells a formulation does not define are refused, and after refinement, coarsening and tearing
// every spring is what a fresh assignment gives, so a refined region has the coarse one's material.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "cloth_test_support.hpp"
#include "topology/coarsen.hpp"
#include "topology/compile.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/membrane_stiffness.hpp"
#include "topology/refine.hpp"
#include "topology/spring_assignment.hpp"
#include "topology/tear.hpp"

namespace tissu {
namespace {

SpringSettings material_springs(StiffnessFormulation formulation, double nu) {
  SpringSettings s;
  s.structural = {true, 0.0, 0.5};
  s.shear = {true, 0.0, 0.2};
  s.bending = {true, 0.0, 0.01};
  Material m;
  m.youngs_modulus_pa = 1e6;
  m.poisson_ratio = nu;
  m.thickness_m = 1e-3;
  m.density_kg_per_m3 = 200.0;
  m.formulation = formulation;
  s.material = m;
  return s;
}

/// 4 x 4 cells of 0.25 m in the xz plane, each split along the same diagonal: right isosceles
/// triangles.
GridOptions unit_grid(GridCells cells) {
  GridOptions o;
  o.width = 1.0;
  o.height = 1.0;
  o.cells_u = 4;
  o.cells_v = 4;
  o.cells = cells;
  o.diagonal = DiagonalPattern::forward;
  return o;
}

using DartStiffness = std::tuple<double, double, double, double>;  // edge, bending, shear,
                                                                   // coupling (N/m)

std::vector<DartStiffness> dart_stiffnesses(ClothComplex& lcc) {
  std::vector<DartStiffness> out;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    const EdgeSprings& edge = lcc.info<1>(d);
    const CornerMechanics& corner = lcc.info(d);
    out.emplace_back(edge.structural.stiffness, edge.bending.stiffness, corner.shear.stiffness,
                     corner.edge_coupling);
  }
  return out;
}

/// Every dart's springs equal what assign_springs() gives from scratch.
void expect_springs_as_assigned_from_scratch(ClothComplex& lcc, const SpringSettings& settings,
                                             const std::string& when) {
  const std::vector<DartStiffness> kept = dart_stiffnesses(lcc);
  assign_springs(lcc, settings);
  const std::vector<DartStiffness> fresh = dart_stiffnesses(lcc);
  ASSERT_EQ(kept.size(), fresh.size());
  int differ = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) differ += kept[i] != fresh[i];
  EXPECT_EQ(differ, 0) << when << ": darts whose springs differ from a fresh assignment";
}

TEST(MaterialSprings, InteriorEdgesGetBothTrianglesShareAndBorderEdgesOne) {
  const SpringSettings settings = material_springs(StiffnessFormulation::delingette2008, 0.3);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(unit_grid(GridCells::triangles)), 0.2, settings, lcc);
  const CompiledCloth compiled = compile(lcc);
  const SpringModel& model = compiled.model;
  // per triangle: legs E h (3 - nu) / (4 (1 - nu^2)), hypotenuse E h / (2 (1 + nu)) (hand values
  // in membrane_stiffness_test), whatever the 0.25 m size
  const double leg = 741.758241758, hypotenuse = 384.615384615;
  int legs_inside = 0, legs_on_border = 0, hypotenuses = 0;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.kind[s] != SpringKind::structural) continue;
    const bool on_border = lcc.is_free<2>(compiled.spring_darts[s]);
    if (model.rest_length[s] > 0.3) {
      EXPECT_NEAR(model.stiffness[s], 2 * hypotenuse, 1e-6);
      ++hypotenuses;
    } else if (on_border) {
      EXPECT_NEAR(model.stiffness[s], leg, 1e-6);
      ++legs_on_border;
    } else {
      EXPECT_NEAR(model.stiffness[s], 2 * leg, 1e-6);
      ++legs_inside;
    }
  }
  EXPECT_EQ(hypotenuses, 16);
  EXPECT_EQ(legs_on_border, 16);
  EXPECT_EQ(legs_inside, 24);
}

TEST(MaterialSprings, Delingette2008CouplesTheEdgesOfEveryTriangle) {
  const SpringSettings settings = material_springs(StiffnessFormulation::delingette2008, 0.3);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(unit_grid(GridCells::triangles)), 0.2, settings, lcc);
  const SpringModel& model = compile(lcc).model;
  ASSERT_EQ(model.couplings.rows(), 3 * 32);  // three pairs of edges in each of 32 triangles
  // the hand values of membrane_stiffness_test: two legs 357.14 N/m, a leg and the hypotenuse
  // -271.96 N/m
  int legs = 0, leg_and_hypotenuse = 0;
  for (Eigen::Index c = 0; c < model.couplings.rows(); ++c) {
    const bool hypotenuse = model.rest_length[model.couplings(c, 0)] > 0.3 ||
                            model.rest_length[model.couplings(c, 1)] > 0.3;
    EXPECT_NEAR(model.coupling_stiffness[c], hypotenuse ? -271.964146610 : 357.142857143, 1e-6);
    ++(hypotenuse ? leg_and_hypotenuse : legs);
  }
  EXPECT_EQ(legs, 32);
  EXPECT_EQ(leg_and_hypotenuse, 64);
  // springs alone (van Gelder) have none
  build_cloth_complex(make_grid_mesh(unit_grid(GridCells::triangles)), 0.2,
                      material_springs(StiffnessFormulation::van_gelder1998, 1.0 / 3), lcc);
  EXPECT_EQ(compile(lcc).model.couplings.rows(), 0);
}

TEST(MaterialSprings, QuadFormulationsSetTheDiagonals) {
  const SpringSettings settings = material_springs(StiffnessFormulation::baudet2009, 0.3);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(unit_grid(GridCells::quads)), 0.2, settings, lcc);
  const RectangleStiffness share = rectangle_stiffness(*settings.material, 0.25, 0.25);
  const SpringModel& model = compile(lcc).model;
  int diagonals = 0;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.kind[s] != SpringKind::shear) continue;
    EXPECT_NEAR(model.stiffness[s], share.diagonal_n_per_m, 1e-9);
    ++diagonals;
  }
  EXPECT_EQ(diagonals, 32);
}

TEST(MaterialSprings, ACellTheFormulationDoesNotDefineIsRefusedByName) {
  using ::testing::AllOf;
  using ::testing::HasSubstr;
  using ::testing::ThrowsMessage;
  ClothComplex lcc;
  const auto build = [&lcc](const GridOptions& grid, StiffnessFormulation formulation, double nu) {
    return [&lcc, grid, formulation, nu] {
      build_cloth_complex(make_grid_mesh(grid), 0.2, material_springs(formulation, nu), lcc);
    };
  };
  EXPECT_THAT(
      build(unit_grid(GridCells::quads), StiffnessFormulation::delingette2008, 0.3),
      ThrowsMessage<std::invalid_argument>(AllOf(
          HasSubstr("\"delingette2008\" is defined on triangles"), HasSubstr("has 4 corners"))));
  EXPECT_THROW(build(unit_grid(GridCells::triangles), StiffnessFormulation::baudet2009, 0.3)(),
               std::invalid_argument);
  // Baudet's long sides go negative when b^2 (3 nu + 2) < a^2: 0.25 x 0.125 m cells at nu = 0
  GridOptions long_cells = unit_grid(GridCells::quads);
  long_cells.height = 0.5;
  EXPECT_THAT(build(long_cells, StiffnessFormulation::baudet2009, 0.0),
              ThrowsMessage<std::invalid_argument>(
                  HasSubstr("positive stiffnesses, not 0.25 x 0.125 m at nu 0")));
}

TEST(MaterialSprings, RefiningCoarseningAndTearingKeepEverySpringAsAFreshAssignmentGivesIt) {
  for (const StiffnessFormulation formulation :
       {StiffnessFormulation::delingette2008, StiffnessFormulation::van_gelder1998}) {
    const SpringSettings settings = material_springs(formulation, 1.0 / 3);
    const std::string name(to_string(formulation));
    GridOptions options = unit_grid(GridCells::triangles);
    options.cells_u = options.cells_v = 8;
    options.diagonal = DiagonalPattern::alternating;
    ClothComplex lcc;
    build_cloth_complex(make_grid_mesh(options), 0.2, settings, lcc);
    const double mass_kg = 0.2;

    ASSERT_GT(
        refine_around_vertex(lcc, nearest_vertex(lcc, {0.5, 0.0, 0.5}), 0.03, 10000, settings), 0);
    test::expect_valid_with_mass(lcc, mass_kg, name + " after refinement");
    expect_springs_as_assigned_from_scratch(lcc, settings, name + " after refinement");

    RefinementOptions flat;  // no criterion over threshold: every split may be undone
    ASSERT_GT(coarsen(lcc, flat, 0.5, settings).merges, 0);
    test::expect_valid_with_mass(lcc, mass_kg, name + " after coarsening");
    expect_springs_as_assigned_from_scratch(lcc, settings, name + " after coarsening");

    ASSERT_GT(cut_along(lcc, {{0.25, 0.0, 0.5}, {0.75, 0.0, 0.5}}, settings).tears, 0);
    test::expect_valid_with_mass(lcc, mass_kg, name + " after tearing");
    expect_springs_as_assigned_from_scratch(lcc, settings, name + " after tearing");
  }
}

}  // namespace
}  // namespace tissu
