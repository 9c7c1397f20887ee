#include "lib/mesh_io/read_mesh.hpp"

#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace tissu {
namespace {

/// Importer messages that mean the file was broken but the importer still returned a scene: the
/// OFF loader clamps out-of-range indices and leaves faces empty when the file is shorter than
/// its header says; the glTF loader drops faces with out-of-range indices. Other messages (e.g. a
/// missing OBJ material library) are harmless.
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

/// Merges the polygons of several assimp meshes into one IndexedMesh, joining vertices at
/// exactly the same (transformed) position.
class MeshMerger {
 public:
  explicit MeshMerger(bool several_meshes) : m_several_meshes(several_meshes) {}

  void add(const aiMesh& in, unsigned mesh_index, const Eigen::Affine3d& transform) {
    std::vector<int> ids(in.mNumVertices, -1);
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (!is_polygon(face)) {
        continue;
      }
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        if (face.mIndices[i] >= in.mNumVertices) {
          throw_index_out_of_range(in, mesh_index, f, face.mIndices[i]);
        }
        ids[face.mIndices[i]] = 0;
      }
    }
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      if (ids[v] == 0) {
        const Eigen::Vector3d p(in.mVertices[v].x, in.mVertices[v].y, in.mVertices[v].z);
        // a non-finite point is kept as read, so the error names the file's coordinates
        ids[v] = vertex_id(p.allFinite() ? Eigen::Vector3d(transform * p) : p);
      }
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (is_polygon(face)) {
        std::vector<int>& out = m_mesh.faces.emplace_back();
        for (unsigned i = 0; i < face.mNumIndices; ++i) {
          out.push_back(ids[face.mIndices[i]]);
        }
      }
    }
  }

  IndexedMesh take() { return std::move(m_mesh); }

 private:
  [[noreturn]] void throw_index_out_of_range(const aiMesh& in, unsigned mesh_index, unsigned face,
                                             unsigned index) const {
    // loaders store indices unsigned: a huge one was most likely negative in the file
    const std::string id = index > static_cast<unsigned>(std::numeric_limits<int>::max())
                               ? std::to_string(static_cast<std::int32_t>(index))
                               : std::to_string(index);
    const std::string where = m_several_meshes ? " of mesh " + std::to_string(mesh_index) : "";
    throw MeshError("face " + std::to_string(face) + where + " refers to vertex " + id +
                    ", but the mesh has " + std::to_string(in.mNumVertices) + " vertices");
  }

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

  bool m_several_meshes;
  IndexedMesh m_mesh;
  std::map<std::array<double, 3>, int> m_ids;
};

void add_node(const aiScene& scene, const aiNode& node, const Eigen::Affine3d& parent,
              MeshMerger& merger) {
  const Eigen::Affine3d transform = parent * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const unsigned mesh_index = node.mMeshes[i];
    if (mesh_index < scene.mNumMeshes && scene.mMeshes[mesh_index] != nullptr) {
      merger.add(*scene.mMeshes[mesh_index], mesh_index, transform);
    }
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) {
    add_node(scene, *node.mChildren[i], transform, merger);
  }
}

/// Reads `file` without post-processing: assimp's steps (e.g. joining vertices) trust the
/// indices, so they run into out-of-range ones before we can report them.
IndexedMesh import_mesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) {
    throw MeshError(name + ": cannot read mesh: no such file");
  }
  if (std::filesystem::is_directory(status)) {
    throw MeshError(name + ": cannot read mesh: it is a directory, not a file");
  }
  const ScopedRepairLog repairs;
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(name, 0);
  if (scene == nullptr) {
    throw MeshError(name + ": cannot read mesh: " + importer.GetErrorString());
  }
  if (!repairs.log().first().empty()) {
    throw MeshError(name + ": cannot read mesh: the importer reported \"" + repairs.log().first() +
                    "\"");
  }
  MeshMerger merger(scene->mNumMeshes > 1);
  if (scene->mRootNode != nullptr) {
    try {
      add_node(*scene, *scene->mRootNode, Eigen::Affine3d::Identity(), merger);
    } catch (const MeshError& e) {
      throw MeshError(name + ": " + e.what());
    }
  }
  return merger.take();
}

}  // namespace

IndexedMesh read_mesh(const std::filesystem::path& file) {
  IndexedMesh mesh = import_mesh(file);
  try {
    validate_indexed_mesh(mesh);
  } catch (const MeshError& e) {
    throw MeshError(file.string() + ": " + e.what());
  }
  return mesh;
}

IndexedMesh read_polygons(const std::filesystem::path& file) {
  return import_mesh(file);
}

}  // namespace tissu
