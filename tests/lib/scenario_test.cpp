#include "lib/scenario/scenario.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "lib/mesh_io/write_mesh.hpp"
#include "lib/obstacle_mesh.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "tests/lib/scenario_errors.hpp"
#include "tests/test_meshes.hpp"
#include "tests/test_temp_dir.hpp"

namespace tissu {
namespace {

using ::testing::HasSubstr;

using test::minimal_scenario_error;

TEST(Scenario, MinimalScenarioGetsDocumentedDefaults) {
  const Scenario s = parse_scenario(test::minimal_scenario, "dir/s.json");
  EXPECT_EQ(s.name, "s");
  ASSERT_TRUE(s.cloth.grid.has_value());
  EXPECT_EQ(s.cloth.grid->cells_u, 4);
  EXPECT_EQ(s.cloth.grid->cells, GridCells::triangles);
  EXPECT_EQ(s.cloth.grid->diagonal, DiagonalPattern::alternating);
  EXPECT_TRUE(s.springs.structural.enabled);
  EXPECT_DOUBLE_EQ(s.springs.structural.stiffness, 100.0);
  EXPECT_FALSE(s.springs.shear.enabled);
  EXPECT_FALSE(s.springs.bending.enabled);
  EXPECT_EQ(s.solver.integrator, Integrator::quasi_newton);
  EXPECT_EQ(s.frames, 3);
  EXPECT_EQ(s.substeps, 10);
  EXPECT_DOUBLE_EQ(s.solver.time_step, 1.0 / 300.0);
  EXPECT_EQ(s.solver.environment.gravity, Eigen::Vector3d(0, 0, -9.81));
  EXPECT_EQ(s.output.mesh_format, MeshFormat::obj);
  EXPECT_TRUE(s.pins.empty());
}

TEST(Scenario, ReadsEverySection) {
  const Scenario s = parse_scenario(R"({
    "name": "full",
    "cloth": {
      "mesh": { "file": "meshes/flag.obj", "u_axis": [0, 1, 0], "v_axis": [0, 0, 2] },
      "density": 0.3,
      "springs": { "structural": { "stiffness": 10, "damping": 1 },
                   "shear": { "stiffness": 5, "enabled": false },
                   "bending": { "stiffness": 1, "damping": 0.5 } }
    },
    "pins": [ { "side": "top", "every": 2 }, { "corners": ["bottom_left"] },
              { "indices": [0, 4] }, { "box": { "min": [0, 0, 0], "max": [1, 1, 1] } } ],
    "environment": { "gravity": [0, -9.8, 0], "air_damping": 0.2,
                     "wind": { "velocity": [1, 2, 3], "gust_amplitude": 0.5, "gust_frequency": 2,
                               "air_density": 1.1, "drag_coefficient": 0.8 } },
    "simulation": { "integrator": "position_verlet", "frames": 7, "frame_rate": 25,
                    "time_step": 0.001, "threads": 2 },
    "output": { "meshes": false, "mesh_format": "ply", "mesh_every": 5 }
  })",
                                    "dir/full.json");
  EXPECT_EQ(s.name, "full");
  EXPECT_EQ(s.cloth.mesh_file, std::filesystem::path("dir/meshes/flag.obj"));
  EXPECT_EQ(s.cloth.frame.v_axis, Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(s.springs.shear.enabled);
  EXPECT_DOUBLE_EQ(s.springs.bending.damping, 0.5);
  ASSERT_EQ(s.pins.size(), 4u);
  EXPECT_EQ(s.pins[0].kind, PinSelector::Kind::side);
  EXPECT_EQ(s.pins[0].every, 2);
  EXPECT_EQ(s.pins[1].corners, std::vector<Corner>{Corner::bottom_left});
  EXPECT_EQ(s.pins[2].indices, (std::vector<int>{0, 4}));
  EXPECT_EQ(s.pins[3].box.max(), Eigen::Vector3d(1, 1, 1));
  EXPECT_DOUBLE_EQ(s.solver.environment.wind.drag_coefficient, 0.8);
  EXPECT_EQ(s.solver.integrator, Integrator::position_verlet);
  EXPECT_EQ(s.substeps, 40);
  EXPECT_DOUBLE_EQ(s.solver.time_step, 0.001);
  EXPECT_EQ(s.threads, 2);
  EXPECT_FALSE(s.output.write_meshes);
  EXPECT_EQ(s.output.mesh_format, MeshFormat::ply);
}

TEST(Scenario, MisspeltKeyIsNamedWithASuggestion) {
  std::string text = test::minimal_scenario;
  text.replace(text.find("\"density\""), 9, "\"densty\"");
  EXPECT_EQ(test::scenario_error_of(text),
            "dir/s.json: cloth.densty: unknown key; did you mean 'density'?");
}

TEST(Scenario, UnknownKeyFarFromAnyIsListedWithTheKnownOnes) {
  EXPECT_THAT(minimal_scenario_error("simulation.zzzzzzzzzz", "1"),
              HasSubstr("dir/s.json: simulation.zzzzzzzzzz: unknown key; known keys here:"));
}

TEST(Scenario, WrongTypesNameTheKeyAndWhatWasExpected) {
  EXPECT_EQ(minimal_scenario_error("cloth.density", "\"heavy\""),
            "dir/s.json: cloth.density: expected a positive number (kg/m^2), got \"heavy\"");
  EXPECT_EQ(minimal_scenario_error("simulation.frames", "2.5"),
            "dir/s.json: simulation.frames: expected an integer from 1 to 10000000, got 2.5");
  EXPECT_EQ(minimal_scenario_error("cloth.grid.size", "[1]"),
            "dir/s.json: cloth.grid.size: expected an array of 2 numbers, each a number between "
            "1e-06 and 1e+06 (m), got [1]");
  EXPECT_THAT(minimal_scenario_error("environment.gravity", "[0, 0]"),
              HasSubstr("environment.gravity: expected an array of 3 finite numbers"));
  EXPECT_THAT(minimal_scenario_error("output", "[]"),
              HasSubstr("dir/s.json: output: expected an object"));
  EXPECT_THAT(minimal_scenario_error("output.meshes", "1"),
              HasSubstr("output.meshes: expected true or false"));
}

TEST(Scenario, OutOfRangeValuesNameTheRange) {
  EXPECT_EQ(minimal_scenario_error("cloth.density", "-1"),
            "dir/s.json: cloth.density: expected a positive number (kg/m^2), got -1");
  EXPECT_THAT(minimal_scenario_error("cloth.springs.structural.damping", "-0.1"),
              HasSubstr("expected a number >= 0 (N s/m), got -0.1"));
  EXPECT_THAT(minimal_scenario_error("cloth.grid.resolution", "[0, 3]"),
              HasSubstr("cloth.grid.resolution: expected a non-empty array of integers >= 1"));
  EXPECT_THAT(
      minimal_scenario_error("simulation.integrator", "\"rk4\""),
      HasSubstr("simulation.integrator: expected one of \"symplectic_euler\", "
                "\"position_verlet\", \"implicit_euler\", \"projective_dynamics\", \"newton\", "
                "\"quasi_newton\", got \"rk4\""));
  EXPECT_THAT(minimal_scenario_error("environment.wind.gust_amplitude", "11"),
              HasSubstr("expected a number between 0 and 10"));
  EXPECT_THAT(minimal_scenario_error("simulation.time_step", "0.007"),
              HasSubstr("simulation.time_step: expected a time step that divides"));
}

TEST(Scenario, MissingRequiredKeysAreNamed) {
  EXPECT_EQ(test::scenario_error_of(R"({"cloth": {"grid": {"size": [1, 1], "resolution": [1, 1]},
                                    "springs": {"structural": {"stiffness": 1}}},
                         "simulation": {"frames": 1}})"),
            "dir/s.json: cloth.density: missing; expected a positive number (kg/m^2)");
  EXPECT_EQ(test::scenario_error_of(R"({"simulation": {"frames": 1}})"),
            "dir/s.json: cloth: missing; expected an object {...}");
  EXPECT_THAT(
      minimal_scenario_error("cloth.springs.structural", "{\"enabled\": false, \"stiffness\": 1}"),
      HasSubstr("cloth.springs.structural: expected structural springs"));
}

TEST(Scenario, ConflictingChoicesAreRejected) {
  EXPECT_THAT(minimal_scenario_error("cloth.mesh", "{\"file\": \"a.obj\"}"),
              HasSubstr("expected exactly one of \"grid\" and \"mesh\""));
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario,
                                      {"simulation.time_step=0.001", "simulation.substeps=3"}),
              HasSubstr("either \"substeps\" or \"time_step\", not both"));
  EXPECT_THAT(
      test::scenario_error_of(test::minimal_scenario, {"pins=[{\"side\": \"top\", \"box\": {}}]"}),
      HasSubstr("dir/s.json: pins[0]: expected exactly one of"));
  EXPECT_THAT(
      test::scenario_error_of(test::minimal_scenario, {"pins=[{\"corners\": [\"middle\"]}]"}),
      HasSubstr("dir/s.json: pins[0].corners[0]: expected one of \"bottom_left\""));
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario,
                                      {"pins=[{\"box\": {\"min\": [1,1,1], \"max\": [0,0,0]}}]"}),
              HasSubstr("pins[0].box.max: expected max >= min"));
}

TEST(Scenario, InvalidJsonGivesTheLineAndColumn) {
  EXPECT_THAT(
      test::scenario_error_of("{ \"cloth\": { ,"),
      HasSubstr("dir/s.json: invalid JSON: parse error at line 1, column 14: syntax error"));
}

TEST(Scenario, OverridesSetNestedValuesAndArrayElements) {
  const Scenario s = parse_scenario(test::minimal_scenario, "dir/s.json",
                                    {"cloth.density=0.5", "simulation.integrator=symplectic_euler",
                                     "pins=[{\"side\": \"top\"}]", "pins.0.every=3"});
  EXPECT_DOUBLE_EQ(s.areal_density, 0.5);
  EXPECT_EQ(s.solver.integrator, Integrator::symplectic_euler);
  ASSERT_EQ(s.pins.size(), 1u);
  EXPECT_EQ(s.pins[0].every, 3);
}

TEST(Scenario, BadOverridesAreNamed) {
  EXPECT_EQ(test::scenario_error_of(test::minimal_scenario, {"cloth.density"}),
            "dir/s.json: --set cloth.density: expected key.path=value");
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario, {"cloth.density.x=1"}),
              HasSubstr("'cloth.density' is not an object"));
  EXPECT_THAT(test::scenario_error_of(test::minimal_scenario, {"pins=[]", "pins.3=1"}),
              HasSubstr("'pins' is an array; expected an index below 0"));
}

TEST(Scenario, MissingFileIsNamed) {
  try {
    load_scenario("no/such/file.json");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_STREQ(e.what(),
                 "no/such/file.json: cannot open the scenario file: No such file or directory");
  }
}

TEST(Scenario, ShippedScenariosLoad) {
  int scenarios = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(TISSU_DATA_DIR) / "scenarios")) {
    const Scenario s = load_scenario(entry.path());
    EXPECT_GT(s.frames, 0) << entry.path();
    ++scenarios;
  }
  EXPECT_GE(scenarios, 3);  // curtain, curtain_uniform, drape
}

TEST(Scenario, ReadsObstaclesOfEveryShape) {
  const Scenario s = parse_scenario(test::minimal_scenario, "dir/s.json", {R"(obstacles=[
      { "type": "plane", "point": [0, 0, -1], "normal": [0, 0, 2], "static_friction": 0.5 },
      { "type": "sphere", "center": [0, 0, 1], "radius": 0.3, "thickness": 0.01,
        "motion": { "velocity": [0, 0, -1] } },
      { "type": "capsule", "from": [0, 0, 0], "to": [1, 0, 0], "radius": 0.1,
        "static_friction": 0.6, "kinetic_friction": 0.4 },
      { "type": "box", "center": [1, 2, 3], "size": [2, 4, 6],
        "rotation": { "axis": [0, 0, 1], "angle": 1.5707963267948966 },
        "motion": { "keyframes": [ { "time": 0, "offset": [0, 0, 0] },
                                   { "time": 2, "offset": [0, 0, 1] } ] } } ])"});
  const std::vector<Obstacle>& o = s.solver.obstacles;
  ASSERT_EQ(o.size(), 4u);
  EXPECT_EQ(o[0].shape, ObstacleShape::plane);
  EXPECT_EQ(o[0].normal, Eigen::Vector3d(0, 0, 1));
  EXPECT_DOUBLE_EQ(o[0].kinetic_friction, 0.5);  // defaults to the static coefficient
  EXPECT_DOUBLE_EQ(o[1].radius_m, 0.3);
  EXPECT_DOUBLE_EQ(o[1].thickness_m, 0.01);
  EXPECT_EQ(o[1].motion.drift_m_per_s, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(o[2].axis_end, Eigen::Vector3d(1, 0, 0));
  EXPECT_DOUBLE_EQ(o[2].kinetic_friction, 0.4);
  EXPECT_EQ(o[3].half_extents_m, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE((o[3].rotation * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(o[3].motion.pose(1.0).translation_m.isApprox(Eigen::Vector3d(0, 0, 0.5)));
}

TEST(Scenario, ReadsSelfCollision) {
  EXPECT_FALSE(parse_scenario(test::minimal_scenario, "s.json").solver.self_collision.enabled);
  const Scenario s = parse_scenario(
      test::minimal_scenario, "s.json",
      {R"(self_collision={ "thickness": 0.003, "friction": 0.2, "impulse_passes": 2 })"});
  EXPECT_TRUE(s.solver.self_collision.enabled);
  EXPECT_DOUBLE_EQ(s.solver.self_collision.thickness_m, 0.003);
  EXPECT_DOUBLE_EQ(s.solver.self_collision.friction, 0.2);
  EXPECT_EQ(s.solver.self_collision.impulse_passes, 2);
  EXPECT_THAT(minimal_scenario_error("self_collision", R"({ "thickness": 0 })"),
              HasSubstr("self_collision.thickness: expected a positive number (m), got 0"));
  EXPECT_THAT(minimal_scenario_error("self_collision", R"({ "thicknes": 0.01 })"),
              HasSubstr("did you mean 'thickness'?"));
}

TEST(Scenario, ReadsTearing) {
  EXPECT_FALSE(parse_scenario(test::minimal_scenario, "s.json").tearing.enabled);
  const Scenario s = parse_scenario(test::minimal_scenario, "s.json", {R"(tearing={
      "strain": 0.2, "max_tears_per_step": 3, "tip_min_edge_length": 0.01, "min_piece_faces": 2,
      "weak_regions": [ { "line": [[0, 0, 0.5], [1, 0, 0.5]], "width": 0.02, "factor": 0.5 },
                        { "box": { "min": [0, 0, 0], "max": [0.1, 0.1, 0.1] }, "factor": 0.8 } ],
      "cuts": [ { "time": 0.5, "line": [[0, 0, 0.2], [0.5, 0, 0.2]] } ] })"});
  const TearingSettings& t = s.tearing;
  EXPECT_TRUE(t.enabled);
  EXPECT_DOUBLE_EQ(t.options.strain_threshold, 0.2);
  EXPECT_EQ(t.options.max_tears_per_step, 3);
  EXPECT_DOUBLE_EQ(t.options.tip_min_edge_length_m, 0.01);
  EXPECT_EQ(t.options.min_piece_faces, 2);
  ASSERT_EQ(t.options.weak_regions.size(), 2u);
  EXPECT_EQ(t.options.weak_regions[0].kind, WeakRegion::Kind::line);
  EXPECT_EQ(t.options.weak_regions[0].points_m.size(), 2u);
  EXPECT_EQ(t.options.weak_regions[1].kind, WeakRegion::Kind::box);
  EXPECT_DOUBLE_EQ(t.options.weak_regions[1].factor, 0.8);
  ASSERT_EQ(t.cuts.size(), 1u);
  EXPECT_DOUBLE_EQ(t.cuts[0].time_s, 0.5);

  const Scenario pulled = parse_scenario(test::minimal_scenario, "s.json",
                                         {R"(pins=[{ "side": "top", "velocity": [0, 0, 0.1] }])"});
  EXPECT_EQ(pulled.pins.at(0).motion.drift_m_per_s, Eigen::Vector3d(0, 0, 0.1));
}

TEST(Scenario, BadTearingIsNamed) {
  EXPECT_THAT(minimal_scenario_error("tearing", "{}"),
              HasSubstr("tearing.strain: expected a positive \"strain\" or at least one of "
                        "\"cuts\" when tearing"));
  EXPECT_THAT(minimal_scenario_error("tearing", R"({ "strian": 0.2 })"),
              HasSubstr("did you mean 'strain'?"));
  EXPECT_THAT(
      minimal_scenario_error("tearing", R"({ "strain": 0.2, "weak_regions": [{ "line": [[0, 0, 0]],
                                  "width": 0.1, "factor": 0.5 }] })"),
      HasSubstr("tearing.weak_regions[0].line: expected an array of at least 2 points"));
  EXPECT_THAT(minimal_scenario_error(
                  "tearing", R"({ "strain": 0.2, "weak_regions": [{ "box": { "min": [0, 0, 0],
                                  "max": [1, 1, 1] }, "factor": 0 }] })"),
              HasSubstr("tearing.weak_regions[0].factor: expected a number in (0, 1], got 0"));
  EXPECT_THAT(minimal_scenario_error("tearing",
                                     R"({ "cuts": [ { "time": 1, "line": [[0, 0, 0], [1, 0, 0]] },
                                            { "time": 0.5, "line": [[0, 0, 0], [1, 0, 0]] } ] })"),
              HasSubstr("tearing.cuts[1].time: expected a time not before the previous cut's"));
  EXPECT_THAT(minimal_scenario_error("pins", R"([{ "side": "top", "velocity": [0, 1] }])"),
              HasSubstr("pins[0].velocity: expected an array of 3 finite numbers"));
}

TEST(Scenario, ReadsAMeshObstacleScaledAndPlaced) {
  const IndexedMesh cube = test::cube_mesh(Eigen::Vector3d::Zero(), 1.0);  // [-1, 1]^3
  const std::filesystem::path file = test::fresh_temp_dir("mesh_obstacle") / "cube.obj";
  write_mesh(file, cube, MeshFormat::obj);
  const Scenario s = parse_scenario(test::minimal_scenario, "dir/s.json",
                                    {R"(obstacles=[{ "type": "mesh", "file": ")" + file.string() +
                                     R"(", "scale": 0.5, "position": [0, 0, 1] }])"});
  ASSERT_EQ(s.solver.obstacles.size(), 1u);
  const Obstacle& o = s.solver.obstacles[0];
  EXPECT_EQ(o.shape, ObstacleShape::mesh);
  EXPECT_NEAR(surface_distance(o, Eigen::Vector3d(0, 0, 2), 0.0).distance_m, 0.5, 1e-12);
  const IndexedMesh drawn = obstacle_mesh(o, 0.0);  // what the renderer shows
  EXPECT_EQ(drawn.faces.size(), 12u);
  for (const Eigen::Vector3d& x : drawn.vertices) EXPECT_NEAR(std::abs(x.x()), 0.5, 1e-12);

  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "mesh", "file": "no_such.obj" }])"),
              HasSubstr("dir/s.json: obstacles[0].file: dir/no_such.obj"));
}

TEST(Scenario, ReadsAMeshObstacleSoupRotatedFromYUp) {
  // a thin pyramid pointing up +y, as a y-up tool writes it, with its faces all listed twice:
  // every edge is shared by four faces, which a cloth would refuse
  IndexedMesh soup;
  soup.vertices = {{-0.1, 0, -0.1}, {0.1, 0, -0.1}, {0.1, 0, 0.1}, {-0.1, 0, 0.1}, {0, 1, 0}};
  soup.faces = {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}};
  const std::vector<std::vector<int>> once = soup.faces;
  soup.faces.insert(soup.faces.end(), once.begin(), once.end());
  const std::filesystem::path file = test::fresh_temp_dir("mesh_obstacle_soup") / "spike.obj";
  write_mesh(file, soup, MeshFormat::obj);
  const Scenario s = parse_scenario(
      test::minimal_scenario, "dir/s.json",
      {R"(obstacles=[{ "type": "mesh", "file": ")" + file.string() +
       R"(", "scale": 2, "rotation": { "axis": [1, 0, 0], "degrees": 90 }, "position": [0, 0, 1] }])"});
  ASSERT_EQ(s.solver.obstacles.size(), 1u);
  // scaled about the origin, +y turned to +z, then lifted: the apex is at (0, 0, 3)
  EXPECT_NEAR(surface_distance(s.solver.obstacles[0], {0, 0, 3.5}, 0.0).distance_m, 0.5, 1e-12);
  EXPECT_LT(surface_distance(s.solver.obstacles[0], {0, 0, 2.5}, 0.0).distance_m, 0.0);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_THAT(s.notes[0], HasSubstr("dir/s.json: obstacles[0].file: "));
  EXPECT_THAT(s.notes[0],
              HasSubstr("dropped 6 duplicate and 0 degenerate faces, kept 6 triangles"));

  EXPECT_THAT(
      minimal_scenario_error("obstacles", R"([{ "type": "mesh", "file": ")" + file.string() +
                                              R"(", "rotation": { "angle": 1, "degrees": 90 } }])"),
      HasSubstr("obstacles[0].rotation.angle: expected exactly one of \"angle\" (rad) "
                "and \"degrees\""));
}

TEST(Scenario, BadObstaclesAreNamed) {
  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "cone" }])"),
              HasSubstr("dir/s.json: obstacles[0].type: expected one of"));
  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "sphere", "center": [0, 0, 0] }])"),
              HasSubstr("obstacles[0].radius: missing; expected a positive number (m)"));
  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "plane", "radius": 1 }])"),
              HasSubstr("obstacles[0].radius: unknown key"));
  EXPECT_THAT(
      minimal_scenario_error(
          "obstacles", R"([{ "type": "plane", "static_friction": 0.2, "kinetic_friction": 0.3 }])"),
      HasSubstr("obstacles[0].kinetic_friction: expected a number between 0 and 0.2 (at most "
                "static_friction)"));
  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "plane", "motion": { "keyframes": [
                  { "time": 1, "offset": [0, 0, 0] }, { "time": 1, "offset": [0, 0, 1] } ] } }])"),
              HasSubstr("obstacles[0].motion.keyframes[1].time: expected a time after the "
                        "previous keyframe's"));
  EXPECT_THAT(minimal_scenario_error("obstacles", R"([{ "type": "plane", "normal": [0, 0, 0] }])"),
              HasSubstr("obstacles[0].normal: expected"));
}

const char* const with_material = R"({
  "cloth": {
    "grid": { "size": [1.0, 0.5], "resolution": [4, 2] },
    "material": { "E": 5e5, "nu": 0.3, "thickness": 5e-4, "density": 200,
                  "formulation": "delingette2008" }
  },
  "simulation": { "frames": 3 }
})";

TEST(Scenario, ReadsAMaterialAndTurnsItsDensityIntoAnArealDensity) {
  const Scenario s = parse_scenario(with_material, "dir/s.json");
  ASSERT_TRUE(s.springs.material.has_value());
  EXPECT_EQ(s.springs.material->youngs_modulus_pa, 5e5);
  EXPECT_EQ(s.springs.material->poisson_ratio, 0.3);
  EXPECT_EQ(s.springs.material->formulation, StiffnessFormulation::delingette2008);
  EXPECT_DOUBLE_EQ(s.areal_density, 0.1);  // 200 kg/m^3 x 0.5 mm
  // without "springs", every kind is on, undamped
  EXPECT_TRUE(s.springs.structural.enabled && s.springs.shear.enabled && s.springs.bending.enabled);
  EXPECT_EQ(s.springs.structural.damping, 0.0);
  const Scenario damped = parse_scenario(
      with_material, "dir/s.json",
      {R"(cloth.springs={"bending": {"enabled": false}, "structural": {"damping": 0.1}})"});
  EXPECT_FALSE(damped.springs.bending.enabled);
  EXPECT_EQ(damped.springs.structural.damping, 0.1);
  EXPECT_EQ(
      parse_scenario(with_material, "s.json",
                     {"cloth.material.formulation=natsupakpong2010", "cloth.grid.cells=quads"})
          .springs.material->formulation,
      StiffnessFormulation::natsupakpong2010);
}

TEST(Scenario, MaterialMistakesAreNamed) {
  EXPECT_EQ(test::scenario_error_of(with_material, {"cloth.material.nu=0.6"}),
            "dir/s.json: cloth.material.nu: expected a Poisson ratio in (-1, 0.5) for formulation "
            "\"delingette2008\": it is a St Venant-Kirchhoff membrane of an isotropic solid, "
            "-1 < nu < 0.5, got 0.6");
  EXPECT_THAT(test::scenario_error_of(with_material, {"cloth.material.formulation=lloyd2007"}),
              HasSubstr("cloth.material.nu: expected a Poisson ratio of 1/3 for formulation "
                        "\"lloyd2007\""));
  EXPECT_THAT(test::scenario_error_of(with_material, {"cloth.material.formulation=baudet2009"}),
              HasSubstr("cloth.material.formulation: expected a formulation defined on the "
                        "grid's triangles (cloth.grid.cells): \"baudet2009\" is defined on "
                        "rectangles"));
  EXPECT_THAT(test::scenario_error_of(with_material, {"cloth.material.formulation=hooke"}),
              HasSubstr("cloth.material.formulation: expected one of"));
  EXPECT_THAT(test::scenario_error_of(with_material, {"cloth.material.E=-1"}),
              HasSubstr("cloth.material.E: expected a positive number"));
  EXPECT_THAT(test::scenario_error_of(with_material, {"cloth.density=0.2"}),
              HasSubstr("cloth.density: expected no \"density\" beside \"material\""));
  EXPECT_THAT(
      test::scenario_error_of(with_material, {R"(cloth.springs={"shear": {"stiffness": 3}})"}),
      HasSubstr("cloth.springs.shear.stiffness: expected no stiffness: with \"material\""));
  EXPECT_THAT(test::scenario_error_of(with_material, {"simulation.integrator=projective_dynamics"}),
              HasSubstr("simulation.integrator: expected \"implicit_euler\""));
  EXPECT_THAT(test::scenario_error_of(
                  with_material, {"cloth.material.formulation=baudet2009", "cloth.grid.cells=quads",
                                  "adaptive={\"strain\": 0.1}"}),
              HasSubstr("cloth.material.formulation: expected a formulation defined on triangles, "
                        "as refinement"));
}

}  // namespace
}  // namespace tissu
