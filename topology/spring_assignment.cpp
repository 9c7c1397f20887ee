#include "topology/spring_assignment.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "topology/complex_navigation.hpp"
#include "topology/eigen_conversions.hpp"
#include "topology/membrane_stiffness.hpp"
#include "topology/rest_geometry.hpp"

namespace tissu {
namespace {

/// A spring of `kind` with the given stiffness, and the kind's damping times `damping_factor`.
StoredSpring make_spring(const SpringKindSettings& kind, double stiffness_n_per_m,
                         double rest_length_m, double damping_factor = 1.0) {
  if (!kind.enabled || !(rest_length_m > 0.0)) return StoredSpring{SpringSlot::absent, 0, 0, 0};
  return StoredSpring{SpringSlot::present, stiffness_n_per_m, damping_factor * kind.damping,
                      rest_length_m};
}

Eigen::Vector3d rest_vector(const ClothComplex& lcc, Dart_const_handle dart) {
  return to_eigen(rest_position(lcc, dart));
}

/// What the face of `dart` gives the springs along the dart's edge and on the dart's diagonal
/// (quads) under `material`.
struct FaceShare {
  double edge_n_per_m = 0.0;
  double diagonal_n_per_m = 0.0;
  double coupling_with_next_n_per_m = 0.0;  ///< with the next dart's edge (triangles)
};

[[noreturn]] void refuse_face(const ClothComplex& lcc, Dart_const_handle dart,
                              const Material& material, std::string_view expected) {
  const Point3& p = rest_position(lcc, dart);
  std::ostringstream out;
  out << "material formulation \"" << to_string(material.formulation) << "\" is defined on "
      << expected << "; the face with a corner at rest position (" << p.x() << ", " << p.y() << ", "
      << p.z() << ") m has " << lcc.darts_of_orbit<1>(dart).size() << " corners";
  throw std::invalid_argument(out.str());
}

FaceShare face_share_of_edge(const ClothComplex& lcc, Dart_const_handle dart,
                             const Material& material) {
  const FormulationCells cells = formulation_cells(material.formulation);
  const auto corners = lcc.darts_of_orbit<1>(dart).size();
  const Dart_const_handle next = lcc.next(dart);
  const Dart_const_handle after = lcc.next(next);
  if (corners == 3 && formulation_defines(material.formulation, 3)) {
    const TriangleStiffness share =
        triangle_stiffness(material, {edge_rest_length_m(lcc, dart), edge_rest_length_m(lcc, next),
                                      edge_rest_length_m(lcc, after)});
    // edges 0 and 1 (this dart's and the next one's) are coupled by coupling 2
    return {share.edge_n_per_m[0], 0.0, share.coupling_n_per_m[2]};
  }
  if (corners == 4 && formulation_defines(material.formulation, 4)) {
    // sides averaged over opposite edges: exact for rectangles, the paper's element
    const double side_a_m = 0.5 * (edge_rest_length_m(lcc, dart) + edge_rest_length_m(lcc, after));
    const double side_b_m =
        0.5 * (edge_rest_length_m(lcc, next) + edge_rest_length_m(lcc, lcc.next(after)));
    const RectangleStiffness share = rectangle_stiffness(material, side_a_m, side_b_m);
    if (share.side_a_n_per_m < 0.0 || share.side_b_n_per_m < 0.0) {
      std::ostringstream sides;
      sides << "cells whose formula gives positive stiffnesses, not " << side_a_m << " x "
            << side_b_m << " m at nu " << material.poisson_ratio;
      refuse_face(lcc, dart, material, sides.str());
    }
    return {share.side_a_n_per_m, share.diagonal_n_per_m};
  }
  refuse_face(lcc, dart, material,
              cells == FormulationCells::triangles    ? "triangles"
              : cells == FormulationCells::rectangles ? "rectangles (quad cells)"
                                                      : "triangles and rectangles");
}

/// The factor on the scenario's bending stiffness for the spring across the edge of `dart`, whose
/// faces were cut from input faces (FaceRest::input_area) by refinement. A bending spring across a
/// hinge of size s (the two faces' rest area A ~ s^2) shortens by about s theta^2 / 4 when the
/// hinge folds by theta, storing k s^2 theta^4 / 32; at a curvature kappa the hinge folds by
/// theta ~ kappa s, and there are ~1/s^2 hinges per unit area, so the cloth stores ~k s^4 kappa^4
/// per unit area. The same cloth at every level therefore needs k ~ 1/s^4:
///   k = k_scenario (A_input / A)^2,
/// exactly 1 on the input mesh, 4 per bisection (each halves the area); the spring's damping scales
/// alike, so that its damping rate stays that of the stiffness. With `follows_hinge_shape`
/// (anisotropic remeshing), a refined hinge's factor is also multiplied by rho^3, rho = l^2 / A its
/// shape (below); the input mesh's hinges keep the scenario's value. The material rule
/// (bending_spring_stiffness) is left as it is: it matches a plate at one fold angle per hinge.
double bending_level_factor(const ClothComplex& lcc, Dart_const_handle dart,
                            bool follows_hinge_shape) {
  const FaceRest& own = lcc.info<2>(dart);
  const FaceRest& across = lcc.info<2>(lcc.opposite<2>(dart));
  const double input_m2 = own.input_area + across.input_area;
  const double now_m2 = own.rest_area + across.rest_area;
  if (!(input_m2 > 0.0) || !(now_m2 > 0.0)) return 1.0;  // a complex built without input areas
  const double ratio = input_m2 / now_m2;
  if (!follows_hinge_shape || !(now_m2 < input_m2 * (1.0 - 1e-12))) return ratio * ratio;
  // The hinge's shape, rho = l^2 / A: its edge's length l over the mean height h = A / l of its
  // two apices (A the two faces' rest area). Folding the hinge by theta shortens its spring by
  // about h theta^2 / 4 and bends the cloth by kappa ~ theta / (2 h); with ~1 / A hinges per unit
  // area the cloth then stores ~k h^5 kappa^4 / l, so the same cloth needs k ~ l / h^5 =
  // rho^3 / A^2: the area rule times rho^3, 1 on a square grid's legs (rho 1), 8 on its
  // hypotenuses (rho 2), more across the long edges of cells stretched along a fold.
  const double edge_m = edge_rest_length_m(lcc, dart);
  const double shape = edge_m * edge_m / now_m2;
  return ratio * ratio * shape * shape * shape;
}

}  // namespace

void assign_dart_springs(ClothComplex& lcc, Dart_handle d, const SpringSettings& settings) {
  const Material* material = settings.material ? &*settings.material : nullptr;
  const FaceShare own = material ? face_share_of_edge(lcc, d, *material) : FaceShare{};
  EdgeSprings& edge = lcc.info<1>(d);
  CornerMechanics& corner = lcc.info(d);
  double edge_stiffness = settings.structural.stiffness;
  if (material) {
    edge_stiffness = own.edge_n_per_m;
    if (!lcc.is_free<2>(d)) {
      edge_stiffness += face_share_of_edge(lcc, lcc.opposite<2>(d), *material).edge_n_per_m;
    }
  }
  edge.structural = make_spring(settings.structural, edge_stiffness, edge_rest_length_m(lcc, d));
  corner.edge_coupling = own.coupling_with_next_n_per_m;

  edge.bending = StoredSpring{SpringSlot::absent, 0, 0, 0};
  if (!lcc.is_free<2>(d)) {
    const Vertex_const_handle here = vertex_after_edge(lcc, d);
    const Vertex_const_handle across = vertex_after_edge(lcc, lcc.opposite<2>(d));
    if (here != across) {
      const double level_factor =
          bending_level_factor(lcc, d, settings.bending_follows_hinge_shape);
      double stiffness = settings.bending.stiffness * level_factor;
      if (material) {
        // from the same dart of the pair on both, so that the two darts agree to the bit
        const Dart_handle e = std::min(d, lcc.opposite<2>(d));
        const Dart_handle o = lcc.opposite<2>(e);
        stiffness = bending_spring_stiffness(
            *material, rest_vector(lcc, e), rest_vector(lcc, o),
            rest_vector(lcc, lcc.next(lcc.next(e))), rest_vector(lcc, lcc.next(lcc.next(o))),
            face_rest_area(lcc, e), static_cast<int>(lcc.darts_of_orbit<1>(e).size()),
            face_rest_area(lcc, o), static_cast<int>(lcc.darts_of_orbit<1>(o).size()));
      }
      edge.bending =
          make_spring(settings.bending, stiffness,
                      rest_distance_m(here->info().rest_position, across->info().rest_position),
                      material ? 1.0 : level_factor);
    }
  }

  corner.shear = StoredSpring{SpringSlot::absent, 0, 0, 0};
  if (lcc.darts_of_orbit<1>(d).size() == 4) {
    const double stiffness = material ? own.diagonal_n_per_m : settings.shear.stiffness;
    corner.shear = make_spring(
        settings.shear, stiffness,
        rest_distance_m(rest_position(lcc, d), rest_position(lcc, lcc.next(lcc.next(d)))));
  }
}

void assign_springs(ClothComplex& lcc, const SpringSettings& settings) {
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    assign_dart_springs(lcc, d, settings);
  }
}

}  // namespace tissu
