#include "solver/spring_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace tissu {
namespace {

// a square 0-1-2-3 with one diagonal 0-2; particle 3 is pinned
SpringModel square() {
  SpringModel model;
  model.mass = Eigen::Vector4d(1.0, 2.0, 4.0, 5.0);
  model.pinned = {0, 0, 0, 1};
  model.springs.resize(5, 2);
  model.springs << 0, 1, 1, 2, 2, 3, 3, 0, 0, 2;
  model.rest_length = Eigen::VectorXd::Ones(5);
  model.stiffness = Eigen::VectorXd::Constant(5, 10.0);
  model.damping = Eigen::VectorXd::Zero(5);
  model.kind.assign(5, SpringKind::structural);
  model.kind[4] = SpringKind::shear;
  model.triangles.resize(2, 3);
  model.triangles << 0, 1, 2, 0, 2, 3;
  return model;
}

TEST(FinalizeModel, FillsInverseMassWithZeroForPinned) {
  SpringModel model = square();
  finalize_model(model);
  EXPECT_EQ(model.inverse_mass, Eigen::Vector4d(1.0, 0.5, 0.25, 0.0));
}

TEST(FinalizeModel, BuildsTheParticleSpringIncidence) {
  SpringModel model = square();
  finalize_model(model);
  const ParticleSpringIncidence& incidence = model.incidence;
  EXPECT_EQ(incidence.offsets, (std::vector<int>{0, 3, 5, 8, 10}));
  EXPECT_EQ(incidence.springs, (std::vector<int>{0, 3, 4, 0, 1, 1, 2, 4, 2, 3}));
  EXPECT_EQ(incidence.first_end, (std::vector<std::int8_t>{1, 0, 1, 0, 1, 0, 1, 0, 0, 1}));
  for (int p = 0; p < model.particle_count(); ++p) {
    for (int e = incidence.offsets[p]; e < incidence.offsets[p + 1]; ++e) {
      EXPECT_EQ(model.springs(incidence.springs[e], incidence.first_end[e] ? 0 : 1), p);
    }
  }
}

TEST(FinalizeModel, ListsEachEdgeOfTheTrianglesOnceInOrder) {
  SpringModel model = square();
  finalize_model(model);
  Eigen::MatrixX2i expected(5, 2);
  expected << 0, 1, 0, 2, 0, 3, 1, 2, 2, 3;
  EXPECT_EQ(model.surface_edges, expected);

  // a fan around particle 0 and a strip, listed in scrambled orders: the same sorted edges as
  // sorting every corner pair and dropping the repeats
  model.triangles.resize(6, 3);
  model.triangles << 3, 0, 1, 2, 1, 0, 0, 3, 2, 1, 3, 2, 2, 3, 1, 1, 2, 0;
  finalize_model(model);
  std::vector<std::pair<int, int>> pairs;
  for (Eigen::Index t = 0; t < model.triangles.rows(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int a = model.triangles(t, c), b = model.triangles(t, (c + 1) % 3);
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  ASSERT_EQ(model.surface_edges.rows(), static_cast<Eigen::Index>(pairs.size()));
  for (std::size_t e = 0; e < pairs.size(); ++e) {
    EXPECT_EQ(model.surface_edges(e, 0), pairs[e].first);
    EXPECT_EQ(model.surface_edges(e, 1), pairs[e].second);
  }
}

TEST(FinalizeModel, IsIdempotent) {
  SpringModel model = square();
  finalize_model(model);
  const ParticleSpringIncidence first = model.incidence;
  finalize_model(model);
  EXPECT_EQ(model.incidence.springs, first.springs);
  EXPECT_EQ(model.incidence.offsets, first.offsets);
}

TEST(FinalizeModel, RejectsBadInput) {
  {
    SpringModel model = square();
    model.springs(2, 1) = 4;
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.springs(2, 1) = 2;  // joins a particle to itself
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.mass[1] = 0.0;  // free particle without mass
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.mass[3] = 0.0;  // a pinned one may have none
    EXPECT_NO_THROW(finalize_model(model));
  }
  {
    SpringModel model = square();
    model.stiffness.resize(4);
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.pinned.pop_back();
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.triangles(1, 2) = -1;
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
  {
    SpringModel model = square();
    model.triangles(0, 1) = 4;  // past the last particle
    EXPECT_THROW(finalize_model(model), std::invalid_argument);
  }
}

TEST(FinalizeModel, ErrorNamesTheElement) {
  SpringModel model = square();
  model.springs(2, 1) = 9;
  try {
    finalize_model(model);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("spring 2"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace tissu
