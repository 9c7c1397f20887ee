#pragma once
/// \file
/// Tearing between two solver steps of a run. Includes CGAL: include it from lib/ sources only.

#include <cstddef>

#include "lib/scenario/scenario.hpp"
#include "topology/compile.hpp"
#include "topology/tearing_options.hpp"

namespace tissu {

/// Tears the cloth of a run after a step where it is overstretched, and cuts it when a scripted
/// cut is due.
class TearStep {
 public:
  explicit TearStep(const Scenario& scenario);

  /// Looks at the stepped state of `cloth` (compiled from `lcc`). When a structural spring
  /// exceeds the lowest tearing strain (a cheap test on the flat model) or a cut is due, tears
  /// `lcc` (topology/tear.hpp) through edit_and_recompile(): when edges were torn, `cloth` is
  /// recompiled, its state kept.
  TearReport after_step(ClothComplex& lcc, CompiledCloth& cloth);

 private:
  const Scenario& m_scenario;
  double m_lowest_tearing_strain = 0.0;  ///< the threshold times the lowest weak factor
  std::size_t m_next_cut = 0;            ///< index of the first cut not made yet
};

}  // namespace tissu
