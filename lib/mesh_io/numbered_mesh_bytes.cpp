#include "lib/mesh_io/numbered_mesh_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace tissu {
namespace {

class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    m_bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put_size(std::size_t size) { put(static_cast<std::uint64_t>(size)); }

  std::string take() { return std::move(m_bytes); }

 private:
  std::string m_bytes;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : m_bytes(bytes) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    require(sizeof(T));
    T value;
    std::memcpy(&value, m_bytes.data() + m_at, sizeof(T));
    m_at += sizeof(T);
    return value;
  }
  /// A count of items of `item_bytes` each, checked against the bytes left so that a damaged
  /// count cannot make the caller allocate more than the message holds.
  std::size_t get_count(std::size_t item_bytes) {
    const std::uint64_t count = get<std::uint64_t>();
    if (count > (m_bytes.size() - m_at) / item_bytes) fail();
    return static_cast<std::size_t>(count);
  }
  std::string get_string() {
    const std::size_t size = get_count(1);
    std::string out = m_bytes.substr(m_at, size);
    m_at += size;
    return out;
  }
  void expect_end() const {
    if (m_at != m_bytes.size()) fail();
  }

 private:
  void require(std::size_t size) const {
    if (m_bytes.size() - m_at < size) fail();
  }
  [[noreturn]] static void fail() {
    throw std::runtime_error("the imported mesh came back truncated or damaged");
  }

  const std::string& m_bytes;
  std::size_t m_at = 0;
};

}  // namespace

std::string numbered_mesh_bytes(const NumberedMesh& in) {
  ByteWriter out;
  out.put_size(in.mesh.vertices.size());
  for (const Eigen::Vector3d& p : in.mesh.vertices) {
    out.put(p.x());
    out.put(p.y());
    out.put(p.z());
  }
  out.put_size(in.mesh.faces.size());
  for (const std::vector<int>& face : in.mesh.faces) {
    out.put_size(face.size());
    for (int v : face) out.put(static_cast<std::int32_t>(v));
  }
  out.put_size(in.mesh.face_uvs.size());
  for (const std::vector<Eigen::Vector2d>& uvs : in.mesh.face_uvs) {
    out.put_size(uvs.size());
    for (const Eigen::Vector2d& uv : uvs) {
      out.put(uv.x());
      out.put(uv.y());
    }
  }
  out.put_size(in.mesh_vertex_of_file_vertex.size());
  for (int v : in.mesh_vertex_of_file_vertex) out.put(static_cast<std::int32_t>(v));
  out.put_size(in.no_numbering_reason.size());
  for (char c : in.no_numbering_reason) out.put(c);
  return out.take();
}

NumberedMesh numbered_mesh_from_bytes(const std::string& bytes) {
  ByteReader in(bytes);
  NumberedMesh out;
  out.mesh.vertices.resize(in.get_count(3 * sizeof(double)));
  for (Eigen::Vector3d& p : out.mesh.vertices) {
    const double x = in.get<double>(), y = in.get<double>(), z = in.get<double>();
    p = {x, y, z};
  }
  out.mesh.faces.resize(in.get_count(sizeof(std::uint64_t)));
  for (std::vector<int>& face : out.mesh.faces) {
    face.resize(in.get_count(sizeof(std::int32_t)));
    for (int& v : face) v = in.get<std::int32_t>();
  }
  out.mesh.face_uvs.resize(in.get_count(sizeof(std::uint64_t)));
  for (std::vector<Eigen::Vector2d>& uvs : out.mesh.face_uvs) {
    uvs.resize(in.get_count(2 * sizeof(double)));
    for (Eigen::Vector2d& uv : uvs) {
      const double u = in.get<double>(), v = in.get<double>();
      uv = {u, v};
    }
  }
  out.mesh_vertex_of_file_vertex.resize(in.get_count(sizeof(std::int32_t)));
  for (int& v : out.mesh_vertex_of_file_vertex) v = in.get<std::int32_t>();
  out.no_numbering_reason = in.get_string();
  in.expect_end();
  return out;
}

}  // namespace tissu
