#include "lib/tear_step.hpp"

#include <algorithm>

#include "solver/spring_strain.hpp"
#include "topology/tear.hpp"

namespace tissu {

TearStep::TearStep(const Scenario& scenario) : m_scenario(scenario) {
  const TearingOptions& options = scenario.tearing.options;
  double lowest_factor = 1.0;
  for (const WeakRegion& region : options.weak_regions) {
    lowest_factor = std::min(lowest_factor, region.factor);
  }
  m_lowest_tearing_strain = options.strain_threshold * lowest_factor;
}

TearReport TearStep::after_step(ClothComplex& lcc, CompiledCloth& cloth) {
  const TearingSettings& tearing = m_scenario.tearing;
  if (!tearing.enabled) return {};
  const double time_s = cloth.state.time;
  const bool cut_due =
      m_next_cut < tearing.cuts.size() && time_s >= tearing.cuts[m_next_cut].time_s;
  const bool overstretched = m_lowest_tearing_strain > 0.0 &&
                             max_spring_strain(cloth.model, cloth.state.x, SpringKind::structural) >
                                 m_lowest_tearing_strain;
  if (!cut_due && !overstretched) return {};

  TearReport report;
  edit_and_recompile(lcc, cloth, [&](ClothComplex& complex) {
    for (; m_next_cut < tearing.cuts.size() && time_s >= tearing.cuts[m_next_cut].time_s;
         ++m_next_cut) {
      report.tears +=
          cut_along(complex, tearing.cuts[m_next_cut].points_m, m_scenario.springs).tears;
    }
    if (overstretched) {
      const TearReport torn =
          tear(complex, tearing.options, m_scenario.adaptive.refinement.max_particles,
               m_scenario.springs);
      report.tears += torn.tears;
      report.tip_refinements += torn.tip_refinements;
    }
    return report.tears > 0;
  });
  return report;
}

}  // namespace tissu
