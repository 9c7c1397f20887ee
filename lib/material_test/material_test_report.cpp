#include "lib/material_test/material_test_report.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

#include "lib/atomic_file.hpp"
#include "lib/render/external_program.hpp"

namespace tissu {
namespace {

double target_shear_modulus_pa(double e_pa, double nu) {
  return e_pa / (2.0 * (1.0 + nu));
}

/// A report's text, built in memory and written whole or not at all (lib/atomic_file.hpp).
std::ostringstream report_text() {
  std::ostringstream out;
  out.precision(6);
  return out;
}

/// Whether `file` ends with a PNG's IEND chunk (length 0, "IEND", its CRC): what an image cut
/// short by a full disk lacks. (gnuplot's exit status does not tell.)
bool ends_like_a_png(const std::filesystem::path& file) {
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return bytes.size() > iend.size() &&
         bytes.compare(bytes.size() - iend.size(), iend.size(), iend) == 0;
}

std::string percent(double measured, double target) {
  std::ostringstream out;
  out.precision(3);
  out << std::showpos << 100.0 * (measured / target - 1.0) << " %";
  return out.str();
}

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

std::string series_name(const MaterialTestRow& row) {
  return std::string(to_string(row.formulation)) + ", " + std::string(to_string(row.sheet));
}

}  // namespace

std::vector<MaterialTestRow> run_material_tests(const MaterialTestOptions& options) {
  std::vector<MaterialTestRow> rows;
  for (int f = 0; f < stiffness_formulation_count; ++f) {
    const auto formulation = static_cast<StiffnessFormulation>(f);
    for (int s = 0; s < test_sheet_count; ++s) {
      const auto sheet = static_cast<TestSheet>(s);
      if (!formulation_defines(formulation, has_quads(sheet) ? 4 : 3)) continue;
      for (const double nu : options.poisson_ratios) {
        MaterialTestRow row;
        row.formulation = formulation;
        row.sheet = sheet;
        row.cells = options.cells;
        row.target_nu = nu;
        row.refused = !supported_poisson_ratios(formulation).contains(nu);
        if (!row.refused) {
          ClothComplex lcc;
          build_test_sheet(sheet, options.cells,
                           Material{options.youngs_modulus_pa, nu, options.thickness_m,
                                    options.density_kg_per_m3, formulation},
                           lcc);
          row.measured = measure_effective_material(lcc, options.thickness_m);
          if (sheet != TestSheet::equilateral_triangles) {
            row.strip = measure_strip_tension(lcc, options.thickness_m);
          }
        }
        rows.push_back(row);
      }
    }
  }
  return rows;
}

void write_material_tables(const std::vector<MaterialTestRow>& rows,
                           const MaterialTestOptions& options, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const double e = options.youngs_modulus_pa;
  std::ostringstream csv = report_text();
  csv << "formulation,sheet,cells,target_E_pa,target_nu,target_G_pa,E_warp_pa,E_weft_pa,"
         "E_diagonal_pa,nu_warp,nu_weft,nu_diagonal,G_pa,E_warp_error,E_diagonal_error,"
         "nu_warp_error,G_error,strip_E_pa,strip_nu\n";
  for (const MaterialTestRow& r : rows) {
    const double g = target_shear_modulus_pa(e, r.target_nu);
    csv << to_string(r.formulation) << ',' << to_string(r.sheet) << ',' << r.cells << ',' << e
        << ',' << r.target_nu << ',' << g;
    if (r.refused) {
      csv << ",refused,,,,,,,,,,,,\n";
      continue;
    }
    const EffectiveMaterial& m = r.measured;
    csv << ',' << m.e_warp_pa << ',' << m.e_weft_pa << ',' << m.e_diagonal_pa << ',' << m.nu_warp
        << ',' << m.nu_weft << ',' << m.nu_diagonal << ',' << m.shear_modulus_pa << ','
        << m.e_warp_pa / e - 1 << ',' << m.e_diagonal_pa / e - 1 << ',' << m.nu_warp - r.target_nu
        << ',' << m.shear_modulus_pa / g - 1 << ',';
    if (r.strip) csv << r.strip->e_pa << ',' << r.strip->nu;
    csv << '\n';
  }

  write_file_atomically(dir / "material_test.csv", csv.str(), "material test table");

  std::ostringstream md = report_text();
  md << "Target E = " << e << " Pa, thickness " << options.thickness_m << " m, " << options.cells
     << " cells a side. E and G: error relative to the target; nu: the measured value. The "
        "first columns come from the homogenised stiffness tensor; the strip pull is a literal "
        "tensile test along the warp with free top and bottom sides (none on the equilateral "
        "sheet, whose sides zigzag).\n\n";
  md << "| formulation | sheet | target nu | E warp | E weft | E diagonal | nu warp | nu weft | "
        "nu diagonal | G | E, strip pull | nu, strip pull |\n";
  md << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  std::map<std::string, std::string> refusals;  // formulation -> the target nu it refused
  for (const MaterialTestRow& r : rows) {
    if (r.refused) {
      std::string& refused = refusals[std::string(to_string(r.formulation))];
      const std::string nu = fixed(r.target_nu, 3);
      if (refused.find(nu) == std::string::npos) refused += (refused.empty() ? "" : ", ") + nu;
      continue;
    }
    md << "| " << to_string(r.formulation) << " | " << to_string(r.sheet) << " | "
       << fixed(r.target_nu, 3) << " | ";
    const EffectiveMaterial& m = r.measured;
    const double g = target_shear_modulus_pa(e, r.target_nu);
    md << percent(m.e_warp_pa, e) << " | " << percent(m.e_weft_pa, e) << " | "
       << percent(m.e_diagonal_pa, e) << " | " << fixed(m.nu_warp, 3) << " | "
       << fixed(m.nu_weft, 3) << " | " << fixed(m.nu_diagonal, 3) << " | "
       << percent(m.shear_modulus_pa, g) << " | "
       << (r.strip ? percent(r.strip->e_pa, e) + " | " + fixed(r.strip->nu, 3) : "— | —") << " |\n";
  }
  for (const auto& [formulation, refused] : refusals) {
    md << "\n"
       << formulation << " refuses target nu " << refused << ": it accepts nu "
       << describe(supported_poisson_ratios(*stiffness_formulation_from_string(formulation)))
       << ".";
  }
  md << "\n";
  write_file_atomically(dir / "material_test.md", md.str(), "material test table");
}

std::string plot_material_tests(const std::vector<MaterialTestRow>& rows,
                                const MaterialTestOptions& options,
                                const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path script = dir / "material_test.gp";
  PendingFile png(dir / "material_test.png", "material test plot");  // gnuplot writes it
  {
    std::ostringstream gp = report_text();
    // one data block per formulation and sheet: target nu, nu warp, E warp / E,
    // E diagonal / E, G / G target
    std::map<std::string, std::ostringstream> blocks;
    std::vector<std::string> order;
    std::vector<std::string> styles;  // colour by formulation, point and dash by sheet
    for (const MaterialTestRow& r : rows) {
      if (r.refused) continue;
      const std::string name = series_name(r);
      if (!blocks.count(name)) {
        order.push_back(name);
        const int sheet = static_cast<int>(r.sheet);
        styles.push_back("lc " + std::to_string(static_cast<int>(r.formulation) + 1) + " pt " +
                         std::to_string(sheet + 4) + " dt " + std::to_string(sheet + 1));
      }
      const double e = options.youngs_modulus_pa;
      blocks[name] << r.target_nu << ' ' << r.measured.nu_warp << ' ' << r.measured.e_warp_pa / e
                   << ' ' << r.measured.e_diagonal_pa / e << ' '
                   << r.measured.shear_modulus_pa / target_shear_modulus_pa(e, r.target_nu) << '\n';
    }
    for (std::size_t i = 0; i < order.size(); ++i) {
      gp << "$s" << i << " << EOD\n" << blocks[order[i]].str() << "EOD\n";
    }
    gp << "set terminal pngcairo noenhanced size 1500,1000 font 'sans,11'\n"
       // tissu passes `output`, a temporary name renamed once the image is whole; run by hand,
       // the script writes the PNG beside itself
       << "if (!exists(\"output\")) output = '" << png.target().string() << "'\n"
       << "set output output\n"
       << "set multiplot layout 2,2 margins 0.05,0.74,0.07,0.92 spacing 0.07,0.1 title "
       << "'Measured against target: " << options.cells
       << " cells a side, E = " << options.youngs_modulus_pa << " Pa, h = " << options.thickness_m
       << " m'\n"
       << "set grid\nset xlabel 'target Poisson ratio'\nset xrange [-0.02:0.47]\n"
       << "set xtics 0.1\nset key at screen 0.99,0.9 right top font 'sans,10'\n";
    const auto panel = [&](const std::string& title, int column, const std::string& reference) {
      gp << "set title \"" << title << "\"\nplot " << reference
         << " lw 2 lc 'black' title 'target'";
      for (std::size_t i = 0; i < order.size(); ++i) {
        gp << ", $s" << i << " using 1:" << column << " with linespoints " << styles[i]
           << " title \"" << order[i] << "\"";
      }
      gp << "\nunset key\n";  // one key, beside the first panel
    };
    panel("Poisson ratio under stress along the warp (x)", 2, "x");
    panel("Young's modulus along the warp / target", 3, "1");
    panel("Young's modulus along the diagonal / target", 4, "1");
    panel("shear modulus / target E / (2 (1 + nu))", 5, "1");
    gp << "unset multiplot\n";
    write_file_atomically(script, gp.str(), "gnuplot script");
  }
  const std::optional<std::filesystem::path> gnuplot = find_on_path("gnuplot");
  if (!gnuplot) return "no gnuplot on the PATH: " + script.string() + " written, no PNG";
  const ProgramResult result =
      run_program(*gnuplot, {"-e", "output='" + png.temporary().string() + "'", script.string()});
  if (result.status != 0) return "gnuplot failed: " + last_output(result.errors);
  if (!ends_like_a_png(png.temporary()))
    return "gnuplot did not write a whole " + png.target().string() +
           " (is the disk full?): " + last_output(result.errors);
  png.commit();
  return "";
}

}  // namespace tissu
