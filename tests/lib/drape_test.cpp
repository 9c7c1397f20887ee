// A cloth dropped on a ball settles over it without entering it or passing through itself, checked
// with CGAL's exact triangle-triangle intersection test.

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/lib/face_intersections.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

const char* const small_drape = R"({
  "cloth": { "grid": { "size": [0.8, 0.8], "resolution": [24, 24], "origin": [-0.4, -0.4, 0.6],
                       "u_axis": [1, 0, 0], "v_axis": [0, 1, 0] },
             "density": 0.2,
             "springs": { "structural": { "stiffness": 1000, "damping": 0.5 },
                          "bending": { "stiffness": 2, "damping": 0.01 } } },
  "environment": { "air_damping": 0.2 },
  "obstacles": [ { "type": "plane", "static_friction": 0.6 },
                 { "type": "sphere", "center": [0, 0, 0.25], "radius": 0.25,
                   "static_friction": 0.4, "kinetic_friction": 0.3 } ],
  "self_collision": { "thickness": 0.004, "friction": 0.1 },
  "simulation": { "frames": 40, "substeps": 10 },
  "output": { "meshes": false }
})";

TEST(Drape, AClothDroppedOnABallStaysOutsideItAndDoesNotPassThroughItself) {
  const Scenario scenario = parse_scenario(small_drape, "drape.json");
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("drape");
  std::vector<MaterialSurface> surfaces;
  options.on_surface = [&](int frame, const MaterialSurface& s) {
    if (frame % 10 == 0) surfaces.push_back(s);
  };
  std::vector<double> mass_kg, kinetic_j;
  options.on_frame = [&](const FrameStats& row) {
    mass_kg.push_back(row.total_mass);
    kinetic_j.push_back(row.kinetic_energy);
  };
  const RunResult result = run_scenario(scenario, options);
  ASSERT_TRUE(result.ok) << result.failure;

  for (double kg : mass_kg) EXPECT_NEAR(kg, 0.2 * 0.8 * 0.8, 1e-12);
  // it is settling: nothing keeps a velocity its position does not follow (0.1 m/s on average
  // would be 4e-4 J)
  EXPECT_LT(kinetic_j.back(), 4e-4) << "J";
  const Eigen::Vector3d centre(0.0, 0.0, 0.25);
  ASSERT_EQ(surfaces.size(), 5u);
  // it has landed: its centre rests on top of the ball, its corners hang or lie lower
  const IndexedMesh& last = surfaces.back().current;
  double lowest_z = 1.0, highest_z = 0.0;
  for (const Eigen::Vector3d& x : last.vertices) {
    lowest_z = std::min(lowest_z, x.z());
    highest_z = std::max(highest_z, x.z());
  }
  EXPECT_NEAR(highest_z, 0.5 + 0.005, 0.01);
  EXPECT_LT(lowest_z, 0.3);
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    for (const Eigen::Vector3d& x : surfaces[k].current.vertices) {
      ASSERT_TRUE(x.allFinite());
      ASSERT_GE((x - centre).norm(), 0.25 + 0.005 - 1e-9) << "sample " << k;
      ASSERT_GE(x.z(), 0.005 - 1e-9);
    }
    EXPECT_EQ(test::intersecting_face_pairs(surfaces[k]), 0) << "at frame " << 10 * k;
  }
}

}  // namespace
}  // namespace tissu
