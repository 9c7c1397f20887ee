#include "solver/forces/aerodynamic_force.hpp"

#include <cmath>
#include <numbers>

#include "solver/parallel.hpp"

namespace tissu {

double gust_signal(double frequency_hz, double time_s) {
  const double phase = 2.0 * std::numbers::pi * frequency_hz * time_s;
  return 0.7 * std::sin(phase) + 0.3 * std::sin(2.3 * phase + 1.3);
}

Eigen::Vector3d wind_velocity(const Wind& wind, double time_s) {
  return wind.velocity * (1.0 + wind.gust_amplitude * gust_signal(wind.gust_frequency, time_s));
}

Eigen::Vector3d triangle_aerodynamic_force(const Eigen::Vector3d& xa, const Eigen::Vector3d& xb,
                                           const Eigen::Vector3d& xc, const Eigen::Vector3d& va,
                                           const Eigen::Vector3d& vb, const Eigen::Vector3d& vc,
                                           const Eigen::Vector3d& wind_velocity_mps,
                                           double air_density_kgpm3, double drag_coefficient) {
  // area-weighted normal: |n2| = 2 A
  const Eigen::Vector3d n2 = (xb - xa).cross(xc - xa);
  const double twice_area = n2.norm();
  if (twice_area <= 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d relative = wind_velocity_mps - (va + vb + vc) / 3.0;
  const double normal_speed = relative.dot(n2) / twice_area;
  // A n = n2 / 2
  return (0.25 * air_density_kgpm3 * drag_coefficient * normal_speed * std::abs(normal_speed)) * n2;
}

void add_aerodynamic_forces(const SpringModel& model, const Wind& wind, double time_s,
                            const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                            Eigen::Matrix3Xd& triangle_forces, Eigen::VectorXd& force) {
  const int triangles = static_cast<int>(model.triangles.rows());
  if (triangles == 0 || wind.air_density * wind.drag_coefficient == 0.0) return;
  const Eigen::Vector3d w = wind_velocity(wind, time_s);
  triangle_forces.resize(3, triangles);

#pragma omp parallel for schedule(static) if (triangles >= min_parallel_items)
  for (int t = 0; t < triangles; ++t) {
    const int a = model.triangles(t, 0);
    const int b = model.triangles(t, 1);
    const int c = model.triangles(t, 2);
    triangle_forces.col(t) =
        triangle_aerodynamic_force(x.segment<3>(3 * a), x.segment<3>(3 * b), x.segment<3>(3 * c),
                                   v.segment<3>(3 * a), v.segment<3>(3 * b), v.segment<3>(3 * c), w,
                                   wind.air_density, wind.drag_coefficient) /
        3.0;
  }

  // serial gather in triangle order: the same sums for any thread count
  for (int t = 0; t < triangles; ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      force.segment<3>(3 * model.triangles(t, corner)) += triangle_forces.col(t);
    }
  }
}

}  // namespace tissu
