#include "topology/build_cloth_complex.hpp"

#include <CGAL/Linear_cell_complex_incremental_builder.h>

#include <string>
#include <vector>

#include "topology/eigen_conversions.hpp"
#include "topology/mass_lumping.hpp"
#include "topology/rest_geometry.hpp"
#include "topology/spring_assignment.hpp"
#include "topology/validity.hpp"

namespace tissu {

void build_cloth_complex(const IndexedMesh& mesh, double areal_density_kg_per_m2,
                         const SpringSettings& springs, ClothComplex& lcc) {
  // the incremental builder asserts on non-manifold or inconsistently oriented input
  validate_indexed_mesh(mesh);
  lcc.clear();

  std::vector<int> builder_id(mesh.vertices.size(), -1);
  for (const auto& face : mesh.faces) {
    for (int v : face) builder_id[v] = 0;
  }
  CGAL::Linear_cell_complex_incremental_builder_3<ClothComplex> builder(lcc);
  int next_id = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (builder_id[v] < 0) continue;
    builder_id[v] = next_id++;
    Vertex_handle vh = builder.add_vertex(to_point(mesh.vertices[v]));
    vh->info().rest_position = vh->point();
    vh->info().source_index = static_cast<int>(v);
  }
  builder.begin_surface();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& face = mesh.faces[f];
    builder.begin_facet();
    for (int v : face) builder.add_vertex_to_facet(static_cast<std::size_t>(builder_id[v]));
    Dart_handle first = builder.end_facet();
    lcc.set_attribute<2>(first, lcc.create_attribute<2>());
    if (mesh.has_uvs()) {
      // the builder's first dart leaves the face's first vertex; corner k is the k-th dart after
      Dart_handle corner = first;
      for (std::size_t k = 0; k < face.size(); ++k, corner = lcc.next(corner)) {
        assert(lcc.vertex_attribute(corner)->info().source_index == face[k]);
        const Eigen::Vector2d& uv = mesh.face_uvs[f][k];
        lcc.info(corner).uv = {uv.x(), uv.y(), true};
      }
    }
  }
  builder.end_surface();
  // the builder creates no edge attributes: one per edge, to be filled by assign_springs
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    lcc.set_attribute<1>(d, lcc.create_attribute<1>());
  }

  assign_face_rest(lcc, areal_density_kg_per_m2);
  lump_masses(lcc);
  assign_springs(lcc, springs);
  // checked in every build (linear in the size, a small part of building): a mesh that passed
  // validate_indexed_mesh but still makes an invalid complex must not run with a wrong mass
  if (const std::vector<std::string> problems = validity_problems(lcc); !problems.empty()) {
    throw MeshError("the mesh makes an invalid cloth complex: " + problems.front());
  }
}

void place_particles(const std::vector<Eigen::Vector3d>& positions, ClothComplex& lcc) {
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v) {
    const auto source = static_cast<std::size_t>(v->info().source_index);
    if (source >= positions.size()) {
      throw std::invalid_argument("place_particles: no position for input vertex " +
                                  std::to_string(source));
    }
    lcc.point_of_vertex_attribute(v) = to_point(positions[source]);
  }
}

}  // namespace tissu
