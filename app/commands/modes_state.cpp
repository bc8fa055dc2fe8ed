#include "modes_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "interrupt.hpp"

namespace unfurl::app {

namespace {

// NAME=VALUE,... over the scene's initial positions.
std::vector<double> given_positions(const sim::Scene& scene, const std::string& text) {
  std::vector<double> q = scene.q0;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) throw UsageError("--q expects NAME=VALUE,..., got '" + item + "'");
    const std::string name = item.substr(0, eq);
    const std::optional<int> j = scene.model.find_joint(name);
    if (!j || !scene.model.joints[*j].is_scalar())
      throw UsageError("--q: no one-coordinate joint '" + name + "' in the scene");
    std::size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item.substr(eq + 1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() - eq - 1 || !std::isfinite(value))
      throw UsageError("--q: '" + item.substr(eq + 1) + "' is not a number (" + name + ")");
    q[scene.model.position_of(*j).value] = value;
  }
  return q;
}

}  // namespace

const std::set<std::string>& modes_state_flags() {
  static const std::set<std::string> flags{"--at", "--q"};
  return flags;
}

const std::set<std::string>& modes_state_switches() {
  static const std::set<std::string> switches{"--settle", "--no-settle"};
  return switches;
}

const char* modes_state_help() {
  return "  --at T                the state of a run of the scene at time T (s), with the latches\n"
         "                        engaged by then; linearized there as it is unless --settle\n"
         "  --q NAME=VALUE,...    positions of one-coordinate joints (the rest as the scene starts),\n"
         "                        latches engaged where their joints are at or past their positions;\n"
         "                        linearized there as it is unless --settle\n"
         "  --settle              solve for the static equilibrium near the state first\n"
         "  --no-settle           linearize at the state as it is\n";
}

int scene_modes(const sim::Scene& scene, const Args& args, sim::ModesResult& modes, std::string& described) {
  if (args.has("--at") && args.has("--q")) throw UsageError("give --at or --q, not both");
  if (args.has("--settle") && args.has("--no-settle")) throw UsageError("give --settle or --no-settle, not both");
  const std::optional<double> at = args.number("--at");
  if (at && !(*at >= 0)) throw UsageError("--at expects a time >= 0");
  sim::LinearizationState state;
  if (const auto q = args.get("--q")) {
    state = sim::given_state(scene, given_positions(scene, *q));
    described = "the given positions";
  } else {
    sim::RunSettings run = scene.run;
    if (at) run.t_end = std::max(*at, run.sample);
    const InterruptScope interrupt;
    sim::RunObserver observer;
    observer.cancel = &interrupt.flag();
    const sim::RunResult result = sim::simulate(scene, run, observer);
    if (result.status == sim::RunStatus::cancelled) return interrupt.exit_status();
    if (result.status == sim::RunStatus::failed) {
      std::fprintf(stderr, "unfurl: the run to the state failed: %s\n", sim::describe(result.failure).c_str());
      return 1;
    }
    state = sim::state_of_run(scene, result.trajectory, at.value_or(run.t_end));
    char text[96];
    std::snprintf(text, sizeof text, "the run's state at t = %g s", state.t);
    described = text;
  }
  sim::ModesSettings settings;
  settings.settle = args.has("--settle") || (!args.has("--no-settle") && !at && !args.has("--q"));
  if (settings.settle) described += ", settled to its static equilibrium";
  try {
    modes = sim::linear_modes(scene, state.q, state.engaged, settings);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "unfurl: the modes: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace unfurl::app
