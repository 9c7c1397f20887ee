#include "topology/tear.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <numeric>

#include "cloth_test_support.hpp"
#include "solver/pd/particle_coloring.hpp"
#include "topology/coarsen.hpp"
#include "topology/compile.hpp"
#include "topology/refine.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;

/// 1 m x 1 m in the x-z plane from the origin, 10 x 10 cells of 0.1 m.
class TearTest : public ::testing::TestWithParam<GridCells> {
 protected:
  void SetUp() override {
    options.width = options.height = 1.0;
    options.cells_u = options.cells_v = 10;
    options.cells = GetParam();
    build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
  }

  void expect_valid_and_mass_conserved() {
    test::expect_valid_with_mass(lcc, density_kg_per_m2 * options.width * options.height);
    EXPECT_NO_THROW(compile(lcc));  // every particle on a face, every spring well formed
  }

  /// The dart from the particle at rest position `from` to the one at `to`, with a face on both
  /// sides (x, z in metres).
  Dart_handle interior_dart(double from_x, double from_z, double to_x, double to_z) {
    auto at = [](Dart_handle d, ClothComplex& c, double x, double z) {
      const Point3& r = c.vertex_attribute(d)->info().rest_position;
      return std::abs(r.x() - x) < 1e-9 && std::abs(r.z() - z) < 1e-9;
    };
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      if (!lcc.is_free<2>(d) && at(d, lcc, from_x, from_z) && at(lcc.next(d), lcc, to_x, to_z))
        return d;
    }
    ADD_FAILURE() << "no interior edge from (" << from_x << ", " << from_z << ") to (" << to_x
                  << ", " << to_z << ")";
    return lcc.darts().begin();
  }

  /// Stretches the sheet by `factor` along z (the rest shape stays).
  void stretch_along_z(double factor) {
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      const Point3& p = v->point();
      v->point() = Point3(p.x(), p.y(), factor * p.z());
    }
  }

  GridOptions options;
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
};

TEST_P(TearTest, AnInteriorEdgeTearsIntoASlitWithoutNewParticles) {
  const std::size_t particles = lcc.vertex_attributes().size();
  const int border = count_boundary_edges(lcc);
  const Dart_handle edge = interior_dart(0.4, 0.5, 0.5, 0.5);
  const Dart_handle other = lcc.opposite<2>(edge);
  const TearReport report = tear_edge(lcc, edge, springs);
  // the two lips are two border edges now, each with springs of its own
  EXPECT_NE(lcc.attribute<1>(edge), lcc.attribute<1>(other));
  EXPECT_EQ(lcc.info<1>(other).bending.slot, SpringSlot::absent);
  EXPECT_EQ(report.tears, 1);
  EXPECT_EQ(report.new_particles, 0);
  EXPECT_EQ(lcc.vertex_attributes().size(), particles);
  EXPECT_EQ(count_boundary_edges(lcc), border + 2);
  EXPECT_EQ(count_pieces(lcc), 1);
  EXPECT_EQ(lcc.info<1>(edge).bending.slot, SpringSlot::absent);
  EXPECT_TRUE(lcc.vertex_attribute(edge)->info().on_crack);
  EXPECT_THROW(tear_edge(lcc, edge, springs), std::invalid_argument);
  expect_valid_and_mass_conserved();
}

TEST_P(TearTest, ATearReachingTheBorderSplitsParticlesAndKeepsMomentum) {
  // give every particle its own velocity, then tear from the border at x = 0 inwards
  int k = 0;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v, ++k) {
    v->info().velocity = Vector3(std::sin(k), std::cos(3.0 * k), 0.1 * k);
  }
  const Eigen::Vector3d momentum_before = test::complex_momentum(lcc);
  const std::size_t particles = lcc.vertex_attributes().size();
  tear_edge(lcc, interior_dart(0.0, 0.5, 0.1, 0.5), springs);
  EXPECT_EQ(lcc.vertex_attributes().size(), particles + 1);  // the border vertex split
  const TearReport second = tear_edge(lcc, interior_dart(0.1, 0.5, 0.2, 0.5), springs);
  EXPECT_EQ(second.new_particles, 1);  // the slit's tip split off the border
  EXPECT_LT((test::complex_momentum(lcc) - momentum_before).norm(), 1e-12 * momentum_before.norm());
  // copies sit where the original was, with its velocity
  std::map<std::pair<double, double>, std::vector<Vertex_handle>> by_rest;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    by_rest[{v->info().rest_position.x(), v->info().rest_position.z()}].push_back(v);
  }
  int copies = 0;
  for (const auto& [rest, vertices] : by_rest) {
    if (vertices.size() < 2) continue;
    ++copies;
    EXPECT_EQ(vertices[0]->point(), vertices[1]->point());
    EXPECT_EQ(vertices[0]->info().velocity, vertices[1]->info().velocity);
    EXPECT_GT(vertices[0]->info().mass, 0.0);
  }
  EXPECT_EQ(copies, 2);
  expect_valid_and_mass_conserved();
}

/// The piece of each particle of the compiled cloth, by flooding its triangles.
std::vector<int> piece_of_particles(const SpringModel& model) {
  std::vector<int> parent(model.particle_count());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int t = 0; t < model.triangles.rows(); ++t) {
    parent[root(model.triangles(t, 1))] = root(model.triangles(t, 0));
    parent[root(model.triangles(t, 2))] = root(model.triangles(t, 0));
  }
  std::vector<int> piece(model.particle_count());
  for (int i = 0; i < model.particle_count(); ++i) piece[i] = root(i);
  return piece;
}

TEST_P(TearTest, ACutAcrossTheSheetGivesTwoPiecesWhoseMassesAddUp) {
  const TearReport report = cut_along(lcc, {{-0.05, 0.0, 0.52}, {1.05, 0.0, 0.48}}, springs);
  EXPECT_EQ(report.tears, 10);  // along the grid line z = 0.5
  EXPECT_EQ(report.new_particles, 11);
  EXPECT_EQ(count_pieces(lcc), 2);
  expect_valid_and_mass_conserved();

  const CompiledCloth cloth = compile(lcc);
  const std::vector<int> piece = piece_of_particles(cloth.model);
  for (int s = 0; s < cloth.model.spring_count(); ++s) {
    EXPECT_EQ(piece[cloth.model.springs(s, 0)], piece[cloth.model.springs(s, 1)])
        << "spring " << s << " joins two pieces";
  }
  // each half weighs density x its own area
  double below_kg = 0.0, above_kg = 0.0;
  const int below = piece[cloth.particle_vertices.front()->info().index_at_last_compile];
  for (Vertex_handle v : cloth.particle_vertices) {
    (piece[v->info().index_at_last_compile] == below ? below_kg : above_kg) += v->info().mass;
  }
  EXPECT_NEAR(below_kg, 0.5 * density_kg_per_m2, 1e-14);
  EXPECT_NEAR(above_kg, 0.5 * density_kg_per_m2, 1e-14);
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d)) {
      EXPECT_EQ(lcc.info<1>(d).bending.slot, SpringSlot::absent);
    }
  }
}

TEST_P(TearTest, ASheetBelowTheThresholdNeverTears) {
  stretch_along_z(1.19);
  TearingOptions tearing;
  tearing.strain_threshold = 0.2;
  EXPECT_EQ(tear(lcc, tearing, 100000, springs).tears, 0);
  EXPECT_EQ(count_pieces(lcc), 1);
}

TEST_P(TearTest, AStretchedSheetTearsAcrossTheStretchAtItsWeakLine) {
  stretch_along_z(1.3);
  TearingOptions tearing;
  tearing.strain_threshold = 0.5;  // the sheet as a whole holds
  tearing.max_tears_per_step = 1000;
  WeakRegion line;
  line.points_m = {{-1.0, 0.0, 0.45}, {2.0, 0.0, 0.45}};
  line.width_m = 0.02;  // holds the midpoints of the edges of the cell row 0.4 < z < 0.5 only
  line.factor = 0.5;
  tearing.weak_regions.push_back(line);
  const TearReport report = tear(lcc, tearing, 100000, springs);
  EXPECT_GE(report.tears, 10);
  EXPECT_GE(count_pieces(lcc), 2);
  expect_valid_and_mass_conserved();
  // the crack runs across the stretch, along the weak row's edges
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (!lcc.is_free<2>(d) || !lcc.vertex_attribute(d)->info().on_crack) continue;
    const Point3& a = lcc.vertex_attribute(d)->info().rest_position;
    const Point3& b = lcc.vertex_attribute(lcc.next(d))->info().rest_position;
    if (a.x() == b.x() && (a.x() == 0.0 || a.x() == 1.0)) continue;  // the sheet's own sides
    EXPECT_NEAR(a.z(), b.z(), 1e-9) << "torn edge not across the stretch";
    EXPECT_NEAR(a.z(), 0.45, 0.05 + 1e-9) << "torn edge away from the weak line";
  }
}

/// The number of compiled triangles of the smallest piece of cloth.
int smallest_piece_triangles(ClothComplex& lcc) {
  const CompiledCloth cloth = compile(lcc);
  const std::vector<int> piece = piece_of_particles(cloth.model);
  std::map<int, int> triangles;
  for (int t = 0; t < cloth.model.triangles.rows(); ++t)
    ++triangles[piece[cloth.model.triangles(t, 0)]];
  int smallest = std::numeric_limits<int>::max();
  for (const auto& [root, count] : triangles) smallest = std::min(smallest, count);
  return smallest;
}

TEST_P(TearTest, TearingShedsNoPieceSmallerThanAsked) {
  auto shred = [&](int min_piece_faces) {
    lcc.clear();
    build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      const Point3& p = v->point();
      v->point() = Point3(1.6 * p.x(), p.y(), 1.6 * p.z());  // stretched 60 % both ways
    }
    TearingOptions tearing;
    tearing.strain_threshold = 0.2;
    tearing.max_tears_per_step = 1000;
    tearing.min_piece_faces = min_piece_faces;
    for (int pass = 0; pass < 10; ++pass) tear(lcc, tearing, 100000, springs);
    expect_valid_and_mass_conserved();
    return smallest_piece_triangles(lcc);
  };
  EXPECT_LT(shred(1), 8);  // shreds without the guard
  EXPECT_GE(shred(8), 8);
}

TEST_P(TearTest, TheTearCountPerPassIsCapped) {
  stretch_along_z(2.0);
  TearingOptions tearing;
  tearing.strain_threshold = 0.1;
  tearing.max_tears_per_step = 3;
  EXPECT_EQ(tear(lcc, tearing, 100000, springs).tears, 3);
  expect_valid_and_mass_conserved();
}

INSTANTIATE_TEST_SUITE_P(TrianglesAndQuads, TearTest,
                         ::testing::Values(GridCells::triangles, GridCells::quads));

class CrackTipTest : public TearTest {};

TEST_P(CrackTipTest, CrackTipsAreRefinedAndCrackLipsAreNotCoarsened) {
  stretch_along_z(1.3);
  TearingOptions tearing;
  tearing.strain_threshold = 0.2;
  tearing.max_tears_per_step = 2;
  tearing.tip_min_edge_length_m = 0.02;
  TearReport report = tear(lcc, tearing, 100000, springs);
  EXPECT_EQ(report.tears, 2);
  EXPECT_GT(report.tip_refinements, 0);
  expect_valid_and_mass_conserved();
  // tear again, now among the refined cells, then coarsen everything that is calm
  report = tear(lcc, tearing, 100000, springs);
  EXPECT_EQ(report.tears, 2);
  auto crack_particles = [&] {
    int n = 0;
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      n += v->info().on_crack;
    }
    return n;
  };
  const int on_crack = crack_particles();
  RefinementOptions calm;
  calm.strain_threshold = 10.0;
  EXPECT_GT(coarsen(lcc, calm, 0.5, springs).merges, 0);
  EXPECT_EQ(crack_particles(), on_crack);
  expect_valid_and_mass_conserved();
}

TEST_P(CrackTipTest, TheCrackRunsAcrossTheStretchNotAlongTheGridLines) {
  // backward diagonals run along (1, -1); stretch the sheet by 40 % along (1, 1) / sqrt 2
  options.diagonal = DiagonalPattern::backward;
  lcc.clear();
  build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
  const Eigen::Vector3d along = Eigen::Vector3d(1, 0, 1).normalized();
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Eigen::Vector3d x = to_eigen(v->point());
    v->point() = to_point(x + 0.4 * x.dot(along) * along);
  }
  TearingOptions tearing;
  tearing.strain_threshold = 0.2;  // grid lines stretch by 21.7 %, the diagonals not at all
  tearing.max_tears_per_step = 6;
  EXPECT_EQ(tear(lcc, tearing, 100000, springs).tears, 6);
  expect_valid_and_mass_conserved();
  int torn = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (!lcc.is_free<2>(d) || !lcc.vertex_attribute(d)->info().on_crack) continue;
    const Point3& a = lcc.vertex_attribute(d)->info().rest_position;
    const Point3& b = lcc.vertex_attribute(lcc.next(d))->info().rest_position;
    const Eigen::Vector3d edge(b.x() - a.x(), 0.0, b.z() - a.z());
    if (a.x() == b.x() && (a.x() == 0.0 || a.x() == 1.0)) continue;  // the sheet's own sides
    if (a.z() == b.z() && (a.z() == 0.0 || a.z() == 1.0)) continue;
    ++torn;
    EXPECT_NEAR(std::abs(edge.normalized().dot(along)), 0.0, 1e-9) << "torn edge not across";
  }
  EXPECT_EQ(torn, 2 * 6);  // both lips of each torn edge
}

TEST_P(CrackTipTest, TheParticleColoringStaysValidAfterRefinementAndTearing) {
  stretch_along_z(1.3);
  RefinementOptions refinement;
  refinement.strain_threshold = 0.1;
  refinement.min_edge_length_m = 0.02;
  EXPECT_GT(refine(lcc, refinement, springs).splits, 0);
  TearingOptions tearing;
  tearing.strain_threshold = 0.2;
  tearing.max_tears_per_step = 10;
  tearing.tip_min_edge_length_m = 0.01;
  EXPECT_EQ(tear(lcc, tearing, 100000, springs).tears, 10);
  const CompiledCloth cloth = compile(lcc);
  EXPECT_TRUE(is_valid_coloring(cloth.model, color_particles(cloth.model)));
}

INSTANTIATE_TEST_SUITE_P(Triangles, CrackTipTest, ::testing::Values(GridCells::triangles));

}  // namespace
}  // namespace tissu
