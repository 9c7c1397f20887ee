#include "topology/validity.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "topology/mass_lumping.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

bool is_finite(const Point3& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}
bool is_finite(const Vector3& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

std::string check_spring(const StoredSpring& s, const char* name) {
  if (s.slot == SpringSlot::unassigned)
    return std::string("an unassigned ") + name + " spring slot";
  if (s.slot == SpringSlot::absent) return {};
  if (!(s.rest_length > 0.0) || !std::isfinite(s.rest_length)) {
    return std::string("a ") + name + " spring has a non-positive rest length";
  }
  if (!(s.stiffness >= 0.0) || !(s.damping >= 0.0)) {
    return std::string("a ") + name + " spring has a negative or NaN stiffness or damping";
  }
  return {};
}

void add_spring_problem(const StoredSpring& spring, const char* name,
                        std::vector<std::string>& problems) {
  if (std::string problem = check_spring(spring, name); !problem.empty()) {
    problems.push_back(std::move(problem));
  }
}

void check_darts(const ClothComplex& lcc, std::vector<std::string>& problems) {
  std::size_t darts = 0, with_uv = 0;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    const CornerUv& uv = lcc.info(d).uv;
    ++darts;
    with_uv += uv.given;
    if (uv.given && !(std::isfinite(uv.u) && std::isfinite(uv.v))) {
      problems.push_back("a dart has a non-finite UV");
    }
    if (lcc.attribute<0>(d) == nullptr) problems.push_back("a dart has no vertex attribute");
    if (lcc.attribute<1>(d) == nullptr) problems.push_back("a dart has no edge attribute");
    if (lcc.attribute<2>(d) == nullptr) problems.push_back("a dart has no face attribute");
    add_spring_problem(lcc.info(d).shear, "shear", problems);
  }
  if (with_uv != 0 && with_uv != darts) {
    problems.push_back(std::to_string(darts - with_uv) + " of " + std::to_string(darts) +
                       " darts have no UV, but the others have one");
  }
}

void check_edges(const ClothComplex& lcc, std::vector<std::string>& problems) {
  std::size_t edges = 0;
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    ++edges;
  }
  if (edges != lcc.attributes<1>().size()) {
    problems.push_back(std::to_string(lcc.attributes<1>().size()) + " edge attributes for " +
                       std::to_string(edges) + " edges");
  }
  for (auto e = lcc.attributes<1>().begin(); e != lcc.attributes<1>().end(); ++e) {
    if (e->dart() == nullptr) problems.push_back("an edge attribute is on no edge");
    add_spring_problem(e->info().structural, "structural", problems);
    add_spring_problem(e->info().bending, "bending", problems);
  }
}

void check_vertices(const ClothComplex& lcc, std::vector<std::string>& problems) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const Particle& p = v->info();
    std::ostringstream who;
    who << "particle from input vertex " << p.source_index;
    if (v->dart() == nullptr) problems.push_back(who.str() + " is on no face");
    if (!is_finite(v->point()) || !is_finite(p.rest_position) || !is_finite(p.velocity)) {
      problems.push_back(who.str() + " has a non-finite position or velocity");
    }
    if (!(p.mass > 0.0)) problems.push_back(who.str() + " has a non-positive mass");
  }
}

void check_faces(const ClothComplex& lcc, std::vector<std::string>& problems) {
  for (auto f = lcc.attributes<2>().begin(); f != lcc.attributes<2>().end(); ++f) {
    if (!(f->info().rest_area > 0.0)) problems.push_back("a face has a non-positive rest area");
    const double measured_m2 = face_rest_area(lcc, f->dart());
    if (std::abs(f->info().rest_area - measured_m2) > 1e-12 * measured_m2) {
      problems.push_back("a face's rest area differs from the area of its material coordinates");
    }
    if (!(f->info().areal_density > 0.0)) problems.push_back("a face has a non-positive density");
  }
}

// one line per distinct problem, with how often it occurs
std::vector<std::string> counted(const std::vector<std::string>& problems) {
  std::map<std::string, int> count;
  std::vector<std::string> order;
  for (const std::string& p : problems) {
    if (count[p]++ == 0) order.push_back(p);
  }
  for (std::string& p : order) {
    if (const int n = count[p]; n > 1) p += " (" + std::to_string(n) + " times)";
  }
  return order;
}

}  // namespace

std::vector<std::string> validity_problems(const ClothComplex& lcc,
                                           double mass_relative_tolerance) {
  std::vector<std::string> problems;
  if (!lcc.is_valid()) problems.push_back("CGAL's is_valid() fails");
  check_darts(lcc, problems);
  check_edges(lcc, problems);
  check_vertices(lcc, problems);
  check_faces(lcc, problems);
  const double expected_kg = complex_expected_mass(lcc);
  const double total_kg = complex_total_mass(lcc);
  if (std::abs(total_kg - expected_kg) > mass_relative_tolerance * expected_kg) {
    std::ostringstream message;
    message.precision(17);
    message << "total mass " << total_kg << " kg differs from density x rest area " << expected_kg
            << " kg";
    problems.push_back(message.str());
  }
  return counted(problems);
}

}  // namespace tissu
