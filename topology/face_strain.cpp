#include "topology/face_strain.hpp"

#include <cmath>

#include "topology/rest_geometry.hpp"

namespace tissu {

double edge_engineering_strain(const ClothComplex& lcc, Dart_const_handle d) {
  const double now_m = std::sqrt(CGAL::squared_distance(lcc.point(d), lcc.point(lcc.next(d))));
  return now_m / edge_rest_length_m(lcc, d) - 1.0;
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

}  // namespace tissu
