#include "solver/integrators/lbfgs_history.hpp"

#include <algorithm>

#include "solver/parallel_sum.hpp"

namespace tissu {
namespace {

// v = a w + (replace ? 0 : v), then u . v (0 without u): one pass over the vectors (3#P each),
// chunked so that the dot product has the same bits on any number of threads
double axpy_then_dot(double a, const double* w, bool replace, Eigen::VectorXd& v, const double* u) {
  return chunked_sum(static_cast<int>(v.size() / 3), [&](int begin, int end) {
    const Eigen::Index start = 3 * begin, size = 3 * (end - begin);
    auto v_chunk = v.segment(start, size);
    const Eigen::Map<const Eigen::VectorXd> w_chunk(w + start, size);
    if (replace) {
      v_chunk = a * w_chunk;
    } else {
      v_chunk += a * w_chunk;
    }
    return u == nullptr ? 0.0 : Eigen::Map<const Eigen::VectorXd>(u + start, size).dot(v_chunk);
  });
}

}  // namespace

void LbfgsHistory::reset(Eigen::Index size, int capacity) {
  if (m_position_changes.rows() != size || m_position_changes.cols() != capacity) {
    m_position_changes.resize(size, capacity);
    m_gradient_changes.resize(size, capacity);
    m_curvature.assign(capacity, 0.0);
    m_alpha.assign(capacity, 0.0);
  }
  m_pairs = 0;
  m_newest = -1;
}

int LbfgsHistory::slot_after(int slot, int newer) const {
  const int capacity = static_cast<int>(m_curvature.size());
  return ((slot + newer) % capacity + capacity) % capacity;
}

bool LbfgsHistory::remember(const Eigen::VectorXd& x, const Eigen::VectorXd& x_new,
                            const Eigen::VectorXd& g, const Eigen::VectorXd& g_new) {
  const int capacity = static_cast<int>(m_curvature.size());
  if (capacity == 0) return false;
  const int room = slot_after(m_newest, 1);
  auto s = m_position_changes.col(room);
  auto t = m_gradient_changes.col(room);
  const double curvature_j = chunked_sum(static_cast<int>(x.size() / 3), [&](int begin, int end) {
    const Eigen::Index start = 3 * begin, size = 3 * (end - begin);
    auto s_chunk = s.segment(start, size);
    auto t_chunk = t.segment(start, size);
    s_chunk = x_new.segment(start, size) - x.segment(start, size);
    t_chunk = g_new.segment(start, size) - g.segment(start, size);
    return s_chunk.dot(t_chunk);
  });
  m_pairs = std::min(m_pairs, capacity - 1);  // the room's old pair, if any, is overwritten
  if (!(curvature_j > 0.0)) return false;
  m_curvature[room] = 1.0 / curvature_j;
  m_newest = room;
  ++m_pairs;
  return true;
}

// run on q = -g so that it ends on the direction itself
double LbfgsHistory::direction(const Eigen::VectorXd& g, const InitialInverse& initial_inverse,
                               Eigen::VectorXd& direction) {
  const int pairs = m_pairs;
  const auto s = [&](int k) { return m_position_changes.col(k).data(); };
  const auto t = [&](int k) { return m_gradient_changes.col(k).data(); };
  direction.resize(g.size());
  // newest pair first: alpha_k = rho_k s_k . q, q -= alpha_k t_k
  int k = m_newest;
  double dot = axpy_then_dot(-1.0, g.data(), true, direction, pairs > 0 ? s(k) : nullptr);
  for (int n = 0; n < pairs; ++n) {
    m_alpha[k] = m_curvature[k] * dot;
    const int older = slot_after(k, -1);
    dot = axpy_then_dot(-m_alpha[k], t(k), false, direction, n + 1 < pairs ? s(older) : nullptr);
    k = older;
  }
  const Eigen::VectorXd& r0 = initial_inverse(direction);  // r = H_0 q
  // oldest pair first: beta = rho_k t_k . r, r += (alpha_k - beta) s_k
  k = pairs > 0 ? slot_after(m_newest, 1 - pairs) : 0;
  dot = axpy_then_dot(1.0, r0.data(), true, direction, pairs > 0 ? t(k) : g.data());
  for (int n = 0; n < pairs; ++n) {
    const double beta = m_curvature[k] * dot;
    const int newer = slot_after(k, 1);
    dot = axpy_then_dot(m_alpha[k] - beta, s(k), false, direction,
                        n + 1 < pairs ? t(newer) : g.data());
    k = newer;
  }
  return dot;
}

}  // namespace tissu
