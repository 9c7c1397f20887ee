// The pins' reaction force equals what the pinned particles hold: the weight they carry at rest.

#include "solver/pin_reaction.hpp"

#include <gtest/gtest.h>

#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

TEST(PinReaction, AHangingMassAtRestIsCarriedWholeByItsPin) {
  // 2 kg below a pinned 1 kg particle, on a spring stretched by m g / k: at equilibrium
  const double mass_kg = 2.0, k_n_per_m = 100.0, g_m_per_s2 = 9.81;
  State state;
  const SpringModel model =
      test::spring_mass(mass_kg, k_n_per_m, 1.0, mass_kg * g_m_per_s2 / k_n_per_m, state);
  Environment environment;
  environment.gravity =
      Eigen::Vector3d(g_m_per_s2, 0.0, 0.0);  // along the spring, away from the pin
  environment.air_damping = 0.0;
  const Eigen::Vector3d reaction = pin_reaction_force(model, environment, state);
  // the pin holds both particles: R = -(1 kg + 2 kg) g
  EXPECT_NEAR(reaction.x(), -3.0 * g_m_per_s2, 1e-12);
  EXPECT_NEAR(reaction.y(), 0.0, 1e-12);
  EXPECT_NEAR(reaction.z(), 0.0, 1e-12);
}

TEST(PinReaction, AStretchedSpringPullsOnThePinBeyondTheWeight) {
  State state;
  const SpringModel model = test::spring_mass(2.0, 100.0, 1.0, 0.5, state);  // 50 N of tension
  Environment environment;
  environment.gravity = Eigen::Vector3d::Zero();
  environment.air_damping = 0.0;
  EXPECT_NEAR(pin_reaction_force(model, environment, state).x(), -50.0, 1e-12);
}

TEST(PinReaction, IsZeroWithoutPins) {
  State state;
  SpringModel model = test::spring_mass(2.0, 100.0, 1.0, 0.5, state);
  model.pinned = {0, 0};
  Environment environment;
  EXPECT_EQ(pin_reaction_force(model, environment, state), Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace tissu
