#include "topology/indexed_mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace tissu {
namespace {

/// One face's traversal of an edge, keyed by its vertex ids in increasing order.
struct HalfEdge {
  int low;       ///< smaller vertex id
  int high;      ///< larger vertex id
  int face;      ///< face that traverses the edge
  bool forward;  ///< true if the face goes from `low` to `high`
};

[[noreturn]] void fail(const std::ostringstream& message) {
  throw MeshError(message.str());
}

/// Faces must be non-empty; their vertices finite.
void check_not_empty_and_finite(const IndexedMesh& mesh) {
  if (mesh.vertices.empty() || mesh.faces.empty()) {
    std::ostringstream message;
    message << "empty mesh: it has " << mesh.vertices.size() << " vertices and "
            << mesh.faces.size() << " faces, but a cloth needs at least one face";
    fail(message);
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    if (!p.allFinite()) {
      std::ostringstream message;
      message << "vertex " << v << " has a non-finite coordinate (" << p.x() << ", " << p.y()
              << ", " << p.z() << ")";
      fail(message);
    }
  }
}

/// Squared diagonal of the axis-aligned bounding box of all vertices.
double bounding_box_diagonal_squared(const IndexedMesh& mesh) {
  Eigen::Vector3d lo = mesh.vertices.front();
  Eigen::Vector3d hi = lo;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).squaredNorm();
}

/// Area of a polygon: half the norm of its vector area (exact for planar faces).
double polygon_area(const IndexedMesh& mesh, const std::vector<int>& face) {
  Eigen::Vector3d twice_vector_area = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& origin = mesh.vertices[face[0]];
  for (std::size_t i = 1; i + 1 < face.size(); ++i) {
    twice_vector_area +=
        (mesh.vertices[face[i]] - origin).cross(mesh.vertices[face[i + 1]] - origin);
  }
  return 0.5 * twice_vector_area.norm();
}

std::string face_ids(const std::vector<int>& face) {
  std::ostringstream out;
  for (std::size_t i = 0; i < face.size(); ++i) {
    out << (i == 0 ? "" : " ") << face[i];
  }
  return out.str();
}

/// Face size, vertex ids in range and distinct, non-zero area.
void check_face(const IndexedMesh& mesh, std::size_t f, double min_area) {
  const std::vector<int>& face = mesh.faces[f];
  if (face.size() < 3 || face.size() > 4) {
    std::ostringstream message;
    message << "face " << f << " has " << face.size()
            << " vertices, but faces must have 3 or 4 vertices";
    fail(message);
  }
  for (int v : face) {
    if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
      std::ostringstream message;
      message << "face " << f << " refers to vertex " << v << ", but the mesh has "
              << mesh.vertices.size() << " vertices";
      fail(message);
    }
  }
  for (std::size_t i = 0; i < face.size(); ++i) {
    for (std::size_t j = i + 1; j < face.size(); ++j) {
      if (face[i] == face[j]) {
        std::ostringstream message;
        message << "face " << f << " repeats vertex " << face[i] << " (vertices " << face_ids(face)
                << "), but a face's vertices must be distinct";
        fail(message);
      }
    }
  }
  const double area = polygon_area(mesh, face);
  if (!(area > min_area)) {
    std::ostringstream message;
    message << "face " << f << " (vertices " << face_ids(face) << ") is degenerate: ";
    if (area == 0.0) {
      message << "it has no area (its vertices lie on one line or at one point)";
    } else {
      message << "its area " << area << " is below " << min_area
              << ", 1e-12 times the squared diagonal of the mesh's bounding box";
    }
    fail(message);
  }
}

/// Every edge shared by at most two faces, which traverse it in opposite directions.
void check_edges(const IndexedMesh& mesh) {
  std::size_t count = 0;
  for (const std::vector<int>& face : mesh.faces) {
    count += face.size();
  }
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(count);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const int a = face[i];
      const int b = face[(i + 1) % face.size()];
      half_edges.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f), a < b});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.low, x.high, x.face) < std::tie(y.low, y.high, y.face);
  });
  for (std::size_t begin = 0; begin < half_edges.size();) {
    std::size_t end = begin + 1;
    while (end < half_edges.size() && half_edges[end].low == half_edges[begin].low &&
           half_edges[end].high == half_edges[begin].high) {
      ++end;
    }
    const HalfEdge& first = half_edges[begin];
    if (end - begin > 2) {
      std::ostringstream message;
      message << "non-manifold edge (" << first.low << ", " << first.high << ") is shared by "
              << end - begin << " faces (";
      for (std::size_t i = begin; i < end; ++i) {
        message << (i == begin ? "" : ", ") << half_edges[i].face;
      }
      message << "), but at most two faces may share an edge";
      fail(message);
    }
    if (end - begin == 2 && half_edges[begin + 1].forward == first.forward) {
      std::ostringstream message;
      message << "inconsistent orientation: faces " << first.face << " and "
              << half_edges[begin + 1].face << " both traverse edge (" << first.low << ", "
              << first.high << ") in the same direction, but neighbouring faces must traverse "
              << "their shared edge in opposite directions";
      fail(message);
    }
    begin = end;
  }
}

/// Union-find over face corners: which corners of a vertex are joined across shared edges.
class CornerSets {
 public:
  explicit CornerSets(std::size_t count) : m_parent(count) {
    for (std::size_t i = 0; i < count; ++i) m_parent[i] = i;
  }
  std::size_t root(std::size_t c) {
    while (m_parent[c] != c) c = m_parent[c] = m_parent[m_parent[c]];
    return c;
  }
  void join(std::size_t a, std::size_t b) { m_parent[root(a)] = root(b); }

 private:
  std::vector<std::size_t> m_parent;
};

/// Every vertex's faces form one fan (edge-connected around it): a "bow-tie" vertex, where two
/// fans touch at a point, would be one particle the complex cannot hold, its faces split between
/// two vertices of the complex that no edge joins. Call after check_edges.
void check_vertex_fans(const IndexedMesh& mesh) {
  // corner (f, i) is face f's i-th vertex; corners get consecutive ids face after face
  std::vector<std::size_t> first_corner(mesh.faces.size() + 1, 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    first_corner[f + 1] = first_corner[f] + mesh.faces[f].size();
  }
  // each directed edge a->b of a face: its corner at a and the corner at b
  struct DirectedEdge {
    int from, to;
    std::size_t from_corner, to_corner;
  };
  std::vector<DirectedEdge> edges;
  edges.reserve(first_corner.back());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::size_t j = (i + 1) % face.size();
      edges.push_back({face[i], face[j], first_corner[f] + i, first_corner[f] + j});
    }
  }
  const auto key = [](int from, int to) { return std::make_pair(from, to); };
  std::sort(edges.begin(), edges.end(), [&](const DirectedEdge& x, const DirectedEdge& y) {
    return key(x.from, x.to) < key(y.from, y.to);
  });
  // faces sharing edge a-b (a->b in one, b->a in the other) meet at a and at b
  CornerSets fans(first_corner.back());
  for (const DirectedEdge& e : edges) {
    const auto twin = std::lower_bound(
        edges.begin(), edges.end(), key(e.to, e.from),
        [&](const DirectedEdge& x, const std::pair<int, int>& k) { return key(x.from, x.to) < k; });
    if (twin == edges.end() || twin->from != e.to || twin->to != e.from) continue;
    fans.join(e.from_corner, twin->to_corner);
    fans.join(e.to_corner, twin->from_corner);
  }
  std::vector<std::size_t> fan_of_vertex(mesh.vertices.size(), first_corner.back());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const std::size_t fan = fans.root(first_corner[f] + i);
      std::size_t& known = fan_of_vertex[face[i]];
      if (known == first_corner.back()) {
        known = fan;
      } else if (known != fan) {
        std::ostringstream message;
        const Eigen::Vector3d& p = mesh.vertices[face[i]];
        message << "non-manifold vertex " << face[i] << " at (" << p.x() << ", " << p.y() << ", "
                << p.z() << "): its faces form separate fans that touch only at this vertex (face "
                << f
                << " is not connected to the others through edges), but a cloth vertex must be "
                << "surrounded by one fan of faces; give each fan its own vertex";
        fail(message);
      }
    }
  }
}

/// Texture coordinates at every face or at none, one finite (u, v) per corner.
void check_uvs(const IndexedMesh& mesh) {
  if (!mesh.has_uvs()) return;
  // the first face with UVs, to name beside one without
  std::size_t with = 0;
  while (with < mesh.face_uvs.size() && mesh.face_uvs[with].empty()) ++with;
  if (with == mesh.face_uvs.size()) {
    std::ostringstream message;
    message << "the mesh has " << mesh.face_uvs.size()
            << " texture coordinate lists, all empty: a mesh without texture coordinates has none";
    fail(message);
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (f >= mesh.face_uvs.size() || mesh.face_uvs[f].empty()) {
      std::ostringstream message;
      message << "face " << f << " has no texture coordinates, but face " << with
              << " has: give every face texture coordinates, or none";
      fail(message);
    }
    const std::vector<Eigen::Vector2d>& uvs = mesh.face_uvs[f];
    if (uvs.size() != mesh.faces[f].size()) {
      std::ostringstream message;
      message << "face " << f << " has " << mesh.faces[f].size() << " corners but " << uvs.size()
              << " texture coordinates";
      fail(message);
    }
    for (std::size_t k = 0; k < uvs.size(); ++k) {
      if (!uvs[k].allFinite()) {
        std::ostringstream message;
        message << "face " << f << " has a non-finite texture coordinate (" << uvs[k].x() << ", "
                << uvs[k].y() << ") at corner " << k;
        fail(message);
      }
    }
  }
  if (mesh.face_uvs.size() > mesh.faces.size()) {
    std::ostringstream message;
    message << "the mesh has texture coordinates for " << mesh.face_uvs.size() << " faces but "
            << mesh.faces.size() << " faces";
    fail(message);
  }
}

}  // namespace

void validate_indexed_mesh(const IndexedMesh& mesh) {
  check_not_empty_and_finite(mesh);
  const double min_area = 1e-12 * bounding_box_diagonal_squared(mesh);
  if (!std::isfinite(min_area)) {  // coordinates beyond ~1e154: face areas overflow to inf
    std::ostringstream message;
    message << "the mesh is too large to measure: its bounding box diagonal squared overflows a "
               "double; coordinates must stay well below 1e150";
    fail(message);
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    check_face(mesh, f, min_area);
  }
  check_edges(mesh);
  check_vertex_fans(mesh);
  check_uvs(mesh);
}

IndexedMesh triangulate_quads(const IndexedMesh& mesh) {
  IndexedMesh out{mesh.vertices, {}, {}};
  const bool with_uvs = mesh.has_uvs();
  // each output face as corners of its input face, which carry the vertex and its UV there
  const auto add = [&](std::size_t face, std::vector<int> corners) {
    std::vector<int>& ids = out.faces.emplace_back();
    std::vector<Eigen::Vector2d>* uvs = with_uvs ? &out.face_uvs.emplace_back() : nullptr;
    // a face without UVs (in a mesh validate_indexed_mesh refuses) stays without
    const bool face_has_uvs = with_uvs && face < mesh.face_uvs.size() &&
                              mesh.face_uvs[face].size() == mesh.faces[face].size();
    for (int k : corners) {
      ids.push_back(mesh.faces[face][k]);
      if (face_has_uvs) uvs->push_back(mesh.face_uvs[face][k]);
    }
  };
  for (std::size_t face = 0; face < mesh.faces.size(); ++face) {
    const std::vector<int>& f = mesh.faces[face];
    if (f.size() != 4) {
      std::vector<int> corners(f.size());
      for (std::size_t k = 0; k < f.size(); ++k) corners[k] = static_cast<int>(k);
      add(face, corners);
      continue;
    }
    const auto length2 = [&](int a, int b) {
      return (mesh.vertices[f[a]] - mesh.vertices[f[b]]).squaredNorm();
    };
    if (length2(0, 2) <= length2(1, 3)) {
      add(face, {0, 1, 2});
      add(face, {0, 2, 3});
    } else {
      add(face, {0, 1, 3});
      add(face, {1, 2, 3});
    }
  }
  return out;
}

}  // namespace tissu
