#include "solver/collision/collision_pairs.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "solver/collision/primitive_distance.hpp"
#include "solver/parallel.hpp"

namespace tissu {
namespace {

using Box = Eigen::AlignedBox3d;

/// The box of a primitive whose particles are `ids`: the union of their boxes, grown by `margin_m`.
template <int N>
Box box_of(const std::array<int, N>& ids, const ParticleBoxes& boxes, double margin_m) {
  Box box;
  for (int p : ids) {
    box.extend(Eigen::Vector3d(boxes.low.col(p)));
    box.extend(Eigen::Vector3d(boxes.high.col(p)));
  }
  box.min().array() -= margin_m;
  box.max().array() += margin_m;
  return box;
}

/// A uniform grid hashed into 64 bits; distinct cells that share a bucket only add candidates,
/// which the box test then drops.
struct CellGrid {
  double cell_m;

  Eigen::Vector3i cell_of(const Eigen::Vector3d& x_m) const {
    return (x_m / cell_m).array().floor().cast<int>();
  }
  /// Teschner's key, then splitmix64's finaliser, so that its low bits, which pick the bucket,
  /// depend on every coordinate's every bit.
  static std::uint64_t key(int i, int j, int k) {
    std::uint64_t z = (static_cast<std::uint64_t>(i) * 73856093u) ^
                      (static_cast<std::uint64_t>(j) * 19349663u) ^
                      (static_cast<std::uint64_t>(k) * 83492791u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }
  template <class Visit>
  void for_each_cell(const Box& box, Visit&& visit) const {
    const Eigen::Vector3i lo = cell_of(box.min()), hi = cell_of(box.max());
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) visit(key(i, j, k));
  }
};

/// Primitives by hashed cell: a counting sort of (cell key, primitive) into a power-of-two number
/// of buckets, built in O(n) and looked up in O(1) (Teschner et al. 2003). A bucket may also hold
/// primitives of other cells with a colliding key; the box test drops them. Within a bucket a
/// primitive's entries are adjacent, since primitives are inserted in order.
struct CellTable {
  std::uint64_t bucket_mask = 0;
  std::vector<int> bucket_start;  ///< #buckets + 1
  std::vector<int> primitives;

  CellTable(const std::vector<Box>& boxes, const CellGrid& grid) {
    std::vector<std::pair<std::uint64_t, int>> entries;  // (key, primitive)
    for (int b = 0; b < static_cast<int>(boxes.size()); ++b) {
      grid.for_each_cell(boxes[b], [&](std::uint64_t key) { entries.emplace_back(key, b); });
    }
    std::uint64_t buckets = 1;
    while (buckets < 2 * entries.size()) buckets *= 2;
    bucket_mask = buckets - 1;
    bucket_start.assign(buckets + 1, 0);
    for (const auto& [key, b] : entries) ++bucket_start[(key & bucket_mask) + 1];
    for (std::uint64_t k = 0; k < buckets; ++k) bucket_start[k + 1] += bucket_start[k];
    primitives.resize(entries.size());
    std::vector<int> cursor(bucket_start.begin(), bucket_start.end() - 1);
    for (const auto& [key, b] : entries) primitives[cursor[key & bucket_mask]++] = b;
  }

  /// Calls visit(primitive) for each primitive in the bucket of `key`, each once.
  template <class Visit>
  void for_each_in(std::uint64_t key, Visit&& visit) const {
    const std::uint64_t bucket = key & bucket_mask;
    for (int k = bucket_start[bucket]; k < bucket_start[bucket + 1]; ++k) {
      if (k == bucket_start[bucket] || primitives[k] != primitives[k - 1]) visit(primitives[k]);
    }
  }
};

/// Runs collect(i, out) for i in [0, n) on every thread and concatenates the outputs in the
/// order of i: blocks of items are handed out dynamically (crumpled regions cost more than flat
/// ones) but each block writes to its own list.
template <class Collect>
std::vector<CandidatePair> collect_in_order(int n, Collect&& collect) {
  constexpr int block = 64;
  const int blocks = (n + block - 1) / block;
  std::vector<std::vector<CandidatePair>> per_block(blocks);
#pragma omp parallel for schedule(dynamic) if (n >= min_parallel_items)
  for (int b = 0; b < blocks; ++b) {
    for (int i = b * block; i < std::min(n, (b + 1) * block); ++i) collect(i, per_block[b]);
  }
  std::vector<CandidatePair> all;
  for (const std::vector<CandidatePair>& part : per_block) {
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

/// Calls visit(primitive) for each primitive of `table` whose box overlaps `box`, once: a pair of
/// overlapping boxes is reported only from the cell holding the low corner of their overlap.
/// Primitives numbered `first` or below are skipped before any test.
template <class Visit>
void for_each_overlapping(const Box& box, const std::vector<Box>& boxes, const CellGrid& grid,
                          const CellTable& table, Visit&& visit, int first = -1) {
  const Eigen::Vector3i lo = grid.cell_of(box.min()), hi = grid.cell_of(box.max());
  for (int i = lo.x(); i <= hi.x(); ++i) {
    for (int j = lo.y(); j <= hi.y(); ++j) {
      for (int k = lo.z(); k <= hi.z(); ++k) {
        table.for_each_in(CellGrid::key(i, j, k), [&](int b) {
          if (b <= first || !box.intersects(boxes[b])) return;
          const Eigen::Vector3i overlap_cell = grid.cell_of(box.min().cwiseMax(boxes[b].min()));
          if (overlap_cell == Eigen::Vector3i(i, j, k)) visit(b);
        });
      }
    }
  }
}

bool all_pinned(const SpringModel& model, const std::array<int, 4>& particles) {
  return std::all_of(particles.begin(), particles.end(), [&](int p) { return model.pinned[p]; });
}

/// Whether the pair's primitives lie closer than `gap_m` in material coordinates `rest_x`.
bool material_neighbours(const CandidatePair& pair, const Eigen::VectorXd& rest_x, double gap_m) {
  std::array<Eigen::Vector3d, 4> r;
  for (int k = 0; k < 4; ++k) r[k] = rest_x.segment<3>(3 * pair.particle[k]);
  Eigen::Vector3d between;
  if (pair.edge_edge) {
    const Eigen::Vector2d st = nearest_between_segments(r[0], r[1], r[2], r[3]);
    between = (r[0] + st[0] * (r[1] - r[0])) - (r[2] + st[1] * (r[3] - r[2]));
  } else {
    const Eigen::Vector3d w = nearest_on_triangle(r[0], r[1], r[2], r[3]);
    between = r[0] - (w[0] * r[1] + w[1] * r[2] + w[2] * r[3]);
  }
  return between.squaredNorm() < gap_m * gap_m;
}

/// The boxes of every vertex (grown by the margin), triangle (not grown) and edge (grown by half
/// of it), and the grid that hashes them: two primitives' boxes overlap when they are closer than
/// the margin.
struct SurfaceBoxes {
  SurfaceBoxes(const SpringModel& model, const ParticleBoxes& boxes, double margin_m)
      : vertex(model.particle_count()),
        triangle(model.triangles.rows()),
        edge(model.surface_edges.rows()) {
    for (std::size_t p = 0; p < vertex.size(); ++p) {
      vertex[p] = box_of<1>({static_cast<int>(p)}, boxes, margin_m);
    }
    for (std::size_t t = 0; t < triangle.size(); ++t) {
      triangle[t] = box_of<3>({model.triangles(t, 0), model.triangles(t, 1), model.triangles(t, 2)},
                              boxes, 0.0);
    }
    for (std::size_t e = 0; e < edge.size(); ++e) {
      edge[e] =
          box_of<2>({model.surface_edges(e, 0), model.surface_edges(e, 1)}, boxes, 0.5 * margin_m);
    }
    // cells twice the mean edge, or larger if a box is more than 8 cells wide: a cloth that is
    // blowing up (m/s in the hundreds) must not fill the table with millions of cells
    double widest_m = 0.0;
    for (const std::vector<Box>* all : {&vertex, &triangle, &edge}) {
      for (const Box& box : *all) widest_m = std::max(widest_m, box.sizes().maxCoeff());
    }
    grid.cell_m =
        std::max({2.0 * mean_edge_length_m(model, boxes), 4.0 * margin_m, widest_m / 8.0});
  }
  std::vector<Box> vertex, triangle, edge;
  CellGrid grid{0.0};
};

/// Makes the candidate pairs of one model, keeping those that are not neighbours.
struct PairMaker {
  const SpringModel& model;
  bool has_rest;
  double material_gap_m;

  void vertex_triangle(int p, int t, std::vector<CandidatePair>& out) const {
    const std::array<int, 4> ids{p, model.triangles(t, 0), model.triangles(t, 1),
                                 model.triangles(t, 2)};
    if (ids[1] == p || ids[2] == p || ids[3] == p) return;
    keep({ids, false}, out);
  }
  void edge_edge(int e, int f, std::vector<CandidatePair>& out) const {
    const int a = model.surface_edges(e, 0), b = model.surface_edges(e, 1);
    const int c = model.surface_edges(f, 0), d = model.surface_edges(f, 1);
    if (a == c || a == d || b == c || b == d) return;
    keep({{a, b, c, d}, true}, out);
  }
  void keep(const CandidatePair& pair, std::vector<CandidatePair>& out) const {
    if (all_pinned(model, pair.particle)) return;
    if (has_rest && material_neighbours(pair, model.rest_x, material_gap_m)) return;
    out.push_back(pair);
  }
};

PairMaker pair_maker(const SpringModel& model, double material_gap_m) {
  return {model, model.rest_x.size() == 3 * model.particle_count() && material_gap_m > 0.0,
          material_gap_m};
}

/// The indices of `rows` (a #items x N index matrix) with a touched particle, in order.
template <class Rows>
std::vector<int> touched_rows(const Rows& rows, const std::vector<char>& touched) {
  std::vector<int> result;
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    for (Eigen::Index k = 0; k < rows.cols(); ++k) {
      if (touched[rows(i, k)]) {
        result.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  return result;
}

std::vector<CandidatePair> concatenated(std::vector<CandidatePair> first,
                                        const std::vector<CandidatePair>& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

}  // namespace

double mean_edge_length_m(const SpringModel& model, const ParticleBoxes& boxes) {
  double sum_m = 0.0;
  for (Eigen::Index e = 0; e < model.surface_edges.rows(); ++e) {
    const int a = model.surface_edges(e, 0), b = model.surface_edges(e, 1);
    sum_m +=
        0.5 * (boxes.low.col(a) + boxes.high.col(a) - boxes.low.col(b) - boxes.high.col(b)).norm();
  }
  return model.surface_edges.rows() > 0 ? sum_m / model.surface_edges.rows() : 0.0;
}

ParticleBoxes ParticleBoxes::swept(const Eigen::VectorXd& start_x, const Eigen::VectorXd& end_x) {
  const auto start = start_x.reshaped(3, start_x.size() / 3);
  const auto end = end_x.reshaped(3, end_x.size() / 3);
  return {start.cwiseMin(end), start.cwiseMax(end)};
}

std::vector<CandidatePair> collision_candidates(const SpringModel& model,
                                                const Eigen::VectorXd& start_x,
                                                const Eigen::VectorXd& end_x, double margin_m,
                                                double material_gap_m) {
  return collision_candidates(model, ParticleBoxes::swept(start_x, end_x), margin_m,
                              material_gap_m);
}

std::vector<CandidatePair> collision_candidates(const SpringModel& model,
                                                const ParticleBoxes& boxes, double margin_m,
                                                double material_gap_m) {
  if (model.triangles.rows() == 0) return {};
  const SurfaceBoxes surface(model, boxes, margin_m);
  const PairMaker make = pair_maker(model, material_gap_m);
  const CellTable triangle_table(surface.triangle, surface.grid);
  std::vector<CandidatePair> pairs =
      collect_in_order(model.particle_count(), [&](int p, auto& out) {
        for_each_overlapping(surface.vertex[p], surface.triangle, surface.grid, triangle_table,
                             [&](int t) { make.vertex_triangle(p, t, out); });
      });
  const CellTable edge_table(surface.edge, surface.grid);
  const int edges = static_cast<int>(surface.edge.size());
  return concatenated(std::move(pairs), collect_in_order(edges, [&](int e, auto& out) {
                        for_each_overlapping(
                            surface.edge[e], surface.edge, surface.grid, edge_table,
                            [&](int f) { make.edge_edge(e, f, out); }, /*first=*/e);
                      }));
}

std::vector<CandidatePair> collision_candidates_touching(const SpringModel& model,
                                                         const ParticleBoxes& boxes,
                                                         double margin_m, double material_gap_m,
                                                         const std::vector<char>& touched) {
  if (model.triangles.rows() == 0) return {};
  const SurfaceBoxes surface(model, boxes, margin_m);
  const PairMaker make = pair_maker(model, material_gap_m);
  std::vector<int> touched_vertices;
  for (int p = 0; p < model.particle_count(); ++p) {
    if (touched[p]) touched_vertices.push_back(p);
  }
  const std::vector<int> touched_triangles = touched_rows(model.triangles, touched);
  const std::vector<int> touched_edges = touched_rows(model.surface_edges, touched);
  std::vector<char> edge_touched(surface.edge.size(), 0);
  for (int e : touched_edges) edge_touched[e] = 1;

  // vertex-triangle pairs: each touched vertex with every triangle, then each touched triangle
  // with the vertices not touched (the others were just paired with it)
  const CellTable triangle_table(surface.triangle, surface.grid);
  std::vector<CandidatePair> pairs =
      collect_in_order(static_cast<int>(touched_vertices.size()), [&](int i, auto& out) {
        const int p = touched_vertices[i];
        for_each_overlapping(surface.vertex[p], surface.triangle, surface.grid, triangle_table,
                             [&](int t) { make.vertex_triangle(p, t, out); });
      });
  const CellTable vertex_table(surface.vertex, surface.grid);
  pairs = concatenated(
      std::move(pairs),
      collect_in_order(static_cast<int>(touched_triangles.size()), [&](int i, auto& out) {
        const int t = touched_triangles[i];
        for_each_overlapping(surface.triangle[t], surface.vertex, surface.grid, vertex_table,
                             [&](int p) {
                               if (!touched[p]) make.vertex_triangle(p, t, out);
                             });
      }));
  // edge-edge pairs: each touched edge with every edge, a pair of touched ones once
  const CellTable edge_table(surface.edge, surface.grid);
  return concatenated(
      std::move(pairs),
      collect_in_order(static_cast<int>(touched_edges.size()), [&](int i, auto& out) {
        const int e = touched_edges[i];
        for_each_overlapping(surface.edge[e], surface.edge, surface.grid, edge_table, [&](int f) {
          if (f != e && !(edge_touched[f] && f < e)) make.edge_edge(e, f, out);
        });
      }));
}

}  // namespace tissu
