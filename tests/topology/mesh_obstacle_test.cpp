// A triangle mesh as an obstacle: distances through CGAL's AABB tree, and a particle resting on it.

#include "topology/mesh_obstacle.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <random>

#include "solver/collision/primitive_distance.hpp"
#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"
#include "tests/test_meshes.hpp"
#include "topology/winding_number.hpp"

namespace tissu {
namespace {

/// The cube [-1, 1]^3 facing outwards; or, open, its top face only (its last two triangles).
IndexedMesh cube(bool closed = true) {
  IndexedMesh m = test::cube_mesh(Eigen::Vector3d::Zero(), 1.0);
  if (!closed) m.faces = {m.faces[10], m.faces[11]};
  return m;
}

/// The nearest distance from x to any triangle of `mesh` (m), by brute force.
double unsigned_distance_m(const IndexedMesh& mesh, const Eigen::Vector3d& x) {
  double best = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& f : mesh.faces) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d& a = mesh.vertices[f[0]];
      const Eigen::Vector3d& b = mesh.vertices[f[k]];
      const Eigen::Vector3d& c = mesh.vertices[f[k + 1]];
      const Eigen::Vector3d w = nearest_on_triangle(x, a, b, c);
      best = std::min(best, (x - (w[0] * a + w[1] * b + w[2] * c)).norm());
    }
  }
  return best;
}

/// A thin square pyramid, closed, facing outwards: base [-0.1, 0.1]^2 at z = 0, apex (0, 0, 1).
IndexedMesh pyramid() {
  IndexedMesh m;
  m.vertices = {{-0.1, -0.1, 0}, {0.1, -0.1, 0}, {0.1, 0.1, 0}, {-0.1, 0.1, 0}, {0, 0, 1}};
  m.faces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return m;
}

/// Whether x is inside the pyramid: below each of its face planes.
bool inside_pyramid(const Eigen::Vector3d& x) {
  const IndexedMesh m = pyramid();
  for (const std::vector<int>& f : m.faces) {
    const Eigen::Vector3d& a = m.vertices[f[0]];
    const Eigen::Vector3d n = (m.vertices[f[1]] - a).cross(m.vertices[f[2]] - a);
    if (n.dot(x - a) >= 0.0) return false;
  }
  return true;
}

/// A closed prism of length 1 along y over the concave pentagon (0, 0) (2, 0) (2, 2) (1, 1)
/// (0, 2) in x, z: a block with a V notch cut into its top. The pentagon is star-shaped from its
/// first corner, so fans from it triangulate the ends; one of their triangles, (0, 0) (2, 2)
/// (1, 1), has no area, and the surface must stay closed without it.
const std::vector<Eigen::Vector2d> notch_outline = {{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
IndexedMesh notched_block() {
  IndexedMesh m;
  const int n = static_cast<int>(notch_outline.size());
  for (double y : {0.0, 1.0}) {
    for (const Eigen::Vector2d& p : notch_outline) m.vertices.emplace_back(p.x(), y, p.y());
  }
  // the outline runs counter-clockwise seen from -y: the y = 0 end faces -y as listed
  std::vector<int> near_end, far_end{n};  // both fans start at the corner (0, 0)
  for (int i = 0; i < n; ++i) near_end.push_back(i);
  for (int i = n - 1; i > 0; --i) far_end.push_back(n + i);
  m.faces = {near_end, far_end};
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.faces.push_back({i, n + i, n + j, j});
  }
  return m;
}

/// Whether x is inside the notched block (crossing number in x, z).
bool inside_notched_block(const Eigen::Vector3d& x) {
  if (x.y() <= 0.0 || x.y() >= 1.0) return false;
  bool inside = false;
  const int n = static_cast<int>(notch_outline.size());
  for (int i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = notch_outline[i];
    const Eigen::Vector2d& b = notch_outline[j];
    if ((a.y() > x.z()) != (b.y() > x.z()) &&
        x.x() < (b.x() - a.x()) * (x.z() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

/// Signed distances and normals of `mesh`'s surface at every point of a lattice over `box`
/// match the brute-force distance with the analytic side.
template <class Inside>
void expect_signed_distances(const IndexedMesh& mesh, const Eigen::AlignedBox3d& box,
                             Inside inside) {
  const auto surface = make_mesh_surface(mesh);
  constexpr int n = 13;
  int checked = 0, ruled_out = 0, beyond_box = 0;
  Eigen::AlignedBox3d mesh_box;
  for (const Eigen::Vector3d& v : mesh.vertices) mesh_box.extend(v);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d t(i / (n - 1.0), j / (n - 1.0), k / (n - 1.0));
        const Eigen::Vector3d x = box.min() + t.cwiseProduct(box.sizes());
        const double gap_m = unsigned_distance_m(mesh, x);
        if (gap_m < 1e-9) continue;  // on the surface: either side is right
        const double expected = inside(x) ? -gap_m : gap_m;
        const SurfaceDistance d = surface->distance(x);
        ASSERT_NEAR(d.distance_m, expected, 1e-12) << "at " << x.transpose();
        // the normal leads from x to the surface inside, from the surface to x outside
        const Eigen::Vector3d nearest = x - d.distance_m * d.normal;
        ASSERT_NEAR(unsigned_distance_m(mesh, nearest), 0.0, 1e-12) << "at " << x.transpose();
        // the nearest point alone: the same point, unsigned, the normal from it to x
        const SurfaceDistance n = surface->nearest(x);
        ASSERT_EQ(n.triangle, d.triangle) << "at " << x.transpose();
        ASSERT_EQ(n.barycentric, d.barycentric) << "at " << x.transpose();
        ASSERT_EQ(n.distance_m, std::abs(d.distance_m)) << "at " << x.transpose();
        ASSERT_EQ(n.normal, d.distance_m < 0.0 ? Eigen::Vector3d(-d.normal) : d.normal)
            << "at " << x.transpose();
        // the cheap bound never exceeds the distance, and rules out what lies beyond the box
        const double at_least_m = surface->distance_at_least_m(x);
        ASSERT_LE(at_least_m, gap_m) << "at " << x.transpose();
        ruled_out += at_least_m > 0.0;
        beyond_box += !mesh_box.contains(x);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, n * n * n / 2);
  EXPECT_EQ(ruled_out, beyond_box);
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

TEST(MeshSurface, SignsDistancesRightAroundAPyramidApexAndEdges) {
  expect_signed_distances(pyramid(),
                          {Eigen::Vector3d(-0.3, -0.3, -0.2), Eigen::Vector3d(0.3, 0.3, 1.3)},
                          inside_pyramid);
  // just above the apex and off its axis: the nearest feature is the apex vertex
  const auto s = make_mesh_surface(pyramid());
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.0, 0.0, 1.2), Eigen::Vector3d(0.05, 0.0, 1.2),
                                   Eigen::Vector3d(-0.03, 0.04, 1.01)}) {
    EXPECT_GT(s->distance(x).distance_m, 0.0) << x.transpose();
  }
}

TEST(MeshSurface, SignsDistancesRightAroundCubeCornersAndEdges) {
  expect_signed_distances(cube(), {Eigen::Vector3d(0.4, 0.4, 0.4), Eigen::Vector3d(1.6, 1.6, 1.6)},
                          [](const Eigen::Vector3d& x) { return x.cwiseAbs().maxCoeff() < 1.0; });
  expect_signed_distances(cube(),
                          {Eigen::Vector3d(-1.5, -0.2, 0.5), Eigen::Vector3d(-0.5, 0.2, 1.5)},
                          [](const Eigen::Vector3d& x) { return x.cwiseAbs().maxCoeff() < 1.0; });
}

TEST(MeshSurface, SignsDistancesRightAroundAConcaveNotch) {
  ObstacleMeshReport report;
  make_mesh_surface(notched_block(), &report);
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.degenerate_faces, 0);  // a flat fan triangle does not drop its face
  expect_signed_distances(notched_block(),
                          {Eigen::Vector3d(0.3, -0.3, 0.3), Eigen::Vector3d(1.7, 1.3, 2.3)},
                          inside_notched_block);
}

/// Three cubes: two overlapping, and one touching the first along an edge only, which four faces
/// then share (a non-manifold edge); the first cube's faces are all listed twice, and one face is
/// degenerate.
IndexedMesh cube_soup() {
  IndexedMesh soup = test::with_part(cube(), test::cube_mesh({1.0, 0.0, 0.0}, 1.0));
  // weld the shared edge x = y = 1 onto the first cube's corners 3 (z = -1) and 7 (z = +1)
  const int offset = static_cast<int>(soup.vertices.size());
  soup = test::with_part(soup, test::cube_mesh({2.0, 2.0, 0.0}, 1.0));
  for (std::vector<int>& f : soup.faces) {
    for (int& v : f) {
      if (v == offset + 0) v = 3;
      if (v == offset + 4) v = 7;
    }
  }
  const std::vector<std::vector<int>> first_cube(soup.faces.begin(), soup.faces.begin() + 12);
  soup.faces.insert(soup.faces.end(), first_cube.begin(), first_cube.end());
  soup.faces.push_back({2, 3, 3});  // and one degenerate face
  return soup;
}

TEST(MeshSurface, AcceptsASoupOfPartsThatTouchAndOverlap) {
  const IndexedMesh soup = cube_soup();
  ObstacleMeshReport report;
  const auto s = make_mesh_surface(soup, &report);
  EXPECT_TRUE(report.closed);
  EXPECT_EQ(report.duplicate_faces, 12);
  EXPECT_EQ(report.degenerate_faces, 1);
  EXPECT_EQ(report.triangles, 36);
  // inside both overlapping cubes: the depth is to the nearest face, here the first cube's
  // x = 1 face, which lies inside the second
  EXPECT_NEAR(s->distance({0.5, 0.0, 0.0}).distance_m, -0.5, 1e-12);
  EXPECT_NEAR(s->distance({1.8, 1.9, 0.0}).distance_m, -0.8, 1e-12);  // inside the third
  EXPECT_NEAR(s->distance({0.5, 1.5, 0.0}).distance_m, 0.5, 1e-12);   // in the notch between
  EXPECT_NEAR(s->distance({-1.5, 0.0, 0.0}).distance_m, 0.5, 1e-12);  // outside
}

TEST(MeshSurface, SignsAsTheSolidAnglesDoWhereClosedPartsOverlap) {
  // inside is where the winding number exceeds 1/2, whichever way it is counted: 2 where the
  // first two cubes overlap
  const IndexedMesh soup = cube_soup();
  const auto surface = make_mesh_surface(soup);
  std::vector<Eigen::Vector3d> corners;
  for (const std::vector<int>& f : soup.faces) {
    if (f[1] == f[2]) continue;  // the degenerate face subtends nothing
    for (int v : f) corners.push_back(soup.vertices[v]);
  }
  const WindingNumberTree solid_angles(corners);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1.5, 3.5);
  int inside = 0, twice = 0;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Vector3d x(coordinate(random), coordinate(random), 0.9 * coordinate(random) - 1);
    const double w = solid_angles.exact_winding_number(x);
    ASSERT_EQ(surface->distance(x).distance_m<0.0, w> 0.5) << "at " << x.transpose();
    inside += w > 0.5;
    twice += w > 1.5;
  }
  EXPECT_GT(inside, 400);
  EXPECT_GT(twice, 100);
}

/// The closed box [lo, hi], each face a fan of four triangles around a point of it: `points`
/// where given (one per face at most, in the face's plane), else the face's centre.
IndexedMesh fanned_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const std::vector<Eigen::Vector3d>& points) {
  IndexedMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                            i & 4 ? hi.z() : lo.z());
  }
  // faces -x, +x, -y, +y, -z, +z, corners counter-clockwise seen from outside
  const int rings[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const double plane = face % 2 ? hi[axis] : lo[axis];
    Eigen::Vector3d centre = 0.5 * (lo + hi);
    centre[axis] = plane;
    for (const Eigen::Vector3d& p : points) {
      if (p[axis] == plane) centre = p;
    }
    const int c = static_cast<int>(m.vertices.size());
    m.vertices.push_back(centre);
    for (int k = 0; k < 4; ++k) m.faces.push_back({c, rings[face][k], rings[face][(k + 1) % 4]});
  }
  return m;
}

TEST(MeshSurface, SignsAPointWhoseRaysRunThroughVertices) {
  // A ray through a vertex crosses every face around it: counting them would be wrong, so the
  // next ray is taken. Outside, between two slabs: the shortest ray (+x) leaves the far slab
  // through a vertex, where four faces meet; the next (-x) crosses the near slab cleanly.
  const Eigen::Vector3d between(1.5, 0.5, 0.5);
  const Eigen::Vector3d plus_x = winding_ray_directions()[0];
  ASSERT_EQ(plus_x.x(), 1.0);
  const IndexedMesh slabs =
      test::with_part(fanned_box({0, -2, -2}, {1, 3, 3}, {}),
                      fanned_box({2, -2, -2}, {2.5, 3, 3}, {between + plus_x}));
  EXPECT_NEAR(make_mesh_surface(slabs)->distance(between).distance_m, 0.5, 1e-12);

  // Inside, every ray through a vertex: the solid angles decide.
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  std::vector<Eigen::Vector3d> exits;  // each direction's dominant coordinate is +-1
  for (const Eigen::Vector3d& d : winding_ray_directions()) exits.push_back(centre + 0.5 * d);
  const auto box = make_mesh_surface(fanned_box({0, 0, 0}, {1, 1, 1}, exits));
  EXPECT_NEAR(box->distance(centre).distance_m, -0.5, 1e-12);
  EXPECT_NEAR(box->distance({0.5, 0.5, 0.25}).distance_m, -0.25, 1e-12);
}

TEST(MeshSurface, RefusesWhatCannotBeQueried) {
  IndexedMesh nan = cube();
  nan.vertices[5].y() = std::nan("");
  EXPECT_THROW(
      {
        try {
          make_mesh_surface(nan);
        } catch (const MeshError& e) {
          EXPECT_STREQ(e.what(), "vertex 5 has a non-finite coordinate");
          throw;
        }
      },
      MeshError);
  IndexedMesh huge = cube();
  huge.vertices[2] *= 1e300;  // its squared distances would overflow CGAL's exact fallback
  EXPECT_THROW(
      {
        try {
          make_mesh_surface(huge);
        } catch (const MeshError& e) {
          EXPECT_STREQ(e.what(),
                       "vertex 2 has a coordinate of 1e+300 m; expected at most 1e+06 m from the "
                       "origin");
          throw;
        }
      },
      MeshError);
  EXPECT_THROW(make_mesh_surface(IndexedMesh{cube().vertices, {}, {}}), MeshError);
  IndexedMesh flat = cube();
  flat.faces = {{0, 1, 1}, {0, 0, 0}};
  EXPECT_THROW(make_mesh_surface(flat), MeshError);
  IndexedMesh segment = cube();
  segment.faces.push_back({0, 1});
  EXPECT_THROW(make_mesh_surface(segment), MeshError);
}

/// A 0.6 m sheet released 0.3 m above the top of `mesh`, centred over `centre_xy`: in the first
/// 0.1 s it falls 5 cm, touching nothing, so it must move exactly as it does without the obstacle.
void expect_free_fall_above(const IndexedMesh& mesh, const Eigen::Vector2d& centre_xy) {
  double top_z = -1e300;
  for (const Eigen::Vector3d& v : mesh.vertices) top_z = std::max(top_z, v.z());
  const auto sheet = [&](State& state) {
    SpringModel model = test::grid_model(13, 13, 0.05, 1e-3, 100.0, 0.0, state);
    for (int p = 0; p < model.particle_count(); ++p) {
      state.x.segment<3>(3 * p) +=
          Eigen::Vector3d(centre_xy.x() - 0.3, centre_xy.y() - 0.3, top_z + 0.3);
    }
    return model;
  };
  SolverParams params;
  params.time_step = 1.0 / 30.0;
  Obstacle obstacle;
  obstacle.shape = ObstacleShape::mesh;
  obstacle.surface = make_mesh_surface(mesh);
  State free_state, state;
  const SpringModel free_model = sheet(free_state), model = sheet(state);
  for (int n = 0; n < 3; ++n) ASSERT_EQ(step(free_model, params, free_state), StepStatus::ok);
  params.obstacles = {obstacle};
  for (int n = 0; n < 3; ++n) ASSERT_EQ(step(model, params, state), StepStatus::ok);
  EXPECT_LT((state.x - free_state.x).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((state.v - free_state.v).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(MeshSurface, ClothAboveSharpFeaturesFallsFreelyUntilItTouches) {
  expect_free_fall_above(pyramid(), {0.0, 0.0});  // over the apex
  // over a cube standing on a corner, its diagonal (1, 1, 1) turned to +z
  IndexedMesh corner_up = cube();
  const Eigen::Quaterniond turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::UnitZ());
  for (Eigen::Vector3d& v : corner_up.vertices) v = turn * v;
  expect_free_fall_above(corner_up, {0.0, 0.0});
  expect_free_fall_above(corner_up, {0.4, 0.2});        // over an edge running down from the corner
  expect_free_fall_above(notched_block(), {1.0, 0.5});  // over the notch
}

TEST(MeshSurface, MeasuresABlownUpParticleWithoutOverflowing) {
  // a particle at 1e200 m, finite: its squared distance overflows, so CGAL's search would fail;
  // its distance is taken to a corner, to a relative 1e-12 of the nearest face's
  const auto surface = make_mesh_surface(cube());
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(1e200, 0, 0), Eigen::Vector3d(0, -3e160, 1e150)}) {
    const SurfaceDistance d = surface->distance(x);
    EXPECT_NEAR(d.distance_m / x.stableNorm(), 1.0, 1e-12) << x.transpose();
    EXPECT_NEAR(d.normal.dot(x.stableNormalized()), 1.0, 1e-12) << x.transpose();
  }
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
  block.motion.keys = {
      {0.0, Eigen::Vector3d(0.0, 0.0, -1.0), Eigen::Vector3d::Zero()}};  // top face at z = 0
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

TEST(MeshSurface, ARotatingMeshTurnsItsDistanceField) {
  // the 2 m cube turns 45 degrees about z through its centre in 1 s: its vertical edge along +x
  // comes to x = sqrt(2)
  Obstacle block;
  block.shape = ObstacleShape::mesh;
  block.surface = make_mesh_surface(cube());
  block.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                       {1.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, M_PI / 4)}};
  const Eigen::Vector3d x(1.5, 0.0, 0.0);
  const SurfaceDistance before = surface_distance(block, x, 0.0);
  EXPECT_NEAR(before.distance_m, 0.5, 1e-12);
  const SurfaceDistance after = surface_distance(block, x, 1.0);
  EXPECT_NEAR(after.distance_m, 1.5 - std::sqrt(2.0), 1e-12);  // to the edge, straight out
  EXPECT_TRUE(after.normal.isApprox(Eigen::Vector3d::UnitX(), 1e-9)) << after.normal.transpose();
  // a point that was 0.2 m outside a face is inside the turned cube, 1 - 1.2 / sqrt(2) deep
  EXPECT_NEAR(surface_distance(block, {1.2, 0.0, 0.0}, 1.0).distance_m, 1.2 / std::sqrt(2.0) - 1.0,
              1e-12);
}

TEST(MeshSurface, TheCheapBoundOnAMovedMeshsDistanceHoldsWhereverItIs) {
  // the cube turned and carried: the bound is taken in the mesh's own frame, as the distance
  Obstacle block;
  block.shape = ObstacleShape::mesh;
  block.surface = make_mesh_surface(cube());
  block.motion.keys = {{0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
                       {1.0, Eigen::Vector3d(3.0, -1.0, 0.5), Eigen::Vector3d(0.3, 0.0, M_PI / 4)}};
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-4.0, 6.0);
  int ruled_out = 0;
  for (double time_s : {0.0, 0.4, 1.0}) {
    const ObstaclePlacement placement = place(block, time_s);
    for (int k = 0; k < 500; ++k) {
      const Eigen::Vector3d x(coordinate(random), coordinate(random), coordinate(random));
      const double at_least_m = surface_distance_at_least_m(block, placement, x);
      ASSERT_LE(at_least_m, std::abs(surface_distance(block, placement, x).distance_m))
          << "at " << x.transpose() << ", t = " << time_s << " s";
      ruled_out += at_least_m > 0.0;
    }
  }
  EXPECT_GT(ruled_out, 1000);  // most of the points lie beyond the 2 m cube's box
}

}  // namespace
}  // namespace tissu
