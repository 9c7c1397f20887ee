#pragma once
/// \file
/// L-BFGS's memory and its search direction (internal to the quasi-Newton integrator): the last
/// pairs s_k = x_{k+1} - x_k, t_k = g_{k+1} - g_k and the two-loop recursion over them (Nocedal &
/// Wright 2006, algorithm 7.4), which gives -H g for the inverse BFGS matrix H that the pairs
/// make of the caller's H_0, oldest pair first (their eq. 6.17). Each pair's update and the next
/// pair's dot product share one pass over the vectors: m + 1 passes a loop for m pairs, not 2 m.
/// Sums are chunked (parallel_sum.hpp): the same bits on any number of threads.

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace tissu {

class LbfgsHistory {
 public:
  /// Room for `capacity` pairs (>= 0) of vectors of `size` entries (3#P); forgets every pair.
  void reset(Eigen::Index size, int capacity);

  /// Forgets every pair (H becomes H_0), keeping the room.
  void clear() { m_pairs = 0; }

  int pairs() const { return m_pairs; }

  /// Stores s = x_new - x (m) and t = g_new - g (N) when s . t > 0, the curvature condition that
  /// keeps H positive definite, and returns whether it did. The history being full, the oldest
  /// pair gives its room either way.
  bool remember(const Eigen::VectorXd& x, const Eigen::VectorXd& x_new, const Eigen::VectorXd& g,
                const Eigen::VectorXd& g_new);

  /// H_0 r (3#P) of a vector q: the caller's initial inverse Hessian.
  using InitialInverse = std::function<const Eigen::VectorXd&(const Eigen::VectorXd& q)>;

  /// direction = -H g, H the inverse Hessian that the stored pairs make of H_0; returns g .
  /// direction (J, < 0 for a descent direction).
  double direction(const Eigen::VectorXd& g, const InitialInverse& initial_inverse,
                   Eigen::VectorXd& direction);

 private:
  /// the column of the pair `newer` pairs newer than the oldest (or older, if negative)
  int slot_after(int slot, int newer) const;

  Eigen::MatrixXd m_position_changes;  ///< size x capacity: s_k (m)
  Eigen::MatrixXd m_gradient_changes;  ///< size x capacity: t_k (N)
  std::vector<double> m_curvature;     ///< capacity: rho_k = 1 / (s_k . t_k) (1/J)
  std::vector<double> m_alpha;         ///< capacity: alpha_k = rho_k s_k . q of the last direction
  int m_pairs = 0;
  int m_newest = -1;  ///< column of the newest pair
};

}  // namespace tissu
