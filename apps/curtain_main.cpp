// curtain: the curtain demo, data/scenarios/curtain.json, written to out/curtain by default.

#include "apps/openmp_waiting.hpp"
#include "apps/run_command.hpp"

int main(int argc, char** argv) {
  tissu::prefer_short_openmp_spin(argv);
  return tissu::run_demo(argc, argv, "curtain: a curtain hanging from rings, stirred by gusty wind",
                         TISSU_DATA_DIR "/scenarios/curtain.json", "out/curtain");
}
