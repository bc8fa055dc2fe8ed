// unfurl generate: scene files of any size (the pantograph with N panel
// pairs, the z-fold with N panels, a hanging chain of N links), written as
// scene text so they load, validate and edit like hand-written ones.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "commands.hpp"
#include "output_file.hpp"
#include "unfurl/studies/scene_generators.hpp"

namespace unfurl::app {

namespace {

const char* kHelp =
    "usage: unfurl generate pantograph --stages N [-o FILE]\n"
    "       unfurl generate zfold --panels N [-o FILE]\n"
    "       unfurl generate chain --links N [-o FILE]\n"
    "\n"
    "Writes a scene file (to FILE, or to standard output):\n"
    "  pantograph   two chains of a frame and N panels cross-linked into a lazy-tongs,\n"
    "               N loops, 3N + 2 bodies; N = 3 is the built-in `pantograph`\n"
    "  zfold        a frame and N panels Z-folded on the bus, a tree; N = 3 is `zfold`\n"
    "  chain        N uniform links hanging under gravity, a tree for scaling runs\n"
    "\n"
    "options:\n"
    "  --stages N, --panels N, --links N   the size (a whole number, at least 1)\n"
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
  const Args args(argv, {"--stages", "--panels", "--links", "-o", "--output"}, {"--help", "-h"});
  if (args.has("--help") || args.has("-h")) {
    std::printf("%s", kHelp);
    return 0;
  }
  if (args.positionals().size() != 1) throw UsageError("expected one kind: pantograph, zfold or chain");
  const std::string& kind = args.positionals()[0];
  std::string text;
  if (kind == "pantograph")
    text = generate_pantograph(size_argument(args, "--stages"));
  else if (kind == "zfold")
    text = generate_zfold(size_argument(args, "--panels"));
  else if (kind == "chain")
    text = generate_chain(size_argument(args, "--links"));
  else
    throw UsageError("unknown kind '" + kind + "' (pantograph, zfold or chain)");
  const auto path = args.has("-o") ? args.get("-o") : args.get("--output");
  if (!path) {
    std::cout << text;
    return 0;
  }
  OutputFile file(*path);
  file.stream() << text;
  file.commit();
  return 0;
}

}  // namespace unfurl::app
