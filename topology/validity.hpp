#pragma once
/// \file
/// Invariants of a cloth complex, checked after building and after every topological edit.

#include <string>
#include <vector>

#include "topology/cloth_complex.hpp"

namespace tissu {

/// What is wrong with `lcc`, one sentence per problem, empty when valid: CGAL's is_valid();
/// every dart on a vertex, an edge and a face attribute, and with a finite UV if and only if the
/// others have one (corner_uvs.hpp); one edge attribute per edge, none
/// orphaned; every vertex attribute on a dart, with a finite position, material coordinates and
/// velocity and a positive mass; every face with a positive rest area equal to the area of its
/// material coordinates; no unassigned spring slot on an edge or a dart; every present spring with
/// a positive rest length, non-negative stiffness and damping; total mass equal to density x rest
/// area within `mass_relative_tolerance`.
std::vector<std::string> validity_problems(const ClothComplex& lcc,
                                           double mass_relative_tolerance = 1e-12);

inline bool is_valid_cloth(const ClothComplex& lcc) {
  return validity_problems(lcc).empty();
}

}  // namespace tissu
