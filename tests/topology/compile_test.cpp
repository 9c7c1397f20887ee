#include "topology/compile.hpp"

#include <gtest/gtest.h>

#include "cloth_test_support.hpp"
#include "topology/current_mesh.hpp"

namespace tissu {
namespace {

TEST(Compile, RestLengthsMatchTheRestShapeAndBackMapsPointAtTheSprings) {
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(6, 4, GridCells::quads)), 0.2, test::all_springs(),
                      lcc);
  const CompiledCloth c = compile(lcc);
  const SpringModel& m = c.model;
  ASSERT_EQ(c.spring_darts.size(), std::size_t(m.spring_count()));
  ASSERT_EQ(c.particle_vertices.size(), std::size_t(m.particle_count()));
  for (int s = 0; s < m.spring_count(); ++s) {
    const double length_m =
        (c.state.x.segment<3>(3 * m.springs(s, 0)) - c.state.x.segment<3>(3 * m.springs(s, 1)))
            .norm();
    EXPECT_NEAR(length_m, m.rest_length[s], 1e-12) << "spring " << s;
    EXPECT_GT(m.rest_length[s], 0.0);
    EXPECT_NE(m.springs(s, 0), m.springs(s, 1));
    // the back-map's dart touches the spring's first particle
    const Dart_handle d = c.spring_darts[s];
    const int origin = lcc.vertex_attribute(d)->info().index_at_last_compile;
    const int after_edge =
        lcc.vertex_attribute(lcc.next(lcc.next(d)))->info().index_at_last_compile;
    EXPECT_TRUE(origin == m.springs(s, 0) || after_edge == m.springs(s, 0)) << "spring " << s;
  }
  for (int i = 0; i < m.particle_count(); ++i) {
    EXPECT_EQ(c.particle_vertices[i]->info().index_at_last_compile, i);
    EXPECT_DOUBLE_EQ(m.mass[i], c.particle_vertices[i]->info().mass);
  }
}

TEST(Compile, WriteBackThenRecompileRoundTripsPositionsAndVelocities) {
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(5, 5, GridCells::triangles)), 0.2,
                      test::all_springs(), lcc);
  CompiledCloth c = compile(lcc);
  State moved = c.state;
  for (Eigen::Index k = 0; k < moved.x.size(); ++k) {
    moved.x[k] += 0.01 * std::sin(double(k));
    moved.v[k] = 0.1 * std::cos(double(k));
  }
  write_back(c, moved, lcc);
  const CompiledCloth again = compile(lcc);
  EXPECT_EQ(again.state.x, moved.x);
  EXPECT_EQ(again.state.v, moved.v);
  // rest data is untouched by motion
  EXPECT_EQ(again.model.rest_length, c.model.rest_length);
  EXPECT_EQ(again.model.mass, c.model.mass);
}

TEST(CurrentMesh, KeepsQuadsAndUsesParticleNumbering) {
  ClothComplex lcc;
  build_cloth_complex(make_grid_mesh(test::grid(3, 2, GridCells::quads)), 0.2, test::all_springs(),
                      lcc);
  const CompiledCloth c = compile(lcc);
  const IndexedMesh mesh = current_mesh(lcc);
  ASSERT_EQ(mesh.vertices.size(), std::size_t(c.model.particle_count()));
  ASSERT_EQ(mesh.faces.size(), 6u);
  for (const auto& face : mesh.faces) EXPECT_EQ(face.size(), 4u);
  for (int i = 0; i < c.model.particle_count(); ++i) {
    EXPECT_EQ(mesh.vertices[i], Eigen::Vector3d(c.state.x.segment<3>(3 * i)));
  }
}

}  // namespace
}  // namespace tissu
