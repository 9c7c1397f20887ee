#include "apps/run_command.hpp"

#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "lib/progress.hpp"
#include "lib/scenario/printable_text.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "lib/simulation.hpp"
#include "topology/indexed_mesh.hpp"
#include "topology/pin_selection.hpp"

namespace tissu {

void add_run_options(CLI::App& app, RunCommand& command) {
  app.add_option("-o,--out", command.output_dir, "output folder (default: out/<scenario name>)");
  app.add_option("-f,--frames", command.frames, "number of frames, instead of the scenario's")
      ->check(CLI::Range(1, max_frames));
  app.add_option("-s,--set", command.overrides,
                 "override a scenario value, e.g. --set cloth.density=0.3 (repeatable)");
  app.add_flag("-q,--quiet", command.quiet, "no progress output");
}

int execute(const RunCommand& command) {
  try {
    const Scenario scenario = load_scenario(command.scenario, command.overrides);
    for (const std::string& note : scenario.notes)
      std::fprintf(stderr, "tissu: note: %s\n", note.c_str());
    // the process's thread count is the program's to set, not the library's
    if (scenario.threads > 0) omp_set_num_threads(scenario.threads);
    RunOptions options;
    options.output_dir = command.output_dir.empty() ? std::filesystem::path("out") / scenario.name
                                                    : std::filesystem::path(command.output_dir);
    options.frames = command.frames;
    ProgressReporter progress = stderr_progress();
    if (!command.quiet) {
      options.on_frame = [&progress](const FrameStats& row) { progress(row); };
      options.on_image = [&progress](int done, int total) { progress.rendered(done, total); };
    }
    std::string unconverged_warning;  // printed after the run, so as not to break the progress bar
    options.on_warning = [&unconverged_warning](const std::string& w) { unconverged_warning = w; };
    const RunResult result = run_scenario(scenario, options);
    if (!unconverged_warning.empty()) {
      std::fprintf(stderr, "tissu: warning: %s; %d such steps in all\n",
                   unconverged_warning.c_str(), result.unconverged_steps);
    }
    if (!result.video_warning.empty()) {
      std::fprintf(stderr, "tissu: warning: %s\n", result.video_warning.c_str());
    }
    if (!result.ok) {
      std::fprintf(stderr, "tissu: simulation failed at %s\n", result.failure.c_str());
      return 2;
    }
    if (!command.quiet) {
      std::fprintf(stderr, "tissu: %d frames (%d images) written to %s\n", result.frames_done,
                   result.images, options.output_dir.c_str());
    }
    return 0;
  } catch (const ScenarioError& e) {
    std::fprintf(stderr, "tissu: %s\n", e.what());
  } catch (const MeshError& e) {
    std::fprintf(stderr, "tissu: %s\n", e.what());
  } catch (const PinError& e) {
    std::fprintf(stderr, "tissu: %s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tissu: error: %s\n", e.what());
  }
  return 1;
}

void print_errors_on_one_line(CLI::App& app, const std::string& program) {
  app.failure_message([program](const CLI::App* failed, const CLI::Error& e) {
    const std::string help = failed->get_parent() ? program + " " + failed->get_name() : program;
    return program + ": " + printable_text(e.what(), 1000) + " (see " + help + " --help)\n";
  });
}

int run_demo(int argc, char** argv, const std::string& description, const std::string& scenario,
             const std::string& output_dir) {
  CLI::App app{description};
  print_errors_on_one_line(app, std::filesystem::path(argv[0]).filename().string());
  RunCommand run;
  run.scenario = scenario;
  run.output_dir = output_dir;
  app.add_option("--scenario", run.scenario, "scenario file")->capture_default_str();
  add_run_options(app, run);
  CLI11_PARSE(app, argc, argv);
  return execute(run);
}

}  // namespace tissu
