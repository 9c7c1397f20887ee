// A triangle mesh as an obstacle: distances through CGAL's AABB tree, and a particle resting on it.

#include "topology/mesh_obstacle.hpp"

#include <gtest/gtest.h>

#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"
#include "tests/test_meshes.hpp"

namespace tissu {
namespace {

/// The cube [-1, 1]^3 facing outwards; or, open, its top face only (its last two triangles).
IndexedMesh cube(bool closed = true) {
  IndexedMesh m = test::cube_mesh(Eigen::Vector3d::Zero(), 1.0);
  if (!closed) m.faces = {m.faces[10], m.faces[11]};
  return m;
}

void expect_surface(const SurfaceQuery& s, const Eigen::Vector3d& x, double distance_m,
                    const Eigen::Vector3d& normal) {
  const SurfaceDistance d = s.distance(x);
  EXPECT_NEAR(d.distance_m, distance_m, 1e-12) << "at " << x.transpose();
  EXPECT_TRUE(d.normal.isApprox(normal, 1e-12)) << d.normal.transpose() << " at " << x.transpose();
}

TEST(MeshSurface, AClosedMeshGivesSignedDistancesLikeTheBoxItIs) {
  const auto s = make_mesh_surface(cube());
  expect_surface(*s, {0.2, 0.3, 1.5}, 0.5, Eigen::Vector3d::UnitZ());
  expect_surface(*s, {0.2, -3.0, 0.1}, 2.0, -Eigen::Vector3d::UnitY());
  expect_surface(*s, {2.0, 2.0, 0.0}, std::sqrt(2.0), Eigen::Vector3d(1, 1, 0).normalized());
  expect_surface(*s, {0.1, 0.2, 0.9}, -0.1, Eigen::Vector3d::UnitZ());  // inside, near the top
  EXPECT_EQ(s->triangle_corners().size(), 36u);                         // 6 quads cut in two
}

TEST(MeshSurface, AnOpenMeshIsATwoSidedShell) {
  const auto s = make_mesh_surface(cube(/*closed=*/false));
  expect_surface(*s, {0.0, 0.5, 1.3}, 0.3, Eigen::Vector3d::UnitZ());
  expect_surface(*s, {0.0, 0.5, 0.6}, 0.4, -Eigen::Vector3d::UnitZ());  // below it: still outside
}

TEST(MeshSurface, RefusesAnInvalidMesh) {
  IndexedMesh broken = cube();
  broken.faces.push_back({0, 1, 99});
  EXPECT_THROW(make_mesh_surface(broken), MeshError);
}

TEST(MeshSurface, AParticleDroppedOnAMovedMeshRestsOnTop) {
  Obstacle block;
  block.shape = ObstacleShape::mesh;
  block.surface = make_mesh_surface(cube());
  block.motion.key_times_s = {0.0};
  block.motion.key_offsets_m = {Eigen::Vector3d(0.0, 0.0, -1.0)};  // top face at z = 0
  State state;
  const SpringModel model =
      test::lone_particle(Eigen::Vector3d(0.3, -0.2, 0.5), Eigen::Vector3d::Zero(), state);
  SolverParams params;
  params.time_step = 1.0 / 300.0;
  params.obstacles = {block};
  for (int n = 0; n < 600; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_NEAR(state.x.z(), block.thickness_m, 1e-9);
  EXPECT_NEAR(state.v.norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace tissu
