// curtain: the curtain demo, data/scenarios/curtain.json, written to out/curtain by default.

#include "apps/passive_openmp.hpp"
#include "apps/run_command.hpp"

int main(int argc, char** argv) {
  tissu::prefer_passive_openmp_waiting(argv);
  return tissu::run_demo(argc, argv, "curtain: a curtain hanging from rings, stirred by gusty wind",
                         TISSU_DATA_DIR "/scenarios/curtain.json", "out/curtain");
}
