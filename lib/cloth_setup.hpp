#pragma once
/// \file
/// The cloth complex a scenario describes. Includes CGAL: for lib/ sources only.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "lib/scenario/scenario.hpp"
#include "topology/cloth_complex.hpp"

namespace tissu {

/// A cloth of at least this many faces is large: setting it up takes seconds (about 8 s for the
/// 2 million triangles of a 1000 x 1000 grid), so its setup stages are reported.
inline constexpr std::size_t large_cloth_faces = 100'000;
/// A mesh file of at least this many bytes is large: its reading is reported.
inline constexpr std::uintmax_t large_mesh_file_bytes = std::uintmax_t{16} << 20;  // 16 MiB

/// Called with one line saying what the setup of a large cloth is about to do, e.g. "building
/// the cloth complex: 1996002 faces, 1000000 particles".
using SetupStage = std::function<void(const std::string&)>;

/// Builds the grid or reads the mesh of `scenario`, assigns rest data, masses and springs, and
/// applies the pins. Throws MeshError or PinError (messages name the file or the pins entry); a
/// mesh with more vertices than max_cloth_particles (lib/scenario/scenario_limits.hpp) is refused
/// before anything is built. Reports reading a large mesh file and building a large cloth
/// through `on_stage`, when given.
void build_scenario_cloth(const Scenario& scenario, ClothComplex& lcc,
                          const SetupStage& on_stage = {});

}  // namespace tissu
