// unfurl modes: natural frequencies, damping ratios and mode shapes of a
// scene linearized about its deployed, latched state (or a run's state at a
// time, or given positions).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "cli.hpp"
#include "commands.hpp"
#include "modes_state.hpp"
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
    "%s"
    "%s"
    "  --quiet               print nothing but errors\n"
    "\n"
    "Exit status: 0 done, 1 the run or the linearization failed, 2 bad scene, 64 bad usage.\n";

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
  valued.insert("--out");
  valued.insert(modes_state_flags().begin(), modes_state_flags().end());
  std::set<std::string> switches{"--help", "-h", "--quiet"};
  switches.insert(modes_state_switches().begin(), modes_state_switches().end());
  const Args args(argv, valued, switches);
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp, modes_state_help(), scene_flags_help());
    return 0;
  }
  if (args.positionals().size() > 1) throw UsageError("modes takes one SCENE (see --help)");
  const std::optional<std::string> scene_arg =
      args.positionals().empty() ? std::nullopt : std::optional(args.positionals()[0]);
  const sim::Scene scene = load_scene(scene_arg, args);
  const std::string dir = args.get("--out").value_or("modes");

  std::string described;
  sim::ModesResult modes;
  if (const int code = scene_modes(scene, args, modes, described)) return code;
  io::make_directory(dir);
  io::write_modes_csv(scene, modes, dir + "/modes.csv");
  io::write_modes_json(scene, modes, described, dir + "/modes.json");
  if (!args.has("--quiet")) print_modes(scene, modes, described, dir);
  return 0;
}

}  // namespace unfurl::app
