// unfurl gui: the interactive workbench.
#include <cstdio>

#include "cli.hpp"
#include "graphics_functions.hpp"
#include "gui/gui_app.hpp"
#include "render_options.hpp"
#include "scene_options.hpp"

namespace unfurl::app {

namespace {
const char* kHelp =
    "usage: unfurl gui [SCENE] [--script FILE] [scene options]\n"
    "       unfurl gui --study STUDY.yaml --out DIR [--case ID]\n"
    "\n"
    "Opens the workbench: a 3D view (left drag orbits, right drag pans, the wheel zooms), a timeline\n"
    "(play, pause, speed, scrub, step, loop; latches marked), the parameters of the scene's springs,\n"
    "latches, loop regulator and integrator (a change re-runs the simulation at once, the previous\n"
    "run stays as a ghost in the plots), plots with values on hover, and export of the frame, of\n"
    "frames or video of a time range, and of the trajectory. The scene file is reloaded when it\n"
    "changes. Needs a display (DISPLAY; Xvfb works).\n"
    "\n"
    "With --study, it opens a study that `unfurl study STUDY.yaml --out DIR` ran: the Study\n"
    "tab shows the counts, histograms of deployment time and peak latch torque, and the table\n"
    "of cases (sortable by any column); a click on a case re-runs it here, where it plays,\n"
    "plots and takes edits like any scene.\n"
    "\n"
    "options:\n"
    "  --script FILE         run a scripted session (see app/gui/gui_script.hpp for the commands)\n"
    "  --window WxH          the window's size in pixels (default 1280x800)\n"
    "  --ui-scale X          text and widget size (default 1; times the monitor's content scale)\n"
    "  --study STUDY.yaml    a study file, with --out DIR: the directory its sweep wrote\n"
    "  --case ID             the case to show first (default: the first finished one)\n"
    "%s";
}  // namespace

int gui_command(const std::vector<std::string>& argv) {
  std::set<std::string> valued = scene_flags();
  valued.insert("--script");
  valued.insert("--study");
  valued.insert("--out");
  valued.insert("--case");
  valued.insert("--window");
  valued.insert("--ui-scale");
  const Args args(argv, valued, {"--help", "-h"});
  if (args.has("--help") || args.has("-h")) {
    std::printf(kHelp, scene_flags_help());
    return 0;
  }
  if (args.positionals().size() > 1) throw UsageError("gui takes one SCENE (see --help)");
  std::vector<ScriptCommand> script;
  if (const auto file = args.get("--script")) script = read_gui_script(*file);
  std::optional<StudyToOpen> study;
  if (const auto file = args.get("--study")) {
    if (!args.get("--out")) throw UsageError("--study needs --out DIR, the directory unfurl study wrote");
    if (!args.positionals().empty()) throw UsageError("--study shows the study's own scene: give no SCENE");
    study = StudyToOpen{*file, *args.get("--out"), args.get("--case").value_or("")};
  } else if (args.get("--out") || args.get("--case")) {
    throw UsageError("--out and --case go with --study");
  }
  const auto [width, height] = parse_pixel_size("--window", args.get("--window").value_or("1280x800"));
  const double ui_scale = args.number("--ui-scale").value_or(1.0);
  if (!(ui_scale >= 0.5 && ui_scale <= 4)) throw UsageError("--ui-scale: expected a number from 0.5 to 4");
  GuiApp app(args.positionals().empty() ? "pantograph" : args.positionals()[0], overrides_from(args), script, study,
             width, height, static_cast<float>(ui_scale));
  return app.run();
}

}  // namespace unfurl::app
