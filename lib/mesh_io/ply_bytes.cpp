#include <cstdint>
#include <cstring>
#include <type_traits>

#include "lib/mesh_io/mesh_encoding.hpp"

namespace tissu {
namespace {

/// Appends the little-endian bytes of `value`, whatever the machine's byte order.
template <class T>
void append_little_endian(std::string& out, T value) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 8);
  using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  Bits bits;
  std::memcpy(&bits, &value, sizeof bits);
  for (std::size_t k = 0; k < sizeof bits; ++k) {
    out += static_cast<char>((bits >> (8 * k)) & 0xff);
  }
}

void append_point(std::string& out, const Eigen::Vector3d& p) {
  for (int k = 0; k < 3; ++k) append_little_endian(out, p[k]);
}

std::string header(const IndexedMesh& mesh, bool with_rest) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\n"
      "comment tissu cloth mesh: the vertices are the particles, in particle order\n"
      "comment x y z: current position (m)\n";
  if (with_rest) {
    out +=
        "comment s t: texture coordinates, the rest (material) position (m) along the cloth's u "
        "axis and its v axis made orthogonal to u\n"
        "comment rest_x rest_y rest_z: rest (material) position (m)\n";
  }
  out += "element vertex " + std::to_string(mesh.vertices.size()) +
         "\nproperty double x\nproperty double y\nproperty double z\n";
  if (with_rest) {
    out +=
        "property double s\nproperty double t\nproperty double rest_x\nproperty double rest_y\n"
        "property double rest_z\n";
  }
  if (mesh.has_uvs()) {
    out +=
        "comment texcoord: the cloth mesh's own texture coordinates, u v at each corner of the "
        "face in vertex_indices order (interpolated where the cloth was refined, kept on both "
        "sides of a tear)\n";
  }
  out += "element face " + std::to_string(mesh.faces.size()) +
         "\nproperty list uchar int vertex_indices\n";
  if (mesh.has_uvs()) out += "property list uchar double texcoord\n";
  out += "end_header\n";
  return out;
}

}  // namespace

std::string ply_bytes(const IndexedMesh& mesh, const VertexRestData* rest) {
  std::string out = header(mesh, rest != nullptr);
  out.reserve(out.size() + mesh.vertices.size() * (rest != nullptr ? 64 : 24) +
              mesh.faces.size() * (mesh.has_uvs() ? 82 : 17));
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    append_point(out, mesh.vertices[v]);
    if (rest != nullptr) {
      append_little_endian(out, rest->texture_uvw[v].x());
      append_little_endian(out, rest->texture_uvw[v].y());
      append_point(out, rest->rest_m[v]);
    }
  }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    out += static_cast<char>(static_cast<unsigned char>(face.size()));
    for (int v : face) append_little_endian(out, static_cast<std::int32_t>(v));
    if (mesh.has_uvs()) {
      out += static_cast<char>(static_cast<unsigned char>(2 * face.size()));
      for (const Eigen::Vector2d& uv : mesh.face_uvs[f]) {
        append_little_endian(out, uv.x());
        append_little_endian(out, uv.y());
      }
    }
  }
  return out;
}

}  // namespace tissu
