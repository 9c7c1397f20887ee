// The cloth against itself: pairs found, crossings stopped, sheets kept apart.

#include "solver/collision/self_collision.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <tuple>

#include "solver/collision/collision_pairs.hpp"
#include "solver/collision/continuous_collision.hpp"
#include "solver/step.hpp"
#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

constexpr int side = 12;               // particles per side of each sheet
constexpr double spacing_m = 0.03;     // 0.33 m sheets
constexpr double thickness_m = 0.004;  // kept between the sheets

/// Two sheets, the upper 5 cm above the lower and shifted by a third of a cell, over a floor.
struct StackedSheets {
  StackedSheets() {
    State lower_state, upper_state;
    const SpringModel lower =
        test::grid_model(side, side, spacing_m, 1e-4, 200.0, 0.01, lower_state);
    const SpringModel upper =
        test::grid_model(side, side, spacing_m, 1e-4, 200.0, 0.01, upper_state);
    for (int p = 0; p < side * side; ++p) {
      lower_state.x.segment<3>(3 * p) += Eigen::Vector3d(0.0, 0.0, 0.2);
      upper_state.x.segment<3>(3 * p) += Eigen::Vector3d(0.01, 0.01, 0.25);
    }
    model = test::joined_models(lower, lower_state, upper, upper_state, state);
    params.integrator = Integrator::implicit_euler;
    params.time_step = 1.0 / 300.0;
    params.environment.air_damping = 0.5;
    Obstacle floor;
    params.obstacles = {floor};
    params.self_collision.enabled = true;
    params.self_collision.thickness_m = thickness_m;
  }
  SpringModel model;
  State state;
  SolverParams params;
};

/// For every particle of the upper sheet above a triangle of the lower one (seen from +z), how far
/// above that triangle it is (m); the smallest such gap.
double smallest_gap_above_lower_sheet(const SpringModel& model, const State& state) {
  const int lower_particles = side * side;
  double smallest_m = std::numeric_limits<double>::infinity();
  for (int p = lower_particles; p < model.particle_count(); ++p) {
    const Eigen::Vector3d x = state.x.segment<3>(3 * p);
    for (Eigen::Index t = 0; t < model.triangles.rows() / 2; ++t) {  // the lower sheet's
      const Eigen::Vector3d a = state.x.segment<3>(3 * model.triangles(t, 0));
      const Eigen::Vector3d b = state.x.segment<3>(3 * model.triangles(t, 1));
      const Eigen::Vector3d c = state.x.segment<3>(3 * model.triangles(t, 2));
      // barycentric coordinates of x in the triangle's projection on the xy plane
      Eigen::Matrix2d edges;
      edges << (b - a).head<2>(), (c - a).head<2>();
      const Eigen::Vector2d l = edges.inverse() * (x - a).head<2>();
      if (l.minCoeff() < 0.0 || l.sum() > 1.0) continue;
      const double below_z = a.z() + l[0] * (b.z() - a.z()) + l[1] * (c.z() - a.z());
      smallest_m = std::min(smallest_m, x.z() - below_z);
    }
  }
  return smallest_m;
}

TEST(SelfCollision, TwoStackedSheetsDroppedOnTheFloorDoNotPassThroughEachOther) {
  StackedSheets scene;
  StepWorkspace workspace;
  for (int n = 0; n < 450; ++n) {  // 1.5 s: they land at about 2 m/s, 7 mm per step
    ASSERT_EQ(step(scene.model, scene.params, scene.state, workspace), StepStatus::ok) << n;
    ASSERT_TRUE(workspace.self_collision.resolved) << "step " << n;
  }
  EXPECT_GT(smallest_gap_above_lower_sheet(scene.model, scene.state), 0.5 * thickness_m);

  // without self-collision the upper sheet sinks into the lower one
  StackedSheets through;
  through.params.self_collision.enabled = false;
  for (int n = 0; n < 450; ++n) step(through.model, through.params, through.state, workspace);
  EXPECT_LT(smallest_gap_above_lower_sheet(through.model, through.state), 0.5 * thickness_m);
}

TEST(SelfCollision, AFastSheetDoesNotTunnelThroughAPinnedOne) {
  // the upper sheet hits the lower one, held at its corners, at 6 m/s: 2 cm per step, five times
  // the thickness, so only the continuous test sees the crossing
  StackedSheets scene;
  scene.params.obstacles.clear();
  for (int corner : {0, side - 1, side * (side - 1), side * side - 1})
    scene.model.pinned[corner] = 1;
  finalize_model(scene.model);
  for (int p = side * side; p < scene.model.particle_count(); ++p) scene.state.v[3 * p + 2] = -6.0;
  StepWorkspace workspace;
  int impacts = 0;
  for (int n = 0; n < 60; ++n) {
    ASSERT_EQ(step(scene.model, scene.params, scene.state, workspace), StepStatus::ok) << n;
    ASSERT_TRUE(workspace.self_collision.resolved) << "step " << n;
    impacts += workspace.self_collision.impacts;
  }
  EXPECT_GT(impacts, 0);
  EXPECT_GT(smallest_gap_above_lower_sheet(scene.model, scene.state), 0.0);
}

TEST(SelfCollision, ALayerPushedByAnotherDoesNotEnterTheFloor) {
  // the lower sheet hovers 3 mm above the reach of a thin floor (1 mm), so the floor does not
  // hold it when the upper one hits it at 20 m/s (6.7 cm per step): self-collision alone pushes
  // it through the floor's surface (to 2.2 cm below it before obstacles had the last word)
  StackedSheets scene;
  Obstacle& floor = scene.params.obstacles.front();
  floor.thickness_m = 0.001;
  for (int p = 0; p < scene.model.particle_count(); ++p) {
    scene.state.x[3 * p + 2] += floor.thickness_m + 0.003 - 0.2;
    if (p >= side * side) scene.state.v[3 * p + 2] = -20.0;
  }
  StepWorkspace workspace;
  double lowest_m = std::numeric_limits<double>::infinity();
  int contacts = 0;
  for (int n = 0; n < 30; ++n) {
    ASSERT_EQ(step(scene.model, scene.params, scene.state, workspace), StepStatus::ok) << n;
    contacts += workspace.self_collision.proximities + workspace.self_collision.impacts;
    for (int p = 0; p < scene.model.particle_count(); ++p)
      lowest_m = std::min(lowest_m, scene.state.x[3 * p + 2]);
  }
  EXPECT_GT(contacts, 0) << "the sheets never met: the scene tests nothing";
  EXPECT_GE(lowest_m, 0.0);  // never below the floor's surface
}

TEST(SelfCollision, ANonFiniteStateIsReportedNotSearched) {
  StackedSheets scene;
  scene.state.x[7] = std::numeric_limits<double>::quiet_NaN();
  StepWorkspace workspace;
  EXPECT_EQ(step(scene.model, scene.params, scene.state, workspace), StepStatus::non_finite);
  EXPECT_EQ(workspace.self_collision.candidates, 0);
}

TEST(SelfCollision, AParticleFlungFarStillHashesInBoundedTime) {
  // a blowing-up step: one particle 1 km away along the diagonal; at 6 cm cells its swept box
  // would cover 10^13 of them
  StackedSheets scene;
  Eigen::VectorXd end_x = scene.state.x;
  end_x.segment<3>(3 * 5) += Eigen::Vector3d(1e3, 1e3, 1e3);
  const std::vector<CandidatePair> pairs =
      collision_candidates(scene.model, scene.state.x, end_x, thickness_m, thickness_m);
  EXPECT_TRUE(std::any_of(pairs.begin(), pairs.end(),
                          [](const CandidatePair& p) { return p.particle[0] == 5; }));
}

TEST(SelfCollision, PairsThatAreNeighboursInTheMaterialAreNotCandidates) {
  // the upper sheet 3 mm above the lower one: as two layers they touch
  StackedSheets scene;
  scene.model.rest_x = scene.state.x;  // two layers 5 cm apart in the material
  for (int p = side * side; p < scene.model.particle_count(); ++p) {
    scene.state.x[3 * p + 2] -= 0.047;
  }
  const auto pairs_across = [&scene](double material_gap_m) {
    const std::vector<CandidatePair> pairs = collision_candidates(
        scene.model, scene.state.x, scene.state.x, thickness_m, material_gap_m);
    return std::count_if(pairs.begin(), pairs.end(), [](const CandidatePair& p) {
      return (p.particle[0] < side * side) != (p.particle[1] < side * side);
    });
  };
  const auto touching = pairs_across(0.0);
  ASSERT_GT(touching, 0);
  EXPECT_EQ(pairs_across(thickness_m), touching);
  // the two lips of one cut sheet: the upper sheet's material points are the lower's, and every
  // pair across, 1 cm apart at most, shares a material point
  for (int p = side * side; p < scene.model.particle_count(); ++p) {
    scene.model.rest_x.segment<3>(3 * p) = scene.model.rest_x.segment<3>(3 * (p - side * side));
  }
  EXPECT_EQ(pairs_across(thickness_m), 0);
  EXPECT_EQ(pairs_across(0.0), touching);  // a gap of 0 turns the rule off
}

TEST(SelfCollision, TheBroadPhaseFindsCloseNonAdjacentPairsOnly) {
  StackedSheets scene;
  // bring the upper sheet to 3 mm above the lower one
  for (int p = side * side; p < scene.model.particle_count(); ++p)
    scene.state.x[3 * p + 2] -= 0.047;
  const std::vector<CandidatePair> pairs =
      collision_candidates(scene.model, scene.state.x, scene.state.x, thickness_m, thickness_m);
  bool lower_with_upper = false;
  for (const CandidatePair& pair : pairs) {
    for (int k = 1; k < 4; ++k) EXPECT_NE(pair.particle[0], pair.particle[k]);
    lower_with_upper =
        lower_with_upper || (pair.particle[0] < side * side) != (pair.particle[1] < side * side);
  }
  EXPECT_TRUE(lower_with_upper);
  // a flat sheet alone: its close pairs in the broad phase are all farther apart than 4 mm
  State flat_state;
  const SpringModel flat = test::grid_model(side, side, spacing_m, 1e-4, 200.0, 0.01, flat_state);
  EXPECT_FALSE(
      collision_candidates(flat, flat_state.x, flat_state.x, thickness_m, thickness_m).empty());
  SelfCollisionOptions options;
  SelfCollisionCache cache;
  options.enabled = true;
  options.thickness_m = thickness_m;
  const SelfCollisionReport report = resolve_self_collisions(flat, options, 1e-3, flat_state.x,
                                                             Eigen::Matrix3Xd(), cache, flat_state);
  EXPECT_EQ(report.proximities, 0);
  EXPECT_EQ(report.impacts, 0);
}

/// A pair as a set element: the same for either order of an edge's ends, of a triangle's corners
/// and of the two edges of an edge-edge pair.
std::array<int, 5> pair_key(const CandidatePair& pair) {
  std::array<int, 4> p = pair.particle;
  if (pair.edge_edge) {
    if (p[0] > p[1]) std::swap(p[0], p[1]);
    if (p[2] > p[3]) std::swap(p[2], p[3]);
    if (std::tie(p[2], p[3]) < std::tie(p[0], p[1])) p = {p[2], p[3], p[0], p[1]};
  } else {
    std::sort(p.begin() + 1, p.end());
  }
  return {pair.edge_edge, p[0], p[1], p[2], p[3]};
}

std::set<std::array<int, 5>> pair_set(const std::vector<CandidatePair>& pairs) {
  std::set<std::array<int, 5>> keys;
  for (const CandidatePair& pair : pairs) keys.insert(pair_key(pair));
  return keys;
}

/// The smallest distance between the pair's primitives at 21 instants of the straight paths from
/// `start_x` to `end_x` (m): at least their closest approach.
double closest_over_step_m(const CandidatePair& pair, const Eigen::VectorXd& start_x,
                           const Eigen::VectorXd& end_x) {
  double closest_m = std::numeric_limits<double>::infinity();
  for (int s = 0; s <= 20; ++s) {
    const Eigen::VectorXd x = start_x + (s / 20.0) * (end_x - start_x);
    PairMotion still;
    for (int k = 0; k < 4; ++k) {
      still.start[k] = x.segment<3>(3 * pair.particle[k]);
      still.displacement[k].setZero();
    }
    closest_m = std::min(closest_m, proximity_at_end(pair, still, 0.0).distance_m);
  }
  return closest_m;
}

/// The stacked sheets with the upper one 6 mm above the lower one: within reach of each other.
StackedSheets sheets_6_mm_apart() {
  StackedSheets scene;
  for (int p = side * side; p < scene.model.particle_count(); ++p)
    scene.state.x[3 * p + 2] -= 0.044;
  return scene;
}

SelfCollisionOptions self_collision_on() {
  SelfCollisionOptions options;
  options.enabled = true;
  options.thickness_m = thickness_m;
  return options;
}

TEST(SelfCollision, KeptPairsHoldEveryPairThatComesWithinTheThicknessWhileAFewParticlesRoam) {
  // the upper sheet 6 mm above the lower one; the lower sheet is still, the upper one trembles by
  // up to 1 mm per step, and a few of its particles (a different few each step) jump by up to
  // 3 cm: their pairs are found again, the others kept
  const StackedSheets scene = sheets_6_mm_apart();
  const int particles = scene.model.particle_count();
  const SelfCollisionOptions options = self_collision_on();
  SelfCollisionCache cache;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd x = scene.state.x;
  int roamers_seen = 0, close_pairs_seen = 0;
  Eigen::Vector3d still_box_low;
  const int still = side * side / 2;  // a particle of the lower sheet
  for (int n = 0; n < 40; ++n) {
    Eigen::VectorXd end_x = x;
    for (int p = side * side; p < particles; ++p) {
      const double reach_m = (p + 7 * n) % 29 == 0 ? 0.03 : 0.001;
      for (int k = 0; k < 3; ++k) end_x[3 * p + k] += reach_m * unit(random);
    }
    State state = scene.state;
    state.x = end_x;
    const Eigen::Vector3d frame_start_m = cache.frame_m;
    resolve_self_collisions(scene.model, options, 1.0 / 60.0, x, Eigen::Matrix3Xd(), cache, state);
    // the boxes are in the cache's frame, which stands still unless the cloth moves as a whole
    const Eigen::VectorXd x_in_frame = relative_to(x, frame_start_m);
    const Eigen::VectorXd end_in_frame = relative_to(end_x, cache.frame_m);
    const std::set<std::array<int, 5>> kept = pair_set(cache.pairs);
    ASSERT_EQ(kept.size(), cache.pairs.size()) << "a pair kept twice, step " << n;
    const std::vector<CandidatePair> within_reach =
        collision_candidates(scene.model, x_in_frame, end_in_frame, thickness_m, thickness_m);
    for (const CandidatePair& pair : within_reach) {
      ASSERT_TRUE(kept.count(pair_key(pair))) << "a pair within reach was not kept, step " << n;
    }
    // the pairs the step tested exactly hold every pair that came within the thickness
    const std::set<std::array<int, 5>> tested =
        pair_set(kept_pairs_within_reach(cache, x_in_frame, end_in_frame, thickness_m));
    for (const CandidatePair& pair : within_reach) {
      if (closest_over_step_m(pair, x, end_x) > thickness_m) continue;
      ++close_pairs_seen;
      ASSERT_TRUE(tested.count(pair_key(pair)))
          << "a pair that came close was not tested, step " << n;
    }
    // the kept pairs are exactly those of a whole search around the particles' boxes
    ASSERT_EQ(cache.boxes.size(), particles);
    EXPECT_EQ(kept, pair_set(collision_candidates(scene.model, cache.boxes,
                                                  thickness_m + cache.skin_m, thickness_m)))
        << "step " << n;
    for (int p = 0; p < particles; ++p) roamers_seen += cache.boxes.is_path(p);
    if (n == 0) still_box_low = cache.boxes.low.col(still);
    x = end_x;
  }
  EXPECT_GT(roamers_seen, 40) << "no particle left its box: the partial search went untested";
  EXPECT_GT(close_pairs_seen, 100);
  // a particle that never moved keeps the box it got at the first step: the cloth was never
  // searched whole again
  EXPECT_EQ(cache.boxes.low.col(still), still_box_low);
}

TEST(SelfCollision, ACarriedClothMeetsTheSameContactsAndKeepsItsPairs) {
  // the upper sheet 6 mm above the lower one, trembling by up to 2 mm and sinking 0.5 mm per step,
  // so that its particles come within the thickness and some cross; once still, once with the
  // whole scene carried 5.4 cm per step (3.2 m/s at 60 steps per second), farther than half the
  // skin: a fixed frame would search the whole cloth over its paths every step
  const StackedSheets scene = sheets_6_mm_apart();
  const int particles = scene.model.particle_count();
  const SelfCollisionOptions options = self_collision_on();
  const Eigen::Vector3d carried_m(0.03, -0.02, -0.04);  // per step
  const double h = 1.0 / 60.0;
  std::array<SelfCollisionCache, 2> cache;
  std::array<State, 2> state{scene.state, scene.state};
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int proximities = 0, impacts = 0;
  for (int n = 0; n < 30; ++n) {
    Eigen::VectorXd step_m = Eigen::VectorXd::Zero(3 * particles);
    for (int p = side * side; p < particles; ++p) {
      for (int k = 0; k < 3; ++k) step_m[3 * p + k] = 0.002 * unit(random);
      step_m[3 * p + 2] -= 0.0005;
    }
    std::array<SelfCollisionReport, 2> report;
    for (int run = 0; run < 2; ++run) {
      const Eigen::VectorXd start_x = state[run].x;
      state[run].x += step_m;
      if (run == 1) state[run].x = relative_to(state[run].x, -carried_m);
      state[run].v.setZero();
      report[run] = resolve_self_collisions(scene.model, options, h, start_x, Eigen::Matrix3Xd(),
                                            cache[run], state[run]);
    }
    ASSERT_EQ(report[1].proximities, report[0].proximities) << "step " << n;
    ASSERT_EQ(report[1].impacts, report[0].impacts) << "step " << n;
    proximities += report[0].proximities;
    impacts += report[0].impacts;
    const Eigen::VectorXd carried_back_x = relative_to(state[1].x, (n + 1) * carried_m);
    ASSERT_LT((carried_back_x - state[0].x).cwiseAbs().maxCoeff(), 1e-9) << "step " << n;
    ASSERT_LT((state[1].v - state[0].v).cwiseAbs().maxCoeff(), 1e-6) << "step " << n;
    // the carried cloth's pairs were kept around points, as the still cloth's
    ASSERT_EQ(cache[1].boxes.size(), particles) << "searched over the paths, step " << n;
  }
  EXPECT_GT(proximities, 100);
  EXPECT_GT(impacts, 0);
}

TEST(SelfCollision, GivesTheSameStepWithOneAndTwoThreads) {
  StackedSheets scene;
  for (int n = 0; n < 60; ++n) step(scene.model, scene.params, scene.state);  // just before landing
  const std::array<State, 2> ends =
      test::step_with_one_and_two_threads(scene.model, scene.params, scene.state, 60);
  EXPECT_EQ(ends[0].x, ends[1].x);
  EXPECT_EQ(ends[0].v, ends[1].v);
}

}  // namespace
}  // namespace tissu
