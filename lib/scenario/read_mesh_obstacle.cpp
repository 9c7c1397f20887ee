#include "lib/scenario/read_mesh_obstacle.hpp"

#include <Eigen/Geometry>
#include <filesystem>
#include <functional>
#include <string>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/point_cache.hpp"
#include "lib/scenario/read_motion.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "topology/mesh_obstacle.hpp"

namespace tissu {
namespace {

namespace fs = std::filesystem;

/// Where the file's coordinates go in the scene: scaled about its origin, rotated about it, then
/// moved by "position".
using Placement = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

/// The path of a `what` at `key` of `o`, relative to the scenario's folder unless absolute, made
/// absolute in the resolved scenario (so that it runs from any folder).
fs::path read_path(JsonObjectReader& o, std::string_view key, const std::string& what) {
  const fs::path given = o.string(key);
  if (given.empty()) o.fail(key, "the path of a " + what + ", not an empty string");
  const fs::path file = given.is_absolute() ? given : fs::path(o.file()).parent_path() / given;
  o.resolve(key, fs::absolute(file).string());
  return file;
}

/// The positions of `mesh`'s vertices given per file vertex (`by_file_vertex`, in the scene's
/// frame), through the numbering of the file that made it. Vertices the reader joined (at the same
/// place in that file) must stay together: `where` names the sample in the error otherwise.
std::vector<Eigen::Vector3d> mesh_positions(const NumberedMesh& mesh,
                                            const std::vector<Eigen::Vector3d>& by_file_vertex,
                                            const std::string& where) {
  const std::vector<int>& mesh_vertex = mesh.mesh_vertex_of_file_vertex;
  std::vector<Eigen::Vector3d> x(mesh.mesh.vertices.size());
  std::vector<int> first_file_vertex(x.size(), -1);
  for (std::size_t f = 0; f < mesh_vertex.size(); ++f) {
    const int m = mesh_vertex[f];
    if (m < 0) continue;  // used by no face
    if (first_file_vertex[m] < 0) {
      first_file_vertex[m] = static_cast<int>(f);
      x[m] = by_file_vertex[f];
    } else if (by_file_vertex[f] != x[m]) {
      throw MeshError(where + ": the file's vertices " + std::to_string(first_file_vertex[m]) +
                      " and " + std::to_string(f) +
                      " are at the same place in the mesh file, so its faces share them, but "
                      "here they move apart; give each place one vertex in the mesh file");
    }
  }
  return x;
}

/// The samples of a PC2 point cache ("point_cache", "frame_rate", "start_time" of `animation`):
/// sample k at start_time + k sample_rate / frame_rate (s), its point p the file's vertex p.
MeshSamples point_cache_samples(JsonObjectReader& animation, const NumberedMesh& mesh,
                                const Placement& placed) {
  const fs::path file = read_path(animation, "point_cache", "PC2 point cache");
  const double frame_rate_hz = animation.number(
      "frame_rate", between(min_frame_rate_hz, max_frame_rate_hz, " (frames per second)"));
  const double start_time_s = animation.number_or("start_time", 0.0, NumberRule{});
  PointCache cache;
  try {
    cache = read_point_cache(file);
  } catch (const PointCacheError& e) {
    throw ScenarioError(animation.file() + ": " + animation.key_path("point_cache") + ": " +
                        e.what());
  }
  const std::size_t points = cache.samples.front().size();
  if (points != mesh.mesh_vertex_of_file_vertex.size()) {
    animation.fail("point_cache", "a cache of one point per vertex of the mesh file (" +
                                      std::to_string(mesh.mesh_vertex_of_file_vertex.size()) +
                                      "), not " + std::to_string(points));
  }
  MeshSamples samples;
  for (std::size_t k = 0; k < cache.samples.size(); ++k) {
    samples.times_s.push_back(start_time_s +
                              static_cast<double>(k) * cache.sample_rate / frame_rate_hz);
    std::vector<Eigen::Vector3d>& x = cache.samples[k];
    for (Eigen::Vector3d& p : x) p = placed(p);
    samples.vertices_m.push_back(mesh_positions(mesh, x, "sample " + std::to_string(k)));
  }
  return samples;
}

/// The samples of "keyframes" of `animation`: [{"time": s, "file": mesh}, ...], each file with the
/// mesh file's vertices in the same order (its faces are the mesh file's).
MeshSamples keyframe_samples(JsonObjectReader& animation, const NumberedMesh& mesh,
                             const Placement& placed) {
  MeshSamples samples;
  for (const ArrayElement& element : animation.array("keyframes")) {
    JsonObjectReader key = object_reader(element, animation.file());
    const double time_s = key.number("time", NumberRule{});
    if (!samples.times_s.empty() && !(time_s > samples.times_s.back())) {
      key.fail("time", "a time after the previous keyframe's (" +
                           std::to_string(samples.times_s.back()) + " s)");
    }
    const fs::path file = read_path(key, "file", "mesh file");
    NumberedMesh keyed;
    try {
      keyed = read_numbered_polygons(file);
    } catch (const MeshError& e) {
      throw ScenarioError(key.file() + ": " + key.key_path("file") + ": " + e.what());
    }
    if (keyed.mesh_vertex_of_file_vertex.size() != mesh.mesh_vertex_of_file_vertex.size()) {
      key.fail("file", "a mesh with the mesh file's " +
                           std::to_string(mesh.mesh_vertex_of_file_vertex.size()) +
                           " vertices, in its order, not " +
                           std::to_string(keyed.mesh_vertex_of_file_vertex.size()));
    }
    std::vector<Eigen::Vector3d> by_file_vertex(keyed.mesh_vertex_of_file_vertex.size(),
                                                Eigen::Vector3d::Zero());
    for (std::size_t f = 0; f < by_file_vertex.size(); ++f) {
      const int m = keyed.mesh_vertex_of_file_vertex[f];
      if (m >= 0) by_file_vertex[f] = placed(keyed.mesh.vertices[m]);
    }
    key.finish();
    samples.times_s.push_back(time_s);
    samples.vertices_m.push_back(mesh_positions(mesh, by_file_vertex, key.path()));
  }
  if (samples.times_s.empty()) animation.fail("keyframes", "at least one keyframe");
  return samples;
}

/// The "animation" object of a mesh obstacle: exactly one of "point_cache" or "keyframes".
MeshSamples read_samples(JsonObjectReader animation, const NumberedMesh& mesh,
                         const Placement& placed) {
  if (animation.has("point_cache") == animation.has("keyframes")) {
    animation.fail("point_cache", "exactly one of \"point_cache\" or \"keyframes\"");
  }
  if (!mesh.has_vertex_numbering()) {
    animation.fail(animation.has("point_cache") ? "point_cache" : "keyframes",
                   "a mesh file whose vertices are numbered (" + mesh.no_numbering_reason + ")");
  }
  MeshSamples samples = animation.has("point_cache") ? point_cache_samples(animation, mesh, placed)
                                                     : keyframe_samples(animation, mesh, placed);
  animation.finish();
  return samples;
}

}  // namespace

MeshObstacleParts read_mesh_obstacle(JsonObjectReader& o, std::vector<std::string>& notes) {
  const fs::path file = read_path(o, "file", "mesh file");
  const double scale =
      o.number_or("scale", 1.0, between(min_obstacle_scale, max_obstacle_scale, ""));
  const Eigen::Matrix3d rotation = o.has("rotation")
                                       ? rotation_of(read_rotation_vector(o.object("rotation")))
                                       : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d position = o.vector3_or("position", Eigen::Vector3d::Zero());
  const Placement placed = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    return rotation * (scale * x) + position;
  };
  MeshObstacleParts parts;
  ObstacleMeshReport report;
  std::string key = "file";
  try {
    NumberedMesh numbered = read_numbered_polygons(file);
    for (Eigen::Vector3d& x : numbered.mesh.vertices) x = placed(x);
    // the whole soup first: it checks the faces and names them by their number in the file
    if (o.has("animation")) {
      key = "animation";
      const MeshSamples samples = read_samples(o.object("animation"), numbered, placed);
      parts.surfaces.push_back(make_mesh_animation(numbered.mesh, samples, &report)->at(0.0));
      numbered.mesh.vertices = samples.vertices_m.front();
      for (const IndexedMesh& part : separate_parts(numbered.mesh)) {
        parts.animations.push_back(make_mesh_animation(part, samples));
      }
    } else {
      parts.surfaces.push_back(make_mesh_surface(numbered.mesh, &report));
    }
    const std::vector<Eigen::Vector3d>& corners = parts.surfaces.front()->triangle_corners();
    for (const Eigen::Vector3d& corner : corners) parts.centre_m += corner;
    parts.centre_m /= static_cast<double>(corners.size());
    if (!parts.animations.empty()) {
      parts.surfaces.clear();
      for (const auto& animation : parts.animations) parts.surfaces.push_back(animation->at(0.0));
    } else if (std::vector<IndexedMesh> split = separate_parts(numbered.mesh); split.size() > 1) {
      parts.surfaces.clear();
      for (const IndexedMesh& part : split) parts.surfaces.push_back(make_mesh_surface(part));
    }
  } catch (const MeshError& e) {
    throw ScenarioError(o.file() + ": " + o.key_path(key) + ": " + e.what());
  }
  if (report.duplicate_faces > 0 || report.degenerate_faces > 0) {
    notes.push_back(o.file() + ": " + o.key_path("file") + ": " + file.string() + ": dropped " +
                    std::to_string(report.duplicate_faces) + " duplicate and " +
                    std::to_string(report.degenerate_faces) + " degenerate faces, kept " +
                    std::to_string(report.triangles) + " triangles");
  }
  return parts;
}

}  // namespace tissu
