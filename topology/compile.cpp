#include "topology/compile.hpp"

#include <map>

#include "topology/eigen_conversions.hpp"

namespace tissu {
namespace {

struct SpringRecord {
  int i, j;
  const StoredSpring* spring;
  SpringKind kind;
  Dart_handle dart;
};

int particle_of(const ClothComplex& lcc, Dart_const_handle dart) {
  return lcc.vertex_attribute(dart)->info().index_at_last_compile;
}

std::vector<SpringRecord> collect_springs(ClothComplex& lcc) {
  std::vector<SpringRecord> records;
  for (auto d = lcc.one_dart_per_cell<1>().begin(); d != lcc.one_dart_per_cell<1>().end(); ++d) {
    const EdgeSprings& edge = lcc.info<1>(d);
    if (edge.structural.slot == SpringSlot::present) {
      records.push_back({particle_of(lcc, d), particle_of(lcc, lcc.next(d)), &edge.structural,
                         SpringKind::structural, d});
    }
    if (edge.bending.slot == SpringSlot::present) {
      const int here = particle_of(lcc, lcc.next(lcc.next(d)));
      const int across = particle_of(lcc, lcc.next(lcc.next(lcc.opposite<2>(d))));
      records.push_back({here, across, &edge.bending, SpringKind::bending, d});
    }
  }
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    if (lcc.darts_of_orbit<1>(d).size() != 4) continue;
    for (Dart_handle corner : {Dart_handle(d), lcc.next(d)}) {
      const StoredSpring& shear = lcc.info(corner).shear;
      if (shear.slot != SpringSlot::present) continue;
      records.push_back({particle_of(lcc, corner), particle_of(lcc, lcc.next(lcc.next(corner))),
                         &shear, SpringKind::shear, corner});
    }
  }
  return records;
}

/// The couplings of every dart between its structural spring and the next dart's, as spring ids.
void collect_couplings(ClothComplex& lcc, const std::vector<SpringRecord>& records,
                       SpringModel& model) {
  std::vector<Dart_handle> coupled;
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (lcc.info(d).edge_coupling != 0.0) coupled.push_back(d);
  }
  model.couplings.resize(0, 2);
  model.coupling_stiffness.resize(0);
  if (coupled.empty()) return;                   // springs alone: no need for the map below
  std::map<Dart_const_handle, int> edge_spring;  // both darts of each structural spring
  for (std::size_t s = 0; s < records.size(); ++s) {
    if (records[s].kind != SpringKind::structural) continue;
    edge_spring[records[s].dart] = static_cast<int>(s);
    if (!lcc.is_free<2>(records[s].dart)) {
      edge_spring[lcc.opposite<2>(records[s].dart)] = static_cast<int>(s);
    }
  }
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> stiffness;
  for (Dart_handle d : coupled) {
    const auto a = edge_spring.find(d), b = edge_spring.find(lcc.next(d));
    if (a == edge_spring.end() || b == edge_spring.end()) continue;  // a spring kind is off
    pairs.emplace_back(a->second, b->second);
    stiffness.push_back(lcc.info(d).edge_coupling);
  }
  model.couplings.resize(static_cast<Eigen::Index>(pairs.size()), 2);
  model.coupling_stiffness.resize(static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    model.couplings.row(static_cast<Eigen::Index>(c)) << pairs[c].first, pairs[c].second;
    model.coupling_stiffness[static_cast<Eigen::Index>(c)] = stiffness[c];
  }
}

Eigen::MatrixX3i collect_triangles(ClothComplex& lcc) {
  std::vector<Eigen::Vector3i> triangles;
  for (auto d = lcc.one_dart_per_cell<2>().begin(); d != lcc.one_dart_per_cell<2>().end(); ++d) {
    const int first = particle_of(lcc, d);
    Dart_handle a = lcc.next(d);
    for (Dart_handle b = lcc.next(a); b != Dart_handle(d); a = b, b = lcc.next(b)) {
      triangles.emplace_back(first, particle_of(lcc, a), particle_of(lcc, b));
    }
  }
  Eigen::MatrixX3i result(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) result.row(t) = triangles[t].transpose();
  return result;
}

}  // namespace

CompiledCloth compile(ClothComplex& lcc, double time_s) {
  CompiledCloth out;
  SpringModel& model = out.model;
  const auto particle_count = static_cast<Eigen::Index>(lcc.vertex_attributes().size());
  model.mass.resize(particle_count);
  model.pinned.assign(particle_count, 0);
  model.rest_x.resize(3 * particle_count);
  out.state.x.resize(3 * particle_count);
  out.state.v.resize(3 * particle_count);
  out.state.time = time_s;
  out.particle_vertices.reserve(particle_count);

  int index = 0;
  for (auto v = lcc.vertex_attributes().begin(); v != lcc.vertex_attributes().end(); ++v, ++index) {
    Particle& p = v->info();
    p.index_at_last_compile = index;
    out.particle_vertices.push_back(v);
    model.mass[index] = p.mass;
    model.pinned[index] = p.pinned ? 1 : 0;
    model.rest_x.segment<3>(3 * index) = to_eigen(p.rest_position);
    out.state.x.segment<3>(3 * index) = to_eigen(v->point());
    out.state.v.segment<3>(3 * index) = to_eigen(p.velocity);
  }

  const std::vector<SpringRecord> records = collect_springs(lcc);
  const auto spring_count = static_cast<Eigen::Index>(records.size());
  model.springs.resize(spring_count, 2);
  model.rest_length.resize(spring_count);
  model.stiffness.resize(spring_count);
  model.damping.resize(spring_count);
  model.kind.resize(spring_count);
  out.spring_darts.reserve(spring_count);
  for (Eigen::Index s = 0; s < spring_count; ++s) {
    const SpringRecord& r = records[s];
    model.springs(s, 0) = r.i;
    model.springs(s, 1) = r.j;
    model.rest_length[s] = r.spring->rest_length;
    model.stiffness[s] = r.spring->stiffness;
    model.damping[s] = r.spring->damping;
    model.kind[s] = r.kind;
    out.spring_darts.push_back(r.dart);
  }
  collect_couplings(lcc, records, model);
  model.triangles = collect_triangles(lcc);
  finalize_model(model);
  return out;
}

void write_back(const CompiledCloth& compiled, const State& state, ClothComplex& lcc) {
  for (std::size_t i = 0; i < compiled.particle_vertices.size(); ++i) {
    const Vertex_handle v = compiled.particle_vertices[i];
    lcc.point_of_vertex_attribute(v) = to_point(state.x.segment<3>(3 * i));
    lcc.info_of_attribute<0>(v).velocity = to_vector(state.v.segment<3>(3 * i));
  }
}

}  // namespace tissu
