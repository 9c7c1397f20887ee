// The solver's caches follow a model recompiled after a topological edit (issue 16): the PD
// factorisation and its two-thread partition, the colouring, the Hessian's pattern and the
// quasi-Newton history are keyed on the model's identity, so a workspace that stepped the cloth
// before a split, a tear or a coarsening steps it afterwards to the same bits as a fresh one.

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "cloth_test_support.hpp"
#include "solver/step.hpp"
#include "topology/apply_pins.hpp"
#include "topology/coarsen.hpp"
#include "topology/compile.hpp"
#include "topology/split_edge.hpp"
#include "topology/tear.hpp"

namespace tissu {
namespace {

constexpr double density_kg_per_m2 = 0.2;
constexpr int steps_each_side = 3;

struct Edit {
  std::string name;
  std::function<bool(ClothComplex&, const SpringSettings&)> apply;  ///< true if it changed lcc
};

// the first interior edge (a face on both sides) of the complex
Dart_handle interior_dart(ClothComplex& lcc) {
  for (auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
    if (!lcc.is_free<2>(d)) return d;
  }
  ADD_FAILURE() << "no interior edge";
  return lcc.darts().begin();
}

const Edit edits[] = {{"split",
                       [](ClothComplex& lcc, const SpringSettings& s) {
                         return split_edge(lcc, interior_dart(lcc), s) != nullptr;
                       }},
                      {"tear",
                       [](ClothComplex& lcc, const SpringSettings& s) {
                         return tear_edge(lcc, interior_dart(lcc), s).tears > 0;
                       }},
                      // the bisection undone: split, then coarsen the calm flat cloth back
                      {"coarsen", [](ClothComplex& lcc, const SpringSettings& s) {
                         split_edge(lcc, interior_dart(lcc), s);
                         return coarsen(lcc, RefinementOptions{}, 0.5, s).merges > 0;
                       }}};

class RecompiledWorkspace : public ::testing::TestWithParam<Integrator> {};

TEST_P(RecompiledWorkspace, StepsAnEditedClothToTheBitsOfAFreshWorkspace) {
  const SpringSettings springs = test::all_springs();
  SolverParams params;
  params.integrator = GetParam();
  params.time_step = 1.0 / 60.0;
  for (const Edit& edit : edits) {
    SCOPED_TRACE(edit.name);
    const GridOptions grid = test::grid(8, 6, GridCells::triangles);
    ClothComplex lcc;
    build_cloth_complex(make_grid_mesh(grid), density_kg_per_m2, springs, lcc);
    PinSelector top;
    top.side = Side::top;
    apply_pins(lcc, {top}, ClothFrame{});
    CompiledCloth cloth = compile(lcc);
    StepWorkspace used;
    for (int k = 0; k < steps_each_side; ++k) {
      ASSERT_NE(step(cloth.model, params, cloth.state, used), StepStatus::non_finite);
    }
    const std::uint64_t before = cloth.model.identity;
    ASSERT_TRUE(
        edit_and_recompile(lcc, cloth, [&](ClothComplex& c) { return edit.apply(c, springs); }));
    ASSERT_NE(cloth.model.identity, before);
    test::expect_valid_with_mass(lcc, density_kg_per_m2 * grid.width * grid.height, edit.name);

    State reused = cloth.state, fresh_state = cloth.state;
    StepWorkspace fresh;
    for (int k = 0; k < steps_each_side; ++k) {
      ASSERT_NE(step(cloth.model, params, reused, used), StepStatus::non_finite);
      ASSERT_NE(step(cloth.model, params, fresh_state, fresh), StepStatus::non_finite);
    }
    EXPECT_TRUE((reused.x.array() == fresh_state.x.array()).all());
    EXPECT_TRUE((reused.v.array() == fresh_state.v.array()).all());
    EXPECT_NE(reused.x, cloth.state.x);  // it moved
  }
}

INSTANTIATE_TEST_SUITE_P(Integrators, RecompiledWorkspace,
                         ::testing::Values(Integrator::implicit_euler,
                                           Integrator::projective_dynamics, Integrator::newton,
                                           Integrator::quasi_newton),
                         [](const ::testing::TestParamInfo<Integrator>& info) {
                           return std::string(to_string(info.param));
                         });

}  // namespace
}  // namespace tissu
