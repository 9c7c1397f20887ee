#include <array>
#include <charconv>
#include <map>
#include <utility>

#include "lib/mesh_io/mesh_encoding.hpp"

namespace tissu {
namespace {

/// Appends `value` in the shortest decimal that reads back to the same double.
void append_number(std::string& out, double value) {
  std::array<char, 32> text;  // the longest double, -1.2345678901234567e-308, has 24 characters
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value);
  out.append(text.data(), result.ptr);
}

void append_line(std::string& out, const char* keyword, const Eigen::Vector3d& p) {
  out += keyword;
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_number(out, p[k]);
  }
  out += '\n';
}

/// The `vt` statements of a file and the one each face corner refers to (0-based).
struct TextureCoordinates {
  std::string lines;                        ///< the `vt` statements
  std::vector<std::vector<int>> of_corner;  ///< #F lists, as mesh.faces; empty for no `vt`
};

/// The mesh's own UVs, one `vt u v` per distinct value in the order the corners first use them
/// (exact values: the two sides of a seam differ).
TextureCoordinates mesh_uvs(const IndexedMesh& mesh) {
  TextureCoordinates out;
  std::map<std::pair<double, double>, int> id_of;
  for (const std::vector<Eigen::Vector2d>& face : mesh.face_uvs) {
    std::vector<int>& ids = out.of_corner.emplace_back();
    for (const Eigen::Vector2d& uv : face) {
      const auto [it, inserted] =
          id_of.try_emplace({uv.x(), uv.y()}, static_cast<int>(id_of.size()));
      if (inserted) {
        out.lines += "vt ";
        append_number(out.lines, uv.x());
        out.lines += ' ';
        append_number(out.lines, uv.y());
        out.lines += '\n';
      }
      ids.push_back(it->second);
    }
  }
  return out;
}

/// The rest texture coordinates, one `vt u v w` per vertex, with the vertex's index.
TextureCoordinates rest_uvws(const IndexedMesh& mesh, const VertexRestData& rest) {
  TextureCoordinates out;
  for (const Eigen::Vector3d& uvw : rest.texture_uvw) append_line(out.lines, "vt", uvw);
  out.of_corner = mesh.faces;
  return out;
}

}  // namespace

std::string obj_text(const IndexedMesh& mesh, const VertexRestData* rest) {
  std::string out = "# tissu cloth mesh: " + std::to_string(mesh.vertices.size()) +
                    " vertices (the particles, in particle order), " +
                    std::to_string(mesh.faces.size()) + " faces\n# v x y z: current position (m)\n";
  TextureCoordinates vt;
  if (mesh.has_uvs()) {
    out +=
        "# vt u v: the cloth mesh's own texture coordinates, per face corner (interpolated where "
        "the cloth was refined, kept on both sides of a tear), one vt per distinct value\n";
    vt = mesh_uvs(mesh);
  } else if (rest != nullptr) {
    out +=
        "# vt u v w: rest (material) position (m) along the cloth's u axis, its v axis made "
        "orthogonal to u, and u x v; vertex k has texture coordinate k\n";
    vt = rest_uvws(mesh, *rest);
  }
  out.reserve(out.size() + mesh.vertices.size() * 70 + vt.lines.size() + mesh.faces.size() * 40);
  for (const Eigen::Vector3d& p : mesh.vertices) append_line(out, "v", p);
  out += vt.lines;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    out += 'f';
    for (std::size_t k = 0; k < mesh.faces[f].size(); ++k) {
      out += ' ';
      out += std::to_string(mesh.faces[f][k] + 1);  // OBJ counts from 1
      if (!vt.of_corner.empty()) {
        out += '/';
        out += std::to_string(vt.of_corner[f][k] + 1);
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace tissu
