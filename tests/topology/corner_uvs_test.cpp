// An input mesh's UVs on the darts: set per corner by the builder (seams kept), interpolated by
// every split, kept by tears, given back by coarsening, and read out by current_mesh.

#include "topology/corner_uvs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "cloth_test_support.hpp"
#include "topology/coarsen.hpp"
#include "topology/compile.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/current_mesh.hpp"
#include "topology/refine.hpp"
#include "topology/split_edge.hpp"
#include "topology/tear.hpp"
#include "topology/validity.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.3;
/// x (m) of the grid line i = 3 of test::grid(6, 4, ...): the UV seam
constexpr double seam_x_m = 0.2 + 3 * 0.25;

/// The UV chart of the faces left (x < seam) or right of the seam: two different affine maps of
/// the rest position, so every vertex on the seam has two UVs. Affine, so the midpoint of two
/// corners' UVs is the UV of their midpoint and every corner made by splits is on its chart.
Eigen::Vector2d chart_uv(const Eigen::Vector3d& rest_m, bool right) {
  const double s = (rest_m.x() - 0.2) / 1.5, t = (rest_m.z() - 0.3) / 0.9;
  return right ? Eigen::Vector2d(s + 0.25, 0.5 * t + 0.1) : Eigen::Vector2d(s, t);
}

/// test::grid(6, 4, triangles) with UVs on the two charts, seam along x = seam_x_m.
IndexedMesh seamed_sheet() {
  IndexedMesh mesh = make_grid_mesh(test::grid(6, 4, GridCells::triangles));
  for (const std::vector<int>& face : mesh.faces) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int v : face) centroid += mesh.vertices[v] / static_cast<double>(face.size());
    std::vector<Eigen::Vector2d>& uvs = mesh.face_uvs.emplace_back();
    for (int v : face) uvs.push_back(chart_uv(mesh.vertices[v], centroid.x() > seam_x_m));
  }
  return mesh;
}

/// Whether the face of `d` lies right of the seam (by its rest centroid).
bool face_is_right(const ClothComplex& lcc, Dart_const_handle d) {
  double x = 0.0;
  int corners = 0;
  for (auto c = lcc.darts_of_orbit<1>(d).begin(); c != lcc.darts_of_orbit<1>(d).end(); ++c) {
    x += lcc.vertex_attribute(c)->info().rest_position.x();
    ++corners;
  }
  return x / corners > seam_x_m;
}

/// Every dart has a UV, the one its face's chart gives its origin.
void expect_every_corner_on_its_chart(const ClothComplex& lcc, const std::string& when) {
  ASSERT_TRUE(has_corner_uvs(lcc)) << when;
  int darts = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d, ++darts) {
    ASSERT_TRUE(lcc.info(d).uv.given) << when << ": dart " << darts;
    const Eigen::Vector2d expected =
        chart_uv(to_eigen(lcc.vertex_attribute(d)->info().rest_position), face_is_right(lcc, d));
    EXPECT_LT((corner_uv(lcc, d) - expected).norm(), 1e-12) << when << ": dart " << darts;
  }
}

/// Each dart's UV, keyed by the rest positions of its origin and its end (a directed edge of the
/// rest shape is in one face only, before and after a tear).
std::map<std::array<double, 6>, Eigen::Vector2d> uvs_by_corner(const ClothComplex& lcc) {
  std::map<std::array<double, 6>, Eigen::Vector2d> out;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    const Point3& a = lcc.vertex_attribute(d)->info().rest_position;
    const Point3& b = lcc.vertex_attribute(lcc.next(d))->info().rest_position;
    out[{a.x(), a.y(), a.z(), b.x(), b.y(), b.z()}] = corner_uv(lcc, d);
  }
  return out;
}

class CornerUvsTest : public ::testing::Test {
 protected:
  void SetUp() override { build_cloth_complex(seamed_sheet(), density_kg_per_m2, springs, lcc); }

  double expected_mass_kg() const { return density_kg_per_m2 * 1.5 * 0.9; }

  /// The dart from the particle of grid vertex (i, j) to that of (k, l).
  Dart_handle dart_between(int i, int j, int k, int l) {
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      if (lcc.vertex_attribute(d)->info().source_index == j * 7 + i &&
          lcc.vertex_attribute(lcc.next(d))->info().source_index == l * 7 + k) {
        return d;
      }
    }
    ADD_FAILURE() << "no edge (" << i << ", " << j << ") -> (" << k << ", " << l << ")";
    return lcc.darts().begin();
  }

  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
};

TEST_F(CornerUvsTest, TheBuilderPutsEachCornersUvOnItsDartAndKeepsTheSeam) {
  expect_every_corner_on_its_chart(lcc, "built");
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "built");
  // a vertex on the seam has the UVs of both charts among its darts
  std::set<std::pair<double, double>> seam_uvs;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.vertex_attribute(d)->info().source_index == 2 * 7 + 3) {
      seam_uvs.insert({lcc.info(d).uv.u, lcc.info(d).uv.v});
    }
  }
  EXPECT_EQ(seam_uvs.size(), 2u);
}

TEST_F(CornerUvsTest, AMeshWithoutUvsGivesNoDartOne) {
  build_cloth_complex(make_grid_mesh(test::grid(6, 4, GridCells::triangles)), density_kg_per_m2,
                      springs, lcc);
  EXPECT_FALSE(has_corner_uvs(lcc));
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    EXPECT_FALSE(lcc.info(d).uv.given);
  }
  split_edge(lcc, dart_between(1, 1, 2, 1), springs);  // new darts get none either
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after a split");
  compile(lcc);
  EXPECT_TRUE(current_mesh(lcc).face_uvs.empty());
}

TEST_F(CornerUvsTest, ADartWithoutAUvAmongDartsWithIsInvalid) {
  EXPECT_TRUE(validity_problems(lcc).empty());
  lcc.info(lcc.darts().begin()).uv.given = false;
  const std::vector<std::string> problems = validity_problems(lcc);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems.front(), "1 of 144 darts have no UV, but the others have one");
}

TEST_F(CornerUvsTest, SplittingASeamEdgeGivesTheNewVertexEachFacesMidpointUv) {
  // the vertical edge (3, 1) -> (3, 2) on the seam, with a face of each chart
  const Dart_handle edge = dart_between(3, 1, 3, 2);
  ASSERT_FALSE(lcc.is_free<2>(edge));
  const Dart_handle across = lcc.opposite<2>(edge);  // (3, 2) -> (3, 1), in the other face
  // the midpoint each face should give, from its own corners' UVs
  const Eigen::Vector2d expected_here =
      0.5 * (corner_uv(lcc, edge) + corner_uv(lcc, lcc.next(edge)));
  const Eigen::Vector2d expected_across =
      0.5 * (corner_uv(lcc, across) + corner_uv(lcc, lcc.next(across)));
  ASSERT_NE(expected_here, expected_across);

  const Dart_handle from_m = split_edge(lcc, edge, springs);
  std::set<std::pair<double, double>> uvs_of_m;
  for (Dart_handle d : darts_leaving(lcc, lcc.vertex_attribute(from_m))) {
    const Eigen::Vector2d uv = corner_uv(lcc, d);
    EXPECT_TRUE(uv == expected_here || uv == expected_across) << uv.transpose();
    uvs_of_m.insert({uv.x(), uv.y()});
  }
  EXPECT_EQ(uvs_of_m.size(), 2u);  // the seam runs on through the new vertex
  expect_every_corner_on_its_chart(lcc, "after splitting the seam edge");
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after splitting the seam edge");
}

TEST_F(CornerUvsTest, SplittingABoundaryEdgeInterpolatesItsOneFace) {
  const Dart_handle edge = dart_between(0, 0, 1, 0);
  ASSERT_TRUE(lcc.is_free<2>(edge));
  const Eigen::Vector2d expected = 0.5 * (corner_uv(lcc, edge) + corner_uv(lcc, lcc.next(edge)));
  const Dart_handle from_m = split_edge(lcc, edge, springs);
  for (Dart_handle d : darts_leaving(lcc, lcc.vertex_attribute(from_m))) {
    EXPECT_EQ(corner_uv(lcc, d), expected);
  }
  expect_every_corner_on_its_chart(lcc, "after a boundary split");
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after a boundary split");
}

TEST_F(CornerUvsTest, RefinementPassesKeepEveryCornerOnItsChart) {
  RefinementOptions refinement;
  refinement.max_edge_length_m = 0.1;
  refinement.min_edge_length_m = 0.01;
  const std::size_t particles = lcc.vertex_attributes().size();
  for (int pass = 0; pass < 2; ++pass) {
    refine(lcc, refinement, springs);
    expect_every_corner_on_its_chart(lcc, "after pass " + std::to_string(pass));
    test::expect_valid_with_mass(lcc, expected_mass_kg(), "after pass " + std::to_string(pass));
  }
  EXPECT_GT(lcc.vertex_attributes().size(), 2 * particles);
}

TEST_F(CornerUvsTest, CoarseningGivesBackTheOriginalUvs) {
  const auto original = uvs_by_corner(lcc);
  RefinementOptions refinement;
  refinement.max_edge_length_m = 0.1;
  refinement.min_edge_length_m = 0.01;
  refine(lcc, refinement, springs);
  refine(lcc, refinement, springs);
  ASSERT_GT(uvs_by_corner(lcc).size(), original.size());
  for (int pass = 0; pass < 50; ++pass) {
    if (coarsen(lcc, RefinementOptions{}, 0.5, springs).merges == 0) break;
    test::expect_valid_with_mass(lcc, expected_mass_kg(),
                                 "coarsening pass " + std::to_string(pass));
  }
  const auto restored = uvs_by_corner(lcc);
  ASSERT_EQ(restored.size(), original.size());
  for (const auto& [corner, uv] : original) {
    ASSERT_TRUE(restored.count(corner));
    EXPECT_EQ(restored.at(corner), uv);  // the darts from before the splits, bit for bit
  }
}

TEST_F(CornerUvsTest, ACutKeepsEveryCornersUvOnBothLipsAndOnEachCopyOfASplitParticle) {
  const auto before = uvs_by_corner(lcc);
  const std::size_t particles = lcc.vertex_attributes().size();
  // across the sheet along the grid line j = 2 (z = 0.75), crossing the seam
  const TearReport report = cut_along(lcc, {{0.1, -0.1, 0.76}, {1.8, -0.1, 0.74}}, springs);
  EXPECT_EQ(report.tears, 6);
  EXPECT_EQ(count_pieces(lcc), 2);
  EXPECT_EQ(lcc.vertex_attributes().size(), particles + 7);
  EXPECT_EQ(uvs_by_corner(lcc), before);  // no dart changed its UV
  expect_every_corner_on_its_chart(lcc, "after the cut");
  test::expect_valid_with_mass(lcc, expected_mass_kg(), "after the cut");
  // each copy of the seam particle on the cut keeps its own faces' two UVs, one per chart
  std::map<Vertex_const_handle, std::set<std::pair<double, double>>> uvs_of_seam_copies;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.vertex_attribute(d)->info().source_index == 2 * 7 + 3) {
      uvs_of_seam_copies[lcc.vertex_attribute(d)].insert({lcc.info(d).uv.u, lcc.info(d).uv.v});
    }
  }
  ASSERT_EQ(uvs_of_seam_copies.size(), 2u);
  for (const auto& [copy, uvs] : uvs_of_seam_copies) EXPECT_EQ(uvs.size(), 2u);
}

TEST_F(CornerUvsTest, CurrentMeshGivesEachCornerItsDartsUv) {
  RefinementOptions refinement;
  refinement.max_edge_length_m = 0.2;
  refine(lcc, refinement, springs);
  cut_along(lcc, {{0.1, -0.1, 0.76}, {1.8, -0.1, 0.74}}, springs);
  compile(lcc);
  const IndexedMesh mesh = current_mesh(lcc);
  const std::vector<Eigen::Vector3d> rest_m = rest_positions(lcc);
  ASSERT_EQ(mesh.face_uvs.size(), mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    ASSERT_EQ(mesh.face_uvs[f].size(), mesh.faces[f].size());
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int v : mesh.faces[f]) centroid += rest_m[v] / 3.0;
    for (std::size_t k = 0; k < mesh.faces[f].size(); ++k) {
      const Eigen::Vector2d expected = chart_uv(rest_m[mesh.faces[f][k]], centroid.x() > seam_x_m);
      EXPECT_LT((mesh.face_uvs[f][k] - expected).norm(), 1e-12) << "face " << f << " corner " << k;
    }
  }
}

}  // namespace
}  // namespace tissu
