#include "solver/forces/spring_force.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace tissu {
namespace {

constexpr double fd_step = 1e-6;  // m or m/s

struct SpringSample {
  Eigen::Vector3d xi, xj, vi, vj;
  double k, l0, nu;
};

// random configurations, both stretched (l0 < |d|) and compressed (l0 > |d|)
std::vector<SpringSample> random_samples(int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<SpringSample> samples;
  for (int n = 0; n < count; ++n) {
    SpringSample sample;
    sample.xi = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    sample.xj = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    sample.vi = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    sample.vj = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    sample.k = 50.0 * (1.5 + unit(rng));
    sample.l0 = (sample.xi - sample.xj).norm() * (1.0 + 0.5 * unit(rng));
    sample.nu = 1.0 + unit(rng);
    samples.push_back(sample);
  }
  return samples;
}

TEST(SpringForce, IsMinusEnergyGradient) {
  for (const SpringSample& s : random_samples(50)) {
    Eigen::Vector3d gradient;
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[a] = fd_step;
      gradient[a] =
          (spring_energy(s.xi + e, s.xj, s.k, s.l0) - spring_energy(s.xi - e, s.xj, s.k, s.l0)) /
          (2.0 * fd_step);
    }
    const Eigen::Vector3d force = spring_force(s.xi, s.xj, s.k, s.l0);
    EXPECT_LT((force + gradient).norm(), 1e-6 * (1.0 + force.norm()));
    // action and reaction
    EXPECT_LT((spring_force(s.xj, s.xi, s.k, s.l0) + force).norm(), 1e-12 * (1.0 + force.norm()));
  }
}

TEST(SpringForce, PullsTowardTheOtherEndWhenStretched) {
  const Eigen::Vector3d xi(0.0, 0.0, 0.0);
  const Eigen::Vector3d xj(2.0, 0.0, 0.0);
  const Eigen::Vector3d stretched = spring_force(xi, xj, 10.0, 1.0);
  EXPECT_DOUBLE_EQ(stretched.x(), 10.0);  // k (|d| - l0) toward j
  const Eigen::Vector3d compressed = spring_force(xi, xj, 10.0, 3.0);
  EXPECT_DOUBLE_EQ(compressed.x(), -10.0);
  EXPECT_DOUBLE_EQ(spring_energy(xi, xj, 10.0, 1.0), 5.0);
}

TEST(SpringForceJacobian, MatchesFiniteDifferences) {
  for (const SpringSample& s : random_samples(50)) {
    Eigen::Matrix3d fd;
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[a] = fd_step;
      fd.col(a) =
          (spring_force(s.xi + e, s.xj, s.k, s.l0) - spring_force(s.xi - e, s.xj, s.k, s.l0)) /
          (2.0 * fd_step);
    }
    const Eigen::Matrix3d jacobian = spring_force_jacobian(s.xi, s.xj, s.k, s.l0);
    EXPECT_LT((jacobian - fd).norm(), 1e-6 * (1.0 + jacobian.norm()));
    EXPECT_LT((jacobian - jacobian.transpose()).norm(), 1e-12 * jacobian.norm());
  }
}

TEST(SpringForceJacobian, ClampedIsExactWhenStretchedAndSemidefiniteWhenCompressed) {
  int compressed = 0;
  for (const SpringSample& s : random_samples(50)) {
    const Eigen::Matrix3d exact = spring_force_jacobian(s.xi, s.xj, s.k, s.l0);
    const Eigen::Matrix3d clamped = spring_force_jacobian_clamped(s.xi, s.xj, s.k, s.l0);
    const Eigen::Vector3d eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(clamped).eigenvalues();
    EXPECT_LE(eigenvalues.maxCoeff(), 1e-9 * s.k);
    if ((s.xi - s.xj).norm() >= s.l0) {
      EXPECT_LT((exact - clamped).norm(), 1e-12 * exact.norm());
    } else {
      ++compressed;
      // the exact Jacobian of a compressed spring is indefinite: that is what the clamp removes
      const Eigen::Vector3d exact_eigenvalues =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(exact).eigenvalues();
      EXPECT_GT(exact_eigenvalues.maxCoeff(), 0.0);
    }
  }
  EXPECT_GT(compressed, 5);
}

TEST(SpringDampingForce, JacobianMatchesFiniteDifferencesAndDissipates) {
  for (const SpringSample& s : random_samples(50)) {
    Eigen::Matrix3d fd;
    for (int a = 0; a < 3; ++a) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e[a] = fd_step;
      fd.col(a) = (spring_damping_force(s.xi, s.xj, s.vi + e, s.vj, s.nu) -
                   spring_damping_force(s.xi, s.xj, s.vi - e, s.vj, s.nu)) /
                  (2.0 * fd_step);
    }
    const Eigen::Matrix3d jacobian = spring_damping_force_jacobian(s.xi, s.xj, s.nu);
    EXPECT_LT((jacobian - fd).norm(), 1e-6 * (1.0 + jacobian.norm()));
    const Eigen::Vector3d force = spring_damping_force(s.xi, s.xj, s.vi, s.vj, s.nu);
    EXPECT_LE(force.dot(s.vi - s.vj), 0.0);  // power of the damper on the relative motion
  }
}

TEST(SpringForce, ZeroLengthGivesZeroNotNaN) {
  const Eigen::Vector3d x(0.3, -0.2, 1.0);
  const Eigen::Vector3d v(1.0, 2.0, 3.0);
  EXPECT_TRUE(spring_force(x, x, 100.0, 0.1).isZero());
  EXPECT_TRUE(spring_force_jacobian(x, x, 100.0, 0.1).isZero());
  EXPECT_TRUE(spring_force_jacobian_clamped(x, x, 100.0, 0.1).isZero());
  EXPECT_TRUE(spring_damping_force(x, x, v, -v, 2.0).isZero());
  EXPECT_TRUE(spring_damping_force_jacobian(x, x, 2.0).isZero());
  EXPECT_TRUE(std::isfinite(spring_energy(x, x, 100.0, 0.1)));
}

TEST(SpringForce, HessianBlockIsTheClampedStiffnessPlusTheViscousTerm) {
  const Eigen::Vector3d xj(0.1, -0.2, 0.3);
  const Eigen::Vector3d n = Eigen::Vector3d(1.0, 2.0, -2.0) / 3.0;
  const double k = 3000.0, c = 45.0;
  // stretched, compressed (no transverse term), and too short to have a direction
  for (const Eigen::Vector3d& d :
       {Eigen::Vector3d(0.3, 0.4, -0.1), Eigen::Vector3d(0.01, 0.02, 0.0),
        Eigen::Vector3d(1e-13, 0.0, 0.0)}) {
    const Eigen::Matrix3d expected =
        -spring_force_jacobian_clamped(xj + d, xj, k, 0.1) + c * n * n.transpose();
    const Eigen::Matrix3d block = full_block(spring_hessian_block(d, k, 0.1, n, c));
    EXPECT_LT((block - expected).cwiseAbs().maxCoeff(), 1e-12 * k) << d.transpose();
  }
}

}  // namespace
}  // namespace tissu
