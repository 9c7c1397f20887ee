#pragma once
/// \file
/// When the solver's loops go parallel (internal).

namespace tissu {

/// Loops over fewer items than this run on one thread: an OpenMP fork-join costs microseconds
/// (far more on a loaded machine), more than a few hundred springs or particles take. Results do
/// not depend on it: every parallel loop writes disjoint outputs in a fixed order.
inline constexpr int min_parallel_items = 256;

}  // namespace tissu
