#pragma once
/// \file
/// Sums of many doubles to round-off independent of their count: the total mass of a cloth is
/// checked against density x rest area to 1e-12 (relative), and a plain running sum over the
/// 2 million faces of a large cloth drifts by up to n eps, 2e-10. Neumaier's variant of Kahan
/// summation (Neumaier 1974) carries the low bits each addition loses, so that the error stays
/// about eps times the sum of the magnitudes, whatever their count.

#include <cmath>

namespace tissu {

class CompensatedSum {
 public:
  void add(double x) {
    const double t = m_sum + x;
    // the low bits of the smaller operand that t could not hold
    m_compensation += std::abs(m_sum) >= std::abs(x) ? (m_sum - t) + x : (x - t) + m_sum;
    m_sum = t;
  }
  double value() const { return m_sum + m_compensation; }

 private:
  double m_sum = 0.0;
  double m_compensation = 0.0;
};

}  // namespace tissu
