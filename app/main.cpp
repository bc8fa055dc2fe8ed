// unfurl: deployment simulator for spacecraft solar arrays and other jointed
// mechanisms. `unfurl COMMAND --help` documents each command.
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.hpp"
#include "commands.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/sim/scene_file.hpp"

namespace {

const char* kUsage =
    "usage: unfurl COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  simulate [SCENE]   run a scene, write trajectory.csv, events.csv, summary.json\n"
    "  render [SCENE]     draw frames, video and plots of a run, headless\n"
    "  gui [SCENE]        the interactive workbench (needs a display)\n"
    "  modes [SCENE]      natural frequencies, damping and mode shapes about the deployed state\n"
    "  study STUDY.yaml   run an off-nominal or Monte Carlo study (locally or under mpirun)\n"
    "  report [SCENE]     error against run time per integrator (work-precision)\n"
    "  export mjcf [SCENE]  write the scene as a MuJoCo model\n"
    "  generate KIND      write a scene of any size (pantograph, zfold, chain)\n"
    "  scenes             list the built-in scenes\n"
    "\n"
    "SCENE is a scene file (.yaml) or a built-in scene name (default: pantograph).\n"
    "`unfurl COMMAND --help` shows a command's options.\n";

int list_scenes() {
  for (const std::string& name : unfurl::sim::builtin_scene_names()) std::printf("%s\n", name.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Writes to a pipe whose reader died (ffmpeg) fail with EPIPE and become
  // an error message instead of ending the process without one.
  std::signal(SIGPIPE, SIG_IGN);
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::printf("%s", kUsage);
    return args.empty() ? 64 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "simulate") return unfurl::app::command_simulate(args);
    if (command == "render") return unfurl::app::command_render(args);
    if (command == "gui") return unfurl::app::command_gui(args);
    if (command == "report") return unfurl::app::command_report(args);
    if (command == "study") return unfurl::app::command_study(args);
    if (command == "modes") return unfurl::app::command_modes(args);
    if (command == "sweep") {  // the command's name until 0.3
      std::fprintf(stderr, "unfurl: `sweep` is now `unfurl study` (running it as that)\n");
      return unfurl::app::command_study(args);
    }
    if (command == "export") return unfurl::app::command_export(args);
    if (command == "generate") return unfurl::app::command_generate(args);
    if (command == "scenes") return list_scenes();
    std::fprintf(stderr, "unfurl: unknown command '%s'\n\n%s", command.c_str(), kUsage);
    return 64;
  } catch (const unfurl::input::InputError& e) {
    std::fprintf(stderr, "unfurl %s: %s\n", command.c_str(), e.what());
    return 2;
  } catch (const unfurl::app::UsageError& e) {
    std::fprintf(stderr, "unfurl %s: %s\n", command.c_str(), e.what());
    return 64;
  } catch (const unfurl::io::OutputError& e) {
    std::fprintf(stderr, "unfurl %s: %s\n", command.c_str(), e.what());
    return 73;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unfurl %s: %s\n", command.c_str(), e.what());
    return 1;
  }
}
