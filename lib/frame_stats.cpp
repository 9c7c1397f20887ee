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

std::vector<StatsColumn> stats_columns(const FrameStats& r) {
  return {{"frame", double(r.frame)},
          {"time", r.time},
          {"particles", double(r.particles)},
          {"springs", double(r.springs)},
          {"faces", double(r.faces)},
          {"pinned", double(r.pinned)},
          {"total_mass", r.total_mass},
          {"kinetic_energy", r.kinetic_energy},
          {"potential_energy", r.potential_energy},
          {"step_ms", r.step_ms},
          {"unconverged_steps", double(r.unconverged_steps)},
          {"splits", double(r.splits)},
          {"merges", double(r.merges)},
          {"contacts", double(r.contacts)},
          {"self_contacts", double(r.self_contacts)},
          {"collision_ms", r.collision_ms},
          {"tears", double(r.tears)},
          {"pieces", double(r.pieces)},
          {"boundary_edges", double(r.boundary_edges)},
          {"pin_force", r.pin_force},
          {"max_stretch", r.max_stretch},
          {"solver_iterations", double(r.solver_iterations)},
          {"strain_limited", double(r.strain_limited)},
          {"threads", double(r.threads)},
          {"flips", double(r.flips)}};
}

StatsCsv::StatsCsv(const std::filesystem::path& file) : m_file(file, "statistics") {
  std::string header;
  for (const StatsColumn& column : stats_columns(FrameStats{})) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  m_file.append(header + "\n");
}

void StatsCsv::write(const FrameStats& r) {
  const std::vector<StatsColumn> columns = stats_columns(r);
  for (const StatsColumn& column : columns)
    check_finite(m_file.file(), r, column.name, column.value);
  std::ostringstream out;
  out.precision(17);  // integers print as integers, doubles read back to the same value
  for (std::size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << columns[k].value;
  out << '\n';
  m_file.append(out.str());
}

}  // namespace tissu
