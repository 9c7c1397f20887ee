#include "topology/material.hpp"

#include <array>
#include <cmath>
#include <sstream>

namespace tissu {
namespace {

struct FormulationFacts {
  std::string_view name;
  FormulationCells cells;
  PoissonRange poisson;
  std::string_view reason;
};

// A network of springs alone obeys Cauchy's relation C12 = C66; an isotropic one then has
// nu = 1/3 under plane stress. Formulations made of springs alone are exact for no other nu.
constexpr double one_third = 1.0 / 3.0;

const std::array<FormulationFacts, stiffness_formulation_count>& facts() {
  static const std::array<FormulationFacts, stiffness_formulation_count> table = {{
      {"van_gelder1998",
       FormulationCells::triangles,
       {one_third, one_third},
       "its springs alone give an isotropic membrane nu = 1/3 (Cauchy's relation), and its "
       "formula has no nu"},
      {"lloyd2007",
       FormulationCells::triangles_and_rectangles,
       {one_third, one_third},
       "its stiffnesses were fitted to a finite element membrane with nu = 1/3, the only value "
       "springs alone can give an isotropic membrane"},
      {"delingette2008",
       FormulationCells::triangles,
       {-1.0, 0.5, false, false},
       "it is a St Venant-Kirchhoff membrane of an isotropic solid, -1 < nu < 0.5"},
      {"baudet2009",
       FormulationCells::rectangles,
       {-1.0 / 3.0, 0.5, false, false},
       "its edge stiffness E (3 nu + 1) / (4 (1 + nu)) on a square is positive only for "
       "nu > -1/3, and an isotropic solid has nu < 0.5"},
      {"natsupakpong2010",
       FormulationCells::rectangles,
       {-1.0, 0.5, false, false},
       "it is fitted to a finite element membrane of an isotropic solid, -1 < nu < 0.5"},
  }};
  return table;
}

const FormulationFacts& facts_of(StiffnessFormulation formulation) {
  return facts()[static_cast<int>(formulation)];
}

std::string number(double value) {
  if (value == one_third) return "1/3";
  if (value == -one_third) return "-1/3";
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

double Material::bending_modulus_n_m() const {
  return youngs_modulus_pa * thickness_m * thickness_m * thickness_m /
         (12.0 * (1.0 - poisson_ratio * poisson_ratio));
}

std::string describe(const PoissonRange& range) {
  if (range.min == range.max) return number(range.min);
  std::ostringstream out;
  out << (range.min_included ? "[" : "(") << number(range.min) << ", " << number(range.max)
      << (range.max_included ? "]" : ")");
  return out.str();
}

std::string_view to_string(StiffnessFormulation formulation) {
  return facts_of(formulation).name;
}

std::optional<StiffnessFormulation> stiffness_formulation_from_string(std::string_view name) {
  for (int f = 0; f < stiffness_formulation_count; ++f) {
    if (facts()[f].name == name) return static_cast<StiffnessFormulation>(f);
  }
  return std::nullopt;
}

FormulationCells formulation_cells(StiffnessFormulation formulation) {
  return facts_of(formulation).cells;
}

bool formulation_defines(StiffnessFormulation formulation, int corners) {
  const FormulationCells cells = formulation_cells(formulation);
  return (corners == 3 && cells != FormulationCells::rectangles) ||
         (corners == 4 && cells != FormulationCells::triangles);
}

PoissonRange supported_poisson_ratios(StiffnessFormulation formulation) {
  return facts_of(formulation).poisson;
}

std::string_view supported_range_reason(StiffnessFormulation formulation) {
  return facts_of(formulation).reason;
}

}  // namespace tissu
