#include "lib/cloth_setup.hpp"

#include "lib/mesh_io/read_mesh.hpp"
#include "topology/apply_pins.hpp"
#include "topology/build_cloth_complex.hpp"
#include "topology/grid_mesh.hpp"

namespace tissu {

void build_scenario_cloth(const Scenario& scenario, ClothComplex& lcc) {
  IndexedMesh mesh = scenario.cloth.grid ? make_grid_mesh(*scenario.cloth.grid)
                                         : read_mesh(scenario.cloth.mesh_file);
  // refinement (adaptive, or around crack tips) bisects triangles: quads are cut once, here
  // (their shear springs become edges)
  if (scenario.refines_cloth()) mesh = triangulate_quads(mesh);
  try {
    build_cloth_complex(mesh, scenario.areal_density, scenario.springs, lcc);
  } catch (const std::invalid_argument& e) {  // a cell the material's formulation does not define
    throw MeshError(scenario.file.string() + ": cloth: " + e.what());
  }
  if (scenario.cloth.grid && scenario.cloth.grid->pleats > 0) {
    place_particles(grid_initial_positions(*scenario.cloth.grid), lcc);
  }
  try {
    apply_pins(lcc, scenario.pins, scenario.cloth.frame);
  } catch (const PinError& e) {
    throw PinError(scenario.file.string() + ": " + e.what());
  }
}

}  // namespace tissu
