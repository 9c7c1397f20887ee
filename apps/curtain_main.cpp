// curtain: the curtain demo, data/scenarios/curtain.json, written to out/curtain by default.

#include <CLI/CLI.hpp>

#include "apps/run_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"curtain: a curtain hanging from rings, stirred by gusty wind"};
  tissu::RunCommand run;
  run.scenario = TISSU_DATA_DIR "/scenarios/curtain.json";
  run.output_dir = "out/curtain";
  app.add_option("--scenario", run.scenario, "scenario file")->capture_default_str();
  tissu::add_run_options(app, run);
  CLI11_PARSE(app, argc, argv);
  return tissu::execute(run);
}
