#include <gtest/gtest.h>

#include <random>
#include <set>

#include "cloth_test_support.hpp"
#include "topology/collapse_vertex.hpp"
#include "topology/complex_navigation.hpp"
#include "topology/flip_edge.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/split_edge.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.3;

double total_rest_area_m2(const ClothComplex& lcc) {
  double area = 0.0;
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    area += f->info().rest_area;
  }
  return area;
}

/// The source ids of the ends of the edge of `d`, the smaller first.
std::pair<int, int> edge_ids(const ClothComplex& lcc, Dart_const_handle d) {
  const int a = lcc.vertex_attribute(d)->info().source_index;
  const int b = lcc.vertex_attribute(lcc.next(d))->info().source_index;
  return {std::min(a, b), std::max(a, b)};
}

class FlipAndCollapseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    options = test::grid(6, 5, GridCells::triangles);
    test::build_grid_pinned_at_top(options, density_kg_per_m2, springs, lcc);
  }
  double expected_mass_kg() const { return density_kg_per_m2 * options.width * options.height; }
  void expect_invariants(const std::string& when) {
    test::expect_valid_with_mass(lcc, expected_mass_kg(), when);
    EXPECT_NEAR(total_rest_area_m2(lcc), options.width * options.height, 1e-12) << when;
  }
  /// An interior edge both of whose ends are input particles and that may be flipped.
  Dart_handle flippable_input_edge() {
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      if (!flip_refusal(lcc, d)) return d;
    }
    ADD_FAILURE() << "no flippable edge";
    return nullptr;
  }
  /// Gives every free particle a random velocity and every pinned one none.
  void set_random_velocities(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> speed(-1.0, 1.0);
    for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
      v->info().velocity = v->info().pinned ? CGAL::NULL_VECTOR
                                            : Vector3(speed(random), speed(random), speed(random));
    }
  }

  GridOptions options;
  SpringSettings springs = test::all_springs();
  ClothComplex lcc;
};

TEST_F(FlipAndCollapseTest, AFlipJoinsTheFarCornersAndKeepsEveryInvariant) {
  const Dart_handle edge = flippable_input_edge();
  const Vertex_const_handle c = vertex_after_edge(lcc, edge);
  const Vertex_const_handle e = vertex_after_edge(lcc, lcc.opposite<2>(edge));
  const Vertex_const_handle a = lcc.vertex_attribute(edge);
  const Vertex_const_handle b = lcc.vertex_attribute(lcc.next(edge));
  const std::size_t vertices = lcc.vertex_attributes().size();
  const std::size_t faces = lcc.attributes<2>().size();
  const std::size_t edges = lcc.attributes<1>().size();

  const Dart_handle c_to_e = flip_edge(lcc, edge, springs);

  EXPECT_EQ(lcc.vertex_attribute(c_to_e), c);
  EXPECT_EQ(lcc.vertex_attribute(lcc.next(c_to_e)), e);
  EXPECT_FALSE(joined_by_edge(lcc, a, b));
  EXPECT_EQ(lcc.vertex_attributes().size(), vertices);
  EXPECT_EQ(lcc.attributes<2>().size(), faces);
  EXPECT_EQ(lcc.attributes<1>().size(), edges);
  expect_invariants("after a flip");

  // flipping the new edge back restores the old one
  const Dart_handle back = flip_edge(lcc, c_to_e, springs);
  EXPECT_TRUE(joined_by_edge(lcc, a, b));
  EXPECT_FALSE(joined_by_edge(lcc, c, e));
  EXPECT_TRUE((lcc.vertex_attribute(back) == a || lcc.vertex_attribute(back) == b));
  expect_invariants("after flipping back");
}

TEST_F(FlipAndCollapseTest, FlipsThatWouldChangeTheClothAreRefused) {
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d)) {
      EXPECT_EQ(flip_refusal(lcc, d), "the edge is on the border");
      EXPECT_THROW(flip_edge(lcc, d, springs), std::invalid_argument);
      break;
    }
  }
  // the quad (a, e, b, c) with c and e both right of b: not convex
  IndexedMesh dart_shape;
  dart_shape.vertices = {{0, 0, 0}, {1, 0, 0}, {3, 1, 0}, {3, -1, 0}};
  dart_shape.faces = {{0, 1, 2}, {1, 0, 3}};
  ClothComplex concave;
  build_cloth_complex(dart_shape, density_kg_per_m2, springs, concave);
  // the same pair folded out of its plane in material coordinates
  IndexedMesh folded = dart_shape;
  folded.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.3}};
  ClothComplex curved;
  build_cloth_complex(folded, density_kg_per_m2, springs, curved);
  // a closed tetrahedron: every pair of corners is already joined
  IndexedMesh tetrahedron;
  tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetrahedron.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  ClothComplex closed;
  build_cloth_complex(tetrahedron, density_kg_per_m2, springs, closed);
  const auto interior_refusal = [](const ClothComplex& cloth) {
    for (auto d = cloth.darts().begin(); d != cloth.darts().end(); ++d) {
      if (!cloth.is_free<2>(d)) return flip_refusal(cloth, d);
    }
    return std::optional<std::string>("no interior edge");
  };
  EXPECT_EQ(interior_refusal(concave), "its quad is not planar and convex in material coordinates");
  EXPECT_EQ(interior_refusal(curved), "its quad is not planar and convex in material coordinates");
  EXPECT_EQ(interior_refusal(closed), "its far corners are already joined");
  // the flat convex pair flips
  IndexedMesh kite = dart_shape;
  kite.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
  ClothComplex convex;
  build_cloth_complex(kite, density_kg_per_m2, springs, convex);
  EXPECT_EQ(interior_refusal(convex), std::nullopt);
  // the same pair with its faces' UVs apart at the shared edge
  kite.face_uvs = {{{0, 0}, {1, 0}, {0.5, 1}}, {{1, 0}, {5, 5}, {0.5, -1}}};
  ClothComplex seam;
  build_cloth_complex(kite, density_kg_per_m2, springs, seam);
  EXPECT_EQ(interior_refusal(seam), "it is a UV seam");
  // nor may the middle of a seam's edge be collapsed along it
  for (auto d = seam.darts().begin(); d != seam.darts().end(); ++d) {
    if (seam.is_free<2>(d)) continue;
    const Dart_handle from_middle = split_edge(seam, d, springs);
    EXPECT_EQ(collapse_refusal(seam, seam.vertex_attribute(from_middle),
                               seam.vertex_attribute(seam.next(from_middle))),
              "an edge at it is a UV seam");
    break;
  }
}

TEST_F(FlipAndCollapseTest, ACollapseUndoesASplitAndKeepsTheFreeMomentum) {
  const std::size_t vertices = lcc.vertex_attributes().size();
  const std::size_t faces = lcc.attributes<2>().size();
  const Dart_handle interior = flippable_input_edge();
  const std::pair<int, int> ends = edge_ids(lcc, interior);
  const Dart_handle from_middle = split_edge(lcc, interior, springs);
  const Vertex_handle middle = lcc.vertex_attribute(from_middle);
  const Vertex_handle end = lcc.vertex_attribute(lcc.next(from_middle));
  set_random_velocities(5);
  const Eigen::Vector3d momentum = test::complex_momentum(lcc);

  ASSERT_EQ(collapse_refusal(lcc, middle, end), std::nullopt);
  collapse_vertex(lcc, middle, end, springs);

  EXPECT_EQ(lcc.vertex_attributes().size(), vertices);
  EXPECT_EQ(lcc.attributes<2>().size(), faces);
  expect_invariants("after collapsing a split's middle");
  EXPECT_LT((test::complex_momentum(lcc) - momentum).norm(), 1e-14);
  // the fan from the kept end over the split's four halves is the two old triangles again
  bool restored = false;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d)
    restored |= edge_ids(lcc, d) == ends;
  EXPECT_TRUE(restored);
}

TEST_F(FlipAndCollapseTest, CollapsesThatWouldChangeTheClothAreRefused) {
  // an input particle
  const Vertex_handle input = lcc.vertex_attributes().begin();
  const Dart_handle out = darts_leaving(lcc, input).front();
  EXPECT_EQ(collapse_refusal(lcc, input, lcc.vertex_attribute(lcc.next(out))),
            "it is a particle of the input mesh");
  // a middle on the bottom border may slide along it, not into the cloth
  Dart_handle bottom = nullptr;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.is_free<2>(d) && edge_ids(lcc, d) == std::pair<int, int>{1, 2}) bottom = d;
  }
  ASSERT_NE(bottom, nullptr);
  const Dart_handle from_middle = split_edge(lcc, bottom, springs);
  const Vertex_handle middle = lcc.vertex_attribute(from_middle);
  int along = 0, inwards = 0;
  for (Dart_handle d : darts_leaving(lcc, middle)) {
    for (Vertex_handle w :
         {lcc.vertex_attribute(lcc.next(d)), lcc.vertex_attribute(lcc.previous(d))}) {
      const bool on_border = w->info().source_index == 1 || w->info().source_index == 2;
      const auto refusal = collapse_refusal(lcc, middle, w);
      if (on_border) {
        EXPECT_EQ(refusal, std::nullopt);
        ++along;
      } else {
        EXPECT_EQ(refusal, "it has too few faces, or would leave the border towards the inside");
        ++inwards;
      }
    }
  }
  EXPECT_GT(along, 0);
  EXPECT_GT(inwards, 0);
}

TEST_F(FlipAndCollapseTest, EveryEditOfARandomSequenceKeepsMassAreaMomentumAndValidity) {
  std::mt19937 random(17);
  set_random_velocities(3);
  int flips = 0, collapses = 0, splits = 0;
  for (int step = 0; step < 300; ++step) {
    std::vector<Dart_handle> darts;
    for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) darts.push_back(d);
    const Dart_handle d = darts[random() % darts.size()];
    const Eigen::Vector3d momentum = test::complex_momentum(lcc);
    const Vertex_handle v = lcc.vertex_attribute(d);
    const Vertex_handle w = lcc.vertex_attribute(lcc.next(d));
    std::string edit;
    if (random() % 3 == 0 && lcc.vertex_attributes().size() < 200) {
      split_edge(lcc, d, springs);
      edit = "split";
      ++splits;
    } else if (!flip_refusal(lcc, d) && random() % 2 == 0) {
      flip_edge(lcc, d, springs);
      edit = "flip";
      ++flips;
    } else if (!collapse_refusal(lcc, v, w)) {
      collapse_vertex(lcc, v, w, springs);
      edit = "collapse";
      ++collapses;
    } else {
      continue;
    }
    const std::string when = edit + " at step " + std::to_string(step);
    expect_invariants(when);
    // pinned particles have no velocity: the free particles' momentum is the whole cloth's
    EXPECT_LT((test::complex_momentum(lcc) - momentum).norm(), 1e-12) << when;
    if (HasFailure()) return;
  }
  EXPECT_GT(flips, 20);
  EXPECT_GT(collapses, 20);
  EXPECT_GT(splits, 20);
}

}  // namespace
}  // namespace tissu
