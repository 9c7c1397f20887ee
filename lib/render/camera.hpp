#pragma once
/// \file
/// A pinhole camera for the renderer: where it stands, what it looks at, its field of view; the
/// view and projection matrices it gives; a default camera that frames a bounding box.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tissu {

/// A perspective camera in world coordinates (m). World up is +z (gravity is -z).
struct Camera {
  Eigen::Vector3d position{0.0, -3.0, 1.0};  ///< eye (m)
  Eigen::Vector3d target{0.0, 0.0, 0.0};     ///< the point at the image centre (m)
  Eigen::Vector3d up{0.0, 0.0, 1.0};         ///< image-up hint, not parallel to target - position
  double fov_y_deg = 40.0;                   ///< vertical field of view (degrees), in (0, 180)
};

/// Throws std::invalid_argument, with a message starting "camera: ", when the field of view is not
/// in (0, 180) degrees, a vector is not finite, the target equals the position, or up is zero or
/// parallel to the view direction.
void validate_camera(const Camera& camera);

/// A camera with vertical field of view `fov_y_deg` looking along `view_direction` at the centre
/// of `bounds`, moved back just far enough that the 8 corners of `bounds`, grown by 8 % around
/// its centre, fit in an image of width/height `aspect`. Throws std::invalid_argument for an
/// empty box, a non-positive aspect, or a view direction that is zero or parallel to `up`.
/// The default view looks along +y from 17 degrees above the horizontal: a cloth hanging in the
/// x-z plane (every shipped hanging scenario: u = x, v = z, whose front u x v faces -y) is seen
/// from the front, left and right symmetric, and a horizontal one (the drape) not edge-on.
Camera framing_camera(const Eigen::AlignedBox3d& bounds, double aspect,
                      Eigen::Vector3d view_direction = {0.0, 1.0, -0.3},
                      Eigen::Vector3d up = {0.0, 0.0, 1.0}, double fov_y_deg = 40.0);

/// The world-to-eye transform (OpenGL convention: the eye looks down -z, y is image up).
/// `camera` must be valid.
Eigen::Matrix4f view_matrix(const Camera& camera);

/// The eye-to-clip perspective transform (OpenGL convention, depth mapped to [-1, 1]) for an image
/// of width/height `aspect`, with clip planes at distances 0 < near_m < far_m in front of the eye.
Eigen::Matrix4f projection_matrix(const Camera& camera, double aspect, double near_m, double far_m);

}  // namespace tissu
