#include "apps/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "apps/stop_signals.hpp"
#include "lib/progress.hpp"
#include "lib/run_record.hpp"
#include "lib/scenario/printable_text.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/scenario/scenario_limits.hpp"
#include "lib/simulation.hpp"
#include "lib/thread_count.hpp"
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

namespace {

/// The one line saying what a run stopped by a signal left, e.g. "stopped by SIGTERM after frame
/// 12 of 60: stats.csv and the meshes of frames 0 to 12 are complete in out/curtain".
std::string stopped_message(int signal_number, const RunResult& result, int frame_count,
                            const Scenario& scenario, const std::filesystem::path& dir) {
  std::string text = std::string("stopped by ") + signal_name(signal_number);
  const std::string frames = "frames 0 to " + std::to_string(result.frames_done);
  if (result.frames_done < frame_count) {
    text += " after frame " + std::to_string(result.frames_done) + " of " +
            std::to_string(frame_count) + ": stats.csv" +
            (scenario.output.write_meshes ? " and the meshes" : "") + " of " + frames +
            " are complete in " + dir.string();
    if (scenario.render.enabled)
      text += "; nothing rendered" +
              std::string(scenario.output.write_meshes ? " (tissu render renders the meshes)" : "");
  } else {
    text += " while rendering: " + frames + " are complete in " + dir.string() + ", with " +
            std::to_string(result.images) + " images and no video";
  }
  return text;
}

/// How a run ended: its exit status, its state for run.json, and the line it prints on stderr.
struct RunEnd {
  int exit_status = 0;
  std::string status;   ///< RunRecord::status
  std::string message;  ///< without the "tissu: " prefix; "" for none
};

RunEnd run_loaded(const RunCommand& command, const Scenario& scenario,
                  const std::filesystem::path& output_dir, StopRequest stop, RunThreads& threads,
                  RunRecord& record, bool& folder_taken) {
  RunOptions options;
  options.output_dir = output_dir;
  options.on_folder_taken = [&folder_taken] { folder_taken = true; };
  options.frames = command.frames;
  options.stop = stop;
  ProgressReporter progress = stderr_progress();
  // threads from the cloth's size (it changes with refinement and tearing) and the cores other
  // processes leave idle, at every frame, unless the scenario or OMP_NUM_THREADS chose them
  options.on_frame = [&](const FrameStats& row) {
    threads.before_frame(row.particles);
    if (!command.quiet) progress(row);
  };
  if (!command.quiet) {
    options.on_setup = [](const std::string& stage) {
      std::fprintf(stderr, "tissu: %s\n", stage.c_str());
    };
    options.on_image = [&progress](int done, int total) { progress.rendered(done, total); };
  }
  std::string unconverged_warning;  // printed after the run, so as not to break the progress bar
  options.on_warning = [&unconverged_warning](const std::string& w) { unconverged_warning = w; };
  const RunResult result = run_scenario(scenario, options);
  record.frames_done = result.frames_done;
  if (!unconverged_warning.empty()) {
    std::fprintf(stderr, "tissu: warning: %s; %d such steps in all\n", unconverged_warning.c_str(),
                 result.unconverged_steps);
  }
  if (!result.video_warning.empty()) {
    std::fprintf(stderr, "tissu: warning: %s\n", result.video_warning.c_str());
  }
  if (!result.ok) return {2, "failed", "simulation failed at " + result.failure};
  if (result.stopped) {
    const int signal_number = *stop.flag;
    // a progress bar is left mid-line on a terminal
    if (!command.quiet && isatty(STDERR_FILENO) == 1) std::fputc('\n', stderr);
    return {stopped_exit_status(signal_number), "stopped",
            stopped_message(signal_number, result, record.frames, scenario, output_dir)};
  }
  if (!command.quiet) {
    std::fprintf(stderr, "tissu: %d frames (%d images) written to %s\n", result.frames_done,
                 result.images, output_dir.c_str());
    if (scenario.output.viewer) {
      std::fprintf(stderr, "tissu: to play them in a browser: tissu view %s\n", output_dir.c_str());
    }
  }
  return {0, "completed", ""};
}

}  // namespace

int execute(const RunCommand& command) {
  // SIGINT and SIGTERM stop the run after its last whole frame (apps/stop_signals.hpp)
  const StopRequest stop = install_stop_signals();
  const auto start = std::chrono::steady_clock::now();
  RunRecord record;
  record.scenario_file = command.scenario;
  record.overrides = command.overrides;
  record.started_utc = utc_now_text();
  std::filesystem::path output_dir;
  bool folder_taken = false;  // run.json goes only into a folder this run has cleared
  RunEnd end{1, "error", ""};
  // counts the other processes' threads ready to run, then measures their use over the run
  // (lib/thread_count.hpp)
  RunThreads threads;
  try {
    const Scenario scenario = load_scenario(command.scenario, command.overrides);
    for (const std::string& note : scenario.notes)
      std::fprintf(stderr, "tissu: note: %s\n", note.c_str());
    // the process's thread count is the program's to set, not the library's: the set-up
    // (building and compiling the cloth) on the cores other processes leave idle, the frames'
    // steps on as many as the cloth's size also pays for (run_loaded)
    threads.before_setup(scenario.threads);
    record.threads = threads.most_threads();
    record.frames = command.frames.value_or(scenario.frames);
    output_dir = command.output_dir.empty() ? std::filesystem::path("out") / scenario.name
                                            : std::filesystem::path(command.output_dir);
    end = run_loaded(command, scenario, output_dir, stop, threads, record, folder_taken);
  } catch (const ScenarioError& e) {
    end.message = e.what();
  } catch (const MeshError& e) {
    end.message = e.what();
  } catch (const PinError& e) {
    end.message = e.what();
  } catch (const std::exception& e) {
    end.message = std::string("error: ") + e.what();
  }
  if (!end.message.empty()) std::fprintf(stderr, "tissu: %s\n", end.message.c_str());
  if (folder_taken) {
    record.status = end.status;
    record.exit_status = end.exit_status;
    record.message = end.message;
    record.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
      write_run_record(output_dir, record);
    } catch (const FileWriteError& e) {  // a full disk: the error above already says so
      if (end.exit_status == 0) {
        std::fprintf(stderr, "tissu: %s\n", e.what());
        return 1;
      }
    }
  }
  return end.exit_status;
}

void print_errors_on_one_line(CLI::App& app, const std::string& program) {
  app.failure_message([program](const CLI::App* failed, const CLI::Error& e) {
    const std::string help = failed->get_parent() ? program + " " + failed->get_name() : program;
    return program + ": " + printable_text(e.what(), 1000) + " (see " + help + " --help)\n";
  });
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    // app.exit prints the help, or the error through the failure message above
    return app.exit(e) == 0 ? 0 : 1;
  }
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
  if (const std::optional<int> status = parse_command_line(app, argc, argv)) return *status;
  return execute(run);
}

}  // namespace tissu
