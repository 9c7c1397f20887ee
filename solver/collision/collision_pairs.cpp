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

template <int N>
Box swept_box(const std::array<int, N>& ids, const Eigen::VectorXd& start_x,
              const Eigen::VectorXd& end_x, double margin_m) {
  Box box;
  for (int p : ids) {
    box.extend(Eigen::Vector3d(start_x.segment<3>(3 * p)));
    box.extend(Eigen::Vector3d(end_x.segment<3>(3 * p)));
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

double mean_edge_length_m(const SpringModel& model, const Eigen::VectorXd& x) {
  double sum_m = 0.0;
  for (Eigen::Index e = 0; e < model.surface_edges.rows(); ++e) {
    sum_m +=
        (x.segment<3>(3 * model.surface_edges(e, 0)) - x.segment<3>(3 * model.surface_edges(e, 1)))
            .norm();
  }
  return model.surface_edges.rows() > 0 ? sum_m / model.surface_edges.rows() : 0.0;
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

}  // namespace

std::vector<CandidatePair> collision_candidates(const SpringModel& model,
                                                const Eigen::VectorXd& start_x,
                                                const Eigen::VectorXd& end_x, double margin_m,
                                                double material_gap_m) {
  const bool has_rest = model.rest_x.size() == 3 * model.particle_count() && material_gap_m > 0.0;
  const auto keep = [&](const CandidatePair& pair) {
    return !all_pinned(model, pair.particle) &&
           !(has_rest && material_neighbours(pair, model.rest_x, material_gap_m));
  };
  const int particles = model.particle_count();
  const int triangles = static_cast<int>(model.triangles.rows());
  const int edges = static_cast<int>(model.surface_edges.rows());
  if (triangles == 0) return {};
  std::vector<Box> vertex_box(particles), triangle_box(triangles), edge_box(edges);
  for (int p = 0; p < particles; ++p) {
    vertex_box[p] = swept_box<1>({p}, start_x, end_x, margin_m);
  }
  for (int t = 0; t < triangles; ++t) {
    triangle_box[t] = swept_box<3>(
        {model.triangles(t, 0), model.triangles(t, 1), model.triangles(t, 2)}, start_x, end_x, 0.0);
  }
  for (int e = 0; e < edges; ++e) {
    edge_box[e] = swept_box<2>({model.surface_edges(e, 0), model.surface_edges(e, 1)}, start_x,
                               end_x, 0.5 * margin_m);
  }

  // cells twice the mean edge, or larger if a box is more than 8 cells wide: a cloth that is
  // blowing up (m/s in the hundreds) must not fill the table with millions of cells
  double widest_m = 0.0;
  for (const std::vector<Box>* boxes : {&vertex_box, &triangle_box, &edge_box}) {
    for (const Box& box : *boxes) widest_m = std::max(widest_m, box.sizes().maxCoeff());
  }
  const CellGrid grid{
      std::max({2.0 * mean_edge_length_m(model, end_x), 4.0 * margin_m, widest_m / 8.0})};

  const CellTable triangle_table(triangle_box, grid);
  std::vector<CandidatePair> pairs = collect_in_order(particles, [&](int p, auto& out) {
    for_each_overlapping(vertex_box[p], triangle_box, grid, triangle_table, [&](int t) {
      const std::array<int, 4> ids{p, model.triangles(t, 0), model.triangles(t, 1),
                                   model.triangles(t, 2)};
      if (ids[1] == p || ids[2] == p || ids[3] == p) return;
      if (const CandidatePair pair{ids, false}; keep(pair)) out.push_back(pair);
    });
  });

  const CellTable edge_table(edge_box, grid);
  std::vector<CandidatePair> edge_pairs = collect_in_order(edges, [&](int e, auto& out) {
    const int a = model.surface_edges(e, 0), b = model.surface_edges(e, 1);
    for_each_overlapping(
        edge_box[e], edge_box, grid, edge_table,
        [&](int f) {
          const int c = model.surface_edges(f, 0), d = model.surface_edges(f, 1);
          const std::array<int, 4> ids{a, b, c, d};
          if (a == c || a == d || b == c || b == d) return;
          if (const CandidatePair pair{ids, true}; keep(pair)) out.push_back(pair);
        },
        /*first=*/e);
  });
  pairs.insert(pairs.end(), edge_pairs.begin(), edge_pairs.end());
  return pairs;
}

}  // namespace tissu
