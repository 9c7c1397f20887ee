#pragma once
/// \file
/// A cloth material given by its elastic constants instead of spring stiffnesses, and the
/// published formulations that turn it into spring stiffnesses (the course's table "Définition
/// des raideurs"; element formulas in membrane_stiffness.hpp). CGAL-free.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tissu {

/// How a material's E, nu and thickness become spring stiffnesses.
enum class StiffnessFormulation : std::uint8_t {
  van_gelder1998,    ///< triangles: k = E h sum(A) / l0^2 (Van Gelder 1998)
  lloyd2007,         ///< triangles and rectangles, fitted to FEM (Lloyd, Szekely & Harders 2007)
  delingette2008,    ///< triangles: St Venant-Kirchhoff membrane (Delingette 2008)
  baudet2009,        ///< rectangles: tensile and shear tests (Baudet et al. 2009)
  natsupakpong2010,  ///< rectangles: fitted to FEM (Natsupakpong & Cavusoglu 2010)
};
inline constexpr int stiffness_formulation_count = 5;

/// The cells a formulation is defined on.
enum class FormulationCells : std::uint8_t { triangles, rectangles, triangles_and_rectangles };

/// An isotropic, linear elastic membrane of uniform thickness.
struct Material {
  double youngs_modulus_pa = 0.0;  ///< E (Pa), > 0
  double poisson_ratio = 0.0;      ///< nu (dimensionless), within the formulation's range
  double thickness_m = 0.0;        ///< h (m), > 0
  double density_kg_per_m3 = 0.0;  ///< rho (kg/m^3), > 0
  StiffnessFormulation formulation = StiffnessFormulation::delingette2008;

  /// Mass per rest area, rho h (kg/m^2).
  double areal_density_kg_per_m2() const { return density_kg_per_m3 * thickness_m; }
  /// Plate bending modulus D = E h^3 / (12 (1 - nu^2)) (N m).
  double bending_modulus_n_m() const;
};

/// The Poisson ratios a formulation accepts: an interval, each end open or closed.
struct PoissonRange {
  double min = 0.0;
  double max = 0.0;
  bool min_included = true;
  bool max_included = true;
  bool contains(double nu) const {
    return (min_included ? nu >= min : nu > min) && (max_included ? nu <= max : nu < max);
  }
};

/// "[0, 0.5)", "1/3" for a single value, as in messages.
std::string describe(const PoissonRange& range);

/// Name as written in scenarios ("delingette2008", ...).
std::string_view to_string(StiffnessFormulation formulation);

/// Inverse of to_string(); empty for an unknown name.
std::optional<StiffnessFormulation> stiffness_formulation_from_string(std::string_view name);

/// The cells the formulation's paper gives formulas for.
FormulationCells formulation_cells(StiffnessFormulation formulation);

/// Whether the formulation defines cells of `corners` corners (3: triangles, 4: rectangles).
bool formulation_defines(StiffnessFormulation formulation, int corners);

/// The Poisson ratios the formulation supports, with the reason given by supported_range_reason().
PoissonRange supported_poisson_ratios(StiffnessFormulation formulation);

/// One sentence: why the formulation supports only supported_poisson_ratios().
std::string_view supported_range_reason(StiffnessFormulation formulation);

}  // namespace tissu
