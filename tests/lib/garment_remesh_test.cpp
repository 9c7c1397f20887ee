// Anisotropic remeshing (topology/remesh.hpp) of a real garment, data/meshes/tshirt.obj: a curved
// rest shape of irregular triangles, front and back sewn together at the sides and shoulders.
// Folded at random again and again, it stays a valid cloth after every pass, with the same mass
// and momentum, while splits, flips and collapses all happen (about 6,700, 1,800 and 6,700 over
// the 12 passes).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lib/cloth_setup.hpp"
#include "lib/scenario/scenario.hpp"
#include "tests/topology/cloth_test_support.hpp"
#include "topology/remesh.hpp"

namespace tissu {
namespace {

/// Moves every particle of `lcc` off its rest position by a fold: a sine wave across the
/// garment, along a random direction, of random wavelength (5 to 20 cm) and amplitude (1 to 3
/// cm); gives each a random velocity (up to 0.5 m/s per axis).
void fold_at_random(ClothComplex& lcc, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d across =
      Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
  const Eigen::Vector3d along =
      Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
  const double wavelength_m = 0.125 + 0.075 * unit(random);
  const double amplitude_m = 0.02 + 0.01 * unit(random);
  const double phase_rad = std::numbers::pi * unit(random);
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Eigen::Vector3d rest = to_eigen(v->info().rest_position);
    const double wave =
        std::sin(2.0 * std::numbers::pi * across.dot(rest) / wavelength_m + phase_rad);
    const Eigen::Vector3d x = rest + amplitude_m * wave * along;
    v->point() = Point3(x.x(), x.y(), x.z());
    v->info().velocity = Vector3(0.5 * unit(random), 0.5 * unit(random), 0.5 * unit(random));
  }
}

TEST(GarmentRemesh, AShirtFoldedAtRandomStaysValidWithItsMassAndMomentum) {
  const Scenario scenario = load_scenario(TISSU_DATA_DIR "/scenarios/tshirt_arms.json", {});
  ClothComplex lcc;
  build_scenario_cloth(scenario, lcc);
  const double mass_kg = complex_total_mass(lcc);
  RefinementOptions options;
  options.anisotropic = true;
  options.curvature_threshold_rad = 0.3;
  options.min_edge_length_m = 0.01;
  std::mt19937 random(19);
  RemeshReport total;
  for (int pass = 0; pass < 12; ++pass) {
    fold_at_random(lcc, random);
    const Eigen::Vector3d momentum_before = test::complex_momentum(lcc);
    const RemeshReport r = remesh(lcc, options, 0.5, scenario.springs);
    total.splits += r.splits;
    total.flips += r.flips;
    total.collapses += r.collapses;
    const std::string when = "pass " + std::to_string(pass);
    test::expect_valid_with_mass(lcc, mass_kg, when);
    EXPECT_LT((test::complex_momentum(lcc) - momentum_before).norm(),
              1e-12 * mass_kg * 0.5 * std::sqrt(3.0))
        << when;
  }
  EXPECT_GT(total.splits, 0);
  EXPECT_GT(total.flips, 0);
  EXPECT_GT(total.collapses, 0);
}

}  // namespace
}  // namespace tissu
