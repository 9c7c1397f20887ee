#include "topology/apply_pins.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

#include "topology/eigen_conversions.hpp"

namespace tissu {
namespace {

struct Candidate {
  Vertex_handle vertex;
  double u;  ///< material coordinate along the frame's u axis (m)
  double v;  ///< material coordinate along the frame's v axis (m)
  Eigen::Vector3d rest;
};

std::vector<Candidate> candidates_of(ClothComplex& lcc, const ClothFrame& frame) {
  std::vector<Candidate> out;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Eigen::Vector3d rest = to_eigen(v->info().rest_position);
    out.push_back({v, rest.dot(frame.u_axis), rest.dot(frame.v_axis), rest});
  }
  return out;
}

/// Vertices on `side`, ordered along it.
std::vector<Candidate> side_vertices(const std::vector<Candidate>& all, Side side) {
  const bool along_u = side == Side::left || side == Side::right;
  const bool at_max = side == Side::right || side == Side::top;
  auto across = [&](const Candidate& c) { return along_u ? c.u : c.v; };
  auto along = [&](const Candidate& c) { return along_u ? c.v : c.u; };
  double low = std::numeric_limits<double>::infinity(), high = -low, extent = 0.0;
  for (const Candidate& c : all) {
    low = std::min(low, across(c));
    high = std::max(high, across(c));
    extent = std::max({extent, std::abs(c.u), std::abs(c.v)});
  }
  const double tolerance_m = 1e-6 * std::max(extent, high - low);
  const double target = at_max ? high : low;
  std::vector<Candidate> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out),
               [&](const Candidate& c) { return std::abs(across(c) - target) <= tolerance_m; });
  std::sort(out.begin(), out.end(),
            [&](const Candidate& a, const Candidate& b) { return along(a) < along(b); });
  return out;
}

Vertex_handle corner_vertex(const std::vector<Candidate>& all, Corner corner) {
  const bool top = corner == Corner::top_left || corner == Corner::top_right;
  const bool left = corner == Corner::top_left || corner == Corner::bottom_left;
  const std::vector<Candidate> row = side_vertices(all, top ? Side::top : Side::bottom);
  return left ? row.front().vertex : row.back().vertex;
}

std::vector<Vertex_handle> select(const std::vector<Candidate>& all, const PinSelector& s,
                                  const std::string& where) {
  std::vector<Vertex_handle> chosen;
  switch (s.kind) {
    case PinSelector::Kind::corners:
      for (Corner c : s.corners) chosen.push_back(corner_vertex(all, c));
      break;
    case PinSelector::Kind::side: {
      if (s.every < 1) throw PinError(where + ": 'every' must be at least 1");
      const std::vector<Candidate> row = side_vertices(all, s.side);
      for (std::size_t k = 0; k < row.size(); ++k) {
        if (k % s.every == 0 || k + 1 == row.size()) chosen.push_back(row[k].vertex);
      }
      break;
    }
    case PinSelector::Kind::indices: {
      std::unordered_map<int, Vertex_handle> by_source;
      for (const Candidate& c : all) by_source.emplace(c.vertex->info().source_index, c.vertex);
      for (int index : s.indices) {
        auto it = by_source.find(index);
        if (it == by_source.end()) {
          throw PinError(where + ": vertex " + std::to_string(index) +
                         " is not a vertex of the cloth (ids run from 0)");
        }
        chosen.push_back(it->second);
      }
      break;
    }
    case PinSelector::Kind::box:
      for (const Candidate& c : all) {
        if (s.box.contains(c.rest)) chosen.push_back(c.vertex);
      }
      break;
  }
  if (chosen.empty()) throw PinError(where + ": selects no particle");
  return chosen;
}

}  // namespace

int apply_pins(ClothComplex& lcc, const std::vector<PinSelector>& selectors,
               const ClothFrame& frame) {
  const std::vector<Candidate> all = candidates_of(lcc, frame);
  if (all.empty()) return 0;
  for (std::size_t k = 0; k < selectors.size(); ++k) {
    const PinSelector& s = selectors[k];
    for (Vertex_handle v : select(all, s, "pins[" + std::to_string(k) + "]")) {
      v->info().pin_group = static_cast<int>(k);
      v->info().pinned = s.attach_at_s <= 0.0;
      if (v->info().pinned)
        v->info().velocity = to_vector(s.motion.point_velocity(to_eigen(v->point()), 0.0));
    }
  }
  return static_cast<int>(std::count_if(
      all.begin(), all.end(), [](const Candidate& c) { return c.vertex->info().pinned; }));
}

}  // namespace tissu
