// An animated obstacle mesh: its surface at any instant between samples, the surface's own
// velocity in contacts and friction, and a fast deforming part that does not pass through a
// particle.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solver/collision/contact_planes.hpp"
#include "solver/collision/obstacle_contacts.hpp"
#include "solver/collision/obstacle_distance_cache.hpp"
#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"
#include "tests/test_meshes.hpp"
#include "topology/mesh_obstacle.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

/// The cube [-1, 1]^3, closed, facing outwards.
IndexedMesh cube() {
  return test::cube_mesh(Eigen::Vector3d::Zero(), 1.0);
}

/// `mesh`'s vertices moved by `f`.
template <class F>
std::vector<Eigen::Vector3d> moved(const IndexedMesh& mesh, F f) {
  std::vector<Eigen::Vector3d> x;
  for (const Eigen::Vector3d& v : mesh.vertices) x.push_back(f(v));
  return x;
}

/// The cube at t = 0, translated by +1 m in x at t = 1 s and scaled by 2 about its centre at
/// t = 2 s.
std::shared_ptr<const SurfaceAnimation> moving_cube() {
  const IndexedMesh c = cube();
  const Eigen::Vector3d dx = Eigen::Vector3d::UnitX();
  MeshSamples samples{
      {0.0, 1.0, 2.0},
      {c.vertices, moved(c, [&](const Eigen::Vector3d& v) { return v + dx; }),
       moved(c, [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(2 * v + dx); })}};
  return make_mesh_animation(c, samples);
}

TEST(MeshAnimation, IsItsSamplesAtTheirTimesLinearBetweenAndHeldOutside) {
  const auto cube = moving_cube();
  const Eigen::Vector3d x(4.0, 0.0, 0.0);
  EXPECT_NEAR(cube->at(0.0)->distance(x).distance_m, 3.0, 1e-12);
  EXPECT_NEAR(cube->at(0.25)->distance(x).distance_m, 2.75, 1e-12);  // its face at x = 1.25
  EXPECT_NEAR(cube->at(1.0)->distance(x).distance_m, 2.0, 1e-12);
  EXPECT_NEAR(cube->at(1.5)->distance(x).distance_m, 1.5, 1e-12);  // half-side 1.5 about x = 1
  EXPECT_NEAR(cube->at(-3.0)->distance(x).distance_m, 3.0, 1e-12);
  EXPECT_NEAR(cube->at(9.0)->distance(x).distance_m, 1.0, 1e-12);
  // inside is still inside: the centre of the grown cube is 2 m from its faces
  EXPECT_NEAR(cube->at(2.0)->distance({1.0, 0.0, 0.0}).distance_m, -2.0, 1e-12);
  // the fastest point: a corner in the growth, sqrt(3) m in 1 s
  EXPECT_NEAR(cube->fastest_speed_m_per_s(), std::sqrt(3.0), 1e-12);
  EXPECT_EQ(cube->at(0.5), cube->at(0.5 + 1e-12));  // built once per instant
}

TEST(MeshSurface, ItsNearestPointIsItsTriangleAtItsBarycentricCoordinates) {
  const auto surface = make_mesh_surface(cube());
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(3, 0.2, -0.4), Eigen::Vector3d(0.3, 0.1, 0.2),
                                   Eigen::Vector3d(2, 2, 2), Eigen::Vector3d(-1.5, 0.3, 1.7)}) {
    const SurfaceDistance d = surface->distance(x);
    ASSERT_GE(d.triangle, 0);
    EXPECT_NEAR(d.barycentric.sum(), 1.0, 1e-12);
    EXPECT_GE(d.barycentric.minCoeff(), -1e-12);
    const Eigen::Vector3d nearest = x - d.distance_m * d.normal;
    EXPECT_LT((point_on(*surface, d.triangle, d.barycentric) - nearest).norm(), 1e-12)
        << x.transpose();
  }
}

TEST(MeshAnimation, RefusesSamplesThatDoNotFitItsMesh) {
  const IndexedMesh c = cube();
  const auto refusal = [&](MeshSamples samples) -> std::string {
    try {
      make_mesh_animation(c, std::move(samples));
    } catch (const MeshError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_THAT(refusal({}), HasSubstr("no samples"));
  EXPECT_THAT(refusal({{0.0, 0.0}, {c.vertices, c.vertices}}),
              HasSubstr("sample 1: time 0.000000 s; expected a finite time after"));
  EXPECT_THAT(refusal({{0.0, 1.0}, {c.vertices, {c.vertices.begin(), c.vertices.end() - 1}}}),
              HasSubstr("sample 1 has 7 vertices; the mesh has 8"));
  std::vector<Eigen::Vector3d> broken = c.vertices;
  broken[3].x() = NAN;
  EXPECT_THAT(refusal({{0.0, 1.0}, {c.vertices, broken}}),
              HasSubstr("sample 1: vertex 3 has a non-finite coordinate"));
  broken[3].x() = -2e6;
  EXPECT_THAT(
      refusal({{0.0, 1.0}, {c.vertices, broken}}),
      HasSubstr("sample 1: vertex 3 has a coordinate of 2e+06 m; expected at most 1e+06 m"));
  // the whole cube flattened onto z = 0: its side triangles lose their area
  EXPECT_THAT(refusal({{0.0, 1.0},
                       {c.vertices, moved(c,
                                          [](const Eigen::Vector3d& v) {
                                            return Eigen::Vector3d(v.x(), v.y(), 0.0);
                                          })}}),
              HasSubstr("sample 1: the triangle of vertices"));
}

/// A square plate [-1, 1]^2 at z = 0, facing up, an open mesh.
IndexedMesh plate() {
  IndexedMesh m;
  m.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(MeshAnimation, FrictionCarriesAParticleAsTheSurfaceStretches) {
  // the plate stretches to twice its length along x in 1 s, about x = 0: the point of it at
  // x = 0.4 m goes to 0.8 m, and a particle resting there with friction goes with it
  const IndexedMesh p = plate();
  Obstacle floor;
  floor.shape = ObstacleShape::mesh;
  floor.static_friction = floor.kinetic_friction = 1.0;
  floor.animation =
      make_mesh_animation(p, {{0.0, 1.0}, {p.vertices, moved(p, [](const Eigen::Vector3d& v) {
                                             return Eigen::Vector3d(2 * v.x(), v.y(), v.z());
                                           })}});
  floor.surface = floor.animation->at(0.0);
  State state;
  const SpringModel model =
      test::lone_particle({0.4, 0.3, floor.thickness_m}, Eigen::Vector3d::Zero(), state);
  SolverParams params;
  params.integrator = Integrator::implicit_euler;
  params.time_step = 1e-3;
  params.obstacles = {floor};
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  // it starts at rest on a surface moving at 0.4 m/s under it and catches up in
  // t_c = 0.4 / (mu g) = 0.041 s, sliding back by 0.4 t_c / 2 = 8.2 mm: it sticks at x = 0.408 m
  // at t_c, the plate's point X = x / (1 + t) = 0.392 m, which is at 2 X = 0.785 m at t = 1 s
  const double stuck_at_m = (0.4 + 0.4 * 0.041 / 2) / 1.041;
  EXPECT_NEAR(state.x.x(), 2 * stuck_at_m, 0.002);
  EXPECT_NEAR(state.x.y(), 0.3, 1e-9);
  EXPECT_NEAR(state.x.z(), floor.thickness_m, 1e-6);
  EXPECT_NEAR(state.v.x(), stuck_at_m, 0.002);  // dx/dt = X

  // without friction the plate slides under it
  floor.static_friction = floor.kinetic_friction = 0.0;
  params.obstacles = {floor};
  const SpringModel still =
      test::lone_particle({0.4, 0.3, floor.thickness_m}, Eigen::Vector3d::Zero(), state);
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(step(still, params, state), StepStatus::ok);
  EXPECT_NEAR(state.x.x(), 0.4, 1e-9);
}

/// Two cubes (half-side 1 m, 5 m apart along x), moved by 1 m along x at t = 1 s and grown by 1.2
/// about the origin at t = 2 s, and also turned and carried by a rigid motion: a mesh obstacle that
/// moves both ways, with room in its box far from its surface.
Obstacle turned_moving_cubes() {
  const IndexedMesh pair = test::with_part(cube(), test::cube_mesh({5.0, 0.0, 0.0}, 1.0));
  const Eigen::Vector3d dx = Eigen::Vector3d::UnitX();
  MeshSamples samples{
      {0.0, 1.0, 2.0},
      {pair.vertices, moved(pair, [&](const Eigen::Vector3d& v) { return v + dx; }),
       moved(pair, [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(1.2 * v + dx); })}};
  Obstacle cube;
  cube.shape = ObstacleShape::mesh;
  cube.animation = make_mesh_animation(pair, samples);
  cube.surface = cube.animation->at(0.0);
  cube.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                      {2.0, Eigen::Vector3d(0.5, -0.3, 0.2), Eigen::Vector3d(0.0, 0.0, 1.2)}};
  return cube;
}

TEST(ObstacleDistanceCache, ItsBoundHoldsForAnyPointAtAnyTime) {
  // d(x, t) >= d_q - |x - x_q| (in the obstacle's frame) - v_max |t - t_q|, inside or outside
  const Obstacle cube = turned_moving_cubes();
  State state;
  const SpringModel model = test::lone_particle(Eigen::Vector3d::Zero(), {0, 0, 0}, state);
  ObstacleDistanceCache cache;
  cache.prepare(model, {cube});
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-3.0, 8.0), time_s(0.0, 2.0), step(-0.5, 0.5);
  int tight = 0;
  for (int i = 0; i < 3000; ++i) {
    const double t_q = time_s(random);
    const Eigen::Vector3d x_q(coordinate(random), coordinate(random), coordinate(random));
    const ObstaclePlacement then = place(cube, t_q);
    cache.record(0, 0, cube, then, t_q, x_q, surface_distance(cube, then, x_q).distance_m);
    const double t = std::clamp(t_q + 0.2 * step(random), 0.0, 2.0);
    const Eigen::Vector3d x = x_q + Eigen::Vector3d(step(random), step(random), step(random));
    const ObstaclePlacement now = place(cube, t);
    const double bound_m = cache.distance_at_least_m(0, 0, cube, now, t, x);
    const double d_m = surface_distance(cube, now, x).distance_m;
    ASSERT_LE(bound_m, d_m) << "from " << x_q.transpose() << " at " << t_q << " s to "
                            << x.transpose() << " at " << t << " s";
    tight += bound_m > d_m - 0.5;
  }
  EXPECT_GT(tight, 1000);  // a bound worth having
  // a new model, or other obstacles, and nothing is known
  State other_state;
  SpringModel other = test::lone_particle(Eigen::Vector3d::Zero(), {0, 0, 0}, other_state);
  finalize_model(other);
  cache.prepare(other, {cube});
  EXPECT_EQ(cache.distance_at_least_m(0, 0, cube, place(cube, 0.0), 0.0, Eigen::Vector3d::Zero()),
            -std::numeric_limits<double>::infinity());
}

TEST(ObstacleDistanceCache, SkipsOnlyQueriesWhoseAnswerItKnows) {
  // particles near and far from the turned, moving, growing cubes, each moved at random every step:
  // the contact planes and the responses are the same with the cache as without, and the cache
  // answers many of the queries
  const Obstacle cube = turned_moving_cubes();
  const std::vector<Obstacle> obstacles{cube};
  const SpringModel model = test::free_particles(400);
  State state;
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  std::mt19937 random(13);
  state.x = Eigen::VectorXd::NullaryExpr(3 * 400, [&] { return coordinate(random); });
  for (int p = 0; p < 400; ++p) state.x[3 * p] = 2.25 * state.x[3 * p] + 2.5;  // x in [-2, 7]
  state.v = Eigen::VectorXd::Zero(3 * 400);
  const double h = 0.02;
  ObstacleDistanceCache cache;
  std::normal_distribution<double> jitter(0.0, 0.02);
  int known_far = 0;
  for (int n = 0; n < 60; ++n) {
    const double time_s = n * h;
    const Eigen::VectorXd start = state.x;
    Eigen::VectorXd first = start;
    for (Eigen::Index i = 0; i < first.size(); ++i) first[i] += jitter(random);
    cache.prepare(model, obstacles);
    for (int p = 0; p < model.particle_count(); ++p) {
      known_far += cache.distance_at_least_m(0, p, cube, place(cube, time_s + h), time_s + h,
                                             first.segment<3>(3 * p)) > 0.05;
    }
    std::vector<ContactPlane> plain, cached;
    find_contact_planes(model, obstacles, 100.0, h, time_s + h, start, first, plain);
    find_contact_planes(model, obstacles, 100.0, h, time_s + h, start, first, cached, &cache);
    ASSERT_EQ(plain.size(), cached.size()) << "step " << n;
    for (std::size_t c = 0; c < plain.size(); ++c) {
      ASSERT_EQ(plain[c].particle, cached[c].particle);
      ASSERT_EQ(plain[c].point, cached[c].point);
      ASSERT_EQ(plain[c].normal, cached[c].normal);
    }
    State without = state, with = state;
    without.x = with.x = first;
    Eigen::Matrix3Xd normals_without, normals_with;
    const int contacts_without =
        resolve_obstacle_contacts(model, obstacles, h, time_s + h, start, without, normals_without);
    const int contacts_with = resolve_obstacle_contacts(model, obstacles, h, time_s + h, start,
                                                        with, normals_with, {}, &cache);
    ASSERT_EQ(contacts_without, contacts_with) << "step " << n;
    ASSERT_EQ(without.x, with.x) << "step " << n;
    ASSERT_EQ(without.v, with.v) << "step " << n;
    state = with;
  }
  EXPECT_GT(known_far, 1000);  // of 24,000 (1,544 when written)
}

TEST(MeshAnimation, AFastLimbDoesNotPassThroughAParticle) {
  // a closed 4 cm thick slab (the cube squeezed along x) that swings at 20 m/s, 0.2 m per step,
  // from x = -0.5 to x = 1.5 in 0.1 s: it jumps over the particle at x = 0 in one step, and must
  // push it ahead instead
  const IndexedMesh c = cube();
  const auto slab_at = [&](double centre_x_m) {
    return moved(c, [&](const Eigen::Vector3d& v) {
      return Eigen::Vector3d(centre_x_m + 0.02 * v.x(), v.y(), v.z());
    });
  };
  Obstacle limb;
  limb.shape = ObstacleShape::mesh;
  limb.animation = make_mesh_animation(c, {{0.0, 0.1}, {slab_at(-0.5), slab_at(1.5)}});
  limb.surface = limb.animation->at(0.0);
  State state;
  const SpringModel model = test::lone_particle({0.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), state);
  SolverParams params;
  params.integrator = Integrator::symplectic_euler;
  params.time_step = 0.01;
  params.environment.gravity.setZero();
  params.obstacles = {limb};
  for (int n = 1; n <= 10; ++n) {
    ASSERT_EQ(step(model, params, state), StepStatus::ok);
    const double front_m = -0.5 + 0.02 + 20.0 * n * params.time_step;
    if (front_m + limb.thickness_m > 0.0) {
      ASSERT_NEAR(state.x.x(), front_m + limb.thickness_m, 1e-9) << "step " << n;
      ASSERT_NEAR(state.v.x(), 20.0, 1e-9) << "step " << n;
    } else {
      ASSERT_EQ(state.x.x(), 0.0) << "step " << n;
    }
  }
}

}  // namespace
}  // namespace tissu
