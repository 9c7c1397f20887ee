#include <array>
#include <charconv>

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

}  // namespace

std::string obj_text(const IndexedMesh& mesh, const VertexRestData* rest) {
  std::string out = "# tissu cloth mesh: " + std::to_string(mesh.vertices.size()) +
                    " vertices (the particles, in particle order), " +
                    std::to_string(mesh.faces.size()) + " faces\n# v x y z: current position (m)\n";
  if (rest != nullptr) {
    out +=
        "# vt u v w: rest (material) position (m) along the cloth's u axis, its v axis made "
        "orthogonal to u, and u x v; vertex k has texture coordinate k\n";
  }
  out.reserve(out.size() + mesh.vertices.size() * (rest != nullptr ? 140 : 70) +
              mesh.faces.size() * 40);
  for (const Eigen::Vector3d& p : mesh.vertices) append_line(out, "v", p);
  if (rest != nullptr) {
    for (const Eigen::Vector3d& uvw : rest->texture_uvw) append_line(out, "vt", uvw);
  }
  for (const std::vector<int>& face : mesh.faces) {
    out += 'f';
    for (int v : face) {
      const std::string id = std::to_string(v + 1);  // OBJ counts from 1
      out += ' ';
      out += id;
      if (rest != nullptr) {
        out += '/';
        out += id;
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace tissu
