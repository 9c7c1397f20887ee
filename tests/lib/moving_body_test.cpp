// Cloth on a moving body: the skirt_walk demo's skirt stays outside every part of the body (legs
// swinging, arms rising) at every frame.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "lib/scenario/scenario.hpp"
#include "lib/simulation.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

TEST(MovingBody, TheSkirtStaysOutsideTheWalkingBody) {
  // two seconds: a whole swing of each leg and an arm raised (data/scenarios/skirt_walk.json)
  const Scenario scenario =
      load_scenario(TISSU_DATA_DIR "/scenarios/skirt_walk.json",
                    {"simulation.frames=60", "render.enabled=false", "output.meshes=false",
                     "output.viewer=false", "output.point_cache=false"});
  RunOptions options;
  options.output_dir = test::fresh_temp_dir("moving_body/skirt");
  // least signed distance + thickness of a particle to a body part (m)
  double deepest_m = std::numeric_limits<double>::infinity();
  int leg_contacts = 0;  // particles within 2 cm of a leg, over the frames
  options.on_surface = [&](int frame, const MaterialSurface& surface) {
    const double time_s = frame / scenario.frame_rate;
    for (std::size_t k = 0; k < scenario.solver.obstacles.size(); ++k) {
      const Obstacle& part = scenario.solver.obstacles[k];
      for (const Eigen::Vector3d& x : surface.current.vertices) {
        const double d = surface_distance(part, x, time_s).distance_m + part.thickness_m;
        deepest_m = std::min(deepest_m, d);
        leg_contacts += (k == 4 || k == 5) && surface_distance(part, x, time_s).distance_m < 0.02;
      }
    }
  };
  const RunResult result = run_scenario(scenario, options);
  ASSERT_TRUE(result.ok) << result.failure;
  // signed distance >= -thickness: no particle inside a part (the thickness is the cloth's half)
  EXPECT_GE(deepest_m, 0.0);
  EXPECT_GT(leg_contacts, 100) << "the legs never reached the skirt: the scene tests nothing";
}

}  // namespace
}  // namespace tissu
