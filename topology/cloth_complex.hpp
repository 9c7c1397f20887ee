#pragma once
/// \file
/// The cloth held in a CGAL linear cell complex (dimension 2 in 3D, CGAL 5.5 API): vertices carry
/// the particles, edges their structural and bending springs, darts the per-corner data (a quad's
/// shear diagonal, Delingette's couplings), faces the rest area and material (docs/complex.md).
/// Heavy header: include it only from topology/ and lib/ sources.

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <Eigen/Core>

#include <cstdint>

#include "topology/kernel.hpp"
#include "topology/refinement_options.hpp"

namespace tissu {

/// Whether a spring slot has been filled, and with what. Edges and darts that CGAL creates start
/// unassigned; the code that creates them must assign them.
enum class SpringSlot : std::uint8_t { unassigned, absent, present };

/// One spring as stored in the complex: on an edge (structural, bending) or on a dart (a quad's
/// shear diagonal).
struct StoredSpring {
  SpringSlot slot = SpringSlot::unassigned;
  double stiffness = 0.0;    ///< k (N/m)
  double damping = 0.0;      ///< nu (N s/m)
  double rest_length = 0.0;  ///< l0 (m), measured between material coordinates
};

/// The springs of an edge (its 1-attribute): stored once, whichever of the edge's one or two darts
/// reads them.
struct EdgeSprings {
  StoredSpring structural;  ///< along the edge
  StoredSpring bending;     ///< across the edge, between the vertices that follow the edge in its
                            ///< two faces (the hinge's apices for triangles); absent on borders
};

/// Texture coordinates of a face corner, carried from the input mesh (IndexedMesh::face_uvs).
struct CornerUv {
  double u = 0.0;
  double v = 0.0;
  bool given = false;  ///< false on every dart of a cloth whose mesh had no UVs, true on all others
};

/// Per-corner data of a dart (a half-edge of one face).
struct CornerMechanics {
  StoredSpring shear;  ///< quads only: diagonal from the dart's origin to the opposite corner
  /// Coupling Gamma (N/m) between the stretches of this dart's structural spring and the next
  /// dart's in the face (energy Gamma dl dl', Delingette 2008's angular term); 0 for none.
  double edge_coupling = 0.0;
  /// UV of the dart's origin in its face (a vertex on a UV seam has different ones in its faces).
  /// CGAL gives the darts it creates none: a split gives its new corners the midpoint of the
  /// UVs of the split edge's ends in that face (corner_uvs.hpp).
  CornerUv uv;
};

/// The particle carried by a vertex; the vertex point is its current position (m).
struct Particle {
  Vector3 velocity = CGAL::NULL_VECTOR;  ///< (m/s)
  double mass = 0.0;                     ///< lumped mass (kg)
  Point3 rest_position = CGAL::ORIGIN;   ///< material coordinates (m)
  bool pinned = false;                   ///< motion prescribed (velocity kept)
  /// The scenario's pins entry that holds it, or will hold it (PinSelector::attach_at_s), -1 for
  /// none: the handle that moves it, and lets it go (lib/pin_handles.hpp)
  int pin_group = -1;
  int source_index = -1;  ///< index in the input grid or mesh, -1 if created
  /// index in the SpringModel last compiled from the complex: valid from a compile() until the
  /// next topological edit, which leaves it stale, or -1 or copied on particles it creates
  int index_at_last_compile = -1;
  /// 0 for input particles; for one made by a split, 1 + the highest level among the corners of
  /// the faces it split. Anything that later changes its neighbourhood has a higher level, so
  /// undoing splits by decreasing level undoes them in a valid order (coarsen.hpp).
  int level = 0;
  /// For a particle made by a split: the material coordinates of one end of the edge it split (the
  /// other end is symmetric about it), so that coarsening knows which edge to restore (m)
  Point3 split_edge_end = CGAL::ORIGIN;
  /// An end of a torn edge: the crack's lips and tips are left alone by coarsening. Copied to
  /// every particle a tear splits off it.
  bool on_crack = false;
  /// For a particle made by a split: how many adaptation passes in a row found its bisection calm
  /// enough to undo (coarsen.hpp); coarsening waits for RefinementOptions::coarsen_after_passes.
  int calm_passes = 0;
};

/// Rest data of a face.
struct FaceRest {
  double rest_area = 0.0;      ///< area in material coordinates (m^2)
  double areal_density = 0.0;  ///< mass per rest area (kg/m^2)
  /// Rest area of the input face this face was cut from (m^2): the reference of the bending
  /// springs' scaling across levels (spring_assignment.hpp). Splits copy it to both halves.
  double input_area = 0.0;
  /// The sizing field at the last adaptation pass: 1 / (target edge length)^2 in rest space
  /// (1/m^2), sizing_field.hpp. Splits copy it to both halves until the next pass.
  double sizing_per_m2 = 0.0;
  /// With anisotropic remeshing, the sizing metric at the last pass: a symmetric tensor M in
  /// material coordinates (1/m^2) under which a rest edge e is as long as the cloth wants there
  /// when e^T M e = 1 (sizing_metric.hpp); zero otherwise.
  Eigen::Matrix3d sizing_metric_per_m2 = Eigen::Matrix3d::Zero();
  /// The term that set sizing_per_m2 at that pass, none where it lets coarsening merge the face.
  SizingTerm sizing_term = SizingTerm::none;
};

struct ClothItems {
  template <class Refs>
  struct Dart_wrapper {
    using Dart_info = CornerMechanics;
    using Vertex_attribute = CGAL::Cell_attribute_with_point<Refs, Particle>;
    using Edge_attribute = CGAL::Cell_attribute<Refs, EdgeSprings>;
    using Face_attribute = CGAL::Cell_attribute<Refs, FaceRest>;
    using Attributes = std::tuple<Vertex_attribute, Edge_attribute, Face_attribute>;
  };
};

using ClothTraits = CGAL::Linear_cell_complex_traits<3, Kernel>;
using ClothComplex = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3, ClothTraits, ClothItems>;
using Dart_handle = ClothComplex::Dart_handle;
using Dart_const_handle = ClothComplex::Dart_const_handle;
using Vertex_handle = ClothComplex::Vertex_attribute_handle;
using Vertex_const_handle = ClothComplex::Vertex_attribute_const_handle;
using Edge_handle = ClothComplex::Attribute_handle<1>::type;
using Face_handle = ClothComplex::Attribute_handle<2>::type;
using Face_const_handle = ClothComplex::Attribute_const_handle<2>::type;

}  // namespace tissu
