// The workbench's window and frame loop: the panels laid out, their
// requests applied, input awaited while nothing changes.
#include "gui_app.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "gui_clock.hpp"
#include "gui_panels.hpp"
#include "scene_options.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/run_files.hpp"
#include "unfurl/render/imgui_layer.hpp"
#include "unfurl/render/window_surface.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace unfurl::app {

GuiApp::GuiApp(const std::string& scene_name, std::vector<sim::Override> command_line_set,
               std::vector<ScriptCommand> script, std::optional<StudyToOpen> study, int width, int height,
               float ui_scale)
    : window_(width, height, "unfurl"), worker_([] { glfwPostEmptyEvent(); }), script_(std::move(script)) {
  state_.command_line_set = std::move(command_line_set);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window_.handle(), true);
  ImGui_ImplOpenGL3_Init("#version 330");
  state_.ui_scale = state_.ui_scale_field = ui_scale;
  apply_ui_scale();
  meshes_ = std::make_unique<render::MeshLibrary>(std::vector<std::string>{});
  if (study) {
    state_.study = open_study(study->study_path, study->dir);
    state_.select_study_tab = true;
    const std::string id = study->case_id.empty() ? state_.study->rows.front().id : study->case_id;
    if (!state_.study->find_case(id))
      throw std::runtime_error(study->study_path + ": no case '" + id + "' (ids: nominal, case-0001, ..., fail-...)");
    if (show_case(id)) return;
    throw std::runtime_error(state_.scene_error);
  }
  if (!load_and_run(scene_name)) {
    // Show the error over a scene that loads: the built-in pantograph.
    const std::string error = state_.scene_error;
    state_.command_line_set.clear();
    load_and_run("pantograph");
    state_.scene_error = error + " (showing the built-in pantograph instead)";
  }
}

GuiApp::~GuiApp() {
  export_job_.reset();
  view_.reset();
  viewport_.reset();
  meshes_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void GuiApp::keyboard_shortcuts(Requests& requests) {
  const ImGuiIO& io = ImGui::GetIO();
  // The keys belong to the field being typed in, or to the file dialog.
  if (io.WantTextInput || state_.file_dialog.shown()) return;
  const auto pressed = [](int glfw_key) { return ImGui::IsKeyPressed(glfw_key, false); };
  const double frame = 1.0 / 30, t_end = state_.scene.run.t_end;
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) requests.undo = true;
    if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) requests.redo = true;
    if (pressed(GLFW_KEY_S)) requests.save_scene = std::string(state_.save_path);
    if (pressed(GLFW_KEY_O)) state_.focus_scene_field = true;
    return;
  }
  if (pressed(GLFW_KEY_SPACE)) state_.playing = !state_.playing;
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT)) state_.playing = false, state_.play_time = std::max(0.0, state_.play_time - frame);
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT)) state_.playing = false, state_.play_time = std::min(t_end, state_.play_time + frame);
  if (pressed(GLFW_KEY_HOME)) state_.play_time = 0;
  if (pressed(GLFW_KEY_END)) state_.play_time = t_end;
  if (pressed(GLFW_KEY_F)) camera_preset("iso");
}

void GuiApp::layout_and_panels(Requests& requests) {
  keyboard_shortcuts(requests);
  int W = 0, H = 0;
  window_.framebuffer_size(W, H);
  const float w = static_cast<float>(W), h = static_cast<float>(H);
  const ImGuiStyle& style = ImGui::GetStyle();
  // The toolbar grows with the lines an error wraps to.
  const std::string error = toolbar_error(state_);
  const float toolbar =
      std::round(ImGui::GetFrameHeightWithSpacing() + 2 * style.WindowPadding.y + 4 +
                 (error.empty() ? 0.0f : ImGui::CalcTextSize(error.c_str(), nullptr, false, w - 24).y + 4));
  // "all" plots take more of the left column than one plot does.
  const bool all_plots = state_.plot_tab >= static_cast<int>(plot_kinds(state_).size());
  const float status = std::round(ImGui::GetFrameHeight() + 2 * style.WindowPadding.y), left = std::round(0.62f * w);
  const float view_h = std::round((all_plots ? 0.36f : 0.5f) * (h - toolbar - status));
  // Buttons, scrubber and its tick labels, without a scroll bar.
  const float timeline = std::round(2 * ImGui::GetFrameHeightWithSpacing() + ImGui::GetTextLineHeight() + 4 +
                                    2 * style.WindowPadding.y + ImGui::GetFontSize() + 2 * style.FramePadding.y + 8);
  // No window backgrounds: the clear colour is the background, so a
  // software renderer (Xvfb, llvmpipe) fills each pixel about once.
  const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground;
  auto place = [&](float x, float y, float ww, float hh) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(ww, hh));
  };

  place(0, 0, w, toolbar);
  ImGui::Begin("toolbar", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
  toolbar_panel(state_, requests);
  ImGui::End();

  place(0, toolbar, left, view_h);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
  ImGui::Begin("View", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  viewport_panel(state_, viewport_ ? viewport_->texture() : 0, swept_bounds());
  ImGui::End();
  ImGui::PopStyleVar();

  place(0, toolbar + view_h, left, timeline);
  ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
  timeline_panel(state_);
  ImGui::End();

  place(0, toolbar + view_h + timeline, left, h - toolbar - view_h - timeline - status);
  ImGui::Begin("Plots", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  plots_panel(state_, plots_ ? plots_->texture() : 0, plot_frames_);
  ImGui::End();

  place(left, toolbar, w - left, h - toolbar - status);
  ImGui::Begin("Settings", nullptr, fixed);
  if (ImGui::BeginTabBar("tabs")) {
    if (ImGui::BeginTabItem("Parameters")) {
      parameters_panel(state_, requests);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Export")) {
      export_panel(state_, requests);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Runs", nullptr, state_.select_runs_tab ? ImGuiTabItemFlags_SetSelected : 0)) {
      runs_panel(state_, requests);
      ImGui::EndTabItem();
    }
    state_.select_runs_tab = false;
    if (ImGui::BeginTabItem("Modes", nullptr, state_.modes.select_tab ? ImGuiTabItemFlags_SetSelected : 0)) {
      modes_panel(state_, requests);
      ImGui::EndTabItem();
    }
    state_.modes.select_tab = false;
    if (state_.study &&
        ImGui::BeginTabItem("Study", nullptr, state_.select_study_tab ? ImGuiTabItemFlags_SetSelected : 0)) {
      study_panel(state_, requests);
      ImGui::EndTabItem();
    }
    state_.select_study_tab = false;
    ImGui::EndTabBar();
  }
  ImGui::End();

  place(0, h - status, w, status);
  ImGui::Begin("status", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
  status_bar(state_);
  ImGui::End();

  file_dialog_panel(state_, requests);
}

void GuiApp::apply(const Requests& r) {
  // An edit (or a reset) is undoable; undo and redo move whole sets of
  // edits between the two stacks. A set that does not load changes nothing.
  auto edit_to = [&](std::vector<sim::Override> edits) {
    std::vector<sim::Override> before = state_.edits;
    if (!set_edits(std::move(edits))) return;
    state_.edited_at = now_seconds();
    state_.undo.push_back(std::move(before));
    state_.redo.clear();
  };
  auto travel = [&](std::vector<std::vector<sim::Override>>& from, std::vector<std::vector<sim::Override>>& to) {
    if (from.empty()) return;
    std::vector<sim::Override> before = state_.edits;
    if (!set_edits(from.back())) return;
    from.pop_back();
    to.push_back(std::move(before));
  };
  if (r.edit && edits_element(r.edit->path, state_.failure_elements)) {
    state_.notice = "not edited: " + r.edit->path + " belongs to the case's failure (" + state_.failure_text +
                    "); the study file sets it";
  } else if (r.edit) {
    // The latest value for a path replaces an earlier one.
    std::vector<sim::Override> edits = state_.edits;
    edits.erase(
        std::remove_if(edits.begin(), edits.end(), [&](const sim::Override& o) { return o.path == r.edit->path; }),
        edits.end());
    edits.push_back(*r.edit);
    edit_to(std::move(edits));
  }
  if (r.reset_edits && !state_.edits.empty()) edit_to({});
  if (r.undo) travel(state_.undo, state_.redo);
  if (r.redo) travel(state_.redo, state_.undo);
  if (r.save_scene) save_scene(*r.save_scene, r.overwrite);
  if (r.open) {
    const auto kept = state_.edits;
    const std::string kept_case = state_.study ? state_.study->shown : "";
    state_.edits.clear();
    if (state_.study) state_.study->shown.clear();
    if (!load_and_run(*r.open)) {
      state_.edits = kept;
      if (state_.study) state_.study->shown = kept_case;
    } else {
      state_.undo.clear();
      state_.redo.clear();
    }
  }
  if (r.open_case && state_.study) show_case(*r.open_case);
  if (r.pin) pin_current_run(*r.pin);
  if (r.unpin && *r.unpin < state_.pinned.size()) {
    state_.pinned.erase(state_.pinned.begin() + static_cast<long>(*r.unpin));
    ++state_.plots_version;
  }
  if (r.reload) load_and_run(state_.scene_name);
  if (r.save_frame) save_view_png(*r.save_frame);
  if (r.save_trajectory) {
    try {
      io::make_directory(std::filesystem::path(*r.save_trajectory).parent_path().string().empty()
                             ? "."
                             : std::filesystem::path(*r.save_trajectory).parent_path().string());
      io::write_trajectory_csv(state_.scene, state_.trajectory, *r.save_trajectory);
      state_.notice = "saved " + *r.save_trajectory;
    } catch (const std::exception& e) {
      state_.notice = e.what();
    }
  }
  if (r.compute_modes) compute_modes();
  if (r.show_mode) show_mode(*r.show_mode);
  if (r.cancel_export && export_job_) export_job_->cancel();
  if (r.export_range && !export_job_) {
    try {
      if (state_.trajectory.empty()) throw std::runtime_error("nothing computed yet");
      ExportRequest request = *r.export_range;
      request.options.camera_frame = state_.camera_frame;
      request.options.exaggerate = state_.exaggeration;
      export_job_ = std::make_unique<ExportJob>(request, state_.scene, state_.visuals, state_.trajectory,
                                                state_.camera, load_arrow_scale());
      state_.export_progress = {true, 0, export_job_->total(), ""};
    } catch (const std::exception& e) {
      state_.export_progress = {false, 0, 0, std::string("export failed: ") + e.what()};
    }
  }
}

bool GuiApp::busy() const {
  return state_.playing || state_.modes.shown >= 0 || !state_.run_settled() ||
         export_job_ || (!script_.finished() && !script_.idling()) || ImGui::GetIO().WantTextInput;
}

bool GuiApp::only_the_run_moves() const {
  return !state_.run_settled() && !state_.playing && state_.modes.shown < 0 && !export_job_ &&
         (script_.finished() || script_.waiting_for_run()) && !ImGui::GetIO().WantTextInput && settling_frames_ == 0;
}

void GuiApp::wait_for_events() {
  // Idle, the window is drawn on events only (and once a second for the
  // scene file's watch): a frame costs a core in software GL. After an
  // event a few more frames let hover and release effects settle.
  if (busy() || settling_frames_ > 0) {
    glfwPollEvents();
    settling_frames_ = std::max(0, settling_frames_ - 1);
    return;
  }
  const double before = now_seconds();
  glfwWaitEventsTimeout(script_.idling() ? std::clamp(script_.idle_left(before), 0.001, 1.0) : 1.0);
  waited_ = now_seconds() - before;
  if (waited_ < 0.99) settling_frames_ = 3;
}

void GuiApp::frame() {
  wait_for_events();
  ++state_.frames;
  sync_run();
  watch_scene_file();
  if (export_job_) {
    const bool more = export_job_->step(8);
    state_.export_progress.done = export_job_->done();
    if (!more) {
      state_.export_progress = {false, 0, 0, export_job_->result()};
      export_job_.reset();
    }
  }
  apply_ui_scale();
  draw_viewport_texture();
  draw_plots_texture();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  Requests requests;
  layout_and_panels(requests);
  ImGui::Render();
  int W = 0, H = 0;
  window_.framebuffer_size(W, H);
  const ImVec4 background = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  render::begin_window_frame(W, H, background.x, background.y, background.z);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  // The script runs here, between drawing and showing, so a screenshot
  // reads back the frame just drawn.
  script_.step(*this, now_seconds());
  window_.swap();
  apply(requests);
}

int GuiApp::run() {
  double last = now_seconds();
  while (!window_.should_close() && !quit_) {
    waited_ = 0;
    frame();
    // At most about 60 frames per second: the solver's threads need the
    // rest. While only a run moves, its growing curves are drawn 20 times a
    // second: a frame costs a core in software GL, and a run takes two
    // threads (the pantograph's re-run took 0.16-0.27 s under Xvfb at the
    // UI's 40 frames/s, against 0.145 s alone). Input, or the run's last
    // sample, ends the wait at once.
    const double before_sleep = now_seconds();
    const bool only_run = only_the_run_moves();
    const double spare = 1.0 / (only_run ? 20 : 60) - (before_sleep - last - waited_);
    if (spare > 0 && only_run)
      glfwWaitEventsTimeout(spare);
    else if (spare > 0)
      std::this_thread::sleep_for(std::chrono::duration<double>(spare));
    const double now = now_seconds();
    // Time spent waiting for input is neither a slow frame nor playback.
    const double dt = now - last - waited_;
    if (waited_ == 0) record_frame_time(dt);
    advance_playback(dt);
    last = now;
  }
  return exit_code_;
}

}  // namespace unfurl::app
