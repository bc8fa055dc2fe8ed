// A scripted GUI session, for tests and demos: one command per line, run
// between frames while the window keeps drawing.
//
//   wait SECONDS          let the UI run (wall-clock seconds)
//   idle SECONDS          leave it idle; its CPU use and frames go in the report
//   wait_run              until the current run has finished
//   play | pause          playback
//   speed X | loop on|off
//   scrub T               move the play-head to T seconds
//   camera NAME           a camera preset
//   orthographic on|off   parallel projection
//   loads on|off [SCALE]  the load arrows on the 3D view (and their length)
//   exaggerate X          flexible bodies drawn bending X times (the view's slider)
//   ui_scale X            the UI scale (as the toolbar's field sets it)
//   browse open|save_scene|frame|trajectory|export_dir|video
//                         show the file dialog of that field (as its button does)
//   set PATH VALUE        change a scene value as the parameters panel does
//                         (for example set springs.0.free_position 1.2)
//   screenshot FILE.png   the whole window, read back from its framebuffer
//   save_frame FILE.png   the 3D view, as the export panel saves it
//   export DIR FROM TO FPS [VIDEO.mp4]   frames (and video) of a range
//   wait_export           until the export has finished
//   cancel_export         stop the export (as its Cancel button does)
//   report FILE.json      the state: runs and their latch times, frame rate
//   open SCENE            another scene (a path or a built-in name)
//   case ID               a case of the study opened with --study
//   undo | redo           the last parameter edit (Ctrl+Z, Ctrl+Y)
//   save_scene FILE.yaml  the edited scene (replacing FILE)
//   plot NAME             the plot tab whose name starts with NAME, or all
//   pin [NAME...]         pin the finished current run (named by the words,
//                         or as the Runs tab offers)
//   unpin K|all           drop pinned run K (from 0) or all of them
//   zoom T0 T1 | zoom all the plots' time span, as the mouse wheel sets it
//   curves JOINT... | curves first12    the joints the plots draw
//   modes                 compute the finished run's modes (the Modes tab's button)
//   mode K                animate mode K (1, 2, ...) in the view; 0: the run again
//   quit
//
// Blank lines and lines starting with # are skipped.
#pragma once

#include <string>
#include <vector>

namespace unfurl::app {

struct ScriptCommand {
  int line = 0;
  std::string name;
  std::vector<std::string> args;
};

// Throws std::runtime_error naming the line of an unknown command or a
// wrong number of arguments.
std::vector<ScriptCommand> read_gui_script(const std::string& path);

}  // namespace unfurl::app
