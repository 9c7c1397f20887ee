#include "topology/refine.hpp"

#include <algorithm>
#include <set>

#include "topology/complex_navigation.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_field.hpp"
#include "topology/split_edge.hpp"

namespace tissu {
namespace {

/// The dart of the longest rest-space edge of the face of `d` (the first in the face's order from
/// `d` among equally long ones): the edge to bisect.
Dart_handle longest_edge(ClothComplex& lcc, Dart_handle d) {
  Dart_handle best = d;
  for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
    if (edge_rest_length_m(lcc, e) > edge_rest_length_m(lcc, best)) best = e;
  }
  return best;
}

/// Bisects the edge of `edge`, the longest of its triangle, without degrading the triangle across
/// it: if the edge is not the longest of that neighbour too, the neighbour is bisected first at
/// its own longest edge, recursively along the longest-edge propagation path (Rivara 1997,
/// "New longest-edge algorithms for the refinement and/or improvement of unstructured
/// triangulations", IJNME 40). Lengths grow strictly along the path, so it ends; every triangle is
/// then cut at its longest edge, which keeps its smallest angle at least half the smallest initial
/// one (Rosenberg & Stenger 1975) and, on a grid of right isosceles triangles, every triangle
/// similar to them. Counts the splits in `splits`; returns false when the particle cap stopped it.
bool bisect_along_longest_edge_path(ClothComplex& lcc, Dart_handle edge, std::size_t particle_cap,
                                    const SpringSettings& settings, int& splits) {
  while (!lcc.is_free<2>(edge)) {
    const Dart_handle neighbours_longest = longest_edge(lcc, lcc.opposite<2>(edge));
    // a tie counts as longest: equal lengths cannot grow along the path
    if (edge_rest_length_m(lcc, neighbours_longest) <=
        edge_rest_length_m(lcc, edge) * (1.0 + 1e-12))
      break;
    if (!bisect_along_longest_edge_path(lcc, neighbours_longest, particle_cap, settings, splits)) {
      return false;
    }
  }
  if (lcc.vertex_attributes().size() >= particle_cap) return false;
  split_edge(lcc, edge, settings);
  ++splits;
  return true;
}

/// An edge to bisect, with its far end to notice when a propagation path bisected it first.
using SplitQueue = std::vector<std::pair<Dart_handle, Vertex_handle>>;

/// Queues the longest rest-space edge of the triangle of `side`, once per edge, if it is at least
/// twice `min_edge_length_m`.
void queue_longest_edge(ClothComplex& lcc, Dart_handle side, double min_edge_length_m,
                        std::set<Dart_const_handle>& queued, SplitQueue& queue) {
  const Dart_handle longest = longest_edge(lcc, side);
  if (edge_rest_length_m(lcc, longest) >= 2.0 * min_edge_length_m &&
      queued.insert(edge_key(lcc, longest)).second) {
    queue.emplace_back(longest, lcc.vertex_attribute(lcc.next(longest)));
  }
}

/// Bisects each queued edge (given with its far end) along its longest-edge propagation path,
/// skipping those an earlier path already bisected; returns the number of bisections.
int bisect_queued(ClothComplex& lcc, const SplitQueue& queue, std::size_t particle_cap,
                  const SpringSettings& settings) {
  int splits = 0;
  for (const auto& [edge, far_end] : queue) {
    if (lcc.vertex_attribute(lcc.next(edge)) != far_end) continue;  // already bisected on a path
    if (!bisect_along_longest_edge_path(lcc, edge, particle_cap, settings, splits)) break;
  }
  return splits;
}

}  // namespace

int refine_around_vertex(ClothComplex& lcc, Vertex_handle vertex, double min_edge_length_m,
                         int max_particles, const SpringSettings& settings) {
  SplitQueue to_split;
  std::set<Dart_const_handle> queued;
  for (Dart_handle d : darts_leaving(lcc, vertex)) {
    queue_longest_edge(lcc, d, min_edge_length_m, queued, to_split);
  }
  return bisect_queued(lcc, to_split, static_cast<std::size_t>(max_particles), settings);
}

RefinementReport refine(ClothComplex& lcc, const RefinementOptions& options,
                        const SpringSettings& settings, const SizingInputs& inputs) {
  compute_sizing(lcc, options, inputs);
  RefinementReport report;
  // the longest edge of each triangle coarser than the field wants, in traversal order so that
  // runs are reproducible
  SplitQueue to_split;
  std::set<Dart_const_handle> queued;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    if (!(face_metric_length2(lcc, d) > 1.0)) continue;
    ++report.candidate_faces;
    queue_longest_edge(lcc, d, options.min_edge_length_m, queued, to_split);
  }
  report.splits =
      bisect_queued(lcc, to_split, static_cast<std::size_t>(options.max_particles), settings);
  return report;
}

}  // namespace tissu
