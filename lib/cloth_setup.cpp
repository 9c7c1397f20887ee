#include "lib/cloth_setup.hpp"

#include <filesystem>
#include <string>
#include <system_error>

#include "lib/mesh_io/read_mesh.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {
namespace {

/// The scenario's pins with their indices turned from the mesh file's own vertex numbers into
/// the ids of `read.mesh`, which apply_pins matches with the particles' source_index. Throws
/// PinError naming the scenario file, the entry's key and the mesh file when the file has no
/// vertex numbering or an index is not one of its vertices.
std::vector<PinSelector> pins_on_mesh_vertices(const Scenario& scenario, const NumberedMesh& read) {
  std::vector<PinSelector> pins = scenario.pins;
  const std::string mesh_file = scenario.cloth.mesh_file.string();
  const std::vector<int>& mesh_vertex = read.mesh_vertex_of_file_vertex;
  for (std::size_t k = 0; k < pins.size(); ++k) {
    if (pins[k].kind != PinSelector::Kind::indices) continue;
    const std::string where =
        scenario.file.string() + ": pins[" + std::to_string(k) + "].indices: ";
    if (!read.has_vertex_numbering()) {
      throw PinError(where + "pins by index need the vertex numbers of the mesh file, and " +
                     mesh_file + " has none (" + read.no_numbering_reason +
                     "): pin by \"side\", \"corners\" or \"box\" instead, or convert the mesh to "
                     "OBJ, PLY or OFF");
    }
    for (int& index : pins[k].indices) {
      if (index < 0 || static_cast<std::size_t>(index) >= mesh_vertex.size()) {
        throw PinError(where + "vertex " + std::to_string(index) + " is not a vertex of " +
                       mesh_file + ", whose vertices are numbered from 0 to " +
                       std::to_string(mesh_vertex.size() - 1) + " in file order");
      }
      if (mesh_vertex[index] < 0) {
        throw PinError(where + "vertex " + std::to_string(index) + " of " + mesh_file +
                       " is used by no face, so it is not a particle of the cloth");
      }
      index = mesh_vertex[index];
    }
  }
  return pins;
}

/// The cloth mesh file of `scenario`, read; errors name the scenario and the key, then the mesh
/// file's own message, as an obstacle's do.
NumberedMesh read_cloth_mesh(const Scenario& scenario, const SetupStage& on_stage) {
  const std::filesystem::path& file = scenario.cloth.mesh_file;
  const std::string where = scenario.file.string() + ": cloth.mesh.file: ";
  std::error_code no_size;
  const std::uintmax_t bytes = std::filesystem::file_size(file, no_size);
  if (on_stage && !no_size && bytes >= large_mesh_file_bytes) {
    on_stage("reading the cloth mesh " + file.string() + ": " + std::to_string(bytes >> 20) +
             " MiB");
  }
  NumberedMesh read;
  try {
    read = read_numbered_mesh(file);
  } catch (const MeshError& e) {
    throw MeshError(where + e.what());
  }
  // each vertex a face uses is a particle (the reader keeps no other)
  if (read.mesh.vertices.size() > static_cast<std::size_t>(max_cloth_particles)) {
    throw MeshError(where + file.string() + ": " + std::to_string(read.mesh.vertices.size()) +
                    " vertices, more than the " + std::to_string(max_cloth_particles) +
                    " particles a cloth may have (the cloth size limit, docs/scenario.md)");
  }
  return read;
}

}  // namespace

void build_scenario_cloth(const Scenario& scenario, ClothComplex& lcc, const SetupStage& on_stage) {
  NumberedMesh read;
  if (scenario.cloth.grid) {
    read.mesh = make_grid_mesh(*scenario.cloth.grid);
  } else {
    read = read_cloth_mesh(scenario, on_stage);
  }
  // grid vertex ids are the mesh's; a file's are mapped to the mesh's
  const std::vector<PinSelector> pins =
      scenario.cloth.grid ? scenario.pins : pins_on_mesh_vertices(scenario, read);
  IndexedMesh& mesh = read.mesh;
  // refinement (adaptive, or around crack tips) bisects triangles: quads are cut once, here
  // (their shear springs become edges); vertex ids are kept
  if (scenario.refines_cloth()) mesh = triangulate_quads(mesh);
  if (on_stage && mesh.faces.size() >= large_cloth_faces) {
    on_stage("building the cloth complex: " + std::to_string(mesh.faces.size()) + " faces, " +
             std::to_string(mesh.vertices.size()) + " particles");
  }
  try {
    build_cloth_complex(mesh, scenario.areal_density, scenario.springs, lcc);
  } catch (const std::invalid_argument& e) {  // a cell the material's formulation does not define
    throw MeshError(scenario.file.string() + ": cloth: " + e.what());
  } catch (const MeshError& e) {  // a grid's, or a file's after triangulation
    throw MeshError(scenario.file.string() + ": " +
                    (scenario.cloth.grid
                         ? std::string("cloth.grid: ")
                         : "cloth.mesh.file: " + scenario.cloth.mesh_file.string() + ": ") +
                    e.what());
  }
  if (scenario.cloth.grid && scenario.cloth.grid->pleats > 0) {
    place_particles(grid_initial_positions(*scenario.cloth.grid), lcc);
  }
  try {
    apply_pins(lcc, pins, scenario.cloth.frame);
  } catch (const PinError& e) {
    throw PinError(scenario.file.string() + ": " + e.what());
  }
}

}  // namespace tissu
