#include "topology/edge_measures.hpp"

#include <algorithm>
#include <cmath>

#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

Vector3 face_normal(const ClothComplex& lcc, Dart_const_handle d) {
  const Point3& a = lcc.point(d);
  const Point3& b = lcc.point(lcc.next(d));
  const Point3& c = lcc.point(lcc.next(lcc.next(d)));
  return CGAL::cross_product(b - a, c - a);
}

}  // namespace

double edge_engineering_strain(const ClothComplex& lcc, Dart_const_handle d) {
  const double now_m = std::sqrt(CGAL::squared_distance(lcc.point(d), lcc.point(lcc.next(d))));
  return now_m / edge_rest_length_m(lcc, d) - 1.0;
}

double edge_strain(const ClothComplex& lcc, Dart_const_handle d) {
  return std::abs(edge_engineering_strain(lcc, d));
}

double edge_dihedral_angle(const ClothComplex& lcc, Dart_const_handle d) {
  if (lcc.is_free<2>(d)) return 0.0;
  const Vector3 n1 = face_normal(lcc, d);
  const Vector3 n2 = face_normal(lcc, lcc.opposite<2>(d));
  const double norms = std::sqrt(n1.squared_length() * n2.squared_length());
  if (!(norms > 0.0)) return 0.0;
  return std::acos(std::clamp(n1 * n2 / norms, -1.0, 1.0));
}

std::vector<float> face_edge_strain(const ClothComplex& lcc) {
  std::vector<float> strain;
  strain.reserve(lcc.attributes<2>().size());
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    double sum = 0.0;
    int edges = 0;
    for (auto e = lcc.darts_of_orbit<1>(d).begin(); e != lcc.darts_of_orbit<1>(d).end(); ++e) {
      sum += edge_engineering_strain(lcc, e);
      ++edges;
    }
    strain.push_back(static_cast<float>(sum / edges));
  }
  return strain;
}

std::vector<float> face_refinement_level(const ClothComplex& lcc) {
  std::vector<float> level;
  level.reserve(lcc.attributes<2>().size());
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    const FaceRest& face = lcc.info<2>(d);
    const bool known = face.input_area > 0.0 && face.rest_area > 0.0;
    level.push_back(known ? static_cast<float>(std::log2(face.input_area / face.rest_area)) : 0.0f);
  }
  return level;
}

std::vector<float> face_sizing_term(const ClothComplex& lcc) {
  std::vector<float> term;
  term.reserve(lcc.attributes<2>().size());
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    term.push_back(static_cast<float>(lcc.info<2>(d).sizing_term));
  }
  return term;
}

}  // namespace tissu
