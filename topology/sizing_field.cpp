#include "topology/sizing_field.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "topology/edge_measures.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/sizing_geometry.hpp"

namespace tissu {
namespace {

Eigen::Vector3d centroid(const std::array<Eigen::Vector3d, 3>& c) {
  return (c[0] + c[1] + c[2]) / 3.0;
}

/// Curvature (1/m) of the dart's interior edge relative to rest, |theta - theta0| / delta0, now
/// and at x + lookahead v (0 when lookahead_s is 0).
struct RelativeCurvature {
  double now_per_m = 0.0;
  double ahead_per_m = 0.0;
};

RelativeCurvature relative_curvature(const ClothComplex& lcc, Dart_const_handle d,
                                     double lookahead_s) {
  const auto rest = [&](Dart_const_handle e) { return to_eigen(rest_position(lcc, e)); };
  const double delta_m =
      (centroid(corners(lcc, d, rest)) - centroid(corners(lcc, lcc.opposite<2>(d), rest))).norm();
  if (!(delta_m > 0.0)) return {};
  const EdgeTurn turn = edge_turn(lcc, d, lookahead_s);
  return {std::abs(turn.now_rad) / delta_m, std::abs(turn.ahead_rad) / delta_m};
}

double longest_rest_edge_m(const ClothComplex& lcc, Dart_const_handle d) {
  double longest = 0.0;
  for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
    longest = std::max(longest, edge_rest_length_m(lcc, e));
  }
  return longest;
}

/// The term with the largest share, or the maximum edge length when its floor is above them all;
/// none where even the face's parent, of longest edge sqrt(2) L (bisection halves a right
/// triangle at its hypotenuse), would be under half the target: 2 L^2 sizing < 1/4, where
/// coarsening at the default hysteresis (0.5) may merge the face back.
SizingTerm leading_term(const TermShares& shares, double floor_per_m2, double sizing_per_m2,
                        double longest_m) {
  if (2.0 * longest_m * longest_m * sizing_per_m2 < 0.25) return SizingTerm::none;
  return largest_share(shares, floor_per_m2);
}

}  // namespace

void compute_sizing(ClothComplex& lcc, const RefinementOptions& o, const SizingInputs& inputs) {
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    f->info().sizing_per_m2 = 0.0;
  }
  // per face: the terms' shares, and its longest rest edge, measured once
  struct FaceTerms {
    TermShares shares;
    double longest_m = 0.0;
  };
  std::unordered_map<const void*, FaceTerms> faces;
  faces.reserve(lcc.attributes<2>().size());
  const auto terms_of = [&](Dart_const_handle side) -> FaceTerms& {
    const auto [entry, added] = faces.try_emplace(&*lcc.attribute<2>(side));
    if (added) entry->second.longest_m = longest_rest_edge_m(lcc, side);
    return entry->second;
  };
  // curvature and strain: per face, the largest over its edges
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    const bool interior = !lcc.is_free<2>(d);
    double now_term = 0.0;    // (kappa now / angle)^2 (1/m^2)
    double ahead_term = 0.0;  // (kappa ahead / angle)^2 (1/m^2)
    if (o.curvature_threshold_rad > 0.0 && interior) {
      const RelativeCurvature kappa = relative_curvature(lcc, d, o.lookahead_s);
      const double now_over = kappa.now_per_m / o.curvature_threshold_rad;
      const double ahead_over = kappa.ahead_per_m / o.curvature_threshold_rad;
      now_term = now_over * now_over;
      ahead_term = ahead_over * ahead_over;
    }
    const double curvature_term = std::max(now_term, ahead_term);
    const double strain_over =
        o.strain_threshold > 0.0 ? edge_strain(lcc, d) / o.strain_threshold : 0.0;
    auto raise = [&](Dart_handle side) {
      FaceTerms& terms = terms_of(side);
      const double strain_term = strain_over * strain_over / (terms.longest_m * terms.longest_m);
      double& sizing = lcc.info<2>(side).sizing_per_m2;
      sizing = std::max(sizing, curvature_term + strain_term);
      TermShares& share = terms.shares;
      share.curvature = std::max(share.curvature, now_term);
      share.velocity = std::max(share.velocity, curvature_term - now_term);
      share.strain = std::max(share.strain, strain_term);
    };
    raise(d);
    if (interior) raise(lcc.opposite<2>(d));
  }
  const bool obstacles = o.obstacle_proximity && inputs.obstacles && !inputs.obstacles->empty();
  const NearestPlanes planes = obstacles ? nearest_planes(lcc, inputs) : NearestPlanes{};
  const double floor_per_m2 =
      o.max_edge_length_m > 0.0 ? 1.0 / (o.max_edge_length_m * o.max_edge_length_m) : 0.0;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    FaceRest& face = lcc.info<2>(d);
    FaceTerms& terms = terms_of(d);
    TermShares& share = terms.shares;
    if (obstacles && lcc.darts_of_orbit<1>(d).size() == 3) {
      share.obstacles = obstacle_metric(lcc, d, planes).trace();
      face.sizing_per_m2 += share.obstacles;
    }
    face.sizing_per_m2 = std::max(face.sizing_per_m2, floor_per_m2);
    face.sizing_term = leading_term(share, floor_per_m2, face.sizing_per_m2, terms.longest_m);
  }
}

double face_metric_length2(const ClothComplex& lcc, Dart_const_handle d) {
  const double longest_m = longest_rest_edge_m(lcc, d);
  return longest_m * longest_m * lcc.info<2>(d).sizing_per_m2;
}

}  // namespace tissu
