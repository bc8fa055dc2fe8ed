// unfurl export mjcf: a scene as a MuJoCo model.
#include <cstdio>
#include <iostream>

#include "cli.hpp"
#include "commands.hpp"
#include "unfurl/io/mjcf_export.hpp"
#include "unfurl/io/output_file.hpp"
#include "scene_options.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl export mjcf [SCENE] [-o FILE.xml] [--set KEY=VALUE ...]\n"
    "\n"
    "Writes SCENE as a MuJoCo model (MJCF) to FILE.xml or standard output: bodies with mass\n"
    "and full inertia at the initial state (joint ref = q0, so MuJoCo's qpos is unfurl's q),\n"
    "hinge and slide joints with stiffness, springref, damping and frictionloss (Coulomb\n"
    "friction; MuJoCo's sticks where unfurl's smoothed law creeps), gravity, the initial state\n"
    "as keyframe 'initial', and each closed loop merged back into one body and closed by an\n"
    "equality/connect at its pivot. What MJCF cannot say (latches, body loads, a moving base)\n"
    "is written as a comment and listed on standard error; latches are also kept as custom\n"
    "numeric data latch:JOINT = position, stiffness, damping, side.\n"
    "\n"
    "options:\n"
    "  -o, --output FILE     where to write (default: standard output)\n"
    "  --set KEY=VALUE       override a value of the scene first (repeatable)\n";

}  // namespace

int command_export(const std::vector<std::string>& argv) {
  const Args args(argv, {"-o", "--output", "--set"}, {"--help", "-h"});
  if (args.has("--help") || args.has("-h")) {
    std::printf("%s", kHelp);
    return 0;
  }
  const auto& positionals = args.positionals();
  if (positionals.empty() || positionals[0] != "mjcf") throw UsageError("expected a format: mjcf");
  if (positionals.size() > 2) throw UsageError("export mjcf takes one SCENE (see --help)");
  const sim::Scene scene = load_scene(positionals.size() == 2 ? std::optional(positionals[1]) : std::nullopt, args);
  const io::MjcfModel model = io::export_mjcf(scene);
  for (const std::string& what : model.not_exported)
    std::fprintf(stderr, "unfurl export: not in the MJCF model: %s\n", what.c_str());
  for (const std::string& what : model.warnings) std::fprintf(stderr, "unfurl export: warning: %s\n", what.c_str());
  const auto path = args.has("-o") ? args.get("-o") : args.get("--output");
  if (!path) {
    std::cout << model.xml;
    return 0;
  }
  io::OutputFile file(*path);
  file.stream() << model.xml;
  file.commit();
  return 0;
}

}  // namespace unfurl::app
