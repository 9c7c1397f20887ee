#pragma once
/// \file
/// A validated simulation scenario (schema: docs/scenario.md). CGAL-free.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lib/mesh_io/write_mesh.hpp"
#include "lib/render/camera.hpp"
#include "lib/render/render_options.hpp"
#include "solver/solver_params.hpp"
#include "topology/grid_options.hpp"
#include "topology/pin_selection.hpp"
#include "topology/refinement_options.hpp"
#include "topology/spring_settings.hpp"
#include "topology/tearing_options.hpp"

namespace tissu {

/// Where the cloth's shape comes from: a generated grid or a mesh file.
struct ClothSource {
  std::optional<GridOptions> grid;  ///< set for a grid cloth
  std::filesystem::path
      mesh_file;     ///< set for a mesh cloth, resolved against the scenario's folder
  ClothFrame frame;  ///< in-plane axes naming the sides (a grid's own u, v)
};

struct OutputOptions {
  bool write_meshes = true;  ///< one mesh file per written frame
  MeshFormat mesh_format = MeshFormat::obj;
  int mesh_every = 1;  ///< write every n-th frame's mesh (frame 0 always)
  /// also a glTF binary, frame_NNNNN.glb, at the frames whose mesh is due (whatever write_meshes)
  bool glb = false;
  /// viewer/: the browser page and frames.js, every frame (lib/viewer_frames.hpp)
  bool viewer = true;
  /// frames.pc2, every frame's positions (lib/point_cache.hpp); only while the particles stay
  /// the same, so on by default without refinement or tearing
  bool point_cache = false;
  /// frames.h5, every frame's positions, velocities, rest positions, triangles and pins
  /// (lib/frame_arrays.hpp); off by default (about 110 bytes per particle and frame)
  bool arrays = false;
};

/// Images of the run, rendered after it with one camera for all frames.
struct RenderSettings {
  bool enabled = false;          ///< write PNG frames (and a video)
  RenderOptions options;         ///< image size, wireframe, colours
  std::optional<Camera> camera;  ///< unset: frames the cloth's bounding box over the whole run
  int every = 1;                 ///< render every n-th frame; image k shows frame k n
  bool video = true;             ///< <name>.mp4 and <name>.gif when ffmpeg is on the PATH
};

/// Adaptive refinement and coarsening while the cloth moves.
struct AdaptiveSettings {
  bool enabled = false;
  int every = 1;  ///< refine and coarsen after every n-th frame
  RefinementOptions refinement;
  /// Coarsen where every criterion is below hysteresis x its threshold, in [0, 1): cells do not
  /// flicker between levels. 0 never coarsens.
  double hysteresis = 0.5;
};

/// Tearing where the cloth is overstretched, and knife cuts at given times.
struct TearingSettings {
  bool enabled = false;
  TearingOptions options;         ///< strain_threshold 0: only the cuts tear
  std::vector<ScriptedCut> cuts;  ///< by increasing time
};

struct Scenario {
  std::string name;            ///< defaults to the file's stem
  std::filesystem::path file;  ///< the scenario file, for messages
  ClothSource cloth;
  double areal_density = 0.0;  ///< mass per rest area (kg/m^2)
  SpringSettings springs;
  std::vector<PinSelector> pins;
  SolverParams solver;       ///< time_step = 1 / (frame_rate substeps)
  int frames = 1;            ///< frames simulated after frame 0
  double frame_rate = 30.0;  ///< frames per simulated second (Hz)
  int substeps = 1;          ///< solver steps per frame
  int threads = 0;           ///< OpenMP threads, 0 for OpenMP's default; applied by the apps
  AdaptiveSettings adaptive;
  TearingSettings tearing;
  OutputOptions output;
  RenderSettings render;
  /// Remarks from loading that are not errors (e.g. an obstacle mesh's dropped duplicate faces),
  /// one line each, naming the file and key; the apps print them before running.
  std::vector<std::string> notes;
  /// The scenario as run, as JSON text: the file after the overrides, with every default read
  /// filled in and mesh paths made absolute (the run folder's scenario.json); it loads again as
  /// this same scenario.
  std::string resolved_json;

  /// Whether the run bisects triangles (adaptive refinement, or refinement around crack tips):
  /// quads are then cut into triangles before it starts.
  bool refines_cloth() const {
    return adaptive.enabled || (tearing.enabled && tearing.options.tip_min_edge_length_m > 0.0);
  }
};

/// Reads, validates and returns the scenario in `file`. Each "key.path=value" of `overrides` is
/// applied to the JSON before validation (value parsed as JSON, else taken as a string). JSON
/// comments are allowed. Throws ScenarioError with one line naming the file, the key path and
/// what was expected.
Scenario load_scenario(const std::filesystem::path& file,
                       const std::vector<std::string>& overrides = {});

/// Same, from JSON text; `file` is used for messages and to resolve relative mesh paths.
Scenario parse_scenario(const std::string& text, const std::filesystem::path& file,
                        const std::vector<std::string>& overrides = {});

}  // namespace tissu
