// tissu: command-line front end. Argument parsing only; the work is in lib/.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>

#include "apps/check_command.hpp"
#include "apps/material_test_command.hpp"
#include "apps/openmp_waiting.hpp"
#include "apps/render_command.hpp"
#include "apps/run_command.hpp"
#include "apps/sweep_command.hpp"
#include "apps/view_command.hpp"
#include "lib/version_info.hpp"

int main(int argc, char** argv) {
  tissu::prefer_short_openmp_spin(argv);
  CLI::App app{"tissu: adaptive mass-spring cloth simulator"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tissu ") + tissu::tissu_version() + " (commit " +
                                        tissu::tissu_commit() + ")");
  tissu::print_errors_on_one_line(app, "tissu");

  tissu::RunCommand run;
  CLI::App* run_app = app.add_subcommand("run", "simulate a scenario file");
  run_app->add_option("scenario", run.scenario, "scenario JSON file (schema: docs/scenario.md)")
      ->required();
  tissu::add_run_options(*run_app, run);

  tissu::CheckCommand check;
  CLI::App* check_app = app.add_subcommand(
      "check", "validate a scenario, its meshes and pins without running it; print it resolved");
  tissu::add_check_options(*check_app, check);

  tissu::RenderCommand render;
  CLI::App* render_app =
      app.add_subcommand("render", "re-render a folder of saved frame meshes, without simulating");
  tissu::add_render_options(*render_app, render);

  tissu::ViewCommand view;
  CLI::App* view_app = app.add_subcommand(
      "view", "print the address of a run's browser viewer (plays its frames, with its curves)");
  tissu::add_view_options(*view_app, view);

  tissu::MaterialTestCommand material_test;
  CLI::App* material_test_app = app.add_subcommand(
      "material-test",
      "measure E, nu and G of every stiffness formulation on test sheets (docs/materials.md)");
  tissu::add_material_test_options(*material_test_app, material_test);

  tissu::SweepCommand sweep;
  CLI::App* sweep_app = app.add_subcommand(
      "sweep", "run a scenario over a grid or random draws of parameters (python3 -m tissu.sweep)");
  tissu::add_sweep_options(*sweep_app, sweep);

  if (const std::optional<int> status = tissu::parse_command_line(app, argc, argv)) return *status;
  if (run_app->parsed()) return tissu::execute(run);
  if (check_app->parsed()) return tissu::execute(check);
  if (view_app->parsed()) return tissu::execute(view);
  if (material_test_app->parsed()) return tissu::execute(material_test);
  if (sweep_app->parsed()) return tissu::execute(sweep);
  return tissu::execute(render);
}
