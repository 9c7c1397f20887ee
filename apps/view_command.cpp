#include "apps/view_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tissu {

void add_view_options(CLI::App& app, ViewCommand& command) {
  app.add_option("folder", command.run_folder, "a run's output folder (tissu run --out)")
      ->required();
}

int execute(const ViewCommand& command) {
  namespace fs = std::filesystem;
  const fs::path viewer = fs::path(command.run_folder) / "viewer";
  std::error_code error;
  if (!fs::is_regular_file(viewer / "index.html", error) ||
      !fs::is_regular_file(viewer / "frames.js", error)) {
    std::fprintf(stderr,
                 "tissu: %s: no viewer in this folder (viewer/index.html and frames.js): a run "
                 "writes it unless output.viewer is false\n",
                 command.run_folder.c_str());
    return 1;
  }
  std::ifstream frames(viewer / "frames.js");
  int count = 0;
  for (std::string line; std::getline(frames, line);) count += line.rfind("tissu.frame(", 0) == 0;
  std::printf("file://%s\n", fs::absolute(viewer / "index.html").lexically_normal().c_str());
  std::fprintf(stderr, "tissu: open this address in a browser; the viewer plays %d frames\n",
               count);
  return 0;
}

}  // namespace tissu
