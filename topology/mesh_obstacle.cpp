#include "topology/mesh_obstacle.hpp"

#include <CGAL/Intersections_3/Segment_3_Triangle_3.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "solver/collision/triangle_bvh.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/winding_number.hpp"

namespace tissu {
namespace {

/// The triangles of an obstacle mesh, as vertex ids, after the checks and clean-up
/// make_mesh_surface documents.
struct ObstacleTriangles {
  std::vector<std::array<int, 3>> kept;
  /// zero-area triangles of distinct vertices (collinear corners, e.g. from a fan across a
  /// polygon's straight angle): they hold no area, but their edges belong to the surface's
  /// boundary chain, which they close
  std::vector<std::array<int, 3>> flat;
};

/// How far from the origin an obstacle's vertex may lie (m): a body scanned in millimetres fits,
/// and squared distances stay far from overflowing CGAL's exact fallback (beyond 1e154 m).
constexpr double max_coordinate_m = 1e6;

/// The reason `x`, vertex `v`, cannot be an obstacle's vertex, or "" if it can.
std::string vertex_refusal(int v, const Eigen::Vector3d& x) {
  if (!x.allFinite()) return "vertex " + std::to_string(v) + " has a non-finite coordinate";
  if (x.cwiseAbs().maxCoeff() > max_coordinate_m) {
    std::ostringstream message;
    message << "vertex " << v << " has a coordinate of " << x.cwiseAbs().maxCoeff()
            << " m; expected at most " << max_coordinate_m << " m from the origin";
    return message.str();
  }
  return "";
}

/// Farther than this from a mesh's box (m), a point is a blown-up particle: its distance is taken
/// to a corner, where CGAL's squared distances would overflow.
constexpr double far_beyond_m = 1e100;

bool has_zero_area(const IndexedMesh& mesh, const std::array<int, 3>& t) {
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  return (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).squaredNorm() == 0.0;
}

ObstacleTriangles obstacle_triangles(const IndexedMesh& mesh, ObstacleMeshReport& report) {
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  for (int v = 0; v < vertex_count; ++v) {
    if (const std::string refusal = vertex_refusal(v, mesh.vertices[v]); !refusal.empty()) {
      throw MeshError(refusal);
    }
  }
  if (mesh.faces.empty()) throw MeshError("the mesh has no faces");
  ObstacleTriangles triangles;
  std::set<std::array<int, 3>> seen;  // each triangle rotated to start at its smallest id
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    if (face.size() < 3) {
      throw MeshError("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                      " vertices; expected at least 3");
    }
    for (int v : face) {
      if (v < 0 || v >= vertex_count) {
        throw MeshError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                        ", but the mesh has " + std::to_string(vertex_count) + " vertices");
      }
    }
    int kept = 0, duplicates = 0;
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      std::array<int, 3> t{face[0], face[k], face[k + 1]};
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // nothing to the boundary
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      if (!seen.insert(t).second) {
        ++duplicates;
      } else if (has_zero_area(mesh, t)) {
        triangles.flat.push_back(t);
      } else {
        triangles.kept.push_back(t);
        ++kept;
      }
    }
    // a face counts as dropped when none of its triangles is kept (a fan across a straight
    // angle has a flat triangle, but the face itself is fine)
    if (kept == 0) ++(duplicates > 0 ? report.duplicate_faces : report.degenerate_faces);
  }
  if (triangles.kept.empty()) {
    throw MeshError("all " + std::to_string(mesh.faces.size()) +
                    " faces are degenerate (a repeated vertex or zero area)");
  }
  report.triangles = static_cast<int>(triangles.kept.size());
  return triangles;
}

/// Whether every directed edge a->b is matched by as many edges b->a: the triangles then bound
/// a volume (the boundary of their chain is empty) and their winding number is an integer.
bool is_closed(const ObstacleTriangles& triangles) {
  std::map<std::pair<int, int>, int> balance;  // (min, max) -> uses min->max minus max->min
  for (const auto* list : {&triangles.kept, &triangles.flat}) {
    for (const std::array<int, 3>& t : *list) {
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        balance[std::minmax(a, b)] += a < b ? 1 : -1;
      }
    }
  }
  return std::all_of(balance.begin(), balance.end(),
                     [](const auto& edge) { return edge.second == 0; });
}

/// Three corners per triangle, in `triangles`' order.
std::vector<Eigen::Vector3d> triangle_corners_of(const std::vector<Eigen::Vector3d>& vertices,
                                                 const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(3 * triangles.size());
  for (const std::array<int, 3>& t : triangles) {
    for (int v : t) corners.push_back(vertices[v]);
  }
  return corners;
}

class MeshSurface final : public SurfaceQuery {
 public:
  /// The surface of `corners` (three per triangle); `shape`, the hierarchy's shape if another
  /// pose of the same triangles has one (an animation's), else built here.
  MeshSurface(std::vector<Eigen::Vector3d> corners, bool closed,
              std::shared_ptr<const TriangleBvhShape> shape = nullptr)
      : m_closed(closed),
        m_bvh(hierarchy_of(std::move(corners), std::move(shape))),
        m_corners(m_bvh.corners()),
        m_box(m_bvh.bounds()) {}

  SurfaceDistance distance(const Eigen::Vector3d& x_m) const override {
    SurfaceDistance result = nearest(x_m);
    if (result.distance_m > 0.0 && m_closed && winding_number(x_m) > 0.5) {
      result.distance_m = -result.distance_m;  // inside
      result.normal = -result.normal;
    }
    return result;
  }

  /// Unsigned: the distance and the direction from the nearest point to x_m.
  SurfaceDistance nearest(const Eigen::Vector3d& x_m) const override {
    if (!(m_box.exteriorDistance(x_m) < far_beyond_m)) {  // or not finite: no tree search
      const Eigen::Vector3d offset = x_m - m_corners[0];
      return {offset.stableNorm(), offset.stableNormalized(), 0, Eigen::Vector3d::UnitX()};
    }
    const auto [index, barycentric, distance_m2] = m_bvh.nearest(x_m);
    const Eigen::Vector3d& a = m_corners[3 * index];
    const Eigen::Vector3d& b = m_corners[3 * index + 1];
    const Eigen::Vector3d& c = m_corners[3 * index + 2];
    const Eigen::Vector3d offset =
        x_m - (barycentric[0] * a + barycentric[1] * b + barycentric[2] * c);
    const double gap_m = offset.norm();
    if (!(gap_m > 1e-12)) return {0.0, (b - a).cross(c - a).normalized(), index, barycentric};
    return {gap_m, offset / gap_m, index, barycentric};
  }

  double distance_at_least_m(const Eigen::Vector3d& x_m) const override {
    return std::max(0.0, m_box.exteriorDistance(x_m) - 1e-9);
  }

  const std::vector<Eigen::Vector3d>& triangle_corners() const override { return m_corners; }

 private:
  /// The winding number of a closed mesh at x_m: its crossings() along the shortest of the rays
  /// out of the box that meets no edge or vertex, else (possible, but rare) hierarchically.
  double winding_number(const Eigen::Vector3d& x_m) const {
    if (m_box.exteriorDistance(x_m) > 0.0) return 0.0;  // no ray from outside the box crosses
    const std::array<Eigen::Vector3d, 6>& directions = winding_ray_directions();
    std::array<std::pair<double, int>, 6> exits;  // (segment's length in directions, direction)
    for (int k = 0; k < 6; ++k) exits[k] = {exit_length(x_m, directions[k]), k};
    std::sort(exits.begin(), exits.end());
    for (const auto& [length, k] : exits) {
      if (const std::optional<int> w = crossings(x_m, length * directions[k])) return *w;
    }
    std::call_once(m_winding_built, [this] { m_winding.emplace(m_corners); });
    return m_winding->winding_number(x_m);
  }

  /// How many times `direction` takes x_m (inside the box) out of the box, rounded up to a power
  /// of two (with the directions' few bits, the segment's end is then exact for points of few
  /// bits: a test can aim it at a vertex).
  double exit_length(const Eigen::Vector3d& x_m, const Eigen::Vector3d& direction) const {
    double exit = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      const double bound = direction[axis] > 0.0 ? m_box.max()[axis] : m_box.min()[axis];
      exit = std::min(exit, (bound - x_m[axis]) / direction[axis]);
    }
    return std::exp2(std::ceil(std::log2(exit + 1e-6 * m_box.diagonal().norm() + 1e-12)));
  }

  /// The winding number of a closed surface at x_m as the signed count of its crossings by the
  /// segment from x_m to x_m + `ray` (outside the box): +1 where it leaves through a face's front,
  /// -1 where it enters (for a closed, boundary-free chain, the integer the solid angles sum to).
  /// Decided by CGAL's exact predicates: nothing when the segment passes through an edge or a
  /// vertex, or starts in a face's plane, where a crossing could count twice or not at all.
  std::optional<int> crossings(const Eigen::Vector3d& x_m, const Eigen::Vector3d& ray) const {
    const Kernel::Point_3 from = to_point(x_m);
    const Kernel::Point_3 to = to_point(x_m + ray);
    const Kernel::Segment_3 segment(from, to);
    const Kernel kernel;
    const auto orientation = kernel.orientation_3_object();
    const auto do_intersect = kernel.do_intersect_3_object();
    int winding = 0;
    bool degenerate = false;
    m_bvh.for_each_near_segment(x_m, x_m + ray, [&](int index) {
      const Kernel::Point_3 t[3] = {to_point(m_corners[3 * index]),
                                    to_point(m_corners[3 * index + 1]),
                                    to_point(m_corners[3 * index + 2])};
      if (!do_intersect(segment, Kernel::Triangle_3(t[0], t[1], t[2]))) return;
      const CGAL::Orientation side = orientation(t[0], t[1], t[2], from);
      degenerate |= side == CGAL::COPLANAR;
      for (int k = 0; k < 3; ++k) {
        degenerate |= orientation(from, to, t[k], t[(k + 1) % 3]) == CGAL::COPLANAR;
      }
      winding += side == CGAL::NEGATIVE ? 1 : -1;  // from behind the face: leaving by its front
    });
    if (degenerate) return std::nullopt;
    return winding;
  }

  /// The hierarchy of `shape` (one built for `corners` if there is none) around `corners`.
  static TriangleBvh hierarchy_of(std::vector<Eigen::Vector3d> corners,
                                  std::shared_ptr<const TriangleBvhShape> shape) {
    if (!shape) shape = std::make_shared<const TriangleBvhShape>(corners);
    return TriangleBvh(std::move(shape), std::move(corners));
  }

  bool m_closed = false;
  TriangleBvh m_bvh;
  const std::vector<Eigen::Vector3d>& m_corners;  // three per triangle, kept by m_bvh
  const Eigen::AlignedBox3d& m_box;               // of every corner, m_bvh's root box
  mutable std::once_flag m_winding_built;         // the fallback's tree, built when first needed
  mutable std::optional<WindingNumberTree> m_winding;
};

/// Checks `samples` against `vertex_count` vertices and `triangles`, as make_mesh_animation says.
void check_samples(const MeshSamples& samples, std::size_t vertex_count,
                   const std::vector<std::array<int, 3>>& triangles) {
  const std::size_t count = samples.times_s.size();
  if (count == 0) throw MeshError("the animation has no samples");
  if (samples.vertices_m.size() != count) {
    throw MeshError("the animation has " + std::to_string(count) + " times but " +
                    std::to_string(samples.vertices_m.size()) + " samples");
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::string sample = "sample " + std::to_string(k);
    const double t = samples.times_s[k];
    if (!std::isfinite(t) || (k > 0 && !(t > samples.times_s[k - 1]))) {
      throw MeshError(sample + ": time " + std::to_string(t) +
                      " s; expected a finite time after the previous sample's");
    }
    const std::vector<Eigen::Vector3d>& x = samples.vertices_m[k];
    if (x.size() != vertex_count) {
      throw MeshError(sample + " has " + std::to_string(x.size()) + " vertices; the mesh has " +
                      std::to_string(vertex_count));
    }
    for (std::size_t v = 0; v < x.size(); ++v) {
      if (const std::string refusal = vertex_refusal(static_cast<int>(v), x[v]); !refusal.empty()) {
        throw MeshError(sample + ": " + refusal);
      }
    }
    for (const std::array<int, 3>& t3 : triangles) {
      if ((x[t3[1]] - x[t3[0]]).cross(x[t3[2]] - x[t3[0]]).squaredNorm() == 0.0) {
        throw MeshError(sample + ": the triangle of vertices " + std::to_string(t3[0]) + ", " +
                        std::to_string(t3[1]) + ", " + std::to_string(t3[2]) +
                        " has no area there (it has some in sample 0)");
      }
    }
  }
}

class MeshAnimation final : public SurfaceAnimation {
 public:
  MeshAnimation(MeshSamples samples, std::vector<std::array<int, 3>> triangles, bool closed)
      : m_samples(std::move(samples)),
        m_triangles(std::move(triangles)),
        m_closed(closed),
        m_shape(std::make_shared<const TriangleBvhShape>(
            triangle_corners_of(m_samples.vertices_m.front(), m_triangles))) {
    std::set<int> used;  // the vertices of its triangles: other parts' may move, not these
    for (const std::array<int, 3>& t : m_triangles) used.insert(t.begin(), t.end());
    for (std::size_t k = 1; k < m_samples.times_s.size(); ++k) {
      const double duration_s = m_samples.times_s[k] - m_samples.times_s[k - 1];
      double fastest_m_per_s = 0.0;
      for (int v : used) {
        const double moved_m = (m_samples.vertices_m[k][v] - m_samples.vertices_m[k - 1][v]).norm();
        fastest_m_per_s = std::max(fastest_m_per_s, moved_m / duration_s);
      }
      // a still segment shares the surface of the first sample of the still run it ends
      const int k0 = static_cast<int>(k) - 1;
      m_still_from.push_back(fastest_m_per_s > 0.0                 ? -1
                             : k0 > 0 && m_still_from[k0 - 1] >= 0 ? m_still_from[k0 - 1]
                                                                   : k0);
      m_fastest_m_per_s = std::max(m_fastest_m_per_s, fastest_m_per_s);
    }
  }

  std::shared_ptr<const SurfaceQuery> at(double time_s) const override {
    const double t = still_instant(time_s);
    const std::lock_guard<std::mutex> lock(m_mutex);
    for (const auto& [built_s, surface] : m_built) {
      if (std::abs(built_s - t) <= same_instant_s) return surface;
    }
    auto surface = std::make_shared<const MeshSurface>(corners_at(t), m_closed, m_shape);
    m_built.emplace_back(t, surface);
    if (m_built.size() > kept_surfaces) m_built.pop_front();
    return surface;
  }

  double fastest_speed_m_per_s() const override { return m_fastest_m_per_s; }

 private:
  static constexpr double same_instant_s = 1e-9;
  static constexpr std::size_t kept_surfaces = 4;

  /// The instant whose surface is the one at `time_s`: the first or last sample's outside the
  /// samples' times, the start of a segment over which nothing moves (a torso while the arms
  /// move: its surface is built once), else `time_s`.
  double still_instant(double time_s) const {
    const std::vector<double>& times = m_samples.times_s;
    const double t = std::clamp(time_s, times.front(), times.back());
    if (times.size() == 1) return t;
    // the segment holding t: the last one for t at the last sample
    const std::size_t segment =
        std::min<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin(),
                              times.size() - 1) -
        1;
    if (m_still_from[segment] >= 0) return times[m_still_from[segment]];
    return t;
  }

  /// Its triangles' corners at t, within the samples' times: linear between the two samples
  /// around it.
  std::vector<Eigen::Vector3d> corners_at(double t) const {
    const std::vector<double>& times = m_samples.times_s;
    const std::size_t after = std::upper_bound(times.begin(), times.end(), t) - times.begin();
    if (after == 0 || after == times.size()) {
      return triangle_corners_of(m_samples.vertices_m[after == 0 ? 0 : times.size() - 1],
                                 m_triangles);
    }
    const double s = (t - times[after - 1]) / (times[after] - times[after - 1]);
    const std::vector<Eigen::Vector3d>& a = m_samples.vertices_m[after - 1];
    const std::vector<Eigen::Vector3d>& b = m_samples.vertices_m[after];
    std::vector<Eigen::Vector3d> corners;
    corners.reserve(3 * m_triangles.size());
    for (const std::array<int, 3>& triangle : m_triangles) {
      for (int v : triangle) corners.push_back((1.0 - s) * a[v] + s * b[v]);
    }
    return corners;
  }

  MeshSamples m_samples;
  std::vector<std::array<int, 3>> m_triangles;
  bool m_closed;
  /// which triangles share a box, from the first sample: each instant only refits the boxes
  std::shared_ptr<const TriangleBvhShape> m_shape;
  double m_fastest_m_per_s = 0.0;
  /// per segment between consecutive samples: where nothing moves, the first sample of the still
  /// run it ends; -1 where something moves
  std::vector<int> m_still_from;
  mutable std::mutex m_mutex;  // guards m_built
  mutable std::deque<std::pair<double, std::shared_ptr<const SurfaceQuery>>> m_built;
};

}  // namespace

const std::array<Eigen::Vector3d, 6>& winding_ray_directions() {
  static const std::array<Eigen::Vector3d, 6> directions{
      Eigen::Vector3d(1.0, 0.0625, -0.03125),  Eigen::Vector3d(-1.0, -0.046875, 0.0625),
      Eigen::Vector3d(0.03125, 1.0, 0.078125), Eigen::Vector3d(-0.078125, -1.0, -0.03125),
      Eigen::Vector3d(0.046875, 0.0625, 1.0),  Eigen::Vector3d(-0.0625, 0.03125, -1.0)};
  return directions;
}

std::shared_ptr<const SurfaceQuery> make_mesh_surface(const IndexedMesh& mesh,
                                                      ObstacleMeshReport* report) {
  ObstacleMeshReport local;
  ObstacleMeshReport& r = report ? *report : local;
  r = {};
  const ObstacleTriangles triangles = obstacle_triangles(mesh, r);
  r.closed = is_closed(triangles);
  return std::make_shared<MeshSurface>(triangle_corners_of(mesh.vertices, triangles.kept),
                                       r.closed);
}

std::vector<IndexedMesh> separate_parts(const IndexedMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());  // union-find over vertices
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  const auto in_range = [&](int v) { return v >= 0 && v < static_cast<int>(parent.size()); };
  for (const std::vector<int>& face : mesh.faces) {
    for (int v : face) {
      if (in_range(v) && in_range(face.front())) parent[root(v)] = root(face.front());
    }
  }
  std::map<int, std::size_t> part_of_root;
  std::vector<IndexedMesh> parts;
  for (const std::vector<int>& face : mesh.faces) {
    // a face with no vertex in range goes with the first part, where make_mesh_surface names it
    const int key = !face.empty() && in_range(face.front()) ? root(face.front()) : -1;
    const auto [it, added] = part_of_root.try_emplace(key, parts.size());
    if (added) parts.push_back({mesh.vertices, {}, {}});
    parts[it->second].faces.push_back(face);
  }
  if (parts.empty()) parts.push_back(mesh);  // no faces: make_mesh_surface says so
  return parts;
}

std::shared_ptr<const SurfaceAnimation> make_mesh_animation(const IndexedMesh& mesh,
                                                            MeshSamples samples,
                                                            ObstacleMeshReport* report) {
  if (samples.vertices_m.empty()) throw MeshError("the animation has no samples");
  if (samples.vertices_m.front().size() != mesh.vertices.size()) {
    throw MeshError("sample 0 has " + std::to_string(samples.vertices_m.front().size()) +
                    " vertices; the mesh has " + std::to_string(mesh.vertices.size()));
  }
  IndexedMesh first = mesh;
  first.vertices = samples.vertices_m.front();
  ObstacleMeshReport local;
  ObstacleMeshReport& r = report ? *report : local;
  r = {};
  const ObstacleTriangles triangles = obstacle_triangles(first, r);
  r.closed = is_closed(triangles);
  check_samples(samples, mesh.vertices.size(), triangles.kept);
  return std::make_shared<MeshAnimation>(std::move(samples), triangles.kept, r.closed);
}

}  // namespace tissu
