#include "solver/collision/self_collision.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>

#include "solver/collision/collision_pairs.hpp"
#include "solver/collision/continuous_collision.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

/// Impact zones stop after this many passes; the step then reports resolved = false.
constexpr int max_zone_passes = 32;

PairMotion motion_of(const CandidatePair& pair, const Eigen::VectorXd& start_x,
                     const Eigen::VectorXd& end_x) {
  PairMotion m;
  for (int k = 0; k < 4; ++k) {
    m.start[k] = start_x.segment<3>(3 * pair.particle[k]);
    m.displacement[k] = end_x.segment<3>(3 * pair.particle[k]) - m.start[k];
  }
  return m;
}

/// Whether the boxes of the pair's two primitives over the step (`step`: each particle's), the
/// first grown by `reach_m`, overlap: pairs kept for a whole skin around their particles are
/// mostly farther apart than that, and this test is far cheaper than the pair's own. (The broad
/// phase's box_of in collision_pairs.cpp builds such boxes too; this one, on a hot path, keeps
/// to Eigen arrays: through AlignedBox a settled step took 10 to 15 % longer.)
bool within_reach(const CandidatePair& pair, const ParticleBoxes& step, double reach_m) {
  const int first_size = pair.first_primitive_size();
  Eigen::Array3d first_low = step.low.col(pair.particle[0]),
                 first_high = step.high.col(pair.particle[0]);
  if (first_size == 2) {
    first_low = first_low.min(step.low.col(pair.particle[1]).array());
    first_high = first_high.max(step.high.col(pair.particle[1]).array());
  }
  Eigen::Array3d second_low = step.low.col(pair.particle[first_size]),
                 second_high = step.high.col(pair.particle[first_size]);
  for (int k = first_size + 1; k < 4; ++k) {
    second_low = second_low.min(step.low.col(pair.particle[k]).array());
    second_high = second_high.max(step.high.col(pair.particle[k]).array());
  }
  return (first_low - reach_m <= second_high).all() && (second_low <= first_high + reach_m).all();
}

/// The distance between the pair's primitives with each particle at its box, when every box is a
/// point; else 0, which rules nothing out (m).
double gap_at_boxes_m(const CandidatePair& pair, const ParticleBoxes& boxes) {
  PairMotion at_boxes;
  for (int k = 0; k < 4; ++k) {
    if (boxes.is_path(pair.particle[k])) return 0.0;
    at_boxes.start[k] = boxes.low.col(pair.particle[k]);
    at_boxes.displacement[k].setZero();
  }
  return proximity_at_end(pair, at_boxes, 0.0).distance_m;
}

/// Fills cache.gap_m for the pairs found since it was last filled.
void add_gaps(SelfCollisionCache& cache) {
  const int first = static_cast<int>(cache.gap_m.size()), n = static_cast<int>(cache.pairs.size());
  cache.gap_m.resize(n);
#pragma omp parallel for schedule(static) if (n - first >= min_parallel_items)
  for (int i = first; i < n; ++i) cache.gap_m[i] = gap_at_boxes_m(cache.pairs[i], cache.boxes);
}

/// test(pair, motion) for every candidate, in parallel, keeping the contacts in candidate order.
template <class Test>
std::vector<ContactPair> contacts_among(const std::vector<CandidatePair>& candidates,
                                        const Eigen::VectorXd& start_x,
                                        const Eigen::VectorXd& end_x, Test&& test) {
  const int n = static_cast<int>(candidates.size());
  std::vector<std::optional<ContactPair>> found(n);
#pragma omp parallel for schedule(static) if (n >= min_parallel_items)
  for (int i = 0; i < n; ++i)
    found[i] = test(candidates[i], motion_of(candidates[i], start_x, end_x));
  std::vector<ContactPair> contacts;
  for (const std::optional<ContactPair>& c : found) {
    if (c) contacts.push_back(*c);
  }
  return contacts;
}

/// The candidates for which keep(pair, i) holds (i: the pair's index), in order; evaluated in
/// parallel.
template <class Keep>
std::vector<CandidatePair> pairs_where(const std::vector<CandidatePair>& candidates, Keep&& keep) {
  const int n = static_cast<int>(candidates.size());
  std::vector<char> kept(n);
#pragma omp parallel for schedule(static) if (n >= min_parallel_items)
  for (int i = 0; i < n; ++i) kept[i] = keep(candidates[i], i);
  std::vector<CandidatePair> result;
  for (int i = 0; i < n; ++i) {
    if (kept[i]) result.push_back(candidates[i]);
  }
  return result;
}

/// |x_p - points_p| for each particle p (m): `x` 3#P, `points` 3 x #P.
Eigen::VectorXd distances_m(const Eigen::VectorXd& x, const Eigen::Matrix3Xd& points) {
  return (x.reshaped(3, points.cols()) - points).colwise().norm().transpose();
}

/// How much closer the pair's primitives can have come when each particle p went at most
/// `went_m[p]` (m): the farthest any corner of the first primitive went plus the farthest any of
/// the second's, since each primitive's closest point is a convex combination of its corners.
double closing_bound_m(const CandidatePair& pair, const Eigen::VectorXd& went_m) {
  const int first_size = pair.first_primitive_size();
  double first_m = 0.0, second_m = 0.0;
  for (int k = 0; k < 4; ++k) {
    double& farthest_m = k < first_size ? first_m : second_m;
    farthest_m = std::max(farthest_m, went_m[pair.particle[k]]);
  }
  return first_m + second_m;
}

/// Step 1's test: the candidates closer than `thickness_m` at the end of the step, in candidate
/// order, and every candidate's distance at the end (`end_distance_m`, m), for may_still_touch.
std::vector<ContactPair> proximities(const std::vector<CandidatePair>& candidates,
                                     const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x,
                                     double thickness_m, std::vector<double>& end_distance_m) {
  const int n = static_cast<int>(candidates.size());
  std::vector<EndProximity> found(n);
#pragma omp parallel for schedule(static) if (n >= min_parallel_items)
  for (int i = 0; i < n; ++i)
    found[i] =
        proximity_at_end(candidates[i], motion_of(candidates[i], start_x, end_x), thickness_m);
  std::vector<ContactPair> contacts;
  end_distance_m.resize(n);
  for (int i = 0; i < n; ++i) {
    end_distance_m[i] = found[i].distance_m;
    if (found[i].contact) contacts.push_back(*found[i].contact);
  }
  return contacts;
}

/// The candidates that may touch (within `tolerance_m`) during the step after step 1 moved the
/// end positions from `before_x` to `end_x`: those first_impact could find crossing. A pair's
/// distance at the end is at least its distance before (`end_distance_m`) less closing_bound_m of
/// how far step 1 moved each particle; conservative advancement (stays_farther_than) rules out
/// the others. On a flat sheet, most candidates are coplanar neighbours a good part of an edge
/// apart: this spares their closest points a second computation.
std::vector<CandidatePair> may_still_touch(const std::vector<CandidatePair>& candidates,
                                           const std::vector<double>& end_distance_m,
                                           const Eigen::VectorXd& before_x,
                                           const Eigen::VectorXd& start_x,
                                           const Eigen::VectorXd& end_x, double tolerance_m) {
  const Eigen::VectorXd moved_m = distances_m(end_x, before_x.reshaped(3, before_x.size() / 3));
  return pairs_where(candidates, [&](const CandidatePair& pair, int i) {
    // twice the tolerance: the bound must not rule out a pair the exact test, in round-off, keeps
    return !stays_farther_than(pair, motion_of(pair, start_x, end_x), 2.0 * tolerance_m,
                               end_distance_m[i] - closing_bound_m(pair, moved_m));
  });
}

/// Per-particle changes summed over pairs, then averaged over the pairs of each particle.
struct Corrections {
  explicit Corrections(int particles)
      : position(Eigen::VectorXd::Zero(3 * particles)),
        velocity(Eigen::VectorXd::Zero(3 * particles)),
        pairs(particles, 0) {}
  Eigen::VectorXd position;  ///< 3#P (m)
  Eigen::VectorXd velocity;  ///< 3#P (m/s)
  std::vector<int> pairs;

  void apply(State& state, double h, bool move_with_velocity) {
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p] == 0) continue;
      const Eigen::Vector3d dv = velocity.segment<3>(3 * p) / pairs[p];
      state.x.segment<3>(3 * p) += position.segment<3>(3 * p) / pairs[p];
      if (move_with_velocity) state.x.segment<3>(3 * p) += h * dv;
      state.v.segment<3>(3 * p) += dv;
    }
  }
};

/// 1/m of the pair's four particles (1/kg), 0 for those that cannot move.
using PairInverseMasses = Eigen::Vector4d;

PairInverseMasses of_pair(const Eigen::VectorXd& inverse_mass, const ContactPair& c) {
  return {inverse_mass[c.particle[0]], inverse_mass[c.particle[1]], inverse_mass[c.particle[2]],
          inverse_mass[c.particle[3]]};
}

/// Who may move when a pair's relative position r = sum_k w_k x_k is corrected along `direction`:
/// particle k would move along w_k direction. A pinned particle never moves. A particle an
/// obstacle holds moves only away from that obstacle (w_k direction . n > 0), never into it: a
/// layer falling through another onto the floor in one step is held by the floor too, and must
/// still be lifted back above the layer it crossed.
struct Mobility {
  const Eigen::VectorXd& inverse_mass;     ///< #P, 0 for pinned particles (1/kg)
  const Eigen::Matrix3Xd& holding_normal;  ///< 3 x #P, 0 where no obstacle holds (or empty)

  PairInverseMasses along(const ContactPair& c, const Eigen::Vector3d& direction) const {
    PairInverseMasses result = of_pair(inverse_mass, c);
    if (holding_normal.cols() == 0) return result;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d n = holding_normal.col(c.particle[k]);
      if (!n.isZero() && !(c.weight[k] * direction.dot(n) > 0.0)) result[k] = 0.0;
    }
    return result;
  }
};

/// sum_k w_k^2 / m_k: the inverse of the pair's effective mass along its normal (1/kg).
double inverse_effective_mass(const PairInverseMasses& inverse_mass, const ContactPair& c) {
  return c.weight.cwiseAbs2().dot(inverse_mass);
}

/// Adds, to particle k of the pair, w_k / m_k times `impulse`: a mass-weighted share of a change
/// `wanted` of the pair's relative position or velocity (impulse = wanted / sum_k w_k^2 / m_k),
/// which conserves momentum since sum_k w_k = 0. No particle's share exceeds |wanted|: when the
/// heavy end of a pair cannot move (pinned, or held by an obstacle), the formula would throw a
/// light end by |wanted| / w_k, unboundedly far for a small weight; impact zones handle the rest.
/// Nothing is shared when no particle of the pair can move.
void share(const PairInverseMasses& inverse_mass, const ContactPair& c,
           const Eigen::Vector3d& wanted, Eigen::VectorXd& out) {
  const double pair_inverse_mass = inverse_effective_mass(inverse_mass, c);
  if (!(pair_inverse_mass > 0.0)) return;
  const double limit = wanted.norm();
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector3d d = c.weight[k] * inverse_mass[k] / pair_inverse_mass * wanted;
    const double size = d.norm();
    if (size > limit) d *= limit / size;
    out.segment<3>(3 * c.particle[k]) += d;
  }
}

Eigen::Vector3d relative(const ContactPair& c, const Eigen::VectorXd& values) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) r += c.weight[k] * values.segment<3>(3 * c.particle[k]);
  return r;
}

void count_pair(const ContactPair& c, Corrections& out) {
  for (int k = 0; k < 4; ++k) ++out.pairs[c.particle[k]];
}

/// Step 1: push close pairs out to the thickness, stop their approach, apply friction. Friction
/// moves no particle an obstacle holds (`held_inverse_mass` is 0 there): the obstacle's friction
/// has set its tangential velocity.
void repel(const Mobility& mobility, const Eigen::VectorXd& held_inverse_mass,
           const std::vector<ContactPair>& close, const SelfCollisionOptions& o, double h,
           State& state) {
  const int particles = static_cast<int>(held_inverse_mass.size());
  Corrections push(particles), friction(particles);
  for (const ContactPair& c : close) {
    const Eigen::Vector3d& n = c.normal;
    const PairInverseMasses apart = mobility.along(c, n);  // both corrections push along +n
    if (!(inverse_effective_mass(apart, c) > 0.0)) continue;
    share(apart, c, (o.thickness_m - c.distance_m) * n, push.position);
    const Eigen::Vector3d v_rel = relative(c, state.v);
    const double v_n = v_rel.dot(n);
    if (v_n < 0.0) {
      share(apart, c, -v_n * n, push.velocity);
      const Eigen::Vector3d v_t = v_rel - v_n * n;
      const double speed_t = v_t.norm();
      if (speed_t > 0.0) {
        const double slowed = std::min(o.friction * -v_n / speed_t, 1.0);
        share(of_pair(held_inverse_mass, c), c, -slowed * v_t, friction.velocity);
      }
    }
    count_pair(c, push);
    count_pair(c, friction);
  }
  push.apply(state, h, /*move_with_velocity=*/false);
  friction.apply(state, h, /*move_with_velocity=*/true);
}

/// Step 2: cancel the approaching relative displacement of each crossing pair along its normal.
void stop_crossings(const Mobility& mobility, const std::vector<ContactPair>& impacts,
                    const Eigen::VectorXd& start_x, double h, State& state) {
  Corrections stop(static_cast<int>(mobility.inverse_mass.size()));
  const Eigen::VectorXd displacement = state.x - start_x;
  for (const ContactPair& c : impacts) {
    const PairInverseMasses apart = mobility.along(c, c.normal);
    const double approach_m = relative(c, displacement).dot(c.normal);
    if (!(inverse_effective_mass(apart, c) > 0.0) || approach_m >= 0.0) continue;
    share(apart, c, -approach_m * c.normal, stop.position);
    count_pair(c, stop);
  }
  stop.velocity = stop.position / h;
  stop.apply(state, h, /*move_with_velocity=*/false);
}

int find_root(std::vector<int>& parent, int p) {
  while (parent[p] != p) p = parent[p] = parent[parent[p]];
  return p;
}

/// Step 3: merges the particles of every impact into zones and moves each zone as one.
int move_zones_rigidly(const SpringModel& model, const Eigen::VectorXd& inverse_mass,
                       const std::vector<ContactPair>& impacts, std::vector<int>& zone_parent,
                       const Eigen::VectorXd& start_x, double h, State& state) {
  for (const ContactPair& c : impacts) {
    for (int k = 1; k < 4; ++k) {
      const int a = find_root(zone_parent, c.particle[0]),
                b = find_root(zone_parent, c.particle[k]);
      if (a != b) zone_parent[std::max(a, b)] = std::min(a, b);
    }
  }
  const int particles = model.particle_count();
  // per zone (indexed by its root): mass, mass-weighted displacement, and the particles in it that
  // cannot be moved (pinned or held by an obstacle), whose mean displacement the zone then takes:
  // it stays where it started on a still pin, and moves with an obstacle that carried a particle
  // (left at its start, a sleeve's zone would stay behind the arm that moves through it)
  std::vector<double> mass_kg(particles, 0.0);
  std::vector<int> size(particles, 0), immovable(particles, 0);
  Eigen::VectorXd weighted_displacement = Eigen::VectorXd::Zero(3 * particles);   // kg m
  Eigen::VectorXd immovable_displacement = Eigen::VectorXd::Zero(3 * particles);  // m, summed
  for (int p = 0; p < particles; ++p) {
    const int root = find_root(zone_parent, p);
    const Eigen::Vector3d displacement = state.x.segment<3>(3 * p) - start_x.segment<3>(3 * p);
    mass_kg[root] += model.mass[p];
    ++size[root];
    weighted_displacement.segment<3>(3 * root) += model.mass[p] * displacement;
    if (inverse_mass[p] == 0.0) {
      ++immovable[root];
      immovable_displacement.segment<3>(3 * root) += displacement;
    }
  }
  int zone_particles = 0;
  for (int p = 0; p < particles; ++p) {
    const int root = find_root(zone_parent, p);
    if (size[root] < 2) continue;  // not in any zone
    ++zone_particles;
    const Eigen::Vector3d d =
        immovable[root] > 0
            ? Eigen::Vector3d(immovable_displacement.segment<3>(3 * root) / immovable[root])
            : Eigen::Vector3d(weighted_displacement.segment<3>(3 * root) / mass_kg[root]);
    if (model.pinned[p]) continue;
    state.x.segment<3>(3 * p) = start_x.segment<3>(3 * p) + d;
    state.v.segment<3>(3 * p) = d / h;
  }
  return zone_particles;
}

/// When more than one particle in this many leaves its box in a step, the whole cloth is searched
/// again: the primitives of those particles would be much of the surface.
constexpr int whole_search_divisor = 8;

/// Whether `x` (m) lies within particle p's box grown by `grow_m` along every axis.
bool within(const ParticleBoxes& boxes, int p, const Eigen::Vector3d& x, double grow_m) {
  return (x - boxes.low.col(p)).minCoeff() >= -grow_m &&
         (boxes.high.col(p) - x).minCoeff() >= -grow_m;
}

/// Whether particle p's step from `start_x` to `end_x` ends within half the skin of its start.
bool slow(int p, const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x, double half_skin_m) {
  return (end_x.segment<3>(3 * p) - start_x.segment<3>(3 * p)).cwiseAbs().maxCoeff() <= half_skin_m;
}

/// Gives particle p its box for the coming steps: its end position when its step stays within
/// half the skin of it, so that it may wander that far; else the step's path, searched again at
/// the next step (is_path).
void place(int p, const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x, double half_skin_m,
           ParticleBoxes& boxes) {
  const Eigen::Vector3d start = start_x.segment<3>(3 * p), end = end_x.segment<3>(3 * p);
  const bool path = !slow(p, start_x, end_x, half_skin_m);
  boxes.low.col(p) = path ? start.cwiseMin(end) : end;
  boxes.high.col(p) = path ? start.cwiseMax(end) : end;
}

/// Whether any of the pair's particles is flagged.
bool has_flagged(const CandidatePair& pair, const std::vector<char>& flagged) {
  return std::any_of(pair.particle.begin(), pair.particle.end(), [&](int p) { return flagged[p]; });
}

/// Brings cache.pairs (and their gaps) up to the pairs to test this step. Every pair of primitives
/// whose paths over the step come within the thickness is among them: a cached pair's particles
/// stay within half the skin of their boxes (per axis), so their primitives' boxes grow by less
/// than the skin the cache was searched with.
/// - No particle left its box: the cached pairs.
/// - A few left (a sliding hem): their pairs are searched again, with new boxes.
/// - Many left (a falling cloth): the whole cloth is searched; with new boxes if few particles
///   move farther than half the skin in the step, else with the step's paths only, and no cache.
/// The skin is the option's, at most half the mean edge: the kept pairs grow with the square of
/// the skin over the edge (a 1 cm skin on 1 cm edges keeps 200 pairs per particle).
void update_kept_pairs(const SpringModel& model, const SelfCollisionOptions& o,
                       const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x,
                       SelfCollisionCache& cache) {
  if (cache.built_for_model != model.identity) {
    cache.skin_m =
        std::min(o.skin_m, 0.5 * mean_edge_length_m(model, ParticleBoxes::swept(end_x, end_x)));
  }
  const double half_skin_m = 0.5 * cache.skin_m;
  const double cached_margin_m = o.thickness_m + cache.skin_m;
  const int particles = model.particle_count();
  if (cache.built_for_model == model.identity && cache.boxes.size() == particles) {
    std::vector<char> leaving(particles, 0);
    int leaving_count = 0;
    for (int p = 0; p < particles; ++p) {
      leaving[p] = cache.boxes.is_path(p) ||
                   !within(cache.boxes, p, start_x.segment<3>(3 * p), half_skin_m) ||
                   !within(cache.boxes, p, end_x.segment<3>(3 * p), half_skin_m);
      leaving_count += leaving[p];
    }
    if (leaving_count == 0) return;
    if (leaving_count * whole_search_divisor <= particles) {
      for (int p = 0; p < particles; ++p) {
        if (leaving[p]) place(p, start_x, end_x, half_skin_m, cache.boxes);
      }
      int kept = 0;
      for (std::size_t i = 0; i < cache.pairs.size(); ++i) {
        if (has_flagged(cache.pairs[i], leaving)) continue;
        cache.pairs[kept] = cache.pairs[i];
        cache.gap_m[kept++] = cache.gap_m[i];
      }
      cache.pairs.resize(kept);
      cache.gap_m.resize(kept);
      const std::vector<CandidatePair> found = collision_candidates_touching(
          model, cache.boxes, cached_margin_m, o.thickness_m, leaving);
      cache.pairs.insert(cache.pairs.end(), found.begin(), found.end());
      add_gaps(cache);
      return;
    }
  }
  cache.built_for_model = model.identity;
  int fast = 0;
  for (int p = 0; p < particles; ++p) fast += !slow(p, start_x, end_x, half_skin_m);
  if (fast * whole_search_divisor <= particles) {
    cache.boxes.low.resize(3, particles);
    cache.boxes.high.resize(3, particles);
    for (int p = 0; p < particles; ++p) place(p, start_x, end_x, half_skin_m, cache.boxes);
    cache.pairs = collision_candidates(model, cache.boxes, cached_margin_m, o.thickness_m);
    cache.gap_m.clear();
    add_gaps(cache);
  } else {
    cache.boxes = {};
    cache.pairs = collision_candidates(model, start_x, end_x, o.thickness_m, o.thickness_m);
    cache.gap_m.assign(cache.pairs.size(), 0.0);
  }
}

SelfCollisionReport resolve(const SpringModel& model, const SelfCollisionOptions& options,
                            double time_step_s, const Eigen::VectorXd& start_x,
                            const Eigen::Matrix3Xd& holding_normal, SelfCollisionCache& cache,
                            State& state) {
  SelfCollisionReport report;
  const double h = time_step_s;
  const double touching_m = 1e-3 * options.thickness_m;  // closest points this near have met
  const Mobility mobility{model.inverse_mass, holding_normal};
  Eigen::VectorXd inverse_mass = model.inverse_mass;  // 0 where held, for friction and zones
  for (Eigen::Index p = 0; p < holding_normal.cols(); ++p) {
    if (!holding_normal.col(p).isZero()) inverse_mass[p] = 0.0;
  }

  // the kept pairs whose primitives may come within the thickness in this step, found in the
  // frame that moves with the cloth
  const Eigen::Vector3d frame_start_m = cache.frame_m;
  const Eigen::Vector3d frame_end_m =
      frame_start_m + frame_step_m(start_x, state.x, 0.5 * options.skin_m);
  const Eigen::VectorXd start_in_frame = relative_to(start_x, frame_start_m);
  const Eigen::VectorXd end_in_frame = relative_to(state.x, frame_end_m);
  update_kept_pairs(model, options, start_in_frame, end_in_frame, cache);
  cache.frame_m = frame_end_m;
  const std::vector<CandidatePair> near =
      kept_pairs_within_reach(cache, start_in_frame, end_in_frame, options.thickness_m);
  report.candidates = static_cast<int>(near.size());
  std::vector<double> end_distance_m;
  const std::vector<ContactPair> close =
      proximities(near, start_x, state.x, options.thickness_m, end_distance_m);
  report.proximities = static_cast<int>(close.size());
  const Eigen::VectorXd before_repel_x = state.x;
  repel(mobility, inverse_mass, close, options, h, state);

  // the impulse passes look for crossings among the pairs found above: their corrections move
  // particles by less than the thickness the boxes were grown by, or undo part of their step
  auto crossings_among = [&](const std::vector<CandidatePair>& pairs) {
    return contacts_among(pairs, start_x, state.x,
                          [&](const CandidatePair& p, const PairMotion& m) {
                            return first_impact(p, m, touching_m);
                          });
  };
  for (int pass = 0; pass < options.impulse_passes; ++pass) {
    const std::vector<ContactPair> impacts =
        pass == 0 ? crossings_among(may_still_touch(near, end_distance_m, before_repel_x, start_x,
                                                    state.x, touching_m))
                  : crossings_among(near);
    if (impacts.empty()) return report;
    report.impacts += static_cast<int>(impacts.size());
    stop_crossings(mobility, impacts, start_x, h, state);
  }
  // impact zones, the last resort: merged among the step's pairs, then checked against a fresh
  // search of the whole cloth, since rigid zone motion is not bounded by the pairs' margin
  auto all_crossings = [&] {
    return crossings_among(collision_candidates(
        model, start_in_frame, relative_to(state.x, frame_end_m), touching_m, options.thickness_m));
  };
  std::vector<int> zone_parent(model.particle_count());
  std::iota(zone_parent.begin(), zone_parent.end(), 0);
  bool fresh_search = false;
  for (int pass = 0; pass < max_zone_passes; ++pass) {
    std::vector<ContactPair> impacts = fresh_search ? all_crossings() : crossings_among(near);
    if (impacts.empty() && !fresh_search) {
      fresh_search = true;
      impacts = all_crossings();
    }
    if (impacts.empty()) return report;
    report.zone_particles =
        move_zones_rigidly(model, inverse_mass, impacts, zone_parent, start_x, h, state);
  }
  report.resolved = all_crossings().empty();
  return report;
}

}  // namespace

Eigen::Vector3d frame_step_m(const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x,
                             double least_m) {
  // any common step is a valid frame: the median of up to 1,024 particles, evenly spread over
  // their numbering, is as good as the whole cloth's and costs nothing beside the step
  const Eigen::Index particles = start_x.size() / 3;
  const Eigen::Index stride = std::max<Eigen::Index>(1, particles / 1024);
  std::vector<double> steps_m;
  Eigen::Vector3d median_m = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3 && particles > 0; ++axis) {
    steps_m.clear();
    for (Eigen::Index p = 0; p < particles; p += stride) {
      steps_m.push_back(end_x[3 * p + axis] - start_x[3 * p + axis]);
    }
    const auto middle = steps_m.begin() + steps_m.size() / 2;
    std::nth_element(steps_m.begin(), middle, steps_m.end());
    median_m[axis] = *middle;
  }
  return median_m.cwiseAbs().maxCoeff() > least_m ? median_m : Eigen::Vector3d::Zero();
}

Eigen::VectorXd relative_to(const Eigen::VectorXd& x, const Eigen::Vector3d& origin_m) {
  Eigen::VectorXd result = x;
  result.reshaped(3, x.size() / 3).colwise() -= origin_m;
  return result;
}

std::vector<CandidatePair> kept_pairs_within_reach(const SelfCollisionCache& cache,
                                                   const Eigen::VectorXd& start_x,
                                                   const Eigen::VectorXd& end_x, double reach_m) {
  const ParticleBoxes step = ParticleBoxes::swept(start_x, end_x);
  const int particles = step.size();
  // how far each particle strays from its box's point over the step: the farther of its start
  // and end, its path being straight (unused where the gap is 0)
  Eigen::VectorXd stray_m = Eigen::VectorXd::Zero(particles);
  if (cache.boxes.size() == particles) {
    stray_m = distances_m(start_x, cache.boxes.low).cwiseMax(distances_m(end_x, cache.boxes.low));
  }
  return pairs_where(cache.pairs, [&](const CandidatePair& pair, int i) {
    return !(cache.gap_m[i] - closing_bound_m(pair, stray_m) > reach_m) &&
           within_reach(pair, step, reach_m);
  });
}

SelfCollisionReport resolve_self_collisions(const SpringModel& model,
                                            const SelfCollisionOptions& options, double time_step_s,
                                            const Eigen::VectorXd& start_x,
                                            const Eigen::Matrix3Xd& holding_normal,
                                            SelfCollisionCache& cache, State& state) {
  if (!options.enabled || model.triangles.rows() == 0) return {};
  const auto start = std::chrono::steady_clock::now();
  SelfCollisionReport report =
      resolve(model, options, time_step_s, start_x, holding_normal, cache, state);
  report.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace tissu
