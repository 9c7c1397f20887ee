#include "apps/check_command.hpp"

#include <cstdio>

#include "lib/scenario/scenario_error.hpp"
#include "lib/simulation.hpp"
#include "topology/indexed_mesh.hpp"
#include "topology/pin_selection.hpp"

namespace tissu {

void add_check_options(CLI::App& app, CheckCommand& command) {
  app.add_option("scenario", command.scenario, "scenario JSON file (schema: docs/scenario.md)")
      ->required();
  app.add_option("-s,--set", command.overrides,
                 "override a scenario value, e.g. --set cloth.density=0.3 (repeatable)");
}

int execute(const CheckCommand& command) {
  std::string error;
  try {
    const Scenario scenario = load_scenario(command.scenario, command.overrides);
    for (const std::string& note : scenario.notes)
      std::fprintf(stderr, "tissu: note: %s\n", note.c_str());
    const ClothSummary cloth = check_scenario(scenario);
    std::printf("%s\n", scenario.resolved_json.c_str());
    std::fprintf(stderr,
                 "tissu: %s is valid: %d particles, %d faces, %d springs, %d pinned, %.6g kg; "
                 "%d frames at %g per second, %d steps each\n",
                 command.scenario.c_str(), cloth.particles, cloth.faces, cloth.springs,
                 cloth.pinned, cloth.total_mass_kg, scenario.frames, scenario.frame_rate,
                 scenario.substeps);
    return 0;
  } catch (const ScenarioError& e) {
    error = e.what();
  } catch (const MeshError& e) {
    error = e.what();
  } catch (const PinError& e) {
    error = e.what();
  } catch (const std::exception& e) {
    error = std::string("error: ") + e.what();
  }
  std::fprintf(stderr, "tissu: %s\n", error.c_str());
  return 1;
}

}  // namespace tissu
