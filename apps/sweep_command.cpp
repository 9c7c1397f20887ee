#include "apps/sweep_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace tissu {

void add_sweep_options(CLI::App& app, SweepCommand& command) {
  app.add_option("sweep", command.sweep, "sweep file (JSON; docs/python.md, \"Sweeps\")")
      ->required();
  app.add_option("--scheduler", command.scheduler,
                 "run on the Dask cluster whose scheduler is at this address (tcp://host:8786)");
  app.add_option("--workers", command.workers, "local processes (default: the cores)")
      ->check(CLI::PositiveNumber);
}

int execute(const SweepCommand& command) {
#if defined(TISSU_PYTHON_EXECUTABLE) && defined(TISSU_PYTHON_DIR)
  const char* old_path = std::getenv("PYTHONPATH");
  const std::string path =
      std::string(TISSU_PYTHON_DIR) + (old_path && *old_path ? ":" + std::string(old_path) : "");
  setenv("PYTHONPATH", path.c_str(), 1);
  std::vector<std::string> args{TISSU_PYTHON_EXECUTABLE, "-m", "tissu.sweep", command.sweep};
  if (!command.scheduler.empty()) args.insert(args.end(), {"--scheduler", command.scheduler});
  if (command.workers > 0) args.insert(args.end(), {"--workers", std::to_string(command.workers)});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::cerr << "tissu: sweep: cannot start " << argv[0] << ": " << std::strerror(errno) << "\n";
#else
  std::cerr << "tissu: sweep: this tissu was built without its Python package "
               "(configure with -DTISSU_PYTHON=ON)\n";
#endif
  return 1;
}

}  // namespace tissu
