#include "lib/render/camera.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

using ::testing::HasSubstr;

/// The message validate_camera throws for `camera`, or "" if it is valid.
std::string camera_error(const Camera& camera) {
  try {
    validate_camera(camera);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// Normalised device coordinates of world point `p`.
Eigen::Vector3d ndc(const Eigen::Matrix4f& view_projection, const Eigen::Vector3d& p) {
  const Eigen::Vector4d clip = view_projection.cast<double>() * p.homogeneous();
  return clip.head<3>() / clip.w();
}

TEST(ValidateCamera, AcceptsTheDefault) {
  EXPECT_EQ(camera_error(Camera{}), "");
}

TEST(ValidateCamera, RejectsAFieldOfViewOutsideZeroTo180) {
  Camera camera;
  camera.fov_y_deg = 0.0;
  EXPECT_THAT(camera_error(camera),
              HasSubstr("camera: field of view must be in (0, 180) degrees, got 0"));
  camera.fov_y_deg = 180.0;
  EXPECT_THAT(camera_error(camera), HasSubstr("got 180"));
  camera.fov_y_deg = std::nan("");
  EXPECT_THAT(camera_error(camera), HasSubstr("field of view"));
}

TEST(ValidateCamera, RejectsTargetEqualToPosition) {
  Camera camera;
  camera.target = camera.position;
  EXPECT_THAT(camera_error(camera), HasSubstr("camera: target equals position"));
}

TEST(ValidateCamera, RejectsUpParallelToTheViewDirection) {
  Camera camera;
  camera.position = {0.0, 0.0, 5.0};
  camera.target = {0.0, 0.0, 0.0};
  camera.up = {0.0, 0.0, 1.0};
  EXPECT_THAT(camera_error(camera), HasSubstr("camera: up is parallel to the view direction"));
  camera.up = Eigen::Vector3d::Zero();
  EXPECT_THAT(camera_error(camera), HasSubstr("camera: up is the zero vector"));
}

TEST(ViewMatrix, PutsTheTargetOnTheNegativeZAxisWithUpAlongY) {
  Camera camera;
  camera.position = {1.0, -4.0, 2.0};
  camera.target = {0.5, 0.0, 1.0};
  const Eigen::Matrix4d view = view_matrix(camera).cast<double>();
  const Eigen::Vector3d target = (view * camera.target.homogeneous()).head<3>();
  EXPECT_NEAR(target.x(), 0.0, 1e-5);
  EXPECT_NEAR(target.y(), 0.0, 1e-5);
  EXPECT_NEAR(target.z(), -(camera.target - camera.position).norm(), 1e-5);
  const Eigen::Vector3d eye = (view * camera.position.homogeneous()).head<3>();
  EXPECT_NEAR(eye.norm(), 0.0, 1e-5);
  // a point above the target (world +z) appears above the image centre
  const Eigen::Vector3d above = (view * Eigen::Vector3d(0.5, 0.0, 2.0).homogeneous()).head<3>();
  EXPECT_GT(above.y(), 0.1);
}

TEST(ProjectionMatrix, MapsTheFieldOfViewEdgeAndTheClipPlanes) {
  Camera camera;
  camera.position = {0.0, 0.0, 0.0};
  camera.target = {0.0, 1.0, 0.0};
  camera.fov_y_deg = 60.0;
  const Eigen::Matrix4f vp = projection_matrix(camera, 2.0, 0.5, 10.0) * view_matrix(camera);
  const double t = std::tan(std::numbers::pi / 6.0);
  // at distance 3 straight ahead, the top edge of the view is 3 tan(30 deg) up
  EXPECT_NEAR(ndc(vp, {0.0, 3.0, 3.0 * t}).y(), 1.0, 1e-5);
  EXPECT_NEAR(ndc(vp, {-2.0 * 3.0 * t, 3.0, 0.0}).x(), -1.0, 1e-5);
  EXPECT_NEAR(ndc(vp, {0.0, 0.5, 0.0}).z(), -1.0, 1e-5);
  EXPECT_NEAR(ndc(vp, {0.0, 10.0, 0.0}).z(), 1.0, 1e-5);
}

TEST(FramingCamera, KeepsEveryCornerOfTheBoxInViewAndFillsIt) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-0.5, -0.1, 0.0), Eigen::Vector3d(0.5, 0.2, 1.5));
  for (const double aspect : {16.0 / 9.0, 1.0, 0.5}) {
    const Camera camera = framing_camera(box, aspect, {0.3, 1.0, -0.3}, {0.0, 0.0, 1.0}, 40.0);
    EXPECT_EQ(camera.target, box.center());
    const Eigen::Matrix4f vp = projection_matrix(camera, aspect, 0.01, 100.0) * view_matrix(camera);
    double extent = 0.0;
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d p =
          ndc(vp, box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)));
      EXPECT_LE(std::abs(p.x()), 1.0) << "aspect " << aspect;
      EXPECT_LE(std::abs(p.y()), 1.0) << "aspect " << aspect;
      extent = std::max({extent, std::abs(p.x()), std::abs(p.y())});
    }
    // tight: the box reaches the 8 % margin on one side
    EXPECT_NEAR(extent, 1.0 / 1.08, 0.03) << "aspect " << aspect;
  }
}

TEST(FramingCamera, TheDefaultViewShowsAHangingClothFromTheFront) {
  // the curtain demo's box: 1.4 m gathered across x, a few cm of pleats along y, 2.4 m tall
  const Eigen::AlignedBox3d curtain(Eigen::Vector3d(-0.7, -0.05, 0.0),
                                    Eigen::Vector3d(0.7, 0.05, 2.4));
  const double aspect = 960.0 / 720.0;
  const Camera camera = framing_camera(curtain, aspect);
  const Eigen::Vector3d view = camera.target - camera.position;
  // horizontally along the cloth's normal (y), from its front (-y) side
  const double off_normal_deg = std::atan2(std::abs(view.x()), view.y()) * 180.0 / std::numbers::pi;
  EXPECT_LT(off_normal_deg, 0.01);
  // so mirror points left and right of the cloth's middle land mirrored in the image
  const Eigen::Matrix4f vp = projection_matrix(camera, aspect, 0.01, 100.0) * view_matrix(camera);
  for (const double z : {0.0, 1.2, 2.4}) {
    const Eigen::Vector3d left = ndc(vp, {-0.7, 0.0, z}), right = ndc(vp, {0.7, 0.0, z});
    EXPECT_NEAR(left.x(), -right.x(), 1e-6) << "z " << z;
    EXPECT_NEAR(left.y(), right.y(), 1e-6) << "z " << z;
  }
}

TEST(FramingCamera, RejectsAnEmptyBoxAndABadViewDirection) {
  EXPECT_THROW(framing_camera(Eigen::AlignedBox3d(), 1.0), std::invalid_argument);
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  EXPECT_THROW(framing_camera(box, 1.0, {0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(framing_camera(box, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace tissu
