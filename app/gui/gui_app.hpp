// The interactive workbench: a GLFW window with Dear ImGui, drawing with
// render/. The simulation thread (SimulationWorker) owns the solver; this
// UI thread draws, copies new samples once per frame, and turns panel
// requests into new runs.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "export_job.hpp"
#include "unfurl/render/framebuffer.hpp"
#include "glfw_window.hpp"
#include "script_runner.hpp"
#include "gui_state.hpp"
#include "unfurl/render/imgui_layer.hpp"
#include "unfurl/render/plot.hpp"
#include "unfurl/render/mesh_library.hpp"
#include "unfurl/render/scene_view.hpp"
#include "simulation_worker.hpp"

namespace unfurl::app {

// A finished study to open with the workbench, and the case to show first.
struct StudyToOpen {
  std::string study_path, dir, case_id;
};

class GuiApp : private ScriptTarget {
 public:
  GuiApp(const std::string& scene_name, std::vector<sim::Override> command_line_set, std::vector<ScriptCommand> script,
         std::optional<StudyToOpen> study = std::nullopt, int width = 1280, int height = 800, float ui_scale = 1);
  ~GuiApp();
  GuiApp(const GuiApp&) = delete;
  GuiApp& operator=(const GuiApp&) = delete;

  // Runs until the window closes (or the script quits); returns the exit code.
  int run();

 private:
  void frame();
  // Whether anything changes without input: playback, a run, an export, a
  // script, a text field being edited.
  bool busy() const;
  // Busy with nothing but a run computing: no playback, export, editing or
  // settling frames, a script at most waiting for the run.
  bool only_the_run_moves() const;
  void wait_for_events();
  void sync_run();
  // Fonts and sizes for the UI scale times the monitor's content scale.
  void apply_ui_scale();
  void advance_playback(double dt);
  // The Modes tab (gui_app_modes.cpp): the modes of the current run's end,
  // and mode k animated in the view (-1: the run again).
  void compute_modes();
  void show_mode(int k);
  void watch_scene_file();
  void draw_viewport_texture();
  void draw_plots_texture();
  void layout_and_panels(Requests& requests);
  void apply(const Requests& requests);
  void record_frame_time(double seconds);

  // ScriptTarget.
  GuiState& state() override { return state_; }
  void request(const Requests& requests) override { apply(requests); }
  bool exporting() const override { return export_job_ != nullptr; }
  void camera_preset(const std::string& name) override;
  void screenshot(const std::string& path) override;
  void save_frame(const std::string& path) override { save_view_png(path); }
  void quit() override { quit_ = true; }

  // Loads the scene with the command-line and panel edits; on success swaps
  // it in (and its meshes) and starts a run. Errors go to state_.scene_error.
  bool load_and_run(const std::string& name);
  // Shows case `id` of the open study (with the current edits); false and
  // state_.scene_error when it does not load.
  bool show_case(const std::string& id);
  void start_run();
  // After a change of scene: drops the pinned runs it cannot be compared
  // with (and the joint choice and zoom with them).
  void keep_comparable_pins(const SceneShape& previous);
  void pin_current_run(const std::string& name);
  void follow_play_head();
  // Replaces the edits and re-runs; false (and the edits as they were) when
  // the scene does not load with them.
  bool set_edits(std::vector<sim::Override> edits);
  // The scene with the edits as YAML; asks first (confirm_overwrite) when
  // the file exists and overwrite is false.
  void save_scene(const std::string& path, bool overwrite);
  void keyboard_shortcuts(Requests& requests);
  Eigen::AlignedBox3f swept_bounds() const;
  void current_poses(std::vector<sim::Pose>& poses) const;
  // The coordinates shown: the mode animation's, the play-head's, or the start.
  void current_coordinates(std::vector<double>& q) const;
  // The run's loads at the play-head as arrows placed by `poses`; none when
  // they are off or a mode is shown. `legend` gets their scale.
  std::vector<render::LoadArrow> current_load_arrows(const std::vector<sim::Pose>& poses, std::string& legend) const;
  // Their lengths for this run and view; none when they are off.
  std::optional<render::LoadArrowScale> load_arrow_scale() const;
  void save_view_png(const std::string& path);

  GlfwWindow window_;
  GuiState state_;
  std::unique_ptr<render::MeshLibrary> meshes_;
  std::unique_ptr<render::SceneView> view_;
  std::unique_ptr<render::Framebuffer> viewport_;
  std::unique_ptr<render::Framebuffer> plots_;
  std::unique_ptr<render::ImGuiLayer> plots_layer_;
  std::vector<render::PlotFrame> plot_frames_;
  // What the 3D view was last drawn for: view, size, run, samples (when the
  // play-head is past them), play-head, camera.
  struct ViewportKey {
    const render::SceneView* view = nullptr;
    int w = 0, h = 0;
    long generation = 0, samples = 0;
    double play_time = 0;  // or the mode animation's clock
    int mode = -1;         // the mode animated
    std::array<float, 9> camera{};  // the camera and the frame it rides in
    float load_scale = 0;           // 0: no load arrows
    float exaggeration = 1;         // flexible bodies' drawn bending
    bool operator==(const ViewportKey& o) const {
      return view == o.view && w == o.w && h == o.h && generation == o.generation && samples == o.samples &&
             play_time == o.play_time && mode == o.mode && camera == o.camera && load_scale == o.load_scale &&
             exaggeration == o.exaggeration;
    }
  };
  ViewportKey viewport_key_;
  double camera_fitted_at_ = 0;  // when the camera was last fitted to the motion
  bool viewport_drawn_ = false;
  using PlotsKey = std::tuple<long, std::size_t, std::size_t, int, int, int, long, bool>;
  PlotsKey plots_key_{};
  double plots_drawn_at_ = 0;
  std::unique_ptr<ExportJob> export_job_;
  SimulationWorker worker_;

  ScriptRunner script_;
  int settling_frames_ = 3;
  double waited_ = 0;  // seconds the last frame waited for input
  bool quit_ = false;
  int exit_code_ = 0;
  double last_file_check_ = 0;
};

}  // namespace unfurl::app
