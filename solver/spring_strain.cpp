#include "solver/spring_strain.hpp"

#include <algorithm>

namespace tissu {

double max_spring_strain(const SpringModel& model, const Eigen::VectorXd& x, SpringKind kind) {
  double largest = -1.0;
  const int springs = model.spring_count();
#pragma omp parallel for reduction(max : largest) schedule(static)
  for (int s = 0; s < springs; ++s) {
    if (model.kind[s] != kind) continue;
    const double length_m =
        (x.segment<3>(3 * model.springs(s, 0)) - x.segment<3>(3 * model.springs(s, 1))).norm();
    largest = std::max(largest, length_m / model.rest_length[s] - 1.0);
  }
  return largest;
}

}  // namespace tissu
