// unfurl generate: scene files of any size (the pantograph with N panel
// pairs, the z-fold with N panels, a hanging chain of N links), written as
// scene text so they load, validate and edit like hand-written ones.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "commands.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl generate pantograph --stages N [--compliant [--no-snubbers] | --flexible] [-o FILE]\n"
    "       unfurl generate zfold --panels N [-o FILE]\n"
    "       unfurl generate chain --links N [-o FILE]\n"
    "       unfurl generate rods --rods N [-o FILE]\n"
    "       unfurl generate beam --segments N [-o FILE]\n"
    "\n"
    "Writes a scene file (to FILE, or to standard output):\n"
    "  pantograph   two chains of a frame and N panels cross-linked into a lazy-tongs,\n"
    "               N loops, 3N + 2 bodies; N = 3 is the built-in `pantograph`; its\n"
    "               springs and latches are (N/3)^2 times the reference's, so every size\n"
    "               deploys and latches in about 6-7 s; with --compliant its cross-links\n"
    "               pivot on bushings (pantograph_compliant's pins, scaled likewise)\n"
    "               between full-mass panels instead: a tree of 2N + 2 bodies, no loops,\n"
    "               each hinge on a snubber that stops it at its stowed angle (limits:)\n"
    "               so that it cannot fold back into the stack; --no-snubbers leaves\n"
    "               them out (N = 3 is then the built-in `pantograph_compliant`); with\n"
    "               --flexible its panels are pantograph_flexible's plates and its loops\n"
    "               close through their bending at compliant pivots (N = 3 is the\n"
    "               built-in `pantograph_flexible`)\n"
    "  zfold        a frame and N panels Z-folded on the bus, a tree; N = 3 is `zfold`\n"
    "  chain        N uniform links hanging under gravity, a tree for scaling runs\n"
    "  rods         two cranks joined by N parallel rods, turning freely through their\n"
    "               flat position (N - 1 redundant loop components; a closed form)\n"
    "  beam         a 10 m beam in bending as N rigid segments with bending springs\n"
    "               (EI / segment length), cantilevered to a hub that a driver spins up\n"
    "               to 6 rad/s over 15 s: Simo and Vu-Quoc's spin-up beam\n"
    "\n"
    "options:\n"
    "  --stages N, --panels N, --links N, --rods N, --segments N\n"
    "                                      the size (a whole number, at least 1)\n"
    "  -o, --output FILE                   where to write (default: standard output)\n";

int size_argument(const Args& args, const std::string& flag) {
  const auto n = args.number(flag);
  if (!n) throw UsageError("missing " + flag + " N");
  if (*n != std::floor(*n) || *n < 1 || *n > 1'000'000)
    throw UsageError(flag + " expects a whole number from 1 to 1000000, got '" + *args.get(flag) + "'");
  return static_cast<int>(*n);
}

}  // namespace

int command_generate(const std::vector<std::string>& argv) {
  const Args args(argv, {"--stages", "--panels", "--links", "--rods", "--segments", "-o", "--output"},
                  {"--help", "-h", "--compliant", "--no-snubbers", "--flexible"});
  if (args.has("--help") || args.has("-h")) {
    std::printf("%s", kHelp);
    return 0;
  }
  if (args.positionals().size() != 1) throw UsageError("expected one kind: pantograph, zfold, chain, rods or beam");
  const std::string& kind = args.positionals()[0];
  const bool compliant = args.has("--compliant");
  if (compliant && kind != "pantograph") throw UsageError("--compliant applies to pantograph only");
  const bool flexible = args.has("--flexible");
  if (flexible && kind != "pantograph") throw UsageError("--flexible applies to pantograph only");
  if (flexible && compliant) throw UsageError("--flexible and --compliant are two different arrays: give one");
  const bool snubbers = !args.has("--no-snubbers");
  if (!snubbers && !compliant) throw UsageError("--no-snubbers applies to a --compliant pantograph only");
  sim::SceneFile scene;
  std::string flag;
  if (kind == "pantograph" && flexible)
    scene = studies::generate_flexible_pantograph(size_argument(args, flag = "--stages"));
  else if (kind == "pantograph")
    scene = studies::generate_pantograph(size_argument(args, flag = "--stages"),
                                         compliant ? studies::CrossPivots::compliant : studies::CrossPivots::rigid,
                                         snubbers ? studies::Snubbers::stowed : studies::Snubbers::none);
  else if (kind == "zfold")
    scene = studies::generate_zfold(size_argument(args, flag = "--panels"));
  else if (kind == "chain")
    scene = studies::generate_chain(size_argument(args, flag = "--links"));
  else if (kind == "rods")
    scene = studies::generate_parallel_rods(size_argument(args, flag = "--rods"));
  else if (kind == "beam")
    scene = studies::generate_beam(size_argument(args, flag = "--segments"));
  else
    throw UsageError("unknown kind '" + kind + "' (pantograph, zfold, chain, rods or beam)");
  const std::string command =
      "unfurl generate " + kind + " " + flag + " " + *args.get(flag) + (compliant ? " --compliant" : "") +
      (snubbers ? "" : " --no-snubbers") + (flexible ? " --flexible" : "");
  const std::string text = sim::write_scene_text(scene, "Generated by `" + command + "`:\n" + scene.scene.description);
  const auto path = args.has("-o") ? args.get("-o") : args.get("--output");
  if (!path) {
    std::cout << text;
    return 0;
  }
  io::OutputFile file(*path);
  file.stream() << text;
  file.commit();
  return 0;
}

}  // namespace unfurl::app
