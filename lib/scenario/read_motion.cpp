#include "lib/scenario/read_motion.hpp"

#include <numbers>
#include <string>

namespace tissu {

Eigen::Vector3d read_rotation_vector(JsonObjectReader rotation) {
  const Eigen::Vector3d axis = rotation.direction_or("axis", Eigen::Vector3d::UnitZ());
  if (rotation.has("angle") == rotation.has("degrees")) {
    rotation.fail("angle", "exactly one of \"angle\" (rad) and \"degrees\"");
  }
  const double angle_rad = rotation.has("angle")
                               ? rotation.number("angle", {})
                               : rotation.number("degrees", {}) * std::numbers::pi / 180.0;
  rotation.finish();
  return angle_rad * axis;
}

RigidMotion read_motion(JsonObjectReader motion, std::optional<Eigen::Vector3d> default_pivot) {
  RigidMotion m;
  m.drift_m_per_s = motion.vector3_or("velocity", m.drift_m_per_s);
  m.interpolation = motion.choice_or("interpolation", "linear", {"linear", "smooth"}) == "smooth"
                        ? KeyInterpolation::smooth
                        : KeyInterpolation::linear;
  if (motion.has("keyframes")) {
    for (const ArrayElement& element : motion.array("keyframes")) {
      JsonObjectReader key = object_reader(element, motion.file());
      RigidKey k;
      k.time_s = key.number("time", non_negative(" (s)"));
      if (!m.keys.empty() && k.time_s <= m.keys.back().time_s) {
        key.fail("time", "a time after the previous keyframe's " +
                             std::to_string(m.keys.back().time_s) + " s");
      }
      k.translation_m = key.vector3_or("offset", Eigen::Vector3d::Zero());
      if (key.has("rotation")) k.rotation_rad = read_rotation_vector(key.object("rotation"));
      key.finish();
      m.keys.push_back(k);
    }
  }
  if (motion.has("pivot") || default_pivot) {
    m.pivot_m = motion.vector3_or("pivot", default_pivot.value_or(Eigen::Vector3d::Zero()));
  } else if (m.rotates()) {
    motion.fail("pivot", "the point the keyframes' rotations turn about ([x, y, z], m)");
  }
  motion.finish();
  return m;
}

}  // namespace tissu
