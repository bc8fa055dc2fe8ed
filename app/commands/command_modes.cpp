// unfurl modes: natural frequencies, damping ratios and mode shapes of a
// scene linearized about its deployed, latched state (or a run's state at a
// time, or given positions).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli.hpp"
#include "commands.hpp"
#include "interrupt.hpp"
#include "scene_options.hpp"
#include "unfurl/io/modes_files.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/sim/modes.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl modes [SCENE] [--out DIR] [--at T | --q NAME=VALUE,...] [--settle | --no-settle]\n"
    "                    [scene options]\n"
    "\n"
    "Linearizes SCENE about a state and writes its natural frequencies, damping ratios and mode\n"
    "shapes into DIR (default modes/): modes.csv (a row per mode, its shape per coordinate) and\n"
    "modes.json (the state, the modes). By default the state is where a run of the scene ends\n"
    "(the deployed, latched array), settled to its static equilibrium. Loops are respected: the\n"
    "modes are those of the independent coordinates, the loops closed by the rigid model's\n"
    "forces. A free-floating bus gives six rigid-body modes; a rigid mechanism at a branch point\n"
    "gives mechanism modes (no stiffness to first order: compliance determines them).\n"
    "\n"
    "options:\n"
    "  --out DIR             where modes.csv and modes.json go (default modes)\n"
    "  --at T                the state of a run of the scene at time T (s), with the latches\n"
    "                        engaged by then; linearized there as it is unless --settle\n"
    "  --q NAME=VALUE,...    positions of one-coordinate joints (the rest as the scene starts),\n"
    "                        latches engaged where their joints are at or past their positions;\n"
    "                        linearized there as it is unless --settle\n"
    "  --settle              solve for the static equilibrium near the state first\n"
    "  --no-settle           linearize at the state as it is\n"
    "%s"
    "  --quiet               print nothing but errors\n"
    "\n"
    "Exit status: 0 done, 1 the run or the linearization failed, 2 bad scene, 64 bad usage.\n";

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

// The shape's three largest entries, in the coordinates' sizes.
std::string shape_summary(const sim::Model& model, const sim::Mode& mode, double length) {
  std::vector<int> order(model.nv);
  for (int c = 0; c < model.nv; ++c) order[c] = c;
  const auto scaled = [&](int c) {
    return std::abs(mode.shape[c]) / (model.velocity_unit(c) == "m/s" ? length : 1.0);
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return scaled(a) > scaled(b); });
  std::string out;
  char buf[96];
  for (int k = 0; k < std::min(3, model.nv); ++k) {
    if (scaled(order[k]) < 0.05) break;
    std::snprintf(buf, sizeof buf, "%s%s %+.2f", out.empty() ? "" : ", ", model.velocity_name(order[k]).c_str(),
                  mode.shape[order[k]]);
    out += buf;
  }
  return out;
}

void print_modes(const sim::Scene& scene, const sim::ModesResult& r, const std::string& state,
                 const std::string& dir) {
  std::printf("scene        %s (%s)\n", scene.name.c_str(), scene.source.c_str());
  std::printf("state        %s; %d coordinates", state.c_str(), r.coordinates);
  if (!scene.loops.empty()) std::printf(", %d independent (loops of rank %d)", r.coordinates - r.loop_rank, r.loop_rank);
  std::printf("\n             %.2g rad from its static equilibrium", r.equilibrium_offset);
  if (r.stiffness_asymmetry > 1e-6) std::printf("; stiffness asymmetric by %.2g (non-conservative forces)", r.stiffness_asymmetry);
  std::printf("\n\n  mode  kind        frequency, Hz  damping ratio  shape (largest coordinates)\n");
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const sim::Mode& m = r.modes[k];
    std::printf("  %4zu  %-10s  %13.6g  %13.4g  %s\n", k + 1, sim::mode_kind_name(m.kind), m.frequency_hz,
                m.damping_ratio, shape_summary(scene.model, m, r.length).c_str());
  }
  const long mechanism = std::count_if(r.modes.begin(), r.modes.end(),
                                       [](const sim::Mode& m) { return m.kind == sim::ModeKind::mechanism; });
  if (r.weak_loop_directions > 0)
    std::printf("\nwarning      the loops are near a branch point: %d of their constraints hold only weakly\n"
                "             here (as where the loads are indeterminate); the rigid model's modes depend on\n"
                "             how near, and the real array's on its pins' and hinges' compliance (bushings,\n"
                "             see pantograph_compliant)\n",
                r.weak_loop_directions);
  if (mechanism > 0 && !scene.loops.empty())
    std::printf("\nwarning      %ld mechanism mode(s): the rigid loops leave motion without first-order stiffness\n"
                "             here (a branch point); the frequencies of the real array there depend on its pins'\n"
                "             and hinges' compliance (bushings, see pantograph_compliant)\n",
                mechanism);
  std::printf("\nfiles        %s/modes.csv, %s/modes.json\n", dir.c_str(), dir.c_str());
}

}  // namespace

int command_modes(const std::vector<std::string>& argv) {
  std::set<std::string> valued = scene_flags();
  valued.insert({"--out", "--at", "--q"});
  const Args args(argv, valued, {"--help", "-h", "--quiet", "--settle", "--no-settle"});
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp, scene_flags_help());
    return 0;
  }
  if (args.positionals().size() > 1) throw UsageError("modes takes one SCENE (see --help)");
  if (args.has("--at") && args.has("--q")) throw UsageError("give --at or --q, not both");
  if (args.has("--settle") && args.has("--no-settle")) throw UsageError("give --settle or --no-settle, not both");
  const std::optional<std::string> scene_arg =
      args.positionals().empty() ? std::nullopt : std::optional(args.positionals()[0]);
  const sim::Scene scene = load_scene(scene_arg, args);
  const std::string dir = args.get("--out").value_or("modes");
  const std::optional<double> at = args.number("--at");
  if (at && !(*at >= 0)) throw UsageError("--at expects a time >= 0");

  sim::LinearizationState state;
  std::string described;
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
      std::fprintf(stderr, "unfurl modes: the run to the state failed: %s\n", sim::describe(result.failure).c_str());
      return 1;
    }
    state = sim::state_of_run(scene, result, at.value_or(run.t_end));
    char text[96];
    std::snprintf(text, sizeof text, "the run's state at t = %g s", state.t);
    described = text;
  }
  sim::ModesSettings settings;
  settings.settle = args.has("--settle") || (!args.has("--no-settle") && !at && !args.has("--q"));
  if (settings.settle) described += ", settled to its static equilibrium";
  sim::ModesResult modes;
  try {
    modes = sim::linear_modes(scene, state.q, state.engaged, settings);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "unfurl modes: %s\n", e.what());
    return 1;
  }
  io::make_directory(dir);
  io::write_modes_csv(scene, modes, dir + "/modes.csv");
  io::write_modes_json(scene, modes, described, dir + "/modes.json");
  if (!args.has("--quiet")) print_modes(scene, modes, described, dir);
  return 0;
}

}  // namespace unfurl::app
