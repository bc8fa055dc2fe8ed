// Loads the built-in pantograph, simulates its first 8 seconds and prints
// how many latches engaged: unfurl used as a library.
#include <cstdio>

#include "unfurl/sim/scene_file.hpp"
#include "unfurl/sim/simulation.hpp"

int main() {
  const unfurl::sim::Scene scene = unfurl::sim::load_builtin_scene("pantograph", {{"run.t_end", "8"}});
  const unfurl::sim::RunResult run = unfurl::sim::simulate(scene, scene.run);
  std::printf("status: %s\nlatches engaged: %zu\n", unfurl::sim::run_status_name(run.status),
              run.trajectory.events.size());
  return run.status == unfurl::sim::RunStatus::finished ? 0 : 1;
}
