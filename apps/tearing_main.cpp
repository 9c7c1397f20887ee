// tearing: the tearing demo, data/scenarios/tearing.json (a notched sheet pulled apart), written to
// out/tearing by default; --scenario data/scenarios/tearing_ball.json drives a ball through a
// sheet.

#include "apps/openmp_waiting.hpp"
#include "apps/run_command.hpp"

int main(int argc, char** argv) {
  tissu::prefer_short_openmp_spin(argv);
  return tissu::run_demo(
      argc, argv, "tearing: a notched sheet pulled apart by two clamps until it tears in two",
      TISSU_DATA_DIR "/scenarios/tearing.json", "out/tearing");
}
