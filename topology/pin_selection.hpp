#pragma once
/// \file
/// Which particles are pinned: selectors over the cloth's material coordinates. CGAL-free.

#include <Eigen/Geometry>
#include <limits>
#include <string>
#include <vector>

#include "solver/rigid_motion.hpp"

namespace tissu {

/// The in-plane frame in which a cloth's sides are named: left/right along u, bottom/top along v.
struct ClothFrame {
  Eigen::Vector3d u_axis{1.0, 0.0, 0.0};  ///< unit
  Eigen::Vector3d v_axis{0.0, 0.0, 1.0};  ///< unit
};

enum class Side { left, right, bottom, top };
enum class Corner { bottom_left, bottom_right, top_left, top_right };

/// One way of choosing particles, by material coordinates or input vertex ids.
struct PinSelector {
  enum class Kind { corners, side, indices, box };
  Kind kind = Kind::side;
  std::vector<Corner> corners;  ///< kind == corners
  Side side = Side::top;        ///< kind == side: vertices on that side, ordered along it ...
  int every = 1;                ///< ... keeping every n-th one and always both ends
  /// kind == indices: vertex ids of the IndexedMesh the cloth was built from (a grid's vertex
  /// ids; for a mesh file, the scenario's 0-based file vertex numbers mapped by
  /// build_scenario_cloth)
  std::vector<int> indices;
  Eigen::AlignedBox3d box;  ///< kind == box: material coordinates inside it (m)
  /// The handle's motion: its drift is the velocity the chosen particles keep (m/s, a handle
  /// moving at constant speed); its keyframes carry them rigidly from where they are when the
  /// handle takes hold (lib/pin_handles.hpp).
  RigidMotion motion;
  double attach_at_s = 0.0;  ///< when the handle takes hold of its particles (s); 0: from the start
  /// when it lets them go, keeping their velocity (s); infinity: never
  double release_at_s = std::numeric_limits<double>::infinity();
};

/// Thrown when a selector selects nothing or names a vertex that does not exist; the message
/// names the selector by its position.
class PinError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tissu
