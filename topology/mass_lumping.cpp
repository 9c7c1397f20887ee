#include "topology/mass_lumping.hpp"

#include <utility>

#include "solver/compensated_sum.hpp"
#include "topology/complex_navigation.hpp"

namespace tissu {

void lump_masses(ClothComplex& lcc) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    lump_vertex_mass(lcc, v);
  }
}

void lump_vertex_mass(ClothComplex& lcc, Vertex_handle vertex) {
  double mass_kg = 0.0;
  for (Dart_const_handle d : darts_leaving(std::as_const(lcc), vertex)) {
    const FaceRest& face = lcc.info<2>(d);
    mass_kg += face.areal_density * face.rest_area / lcc.darts_of_orbit<1>(d).size();
  }
  vertex->info().mass = mass_kg;
}

double complex_total_mass(const ClothComplex& lcc) {
  CompensatedSum total_kg;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    total_kg.add(v->info().mass);
  }
  return total_kg.value();
}

double complex_expected_mass(const ClothComplex& lcc) {
  CompensatedSum total_kg;
  for (auto face = lcc.attributes<2>().begin(); face != lcc.attributes<2>().end(); ++face) {
    total_kg.add(face->info().areal_density * face->info().rest_area);
  }
  return total_kg.value();
}

}  // namespace tissu
