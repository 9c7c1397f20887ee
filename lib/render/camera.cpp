#include "lib/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

std::string to_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

/// Right, true up and forward unit vectors of an eye looking along `forward` with up hint `up`.
struct Basis {
  Eigen::Vector3d right, up, forward;
};

Basis eye_basis(const Eigen::Vector3d& forward, const Eigen::Vector3d& up) {
  Basis b;
  b.forward = forward.normalized();
  b.right = b.forward.cross(up).normalized();
  b.up = b.right.cross(b.forward);
  return b;
}

bool parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return a.normalized().cross(b.normalized()).norm() < 1e-9;
}

}  // namespace

void validate_camera(const Camera& camera) {
  const double fov = camera.fov_y_deg;
  if (!(fov > 0.0 && fov < 180.0))
    throw std::invalid_argument("camera: field of view must be in (0, 180) degrees, got " +
                                to_text(fov));
  if (!camera.position.allFinite()) throw std::invalid_argument("camera: position is not finite");
  if (!camera.target.allFinite()) throw std::invalid_argument("camera: target is not finite");
  if (!camera.up.allFinite()) throw std::invalid_argument("camera: up is not finite");
  const Eigen::Vector3d view = camera.target - camera.position;
  const double scale = std::max({1.0, camera.position.norm(), camera.target.norm()});
  if (view.norm() <= 1e-12 * scale) throw std::invalid_argument("camera: target equals position");
  if (camera.up.norm() == 0.0) throw std::invalid_argument("camera: up is the zero vector");
  if (parallel(view, camera.up))
    throw std::invalid_argument("camera: up is parallel to the view direction");
}

Camera framing_camera(const Eigen::AlignedBox3d& bounds, double aspect,
                      Eigen::Vector3d view_direction, Eigen::Vector3d up, double fov_y_deg) {
  if (bounds.isEmpty()) throw std::invalid_argument("framing camera: the bounding box is empty");
  if (!(aspect > 0.0) || !std::isfinite(aspect))
    throw std::invalid_argument("framing camera: aspect must be positive, got " + to_text(aspect));
  if (!(view_direction.norm() > 0.0) || !view_direction.allFinite())
    throw std::invalid_argument("framing camera: view direction must be a non-zero vector");
  if (!(up.norm() > 0.0) || parallel(view_direction, up))
    throw std::invalid_argument("framing camera: up is zero or parallel to the view direction");

  const Basis b = eye_basis(view_direction, up);
  const double tan_y = std::tan(radians(fov_y_deg) / 2.0);
  const double tan_x = tan_y * aspect;
  const Eigen::Vector3d centre = bounds.center();
  const double size = std::max(bounds.diagonal().norm(), 1e-6);  // a point still gets a camera
  const double margin = 1.08;

  // distance d from the centre such that every corner c, at offset (x, y, z) in the eye basis
  // (z away from the eye), satisfies |x| <= (d + z) tan_x and |y| <= (d + z) tan_y.
  double distance = 0.0;
  double nearest = 0.0;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner = bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
    const Eigen::Vector3d offset = margin * (corner - centre);
    const double x = offset.dot(b.right), y = offset.dot(b.up), z = offset.dot(b.forward);
    distance = std::max({distance, std::abs(x) / tan_x - z, std::abs(y) / tan_y - z});
    nearest = std::max(nearest, -z);
  }
  distance = std::max({distance, nearest + 0.05 * size, 0.05 * size});

  Camera camera;
  camera.target = centre;
  camera.position = centre - distance * b.forward;
  camera.up = up;
  camera.fov_y_deg = fov_y_deg;
  validate_camera(camera);
  return camera;
}

Eigen::Matrix4f view_matrix(const Camera& camera) {
  const Basis b = eye_basis(camera.target - camera.position, camera.up);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = b.right.transpose();
  view.block<1, 3>(1, 0) = b.up.transpose();
  view.block<1, 3>(2, 0) = -b.forward.transpose();
  view(0, 3) = -b.right.dot(camera.position);
  view(1, 3) = -b.up.dot(camera.position);
  view(2, 3) = b.forward.dot(camera.position);
  return view.cast<float>();
}

Eigen::Matrix4f projection_matrix(const Camera& camera, double aspect, double near_m,
                                  double far_m) {
  const double f = 1.0 / std::tan(radians(camera.fov_y_deg) / 2.0);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far_m + near_m) / (near_m - far_m);
  p(2, 3) = 2.0 * far_m * near_m / (near_m - far_m);
  p(3, 2) = -1.0;
  return p.cast<float>();
}

}  // namespace tissu
