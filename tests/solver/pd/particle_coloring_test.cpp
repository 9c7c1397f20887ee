#include "solver/pd/particle_coloring.hpp"

#include <gtest/gtest.h>

#include "tests/solver/test_models.hpp"

namespace tissu {
namespace {

TEST(ParticleColoring, NoSpringJoinsTwoParticlesOfOneColourOnRandomGraphs) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    State state;
    const int particles = 10 + 7 * static_cast<int>(seed);
    const SpringModel model = test::random_model(particles, 4 * particles, 0, seed, state);
    const ParticleColoring coloring = color_particles(model);
    EXPECT_TRUE(is_valid_coloring(model, coloring)) << "seed " << seed;
    // greedy bound: at most max degree + 1 colours
    int max_degree = 0;
    for (int p = 0; p < particles; ++p) {
      max_degree =
          std::max(max_degree, model.incidence.offsets[p + 1] - model.incidence.offsets[p]);
    }
    EXPECT_LE(coloring.color_count(), max_degree + 1);
  }
}

TEST(ParticleColoring, GridWithStructuralShearAndBendingSprings) {
  State state;
  const SpringModel model = test::grid_model(17, 13, 0.1, 0.01, 100.0, 0.0, state);
  const ParticleColoring coloring = color_particles(model);
  EXPECT_TRUE(is_valid_coloring(model, coloring));
  // red-black (two colours) cannot work once shear springs close triangles
  EXPECT_GT(coloring.color_count(), 2);
  EXPECT_LE(coloring.color_count(), 13);  // degree 12 + 1
  // every particle appears once in the colour order
  std::vector<int> seen(model.particle_count(), 0);
  for (const int p : coloring.order) ++seen[p];
  for (const int count : seen) EXPECT_EQ(count, 1);
}

TEST(ParticleColoring, StructuralOnlyGridIsRedBlack) {
  State state;
  SpringModel model = test::grid_model(8, 8, 0.1, 0.01, 100.0, 0.0, state);
  std::vector<int> keep;
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.kind[s] == SpringKind::structural) keep.push_back(s);
  }
  SpringModel structural = model;
  const auto count = static_cast<Eigen::Index>(keep.size());
  structural.springs.resize(count, 2);
  structural.rest_length.resize(count);
  structural.stiffness.resize(count);
  structural.damping.resize(count);
  structural.kind.assign(keep.size(), SpringKind::structural);
  for (Eigen::Index k = 0; k < count; ++k) {
    structural.springs.row(k) = model.springs.row(keep[k]);
    structural.rest_length[k] = model.rest_length[keep[k]];
    structural.stiffness[k] = model.stiffness[keep[k]];
    structural.damping[k] = model.damping[keep[k]];
  }
  finalize_model(structural);
  const ParticleColoring coloring = color_particles(structural);
  EXPECT_TRUE(is_valid_coloring(structural, coloring));
  EXPECT_EQ(coloring.color_count(), 2);
}

TEST(ParticleColoring, DetectsAnInvalidColouring) {
  State state;
  const SpringModel model = test::grid_model(4, 4, 0.1, 0.01, 100.0, 0.0, state);
  ParticleColoring coloring = color_particles(model);
  coloring.color[model.springs(0, 0)] = coloring.color[model.springs(0, 1)];
  EXPECT_FALSE(is_valid_coloring(model, coloring));
}

}  // namespace
}  // namespace tissu
