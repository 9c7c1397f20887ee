#pragma once
/// \file
/// Rest geometry of the cloth complex: lengths and areas measured in material coordinates, so
/// that they do not depend on the current deformation.

#include "topology/cloth_complex.hpp"

namespace tissu {

/// Material coordinates of the dart's origin (m).
const Point3& rest_position(const ClothComplex& lcc, Dart_const_handle dart);

/// Distance between two points in material coordinates (m).
double rest_distance_m(const Point3& a_m, const Point3& b_m);

/// Rest length of the dart's edge, the distance of its ends' material coordinates (m).
double edge_rest_length_m(const ClothComplex& lcc, Dart_const_handle dart);

/// Area of the face of `dart` in material coordinates (m^2): the norm of the polygon's vector area
/// 1/2 sum_k p_k x p_{k+1}, exact for triangles and planar quads.
double face_rest_area(const ClothComplex& lcc, Dart_const_handle dart);

/// Sets every face's rest area and areal density, and makes it its own input face
/// (FaceRest::input_area).
void assign_face_rest(ClothComplex& lcc, double areal_density_kg_per_m2);

}  // namespace tissu
