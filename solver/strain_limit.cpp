#include "solver/strain_limit.hpp"

namespace tissu {
namespace {

/// A spring this little beyond its limit (relative) is left as it is: the round-off of a
/// correction would otherwise count as a correction, and the sweeps would never stop.
constexpr double within = 1e-9;

}  // namespace

int limit_strain(const SpringModel& model, double limit, double time_step_s, State& state,
                 int sweeps) {
  if (!(limit > 0.0)) return 0;
  int first_sweep_corrections = 0;
  const int springs = model.spring_count();
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    int corrections = 0;
    // forwards, then backwards: a chain of springs under load (a sheet hanging from its pins)
    // converges in fewer sweeps than always in one order
    for (int k = 0; k < springs; ++k) {
      const int s = sweep % 2 == 0 ? k : springs - 1 - k;
      if (model.kind[s] != SpringKind::structural) continue;
      const int i = model.springs(s, 0), j = model.springs(s, 1);
      const double wi = model.inverse_mass[i], wj = model.inverse_mass[j];  // 0 when pinned
      if (wi + wj == 0.0) continue;
      const Eigen::Vector3d d = state.x.segment<3>(3 * j) - state.x.segment<3>(3 * i);
      const double length_m = d.norm(), longest_m = (1.0 + limit) * model.rest_length[s];
      if (!(length_m > (1.0 + within) * longest_m)) continue;
      // i moves by wi c and j by -wj c: equal and opposite momenta, the spring at longest_m
      const Eigen::Vector3d c = ((length_m - longest_m) / (length_m * (wi + wj))) * d;
      state.x.segment<3>(3 * i) += wi * c;
      state.x.segment<3>(3 * j) -= wj * c;
      state.v.segment<3>(3 * i) += (wi / time_step_s) * c;
      state.v.segment<3>(3 * j) -= (wj / time_step_s) * c;
      ++corrections;
    }
    if (sweep == 0) first_sweep_corrections = corrections;
    if (corrections == 0) break;
  }
  return first_sweep_corrections;
}

}  // namespace tissu
