#include "lib/mesh_io/write_mesh.hpp"

#include <Eigen/Geometry>
#include <sstream>
#include <stdexcept>
#include <string>

#include "lib/atomic_file.hpp"
#include "lib/mesh_io/mesh_encoding.hpp"

namespace tissu {
namespace {

/// Throws std::runtime_error "<file>: cannot write mesh: <what>".
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": cannot write mesh: " + what);
}

void check_faces(const std::filesystem::path& file, const IndexedMesh& mesh) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    if (face.size() < 3 || face.size() > 255) {
      fail(file, "face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                     " vertices, expected 3 to 255");
    }
    for (int v : face) {
      if (v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size()) {
        fail(file, "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                       ", but the mesh has " + std::to_string(mesh.vertices.size()) + " vertices");
      }
    }
    if (!mesh.has_uvs()) continue;
    const std::size_t uvs = f < mesh.face_uvs.size() ? mesh.face_uvs[f].size() : 0;
    if (uvs != face.size()) {
      fail(file, "face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                     " vertices but " + std::to_string(uvs) + " texture coordinates");
    }
    if (face.size() > 127) {  // PLY's uchar count of its texcoord list: 2 numbers per corner
      fail(file, "face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                     " vertices, expected at most 127 with texture coordinates");
    }
  }
  if (mesh.face_uvs.size() > mesh.faces.size()) {
    fail(file, "texture coordinates for " + std::to_string(mesh.face_uvs.size()) + " faces, but " +
                   std::to_string(mesh.faces.size()) + " faces");
  }
}

/// Refuses a non-finite coordinate: a file holding inf or NaN is no mesh any reader can use (OBJ
/// readers drop or merge such vertices), and it means that whatever made it went wrong.
void check_finite(const std::filesystem::path& file, const std::vector<Eigen::Vector3d>& points,
                  const char* what) {
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (points[v].allFinite()) continue;
    std::ostringstream text;
    text << "vertex " << v << " has the " << what << " (" << points[v].x() << ", " << points[v].y()
         << ", " << points[v].z() << "), which is not finite";
    fail(file, text.str());
  }
}

/// The file's bytes go to a temporary beside it, renamed over it once complete: a full disk or a
/// killed process never leaves a truncated mesh under its name (lib/atomic_file.hpp).
void write_file(const std::filesystem::path& file, const std::string& contents) {
  write_file_atomically(file, contents, "mesh");
}

void write(const std::filesystem::path& file, const IndexedMesh& mesh, const VertexRestData* rest,
           MeshFormat format) {
  check_faces(file, mesh);
  check_finite(file, mesh.vertices, "position");
  if (rest) check_finite(file, rest->rest_m, "rest position");
  switch (format) {
    case MeshFormat::obj:
      return write_file(file, obj_text(mesh, rest));
    case MeshFormat::ply:
      return write_file(file, ply_bytes(mesh, rest));
    case MeshFormat::glb:
      try {
        return write_file(file, glb_bytes(mesh, rest ? &rest->texture_uvw : nullptr));
      } catch (const FileWriteError&) {
        throw;
      } catch (const std::runtime_error& e) {
        fail(file, e.what());
      }
  }
}

}  // namespace

MeshFormat mesh_format_from_string(std::string_view name) {
  if (name == "obj") {
    return MeshFormat::obj;
  }
  if (name == "ply") {
    return MeshFormat::ply;
  }
  if (name == "glb") {
    return MeshFormat::glb;
  }
  throw std::invalid_argument("unknown mesh format \"" + std::string(name) +
                              "\": expected \"obj\", \"ply\" or \"glb\"");
}

const char* extension(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return "obj";
    case MeshFormat::ply:
      return "ply";
    case MeshFormat::glb:
      return "glb";
  }
  return "";
}

std::vector<Eigen::Vector3d> rest_texture_coordinates(const std::vector<Eigen::Vector3d>& rest_m,
                                                      const ClothFrame& frame) {
  const Eigen::Vector3d u = frame.u_axis.normalized();
  Eigen::Vector3d normal = u.cross(frame.v_axis);
  if (!(normal.norm() > 1e-12)) {  // v along u: any normal will do
    normal = u.unitOrthogonal();
  }
  normal.normalize();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Eigen::Vector3d> uvw;
  uvw.reserve(rest_m.size());
  for (const Eigen::Vector3d& r : rest_m) uvw.emplace_back(r.dot(u), r.dot(v), r.dot(normal));
  return uvw;
}

void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh, MeshFormat format) {
  write(file, mesh, nullptr, format);
}

void write_mesh(const std::filesystem::path& file, const IndexedMesh& mesh,
                const RestCoordinates& rest, MeshFormat format) {
  if (rest.rest_m.size() != mesh.vertices.size()) {
    fail(file, std::to_string(rest.rest_m.size()) + " rest positions for " +
                   std::to_string(mesh.vertices.size()) + " vertices");
  }
  const std::vector<Eigen::Vector3d> uvw = rest_texture_coordinates(rest.rest_m, rest.frame);
  const VertexRestData data{uvw, rest.rest_m};
  write(file, mesh, &data, format);
}

}  // namespace tissu
