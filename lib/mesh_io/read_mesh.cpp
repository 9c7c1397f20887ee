#include "lib/mesh_io/read_mesh.hpp"

#include <assimp/scene.h>
#include <unistd.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "lib/mesh_io/mesh_file_checks.hpp"
#include "lib/mesh_io/numbered_mesh_bytes.hpp"
#include "lib/mesh_io/read_obj.hpp"

namespace tissu {
namespace {

/// Importer messages that mean the file was broken but the importer still returned a scene: the
/// OFF loader clamps out-of-range indices and leaves faces empty when the file is shorter than
/// its header says; the glTF loader drops faces with out-of-range indices. Other messages (e.g. a
/// missing texture or material file) are harmless.
bool reports_repaired_input(std::string_view message) {
  return message.find("out of range") != std::string_view::npos ||
         message.find("out-of-range") != std::string_view::npos ||
         message.find("incorrect") != std::string_view::npos;
}

/// Keeps the first warning or error that reports a repaired input.
class RepairLog : public Assimp::LogStream {
 public:
  void write(const char* message) override {
    std::string_view text(message);
    // assimp prefixes "Error, T0: " and appends a newline
    if (const std::size_t colon = text.find(": "); colon != std::string_view::npos) {
      text.remove_prefix(colon + 2);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) {
      text.remove_suffix(1);
    }
    if (m_first.empty() && reports_repaired_input(text)) {
      m_first = text;
    }
  }

  /// The first message that reports a repaired input, or "" if there was none.
  const std::string& first() const { return m_first; }

 private:
  std::string m_first;
};

/// Attaches a RepairLog to assimp's global logger for its lifetime, creating a silent logger if
/// none is installed. The mutex keeps concurrent read_mesh calls from sharing it.
class ScopedRepairLog {
 public:
  ScopedRepairLog() : m_lock(mutex()) {
    if (Assimp::DefaultLogger::isNullLogger()) {
      Assimp::DefaultLogger::create(nullptr, Assimp::Logger::NORMAL, 0);
      m_created = true;
    }
    Assimp::DefaultLogger::get()->attachStream(&m_log, kSeverity);
  }
  ~ScopedRepairLog() {
    Assimp::DefaultLogger::get()->detachStream(&m_log, kSeverity);
    if (m_created) {
      Assimp::DefaultLogger::kill();
    }
  }
  ScopedRepairLog(const ScopedRepairLog&) = delete;
  ScopedRepairLog& operator=(const ScopedRepairLog&) = delete;

  const RepairLog& log() const { return m_log; }

 private:
  static constexpr unsigned kSeverity = Assimp::Logger::Warn | Assimp::Logger::Err;
  static std::mutex& mutex() {
    static std::mutex instance;
    return instance;
  }

  std::lock_guard<std::mutex> m_lock;
  RepairLog m_log;
  bool m_created = false;
};

Eigen::Affine3d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d dense;
  dense << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return Eigen::Affine3d(dense);
}

bool is_polygon(const aiFace& face) {
  return face.mNumIndices >= 3;
}

/// Polygons of one source: positions, and faces of ids into them that are in range.
struct Polygons {
  std::vector<Eigen::Vector3d> positions;  ///< (m)
  std::vector<std::vector<int>> faces;
  /// #F lists of the UV at each corner of the face, or empty for a face without (all faces of a
  /// source without UVs); may be left empty then
  std::vector<std::vector<Eigen::Vector2d>> face_uvs;
};

/// The polygons of `in` (points and lines left out), its positions moved by `transform`.
/// Throws MeshError for an index out of range, naming the mesh when the scene has several.
Polygons polygons_of(const aiMesh& in, unsigned mesh_index, bool several_meshes,
                     const Eigen::Affine3d& transform) {
  Polygons out;
  for (unsigned v = 0; v < in.mNumVertices; ++v) {
    const Eigen::Vector3d p(in.mVertices[v].x, in.mVertices[v].y, in.mVertices[v].z);
    // a non-finite point is kept as read, so the error names the file's coordinates
    out.positions.push_back(p.allFinite() ? Eigen::Vector3d(transform * p) : p);
  }
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (!is_polygon(face)) continue;
    std::vector<int>& ids = out.faces.emplace_back();
    // UVs are per vertex in assimp (its loaders split vertices at UV seams); the merger joins
    // the vertices again and keeps the UVs per corner
    std::vector<Eigen::Vector2d>& uvs = out.face_uvs.emplace_back();
    for (unsigned i = 0; i < face.mNumIndices; ++i) {
      const unsigned index = face.mIndices[i];
      if (index >= in.mNumVertices) {
        // loaders store indices unsigned: a huge one was most likely negative in the file
        const std::string id = index > static_cast<unsigned>(std::numeric_limits<int>::max())
                                   ? std::to_string(static_cast<std::int32_t>(index))
                                   : std::to_string(index);
        const std::string where = several_meshes ? " of mesh " + std::to_string(mesh_index) : "";
        throw MeshError("face " + std::to_string(f) + where + " refers to vertex " + id +
                        ", but the mesh has " + std::to_string(in.mNumVertices) + " vertices");
      }
      ids.push_back(static_cast<int>(index));
      if (in.mTextureCoords[0] != nullptr) {
        const aiVector3D& uv = in.mTextureCoords[0][index];
        uvs.emplace_back(uv.x, uv.y);
      }
    }
  }
  return out;
}

/// Merges the polygons of several sources into one IndexedMesh, joining vertices at exactly the
/// same position and leaving out those no face uses. Each face keeps its corners' UVs; the mesh
/// has none when no face has, and the faces without UVs keep an empty list when some have (which
/// validate_indexed_mesh refuses).
class MeshMerger {
 public:
  /// Adds `in`; returns the mesh vertex of each of its positions, -1 for one no face uses.
  std::vector<int> add(const Polygons& in) {
    std::vector<char> used(in.positions.size(), 0);
    for (const std::vector<int>& face : in.faces) {
      for (int v : face) used[v] = 1;
    }
    std::vector<int> ids(in.positions.size(), -1);
    for (std::size_t v = 0; v < in.positions.size(); ++v) {
      if (used[v]) ids[v] = vertex_id(in.positions[v]);
    }
    for (std::size_t f = 0; f < in.faces.size(); ++f) {
      std::vector<int>& out = m_mesh.faces.emplace_back();
      for (int v : in.faces[f]) out.push_back(ids[v]);
      m_mesh.face_uvs.push_back(f < in.face_uvs.size() ? in.face_uvs[f]
                                                       : std::vector<Eigen::Vector2d>{});
      m_any_uvs = m_any_uvs || !m_mesh.face_uvs.back().empty();
    }
    return ids;
  }

  IndexedMesh take() {
    if (!m_any_uvs) m_mesh.face_uvs.clear();
    return std::move(m_mesh);
  }

 private:
  /// Id of the vertex at `p`, added if new; non-finite positions are never joined.
  int vertex_id(const Eigen::Vector3d& p) {
    const int next = static_cast<int>(m_mesh.vertices.size());
    if (p.allFinite()) {
      const auto [it, inserted] = m_ids.try_emplace({p.x(), p.y(), p.z()}, next);
      if (!inserted) {
        return it->second;
      }
    }
    m_mesh.vertices.push_back(p);
    return next;
  }

  IndexedMesh m_mesh;
  std::map<std::array<double, 3>, int> m_ids;
  bool m_any_uvs = false;  ///< whether a face added so far has UVs
};

/// The meshes a scene places, in node order, each with its node transforms.
struct PlacedMesh {
  unsigned mesh_index = 0;
  Eigen::Affine3d transform;
};

void collect_placed_meshes(const aiScene& scene, const aiNode& node, const Eigen::Affine3d& parent,
                           std::vector<PlacedMesh>& out) {
  const Eigen::Affine3d transform = parent * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const unsigned mesh_index = node.mMeshes[i];
    if (mesh_index < scene.mNumMeshes && scene.mMeshes[mesh_index] != nullptr) {
      out.push_back({mesh_index, transform});
    }
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) {
    collect_placed_meshes(scene, *node.mChildren[i], transform, out);
  }
}

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// Why a file read through assimp has no vertex numbering, or "" if its single placed mesh keeps
/// the file's vertex order (assimp's PLY, OFF and glTF importers do).
std::string no_numbering_reason(const std::string& extension, const aiScene& scene,
                                std::size_t placed_meshes) {
  if (extension == ".stl") {
    return "STL stores every triangle's corners on their own, so its vertices have no numbers";
  }
  if (extension != ".ply" && extension != ".off" && extension != ".gltf" && extension != ".glb") {
    return "tissu knows the vertex numbers of OBJ, PLY, OFF and glTF/GLB files only";
  }
  if (scene.mNumMeshes != 1 || placed_meshes != 1) {
    return "the file holds " + std::to_string(scene.mNumMeshes) + " meshes placed " +
           std::to_string(placed_meshes) + " times, so a vertex number could mean several vertices";
  }
  return "";
}

/// Reads an OBJ file with read_obj: the file's vertex numbers are those of its `v` statements.
NumberedMesh import_obj(const std::filesystem::path& file) {
  ObjPolygons obj = read_obj(file);
  std::vector<std::vector<Eigen::Vector2d>> face_uvs(obj.faces.size());
  for (std::size_t f = 0; f < obj.faces.size(); ++f) {
    for (int t : obj.face_texture_coordinates[f]) {
      face_uvs[f].push_back(obj.texture_coordinates[t].head<2>());  // w, if given, is dropped
    }
  }
  MeshMerger merger;
  NumberedMesh out;
  out.mesh_vertex_of_file_vertex =
      merger.add({std::move(obj.positions), std::move(obj.faces), std::move(face_uvs)});
  out.mesh = merger.take();
  return out;
}

/// Reads `file` through assimp, without post-processing: assimp's steps (e.g. joining vertices)
/// trust the indices, so they run into out-of-range ones before we can report them.
NumberedMesh import_with_assimp(const std::filesystem::path& file) {
  const std::string name = file.string();
  const ScopedRepairLog repairs;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(name, 0);
  if (scene == nullptr) {
    const std::string error = importer.GetErrorString();
    if (error.find("bad_alloc") != std::string::npos) {  // assimp reports std::bad_alloc's what()
      throw MeshError(name +
                      ": cannot read mesh: the importer (assimp) ran out of memory on it: "
                      "the file is damaged, or too large for the memory limit");
    }
    throw MeshError(name + ": cannot read mesh: " + error);
  }
  if (!repairs.log().first().empty()) {
    throw MeshError(name + ": cannot read mesh: the importer reported \"" + repairs.log().first() +
                    "\"");
  }
  std::vector<PlacedMesh> placed;
  if (scene->mRootNode != nullptr) {
    collect_placed_meshes(*scene, *scene->mRootNode, Eigen::Affine3d::Identity(), placed);
  }
  MeshMerger merger;
  NumberedMesh out;
  for (const PlacedMesh& p : placed) {
    try {
      out.mesh_vertex_of_file_vertex = merger.add(polygons_of(
          *scene->mMeshes[p.mesh_index], p.mesh_index, scene->mNumMeshes > 1, p.transform));
    } catch (const MeshError& e) {
      throw MeshError(name + ": " + e.what());
    }
  }
  out.mesh = merger.take();
  out.no_numbering_reason = no_numbering_reason(lowercase_extension(file), *scene, placed.size());
  if (!out.has_vertex_numbering() || placed.empty()) out.mesh_vertex_of_file_vertex.clear();
  return out;
}

/// Default limits on the importer's child process for a file of `file_bytes`: 20 s plus 0.1 s
/// per MiB (a 1 GiB file gets 2 min), and 2 GiB plus 32 bytes per byte of file, at most three
/// quarters of the machine's memory.
SandboxLimits default_importer_limits(std::uintmax_t file_bytes) {
  SandboxLimits limits;
  limits.wall_time = std::chrono::milliseconds(20'000 + 100 * (file_bytes >> 20));
  const double physical =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  const double wanted = 2.0 * (1 << 30) + 32.0 * static_cast<double>(file_bytes);
  limits.memory_bytes =
      static_cast<std::size_t>(physical > 0 ? std::min(wanted, 0.75 * physical) : wanted);
  return limits;
}

/// import_with_assimp(file) in a child process (sandboxed_call.hpp): assimp 5.2's loaders crash,
/// loop forever or allocate without bound on some damaged files, which must not take tissu with
/// them. Its failures become a MeshError naming the file.
NumberedMesh import_with_assimp_isolated(const std::filesystem::path& file,
                                         const SandboxLimits& limits) {
  std::string bytes;
  try {
    bytes = sandboxed_call([&] { return numbered_mesh_bytes(import_with_assimp(file)); }, limits);
  } catch (const SandboxFailure& e) {
    const char* why = e.kind() == SandboxFailure::Kind::over_a_limit
                          ? ": the file is damaged, or too large for the limit"
                      : e.kind() == SandboxFailure::Kind::crashed ? ": the file is damaged"
                                                                  : "";
    throw MeshError(file.string() + ": cannot read mesh: the importer (assimp) " + e.what() +
                    (e.kind() == SandboxFailure::Kind::not_started ? "" : " on it") + why);
  } catch (const std::exception& e) {  // a MeshError of import_with_assimp, passed back
    throw MeshError(e.what());
  }
  try {
    return numbered_mesh_from_bytes(bytes);
  } catch (const std::exception& e) {
    throw MeshError(file.string() + ": cannot read mesh: " + e.what());
  }
}

/// The polygons of `file`, unchecked, with the file's vertex numbering.
NumberedMesh import_numbered(const std::filesystem::path& file, const MeshImportLimits& limits) {
  const std::uintmax_t size = check_mesh_file(file, limits.max_file_bytes);
  if (lowercase_extension(file) == ".obj") return import_obj(file);
  return import_with_assimp_isolated(file, limits.importer.value_or(default_importer_limits(size)));
}

}  // namespace

NumberedMesh read_numbered_mesh(const std::filesystem::path& file, const MeshImportLimits& limits) {
  NumberedMesh out = import_numbered(file, limits);
  try {
    validate_indexed_mesh(out.mesh);
  } catch (const MeshError& e) {
    throw MeshError(file.string() + ": " + e.what());
  }
  return out;
}

IndexedMesh read_mesh(const std::filesystem::path& file, const MeshImportLimits& limits) {
  return read_numbered_mesh(file, limits).mesh;
}

IndexedMesh read_polygons(const std::filesystem::path& file, const MeshImportLimits& limits) {
  return read_numbered_polygons(file, limits).mesh;
}

NumberedMesh read_numbered_polygons(const std::filesystem::path& file,
                                    const MeshImportLimits& limits) {
  NumberedMesh out = import_numbered(file, limits);
  out.mesh.face_uvs.clear();  // obstacles have no use for them, on some faces or all
  return out;
}

}  // namespace tissu
