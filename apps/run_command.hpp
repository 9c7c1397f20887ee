#pragma once
// Options shared by the tissu CLI's run command and the demo programs.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tissu {

struct RunCommand {
  std::string scenario;
  std::string output_dir;
  std::optional<int> frames;
  std::vector<std::string> overrides;
  bool quiet = false;
};

/// --out, --frames, --set, --quiet.
void add_run_options(CLI::App& app, RunCommand& command);

/// Loads and runs the scenario; prints errors as one line on stderr. Returns the exit status:
/// 0 on success, 1 for bad input or a file that cannot be written (a full disk), 2 when the
/// simulation failed, 130 or 143 when SIGINT or SIGTERM stopped it (after its last whole frame).
int execute(const RunCommand& command);

/// Makes CLI11 print a command-line error as one line, "PROGRAM: what is wrong (see PROGRAM
/// [SUBCOMMAND] --help)", instead of its two. Call before adding subcommands: they copy it.
void print_errors_on_one_line(CLI::App& app, const std::string& program);

/// Parses the command line into `app`'s options: nullopt to go on, else the exit status to return
/// at once: 0 after printing --help, 1 after printing a command-line error (bad input, as a bad
/// scenario is), whatever CLI11's own code for it.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

/// A demo program's main: --scenario (defaulting to `scenario`) plus the run options, output to
/// `output_dir` unless --out says otherwise; returns execute()'s exit status.
int run_demo(int argc, char** argv, const std::string& description, const std::string& scenario,
             const std::string& output_dir);

}  // namespace tissu
