#include "topology/cloth_properties.hpp"

#include <cmath>

namespace tissu {
namespace {

const Point3& rest_position(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.vertex_attribute(dart)->info().rest_position;
}

double rest_distance(const Point3& a, const Point3& b) {
  return std::sqrt(CGAL::squared_distance(a, b));
}

DartSpring make_spring(const SpringKindSettings& kind, double rest_length_m) {
  if (!kind.enabled || !(rest_length_m > 0.0)) return DartSpring{SpringSlot::absent, 0, 0, 0};
  return DartSpring{SpringSlot::present, kind.stiffness, kind.damping, rest_length_m};
}

}  // namespace

double face_rest_area(const ClothComplex& lcc, Dart_const_handle dart) {
  Vector3 twice_vector_area = CGAL::NULL_VECTOR;
  for (auto d = lcc.darts_of_orbit<1>(dart).begin(); d != lcc.darts_of_orbit<1>(dart).end(); ++d) {
    const Vector3 p = rest_position(lcc, d) - CGAL::ORIGIN;
    const Vector3 q = rest_position(lcc, lcc.next(d)) - CGAL::ORIGIN;
    twice_vector_area = twice_vector_area + CGAL::cross_product(p, q);
  }
  return 0.5 * std::sqrt(twice_vector_area.squared_length());
}

void assign_face_rest(ClothComplex& lcc, double areal_density_kg_per_m2) {
  for (auto face = lcc.attributes<2>().begin(); face != lcc.attributes<2>().end(); ++face) {
    face->info().rest_area = face_rest_area(lcc, face->dart());
    face->info().areal_density = areal_density_kg_per_m2;
  }
}

void lump_masses(ClothComplex& lcc) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    lump_vertex_mass(lcc, v);
  }
}

double edge_rest_length_m(const ClothComplex& lcc, Dart_const_handle dart) {
  return rest_distance(rest_position(lcc, dart), rest_position(lcc, lcc.next(dart)));
}

Vertex_handle nearest_vertex(ClothComplex& lcc, const Eigen::Vector3d& rest_point_m) {
  const auto distance2 = [&](Vertex_handle v) {
    const Point3& r = v->info().rest_position;
    return (Eigen::Vector3d(r.x(), r.y(), r.z()) - rest_point_m).squaredNorm();
  };
  Vertex_handle nearest = lcc.vertex_attributes().begin();
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    if (distance2(v) < distance2(nearest)) nearest = v;
  }
  return nearest;
}

Vertex_handle vertex_after_edge(ClothComplex& lcc, Dart_handle dart) {
  return lcc.vertex_attribute(lcc.next(lcc.next(dart)));
}

void assign_dart_springs(ClothComplex& lcc, Dart_handle d, const SpringSettings& settings) {
  DartMechanics& mechanics = lcc.info(d);
  mechanics.edge = make_spring(settings.structural, edge_rest_length_m(lcc, d));

  mechanics.bending = DartSpring{SpringSlot::absent, 0, 0, 0};
  if (!lcc.is_free<2>(d)) {
    Vertex_handle here = vertex_after_edge(lcc, d);
    Vertex_handle across = vertex_after_edge(lcc, lcc.opposite<2>(d));
    if (here != across) {
      mechanics.bending =
          make_spring(settings.bending,
                      rest_distance(here->info().rest_position, across->info().rest_position));
    }
  }

  mechanics.shear = DartSpring{SpringSlot::absent, 0, 0, 0};
  if (lcc.darts_of_orbit<1>(d).size() == 4) {
    mechanics.shear = make_spring(
        settings.shear,
        rest_distance(rest_position(lcc, d), rest_position(lcc, lcc.next(lcc.next(d)))));
  }
}

void assign_springs(ClothComplex& lcc, const SpringSettings& settings) {
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    assign_dart_springs(lcc, d, settings);
  }
}

void lump_vertex_mass(ClothComplex& lcc, Vertex_handle vertex) {
  double mass_kg = 0.0;
  for (Dart_handle d : darts_leaving(lcc, vertex)) {
    const FaceRest& face = lcc.info<2>(d);
    mass_kg += face.areal_density * face.rest_area / lcc.darts_of_orbit<1>(d).size();
  }
  vertex->info().mass = mass_kg;
}

std::vector<Dart_handle> darts_leaving(ClothComplex& lcc, Vertex_handle vertex) {
  std::vector<Dart_handle> out;
  for (auto d = lcc.darts_of_cell<0>(vertex->dart()).begin();
       d != lcc.darts_of_cell<0>(vertex->dart()).end(); ++d) {
    if (lcc.vertex_attribute(d) == vertex) out.push_back(d);
  }
  return out;
}

double complex_total_mass(const ClothComplex& lcc) {
  double total_kg = 0.0;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    total_kg += v->info().mass;
  }
  return total_kg;
}

double complex_expected_mass(const ClothComplex& lcc) {
  double total_kg = 0.0;
  for (auto face = lcc.attributes<2>().begin(); face != lcc.attributes<2>().end(); ++face) {
    total_kg += face->info().areal_density * face->info().rest_area;
  }
  return total_kg;
}

}  // namespace tissu
