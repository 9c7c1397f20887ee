#pragma once
// Grids and meshes shared by the topology tests.

#include <gtest/gtest.h>

#include <string>

#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/grid_mesh.hpp"
#include "topology/mass_lumping.hpp"
#include "topology/validity.hpp"

namespace tissu::test {

/// Every invariant of validity_problems() holds and the particles weigh `expected_kg` to 1e-12
/// relative; `when` names the moment in failure messages.
inline void expect_valid_with_mass(const ClothComplex& lcc, double expected_kg,
                                   const std::string& when = "") {
  const std::vector<std::string> problems = validity_problems(lcc);
  EXPECT_TRUE(problems.empty()) << when << ": " << problems.front();
  EXPECT_NEAR(complex_total_mass(lcc), expected_kg, 1e-12 * expected_kg) << when;
}

/// Total linear momentum sum m v of the particles (kg m/s).
inline Eigen::Vector3d complex_momentum(const ClothComplex& lcc) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    p += v->info().mass * to_eigen(v->info().velocity);
  }
  return p;
}

inline SpringSettings all_springs() {
  SpringSettings s;
  s.structural = {true, 1000.0, 0.5};
  s.shear = {true, 300.0, 0.2};
  s.bending = {true, 5.0, 0.01};
  return s;
}

inline GridOptions grid(int cells_u, int cells_v, GridCells cells,
                        DiagonalPattern diagonal = DiagonalPattern::alternating) {
  GridOptions o;
  o.width = 1.5;
  o.height = 0.9;
  o.cells_u = cells_u;
  o.cells_v = cells_v;
  o.cells = cells;
  o.diagonal = diagonal;
  o.origin = Eigen::Vector3d(0.2, -0.1, 0.3);
  return o;
}

/// Builds the grid cloth of `options` into `lcc` at `density_kg_per_m2` with `springs`, and pins
/// its top side; returns how many particles are pinned.
inline int build_grid_pinned_at_top(const GridOptions& options, double density_kg_per_m2,
                                    const SpringSettings& springs, ClothComplex& lcc) {
  build_cloth_complex(make_grid_mesh(options), density_kg_per_m2, springs, lcc);
  PinSelector top;
  top.side = Side::top;
  return apply_pins(lcc, {top}, ClothFrame{});
}

/// A hexagonal fan of six triangles around a centre vertex, plus a quad on one side.
inline IndexedMesh fan_with_quad() {
  IndexedMesh m;
  m.vertices.push_back({0, 0, 0});
  for (int k = 0; k < 6; ++k) {
    const double a = k * 3.14159265358979 / 3.0;
    m.vertices.push_back({std::cos(a), 0.0, std::sin(a)});
  }
  for (int k = 0; k < 6; ++k) m.faces.push_back({0, 1 + k, 1 + (k + 1) % 6});
  // quad outside the edge (1, 2), counter-clockwise like its neighbour across that edge
  const Eigen::Vector3d out = (m.vertices[1] + m.vertices[2]) * 0.9;  // 1.8 x the edge midpoint
  m.vertices.push_back(out + (m.vertices[2] - m.vertices[1]) * 0.5);
  m.vertices.push_back(out - (m.vertices[2] - m.vertices[1]) * 0.5);
  m.faces.push_back({2, 1, 8, 7});
  return m;
}

}  // namespace tissu::test
