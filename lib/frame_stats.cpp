#include "lib/frame_stats.hpp"

#include <stdexcept>

namespace tissu {

StatsCsv::StatsCsv(const std::filesystem::path& file) : m_out(file) {
  if (!m_out) throw std::runtime_error(file.string() + ": cannot write statistics");
  m_out.precision(17);
  m_out << "frame,time,particles,springs,faces,pinned,total_mass,kinetic_energy,"
           "potential_energy,step_ms,unconverged_steps,splits,merges,contacts,self_contacts,"
           "collision_ms,tears,pieces,boundary_edges\n";
}

void StatsCsv::write(const FrameStats& r) {
  m_out << r.frame << ',' << r.time << ',' << r.particles << ',' << r.springs << ',' << r.faces
        << ',' << r.pinned << ',' << r.total_mass << ',' << r.kinetic_energy << ','
        << r.potential_energy << ',' << r.step_ms << ',' << r.unconverged_steps << ',' << r.splits
        << ',' << r.merges << ',' << r.contacts << ',' << r.self_contacts << ',' << r.collision_ms
        << ',' << r.tears << ',' << r.pieces << ',' << r.boundary_edges << '\n';
  m_out.flush();
}

}  // namespace tissu
