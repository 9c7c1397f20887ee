// LbfgsHistory: the compact L-BFGS direction is the inverse BFGS matrix's, built pair by pair from
// H_0, with a full history, after a pair it refused, and on one or two threads.

#include "solver/integrators/lbfgs_history.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "tests/test_thread_count.hpp"

namespace tissu {
namespace {

constexpr int particles = 300;  // two chunks of the sums (parallel_sum.hpp)
constexpr int size = 3 * particles;

// a quadratic energy E(x) = 1/2 x^T A x - b^T x with A symmetric positive definite
struct Quadratic {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
  Eigen::VectorXd gradient(const Eigen::VectorXd& x) const { return a * x - b; }
};

Quadratic random_quadratic(unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd m(size, 40);  // A = I + M M^T / 40: SPD, its spectrum spread from 1 to about 60
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = normal(random);
  Quadratic q{m * m.transpose() / 40.0 + Eigen::MatrixXd::Identity(size, size), {}};
  q.b = Eigen::VectorXd::NullaryExpr(size, [&] { return normal(random); });
  return q;
}

Eigen::VectorXd random_vector(std::mt19937& random) {
  std::normal_distribution<double> normal;
  return Eigen::VectorXd::NullaryExpr(size, [&] { return normal(random); });
}

// -H g with H from H_0 = diag(h0) by the BFGS inverse update, oldest pair first (Nocedal & Wright
// 2006, eq. 6.17): H <- (I - rho s t^T) H (I - rho t s^T) + rho s s^T, expanded with u = H t as
// H - rho (s u^T + u s^T) + (rho^2 t . u + rho) s s^T
Eigen::VectorXd dense_direction(const Eigen::VectorXd& h0, const std::vector<Eigen::VectorXd>& s,
                                const std::vector<Eigen::VectorXd>& t, const Eigen::VectorXd& g) {
  Eigen::MatrixXd h = h0.asDiagonal();
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double rho = 1.0 / s[k].dot(t[k]);
    const Eigen::VectorXd u = h * t[k];
    h -= rho * (s[k] * u.transpose() + u * s[k].transpose());
    h += (rho * rho * t[k].dot(u) + rho) * s[k] * s[k].transpose();
  }
  return -h * g;
}

TEST(LbfgsHistory, GivesTheInverseBfgsMatrixsDirectionWithAFullHistory) {
  const Quadratic energy = random_quadratic(1);
  std::mt19937 random(2);
  const Eigen::VectorXd h0 = Eigen::VectorXd::LinSpaced(size, 0.5, 2.0);  // H_0 = diag(h0)
  Eigen::VectorXd r0;
  const LbfgsHistory::InitialInverse initial_inverse =
      [&](const Eigen::VectorXd& q) -> const Eigen::VectorXd& { return r0 = h0.cwiseProduct(q); };
  constexpr int capacity = 5;

  LbfgsHistory history;
  history.reset(size, capacity);
  std::vector<Eigen::VectorXd> s, t;
  Eigen::VectorXd x = random_vector(random);
  Eigen::VectorXd direction;
  for (int pair = 0; pair < 8; ++pair) {  // more pairs than room: the oldest give theirs
    const Eigen::VectorXd g = energy.gradient(x);
    const double slope = history.direction(g, initial_inverse, direction);
    const Eigen::VectorXd expected = dense_direction(h0, s, t, g);
    EXPECT_LT((direction - expected).norm(), 1e-10 * expected.norm()) << pair;
    EXPECT_NEAR(slope, g.dot(expected), 1e-10 * std::abs(g.dot(expected))) << pair;
    EXPECT_LT(slope, 0.0);
    const Eigen::VectorXd x_new = x + 0.1 * direction + 0.01 * random_vector(random);
    ASSERT_TRUE(history.remember(x, x_new, g, energy.gradient(x_new)));
    s.push_back(x_new - x);
    t.push_back(energy.gradient(x_new) - g);
    if (s.size() > capacity) {
      s.erase(s.begin());
      t.erase(t.begin());
    }
    EXPECT_EQ(history.pairs(), static_cast<int>(s.size()));
    x = x_new;
  }
}

TEST(LbfgsHistory, APairWithoutCurvatureIsRefusedAndAFullHistoryLosesItsOldest) {
  const Quadratic energy = random_quadratic(3);
  std::mt19937 random(4);
  const Eigen::VectorXd h0 = Eigen::VectorXd::Constant(size, 0.7);
  Eigen::VectorXd r0;
  const LbfgsHistory::InitialInverse initial_inverse =
      [&](const Eigen::VectorXd& q) -> const Eigen::VectorXd& { return r0 = h0.cwiseProduct(q); };
  constexpr int capacity = 3;
  LbfgsHistory history;
  history.reset(size, capacity);
  std::vector<Eigen::VectorXd> s, t;
  Eigen::VectorXd x = random_vector(random);
  for (int pair = 0; pair < capacity; ++pair) {
    const Eigen::VectorXd x_new = x + 0.1 * random_vector(random);
    ASSERT_TRUE(history.remember(x, x_new, energy.gradient(x), energy.gradient(x_new)));
    s.push_back(x_new - x);
    t.push_back(energy.gradient(x_new) - energy.gradient(x));
    x = x_new;
  }
  // a gradient that decreases along the step: s . t < 0
  const Eigen::VectorXd x_new = x + 0.1 * random_vector(random);
  const Eigen::VectorXd g = energy.gradient(x);
  EXPECT_FALSE(history.remember(x, x_new, g, g - (x_new - x)));
  EXPECT_EQ(history.pairs(), capacity - 1);  // its room was the oldest pair's
  s.erase(s.begin());
  t.erase(t.begin());
  Eigen::VectorXd direction;
  history.direction(g, initial_inverse, direction);
  const Eigen::VectorXd expected = dense_direction(h0, s, t, g);
  EXPECT_LT((direction - expected).norm(), 1e-10 * expected.norm());

  history.clear();  // H = H_0
  history.direction(g, initial_inverse, direction);
  EXPECT_LT((direction + h0.cwiseProduct(g)).norm(), 1e-14 * g.norm());
}

TEST(LbfgsHistory, GivesTheSameBitsOnOneAndTwoThreads) {
  const Quadratic energy = random_quadratic(5);
  std::vector<Eigen::VectorXd> directions;
  for (const int threads : {1, 2}) {
    const test::ScopedThreadCount scope(threads);
    std::mt19937 random(6);
    Eigen::VectorXd r0;
    const LbfgsHistory::InitialInverse initial_inverse =
        [&](const Eigen::VectorXd& q) -> const Eigen::VectorXd& { return r0 = 0.5 * q; };
    LbfgsHistory history;
    history.reset(size, 4);
    Eigen::VectorXd x = random_vector(random), direction;
    for (int pair = 0; pair < 6; ++pair) {
      const Eigen::VectorXd g = energy.gradient(x);
      history.direction(g, initial_inverse, direction);
      const Eigen::VectorXd x_new = x + 0.1 * direction + 0.01 * random_vector(random);
      history.remember(x, x_new, g, energy.gradient(x_new));
      x = x_new;
    }
    directions.push_back(direction);
  }
  EXPECT_EQ(directions[0], directions[1]);
}

}  // namespace
}  // namespace tissu
