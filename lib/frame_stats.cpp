#include "lib/frame_stats.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tissu {
namespace {

/// Throws if `value`, the column `name` of `row`, is not finite.
void check_finite(const std::filesystem::path& file, const FrameStats& row, const char* name,
                  double value) {
  if (std::isfinite(value)) return;
  std::ostringstream text;
  text << file.string() << ": frame " << row.frame << ": " << name << " is " << value
       << ", not a finite number: row not written";
  throw std::runtime_error(text.str());
}

}  // namespace

StatsCsv::StatsCsv(const std::filesystem::path& file) : m_file(file, "statistics") {
  m_file.append(
      "frame,time,particles,springs,faces,pinned,total_mass,kinetic_energy,"
      "potential_energy,step_ms,unconverged_steps,splits,merges,contacts,self_contacts,"
      "collision_ms,tears,pieces,boundary_edges,pin_force,max_stretch\n");
}

void StatsCsv::write(const FrameStats& r) {
  const std::filesystem::path& file = m_file.file();
  check_finite(file, r, "time", r.time);
  check_finite(file, r, "total_mass", r.total_mass);
  check_finite(file, r, "kinetic_energy", r.kinetic_energy);
  check_finite(file, r, "potential_energy", r.potential_energy);
  check_finite(file, r, "step_ms", r.step_ms);
  check_finite(file, r, "collision_ms", r.collision_ms);
  check_finite(file, r, "pin_force", r.pin_force);
  check_finite(file, r, "max_stretch", r.max_stretch);
  std::ostringstream out;
  out.precision(17);
  out << r.frame << ',' << r.time << ',' << r.particles << ',' << r.springs << ',' << r.faces << ','
      << r.pinned << ',' << r.total_mass << ',' << r.kinetic_energy << ',' << r.potential_energy
      << ',' << r.step_ms << ',' << r.unconverged_steps << ',' << r.splits << ',' << r.merges << ','
      << r.contacts << ',' << r.self_contacts << ',' << r.collision_ms << ',' << r.tears << ','
      << r.pieces << ',' << r.boundary_edges << ',' << r.pin_force << ',' << r.max_stretch << '\n';
  m_file.append(out.str());
}

}  // namespace tissu
