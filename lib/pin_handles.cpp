#include "lib/pin_handles.hpp"

#include <algorithm>

#include "solver/speed_limit.hpp"
#include "topology/eigen_conversions.hpp"

namespace tissu {
namespace {

/// Whether `event_s` falls in (done_until_s, due_until_s].
bool due(double event_s, double done_until_s, double due_until_s) {
  return event_s > done_until_s && event_s <= due_until_s;
}

}  // namespace

void PinHandles::before_step(ClothComplex& lcc, CompiledCloth& cloth, double time_step_s) {
  const double time_s = cloth.state.time;
  // an event is due at the step whose start is nearest to it; t = 0 events are the initial pins
  const double due_until_s = time_s + 0.5 * time_step_s;
  const double done_until_s = std::max(m_done_until_s, 0.0);
  bool any_due = false;
  for (const PinSelector& pin : m_pins) {
    any_due = any_due || due(pin.attach_at_s, done_until_s, due_until_s) ||
              due(pin.release_at_s, done_until_s, due_until_s);
  }
  if (any_due) {
    edit_and_recompile(lcc, cloth, [&](ClothComplex& complex) {
      bool changed = false;
      for (auto v = complex.vertex_attributes().begin(); v != complex.vertex_attributes().end();
           ++v) {
        Particle& p = v->info();
        if (p.pin_group < 0) continue;
        const PinSelector& pin = m_pins[p.pin_group];
        const bool hold = due(pin.attach_at_s, done_until_s, due_until_s) && !p.pinned;
        const bool release = due(pin.release_at_s, done_until_s, due_until_s) && p.pinned;
        if (hold) {
          p.pinned = true;
          p.velocity = to_vector(pin.motion.point_velocity(to_eigen(v->point()), time_s));
        }
        if (release) p.pinned = false;
        changed = changed || hold != release;
      }
      return changed;
    });
  }
  m_done_until_s = due_until_s;

  const double h = time_step_s;
  for (int p = 0; p < cloth.model.particle_count(); ++p) {
    if (!cloth.model.pinned[p]) continue;
    const int group = cloth.particle_vertices[p]->info().pin_group;
    if (group < 0 || m_pins[group].motion.keys.empty()) continue;
    const Eigen::Vector3d x = cloth.state.x.segment<3>(3 * p);
    cloth.state.v.segment<3>(3 * p) = (m_pins[group].motion.carry(x, time_s, time_s + h) - x) / h;
  }
}

double PinHandles::fastest_speed_m_per_s(const State& state) const {
  double fastest_m_per_s = 0.0;
  for (const PinSelector& pin : m_pins) {
    const double reach_m =
        pin.motion.rotates() ? farthest_particle_m(state, pin.motion.pivot_m) : 0.0;
    fastest_m_per_s = std::max(fastest_m_per_s, pin.motion.fastest_speed_m_per_s(reach_m));
  }
  return fastest_m_per_s;
}

}  // namespace tissu
