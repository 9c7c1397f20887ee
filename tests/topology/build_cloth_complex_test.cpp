#include "topology/build_cloth_complex.hpp"

#include <gtest/gtest.h>

#include "cloth_test_support.hpp"
#include "topology/compile.hpp"
#include "topology/mass_lumping.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.25;

struct GridCase {
  int cells_u, cells_v;
  GridCells cells;
  DiagonalPattern diagonal;
};

class GridComplexTest : public ::testing::TestWithParam<GridCase> {};

std::array<int, spring_kind_count> count_by_kind(const SpringModel& model) {
  std::array<int, spring_kind_count> count{};
  for (SpringKind k : model.kind) ++count[static_cast<int>(k)];
  return count;
}

TEST_P(GridComplexTest, MassEqualsDensityTimesAreaAndSpringsAreCountedPerKind) {
  const GridCase c = GetParam();
  const GridOptions options = test::grid(c.cells_u, c.cells_v, c.cells, c.diagonal);
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, test::all_springs(), lcc);

  const std::vector<std::string> problems = validity_problems(lcc);
  EXPECT_TRUE(problems.empty()) << problems.front();
  const double area_m2 = options.width * options.height;
  EXPECT_NEAR(complex_total_mass(lcc), density_kg_per_m2 * area_m2,
              1e-12 * density_kg_per_m2 * area_m2);

  const CompiledCloth compiled = compile(lcc);
  const int nu = c.cells_u, nv = c.cells_v;
  const int grid_edges = nu * (nv + 1) + nv * (nu + 1);
  const int boundary_edges = 2 * (nu + nv);
  const auto count = count_by_kind(compiled.model);
  EXPECT_EQ(compiled.model.particle_count(), (nu + 1) * (nv + 1));
  if (c.cells == GridCells::quads) {
    EXPECT_EQ(count[int(SpringKind::structural)], grid_edges);
    EXPECT_EQ(count[int(SpringKind::shear)], 2 * nu * nv);
    EXPECT_EQ(count[int(SpringKind::bending)], grid_edges - boundary_edges);
    EXPECT_EQ(compiled.model.triangles.rows(), 2 * nu * nv);
  } else {
    const int edges = grid_edges + nu * nv;  // plus one diagonal per cell
    EXPECT_EQ(count[int(SpringKind::structural)], edges);
    EXPECT_EQ(count[int(SpringKind::shear)], 0);
    EXPECT_EQ(count[int(SpringKind::bending)], edges - boundary_edges);
    EXPECT_EQ(compiled.model.triangles.rows(), 2 * nu * nv);
  }
  EXPECT_NEAR(compiled.model.mass.sum(), density_kg_per_m2 * area_m2,
              1e-12 * density_kg_per_m2 * area_m2);
}

INSTANTIATE_TEST_SUITE_P(
    Grids, GridComplexTest,
    ::testing::Values(GridCase{1, 1, GridCells::triangles, DiagonalPattern::forward},
                      GridCase{7, 5, GridCells::triangles, DiagonalPattern::forward},
                      GridCase{6, 9, GridCells::triangles, DiagonalPattern::backward},
                      GridCase{16, 16, GridCells::triangles, DiagonalPattern::alternating},
                      GridCase{1, 1, GridCells::quads, DiagonalPattern::forward},
                      GridCase{12, 5, GridCells::quads, DiagonalPattern::forward}));

TEST(BuildClothComplex, MixedMeshHasExpectedMassAndSprings) {
  const IndexedMesh mesh = test::fan_with_quad();
  ClothComplex lcc;
  build_cloth_complex(mesh, density_kg_per_m2, test::all_springs(), lcc);
  EXPECT_TRUE(is_valid_cloth(lcc));

  // six unit equilateral triangles, and a 1 x (0.8 sqrt(3)/2) rectangle outside the rim
  const double area_m2 = 6.0 * std::sqrt(3.0) / 4.0 + 0.8 * std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(complex_total_mass(lcc), density_kg_per_m2 * area_m2, 1e-9);
  EXPECT_NEAR(complex_total_mass(lcc), complex_expected_mass(lcc), 1e-15);

  const CompiledCloth compiled = compile(lcc);
  const auto count = count_by_kind(compiled.model);
  EXPECT_EQ(compiled.model.particle_count(), 9);
  EXPECT_EQ(count[int(SpringKind::structural)], 12 + 3);  // 6 spokes, 6 rim, 3 new quad sides
  EXPECT_EQ(count[int(SpringKind::shear)], 2);
  EXPECT_EQ(count[int(SpringKind::bending)], 6 + 1);  // 6 spokes and the shared rim edge
}

TEST(BuildClothComplex, LeavesOutUnusedVerticesAndKeepsSourceIndices) {
  IndexedMesh mesh;
  mesh.vertices = {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  mesh.faces = {{1, 2, 3}};
  ClothComplex lcc;
  build_cloth_complex(mesh, density_kg_per_m2, test::all_springs(), lcc);
  ASSERT_EQ(lcc.vertex_attributes().size(), 3u);
  std::vector<int> sources;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    sources.push_back(v->info().source_index);
  }
  std::sort(sources.begin(), sources.end());
  EXPECT_EQ(sources, (std::vector<int>{1, 2, 3}));
  EXPECT_TRUE(is_valid_cloth(lcc));
}

TEST(BuildClothComplex, DisabledKindsGiveNoSprings) {
  SpringSettings springs;
  springs.structural = {true, 100.0, 0.0};
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(4, 4, GridCells::quads)), density_kg_per_m2,
                      springs, lcc);
  EXPECT_TRUE(is_valid_cloth(lcc));
  const CompiledCloth compiled = compile(lcc);
  for (SpringKind k : compiled.model.kind) EXPECT_EQ(k, SpringKind::structural);
}

TEST(BuildClothComplex, RejectsInvalidMeshWithMeshError) {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 1}};
  mesh.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // edge (0,1) in three faces
  ClothComplex lcc;
  EXPECT_THROW(build_cloth_complex(mesh, density_kg_per_m2, test::all_springs(), lcc), MeshError);
}

}  // namespace
}  // namespace tissu
