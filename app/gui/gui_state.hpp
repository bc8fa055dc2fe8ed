// What the GUI holds between frames (the UI thread's own state) and what
// its panels ask for. Panels are functions of the state that draw with
// Dear ImGui; they change UI-only state (play-head, camera) directly and
// return requests for everything that involves the solver or files, which
// the application applies between frames.
#pragma once

#include <chrono>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "unfurl/render/camera.hpp"
#include "unfurl/render/camera_frame.hpp"
#include "file_dialog.hpp"
#include "render_options.hpp"
#include "run_comparison.hpp"
#include "unfurl/sim/modes.hpp"
#include "unfurl/sim/scene.hpp"
#include "unfurl/sim/scene_file.hpp"
#include "simulation_worker.hpp"
#include "study_browser.hpp"
#include "unfurl/sim/trajectory.hpp"

namespace unfurl::app {

struct ExportRequest {
  std::string dir = "out/gui_export";
  RenderOptions options;
  bool frames = true;
};

struct Requests {
  std::optional<sim::Override> edit;    // a parameter: restart the run with it
  bool reset_edits = false;             // back to the scene file's values
  bool undo = false, redo = false;      // of the parameter edits
  std::optional<std::string> save_scene;  // the edited scene as YAML
  bool overwrite = false;               // save_scene may replace an existing file
  std::optional<std::string> open;      // another scene (path or built-in name)
  std::optional<std::string> open_case; // a case of the open study, by id
  std::optional<std::string> pin;       // keep the current (finished) run under this name
  std::optional<std::size_t> unpin;     // drop pinned run k
  bool reload = false;
  std::optional<std::string> save_frame;       // PNG of the current view
  std::optional<std::string> save_trajectory;  // CSV of the current run
  std::optional<ExportRequest> export_range;   // frames / video of a time range
  bool cancel_export = false;
  bool compute_modes = false;          // of the current run's end
  std::optional<int> show_mode;        // animate mode k in the view; -1: the run again
};

struct ExportProgress {
  bool active = false;
  std::size_t done = 0, total = 0;
  std::string message;  // the last result or error
};

// The text fields and settings of the export panel.
struct ExportForm {
  char frame_path[256] = "out/gui_frame.png";
  char csv_path[256] = "out/gui_trajectory.csv";
  char dir[256] = "out/gui_export";
  char video[256] = "out/gui_export/deployment.mp4";
  float from = 0, to = 0, fps = 30;
  int size[2] = {1280, 720};
  bool with_video = true, frames = true;
};

// The Modes tab: the modes of the current run's deployed end (settled to
// its static equilibrium), one of them animated in the view in place of
// the run.
struct ModesView {
  std::optional<sim::ModesResult> result;
  long generation = -1;      // the run they are of
  std::string error;         // why they could not be computed
  int shown = -1;            // the mode animated, or -1: the run
  float amplitude = 0.1f;    // its largest coordinate, rad
  double clock = 0;          // the animation's time, s
  static constexpr double kPeriod = 2;  // s per drawn cycle
  sim::Trajectory animation;
  bool select_tab = false;   // bring the Modes tab to the front once
  bool current(long generation_now) const { return result && generation == generation_now; }
};

// Which field a file dialog's choice goes to.
enum class FileField { none, open_scene, save_scene, frame, trajectory, export_dir, video };

struct GuiState {
  char scene_path[512] = "";  // the toolbar's field
  // The scene: its source, the edits made in the GUI, the loaded result.
  std::string scene_name;                 // as given: a path or a built-in name
  std::vector<sim::Override> command_line_set;         // --set from the command line
  std::vector<sim::Override> edits;                    // from the parameters panel
  std::vector<std::vector<sim::Override>> undo, redo;  // earlier and undone sets of edits
  char save_path[256] = "";                // the Save scene field
  std::string confirm_overwrite;           // a file the user is asked about
  bool ask_overwrite = false;              // open the question (once)
  bool focus_scene_field = false;          // Ctrl+O: type a scene
  sim::Scene scene;
  sim::SceneVisuals visuals;
  std::string scene_error;                 // why the last load failed
  std::optional<std::filesystem::file_time_type> scene_mtime;
  // A finished study, when one is open; its case on show (study->shown)
  // replaces the scene file as what the edits apply to.
  std::optional<StudyBrowser> study;
  bool select_study_tab = false;  // bring the Study tab to the front once
  // What the shown case's failure put into the scene (study_browser.hpp):
  // read-only in the panel; and the failure, described.
  std::vector<std::string> failure_elements;
  std::string failure_text;
  // The joint whose latch the case's failure took out: its run counts it as
  // never latched (not deployed), as the study does.
  std::vector<std::string> failed_latches;

  // The runs: the current one as far as computed, and the previous one.
  long generation = -1;
  long requested_generation = 0;
  // The first run of the scene on show: runs before it belong to another
  // scene (other bodies, other coordinates) and are neither drawn nor kept
  // as the ghost.
  long scene_first_generation = 0;
  sim::Trajectory trajectory;
  sim::Trajectory ghost;
  RunProgress progress;
  // Runs kept for comparison, drawn with the current one and tabled
  // against it (the Runs tab); they stay while the scene keeps its shape.
  std::vector<PinnedRun> pinned;
  char pin_name[64] = "";
  std::string pin_name_offered;  // the name the field last offered
  bool select_runs_tab = false;

  // Playback.
  double play_time = 0;
  bool playing = false;
  float speed = 1;
  bool loop = true;

  // View.
  render::Camera camera;
  render::CameraFrame camera_frame = render::CameraFrame::bus;  // a free-floating bus's
  // Loads drawn as arrows on the 3D view (load_arrows.hpp), each kind's
  // largest `load_scale` times the default length; the legend of those drawn.
  bool show_loads = false;
  float load_scale = 1;
  std::string load_legend;
  // Flexible bodies' elastic displacements drawn this many times.
  float exaggeration = 1;
  int load_arrows_drawn = 0;  // in the view as last drawn
  std::string camera_name = "iso";  // the preset the view shows; "" once orbited
  bool camera_fitted = false;
  int viewport_width = 0, viewport_height = 0;
  int plots_width = 0, plots_height = 0;
  int plot_tab = 0;  // one of the scene's plots, or the last tab: all of them
  std::vector<int> plot_coordinates;  // the joints the plots draw; empty: the first 12
  std::optional<std::pair<double, double>> time_zoom;  // the plots' time span; none: the whole run
  long plots_version = 0;  // changes with what the plots show beyond the runs' data

  // The UI's scale, on top of the monitor's content scale: fonts, widgets
  // and plots (the toolbar's field edits ui_scale_field, applied on release).
  float ui_scale = 1, ui_scale_field = 1;
  float applied_scale = 0;  // font size / 17 of the atlas in use

  // Frames drawn; what the last scripted idle cost (CPU seconds per second
  // over all threads, and frames; -1 before one).
  long frames = 0;
  double idle_cpu_fraction = -1;
  long idle_frames = -1;

  // Frame rate: recent frame durations, and the worst while a run computes.
  std::deque<double> frame_seconds;
  double fps = 0;
  long frames_while_running = 0;
  double seconds_while_running = 0, worst_frame_while_running = 0;

  // The last edit, and when the plots first showed its whole run: the
  // edit-to-new-curves latency (steady-clock seconds; 0 before).
  double edited_at = 0, curves_at = 0;

  FileDialog file_dialog;
  FileField file_field = FileField::none;

  ExportForm export_form;
  ExportProgress export_progress;
  ModesView modes;

  // The last requested run has run to its end (finished or failed): it is
  // neither computing nor waiting for the simulation thread to take it.
  bool run_settled() const { return !progress.running && generation >= requested_generation; }
  // ... or has all its samples, its summary still to come.
  bool run_integrated() const {
    return (!progress.running || progress.integrated) && generation >= requested_generation;
  }
  // ... and has a result to keep: what "Pin this run" needs.
  bool run_pinnable() const { return run_settled() && progress.summary && !trajectory.empty(); }
  std::string notice;  // the last file saved, or error
};

}  // namespace unfurl::app
