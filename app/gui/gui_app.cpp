#include "gui_app.hpp"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "unfurl/render/frame_renderer.hpp"
#include "unfurl/render/imgui_layer.hpp"
#include "unfurl/render/window_surface.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/io/png_file.hpp"
#include "gui_panels.hpp"
#include "unfurl/io/run_files.hpp"
#include "scene_options.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace unfurl::app {

namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::optional<std::filesystem::file_time_type> modification_time(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const auto t = std::filesystem::last_write_time(path, ec);
  return ec ? std::nullopt : std::optional(t);
}

}  // namespace

GuiApp::GuiApp(const std::string& scene_name, std::vector<sim::Override> command_line_set,
               std::vector<ScriptCommand> script, std::optional<StudyToOpen> study, int width, int height,
               float ui_scale)
    : window_(width, height, "unfurl"), script_(std::move(script)) {
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

void GuiApp::apply_ui_scale() {
  // The font is rasterized at its size (a scaled bitmap would blur): the
  // atlas is rebuilt when the scale changes, between frames.
  const float scale = std::clamp(state_.ui_scale * window_.content_scale(), 0.5f, 4.0f);
  if (scale == state_.applied_scale) return;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  render::load_font(std::round(17 * scale));
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
  ImGui::GetStyle() = ImGuiStyle();
  ImGui::StyleColorsDark();
  ImGui::GetStyle().ScaleAllSizes(scale);
  state_.applied_scale = scale;
  plots_layer_.reset();  // its own font, made again at the new size
  plots_.reset();
}

bool GuiApp::show_case(const std::string& id) {
  const std::string shown = state_.study->shown;
  const std::vector<sim::Override> edits = state_.edits;
  state_.study->shown = id;
  if (shown != id) state_.edits.clear();
  if (load_and_run(state_.study->study.scene)) {
    if (shown != id) state_.undo.clear(), state_.redo.clear();
    return true;
  }
  state_.study->shown = shown;
  state_.edits = edits;
  return false;
}

namespace {

// Whether a run of `a` can be drawn as the ghost of `b`: the same bodies,
// coordinates, latches and loops (a study's failure cases add or remove
// latches).
bool same_structure(const sim::Scene& a, const sim::Scene& b) {
  return a.name == b.name && a.model.size() == b.model.size() && a.model.nq == b.model.nq &&
         a.latches().size() == b.latches().size() && a.loops.size() == b.loops.size();
}

}  // namespace

bool GuiApp::load_and_run(const std::string& name) {
  try {
    std::vector<sim::Override> overrides = state_.command_line_set;
    overrides.insert(overrides.end(), state_.edits.begin(), state_.edits.end());
    const studies::StudyCase* shown_case =
        state_.study && !state_.study->shown.empty() ? state_.study->find_case(state_.study->shown) : nullptr;
    sim::SceneFile file = shown_case ? studies::case_scene_file(state_.study->study, *shown_case, overrides)
                                     : read_scene_named(name, overrides);
    sim::Scene& scene = file.scene;
    std::vector<std::string> injected;
    if (shown_case && shown_case->failure) injected = failure_elements(scene, *shown_case->failure);
    auto meshes = std::make_unique<render::MeshLibrary>(mesh_directories(scene));
    auto view = std::make_unique<render::SceneView>(scene, file.visuals, *meshes);
    const bool same_scene = name == state_.scene_name && same_structure(scene, state_.scene);
    const SceneShape previous_shape = scene_shape(state_.scene);
    state_.scene = std::move(scene);
    state_.visuals = std::move(file.visuals);
    state_.scene_name = name;
    state_.scene_mtime = modification_time(name);
    state_.scene_error.clear();
    state_.failure_elements = std::move(injected);
    state_.failure_text = shown_case && shown_case->failure ? shown_case->failure->describe() : "";
    view_ = std::move(view);
    meshes_ = std::move(meshes);
    start_run();
    if (!same_scene) {
      state_.camera_fitted = false;
      state_.play_time = 0;
      state_.scene_first_generation = state_.requested_generation;
      state_.trajectory = sim::Trajectory{};
      state_.ghost = sim::Trajectory{};
      keep_comparable_pins(previous_shape);
    }
    return true;
  } catch (const std::exception& e) {
    state_.scene_error = e.what();
    return false;
  }
}

void GuiApp::keep_comparable_pins(const SceneShape& previous) {
  // Pinned runs stay with runs of the same shape (a study's cases, an
  // edited scene); another scene's would be read with the wrong indices.
  const SceneShape shape = scene_shape(state_.scene);
  const std::size_t before = state_.pinned.size();
  state_.pinned.erase(std::remove_if(state_.pinned.begin(), state_.pinned.end(),
                                     [&](const PinnedRun& p) { return !(p.shape == shape); }),
                      state_.pinned.end());
  if (state_.pinned.size() < before)
    state_.notice = std::to_string(before - state_.pinned.size()) + " pinned run(s) of another scene dropped";
  if (!(shape == previous)) state_.plot_coordinates.clear(), state_.time_zoom.reset();
  ++state_.plots_version;
}

void GuiApp::pin_current_run(const std::string& name) {
  if (!state_.run_pinnable()) {
    state_.notice = "not pinned: the run has not finished";
    return;
  }
  PinnedRun p;
  p.name = name.empty() ? "run " + std::to_string(state_.generation) : name;
  std::snprintf(p.name_field, sizeof p.name_field, "%s", p.name.c_str());
  p.shape = scene_shape(state_.scene);
  p.trajectory = state_.trajectory;
  p.summary = state_.progress.summary;
  // The first colour no pinned run has.
  int k = 0;
  while (k < 6 && std::any_of(state_.pinned.begin(), state_.pinned.end(),
                              [&](const PinnedRun& q) { return q.color == pinned_color(k); }))
    ++k;
  p.color = pinned_color(k < 6 ? k : static_cast<int>(state_.pinned.size()));
  state_.pinned.push_back(std::move(p));
  state_.select_runs_tab = true;
  ++state_.plots_version;
  state_.notice = "pinned " + state_.pinned.back().name;
}

void GuiApp::start_run() { state_.requested_generation = worker_.run(state_.scene); }

void GuiApp::sync_run() {
  const long before = state_.generation;
  state_.progress = worker_.sync(state_.generation, state_.trajectory, state_.ghost);
  if (state_.generation < state_.scene_first_generation) {
    // The previous scene's run, still winding down: not this scene's.
    state_.trajectory = sim::Trajectory{};
    state_.ghost = sim::Trajectory{};
    return;
  }
  if (state_.generation != before && state_.ghost.samples.size() < 2) state_.ghost = sim::Trajectory{};
}

void GuiApp::advance_playback(double dt) {
  if (!state_.playing) return;
  const double t_end = state_.scene.run.t_end, next = state_.play_time + dt * state_.speed;
  // While the run computes, playback waits at what is known; the play-head
  // itself keeps any time it was given (a re-run keeps it).
  if (state_.progress.running && next > state_.progress.t_reached) return;
  if (next <= t_end) {
    state_.play_time = next;
    follow_play_head();
  } else if (state_.loop) {
    state_.play_time = 0;
  } else {
    state_.play_time = t_end;
    state_.playing = false;
  }
}

void GuiApp::follow_play_head() {
  // Playback past a zoomed span turns the page: the span moves on and keeps
  // its width, so the plots show what the 3D view shows.
  if (!state_.time_zoom) return;
  auto& [t0, t1] = *state_.time_zoom;
  if (state_.play_time >= t0 && state_.play_time <= t1) return;
  const double width = t1 - t0;
  t0 = std::clamp(state_.play_time, 0.0, std::max(0.0, state_.scene.run.t_end - width));
  t1 = t0 + width;
  ++state_.plots_version;
}

void GuiApp::watch_scene_file() {
  const double now = now_seconds();
  if (now - last_file_check_ < 1.0) return;
  last_file_check_ = now;
  const auto mtime = modification_time(state_.scene_name);
  if (mtime && state_.scene_mtime && *mtime != *state_.scene_mtime) {
    state_.scene_mtime = mtime;
    if (load_and_run(state_.scene_name)) state_.notice = "reloaded " + state_.scene_name + " (the file changed)";
  }
}

void GuiApp::current_poses(std::vector<sim::Pose>& poses) const {
  std::vector<double> q = state_.scene.q0;
  if (!state_.trajectory.empty()) state_.trajectory.coordinates_at(state_.play_time, q);
  render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, q.data(), poses);
}

Eigen::AlignedBox3f GuiApp::swept_bounds() const {
  Eigen::AlignedBox3f bounds;
  std::vector<sim::Pose> poses;
  render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, state_.scene.q0.data(), poses);
  bounds.extend(view_->bounds(poses));
  const sim::Trajectory& tr = state_.trajectory;
  const std::size_t stride = std::max<std::size_t>(1, tr.samples.size() / 100);
  std::vector<double> q;
  for (std::size_t k = 0; k < tr.samples.size(); k += stride) {
    q.assign(tr.samples[k].y.begin(), tr.samples[k].y.begin() + state_.scene.model.nq);
    render::poses_in_camera_frame(state_.camera_frame, state_.scene.model, q.data(), poses);
    bounds.extend(view_->bounds(poses));
  }
  return bounds;
}

void GuiApp::draw_viewport_texture() {
  const int w = std::max(16, state_.viewport_width), h = std::max(16, state_.viewport_height);
  if (!viewport_ || viewport_->width() != w || viewport_->height() != h) {
    viewport_ = std::make_unique<render::Framebuffer>(w, h);
    viewport_drawn_ = false;
  }
  // Frame the whole motion until the first run is done (or after "reset"),
  // twice a second while it streams in: each refit redraws the view.
  const bool run_done = state_.run_settled();
  if (!state_.camera_fitted && (run_done || now_seconds() - camera_fitted_at_ >= 0.5)) {
    camera_fitted_at_ = now_seconds();
    const bool orthographic = state_.camera.orthographic;
    state_.camera = *render::camera_preset("iso", swept_bounds(), float(w) / h);
    state_.camera.orthographic = orthographic;
    state_.camera_name = "iso";
    state_.camera_fitted = run_done;
  }
  // Redrawn only when what it shows changed: while a run computes, a
  // software renderer would otherwise spend a core redrawing a still view.
  const render::Camera& c = state_.camera;
  const sim::Trajectory& tr = state_.trajectory;
  const bool past_computed = tr.empty() || state_.play_time > tr.t_end();
  const ViewportKey key{view_.get(), w, h, state_.generation,
                        past_computed ? static_cast<long>(tr.samples.size()) : -1L, state_.play_time,
                        {c.target.x(), c.target.y(), c.target.z(), c.azimuth_deg, c.elevation_deg, c.distance,
                         c.fov_deg, c.orthographic ? 1.0f : 0.0f, static_cast<float>(state_.camera_frame)}};
  if (key == viewport_key_ && viewport_drawn_) return;
  viewport_key_ = key;
  viewport_drawn_ = true;
  std::vector<sim::Pose> poses;
  current_poses(poses);
  viewport_->bind();
  view_->draw(poses, state_.camera, w, h);
  viewport_->resolve();
}

void GuiApp::draw_plots_texture() {
  // Plots are the costliest thing to draw in software GL: redraw them only
  // when their data or size changed, at most twice a second while a
  // run streams in. The play-head is drawn over them by the panel.
  const int w = std::max(16, state_.plots_width), h = std::max(16, state_.plots_height);
  const PlotsKey key{state_.generation, state_.trajectory.samples.size(), state_.ghost.samples.size(), w, h,
                     state_.plot_tab, state_.plots_version};
  const double now = now_seconds();
  if (plots_ && key == plots_key_) return;
  if (plots_ && state_.progress.running && now - plots_drawn_at_ < 0.5) return;
  if (!plots_ || plots_->width() != w || plots_->height() != h) plots_ = std::make_unique<render::Framebuffer>(w, h, 1);
  if (!plots_layer_) plots_layer_ = std::make_unique<render::ImGuiLayer>(std::round(15 * state_.applied_scale));
  plots_key_ = key;
  plots_drawn_at_ = now;
  plot_frames_.clear();
  plots_->bind();
  const ImVec4 background = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  render::clear_bound_framebuffer(background.x, background.y, background.z);
  plots_layer_->begin_frame(w, h);
  const std::vector<render::PlotKind> kinds = shown_plots(state_);
  const render::PlotChoice choice = plot_choice(state_);
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const ImVec4 cell = plot_cell(k, kinds.size(), ImVec2(static_cast<float>(w), static_cast<float>(h)));
    if (state_.trajectory.empty()) continue;
    const render::PlotSpec spec = render::trajectory_plot(kinds[k], state_.scene, state_.trajectory, choice);
    plot_frames_.push_back(render::draw_plot(plots_layer_->draw_list(), ImVec2(cell.x, cell.y), ImVec2(cell.z, cell.w),
                                             spec, false));
  }
  plots_layer_->end_frame();
  plots_->resolve();
  if (state_.run_settled() && state_.edited_at > state_.curves_at) state_.curves_at = now_seconds();
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
  const bool all_plots = state_.plot_tab >= static_cast<int>(render::plot_kinds(state_.scene).size());
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

bool GuiApp::set_edits(std::vector<sim::Override> edits) {
  std::vector<sim::Override> before = std::move(state_.edits);
  state_.edits = std::move(edits);
  if (load_and_run(state_.scene_name)) return true;
  state_.edits = std::move(before);
  return false;
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
  if (r.cancel_export && export_job_) export_job_->cancel();
  if (r.export_range && !export_job_) {
    try {
      if (state_.trajectory.empty()) throw std::runtime_error("nothing computed yet");
      ExportRequest request = *r.export_range;
      request.options.camera_frame = state_.camera_frame;
      export_job_ = std::make_unique<ExportJob>(request, state_.scene, state_.visuals, state_.trajectory,
                                                state_.camera);
      state_.export_progress = {true, 0, export_job_->total(), ""};
    } catch (const std::exception& e) {
      state_.export_progress = {false, 0, 0, std::string("export failed: ") + e.what()};
    }
  }
}

void GuiApp::save_scene(const std::string& path, bool overwrite) {
  try {
    if (state_.study && !state_.study->shown.empty())
      throw std::runtime_error("a study case is saved by its study file (its injected failure is not a scene value)");
    std::error_code ec;
    if (!overwrite && std::filesystem::exists(path, ec)) {
      state_.confirm_overwrite = path;
      state_.ask_overwrite = true;
      state_.notice = path + " exists: replace it? (Parameters tab)";
      return;
    }
    std::vector<sim::Override> overrides = state_.command_line_set;
    overrides.insert(overrides.end(), state_.edits.begin(), state_.edits.end());
    const std::string text = sim::scene_text_with(scene_text_named(state_.scene_name), state_.scene.source, overrides);
    sim::read_scene_text(text, path);  // it must read back
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!dir.empty()) io::make_directory(dir);
    io::OutputFile file(path);
    file.stream() << text;
    file.commit();
    state_.notice = "saved " + path;
  } catch (const std::exception& e) {
    state_.notice = std::string("not saved: ") + e.what();
  }
}

void GuiApp::save_view_png(const std::string& path) {
  try {
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!dir.empty()) io::make_directory(dir);
    // At the export form's size, not the viewport's: the same camera and
    // play-head, drawn again off screen.
    const int w = std::clamp(state_.export_form.size[0], 16, 8192), h = std::clamp(state_.export_form.size[1], 16, 8192);
    render::FrameRenderer renderer(state_.scene, state_.visuals, w, h, mesh_directories(state_.scene));
    std::vector<sim::Pose> poses;
    current_poses(poses);
    render::Image image;
    renderer.frame(poses, state_.play_time, state_.camera, image);
    io::write_png(image, path);
    state_.notice = "saved " + path + " (" + std::to_string(w) + "x" + std::to_string(h) + ")";
  } catch (const std::exception& e) {
    state_.notice = e.what();
  }
}

void GuiApp::screenshot(const std::string& path) {
  int W = 0, H = 0;
  window_.framebuffer_size(W, H);
  render::Image image;
  render::read_window(W, H, image);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  if (!dir.empty()) io::make_directory(dir);
  io::write_png(image, path, 6);
}

void GuiApp::camera_preset(const std::string& name) {
  if (const auto cam = render::camera_preset(name, swept_bounds(),
                                             float(state_.viewport_width) / std::max(1, state_.viewport_height))) {
    const bool orthographic = state_.camera.orthographic;
    state_.camera = *cam;
    state_.camera.orthographic = orthographic;
    state_.camera_name = name;
    state_.camera_fitted = true;
  }
}

void GuiApp::record_frame_time(double seconds) {
  state_.frame_seconds.push_back(seconds);
  if (state_.frame_seconds.size() > 60) state_.frame_seconds.pop_front();
  double total = 0;
  for (double s : state_.frame_seconds) total += s;
  state_.fps = total > 0 ? state_.frame_seconds.size() / total : 0;
  if (state_.progress.running) {
    ++state_.frames_while_running;
    state_.seconds_while_running += seconds;
    state_.worst_frame_while_running = std::max(state_.worst_frame_while_running, seconds);
  }
}

bool GuiApp::busy() const {
  return state_.playing || !state_.run_settled() ||
         export_job_ || (!script_.finished() && !script_.idling()) || ImGui::GetIO().WantTextInput;
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
    // At most about 60 frames per second: the solver thread needs the rest.
    const double before_sleep = now_seconds();
    const double spare = 1.0 / 60 - (before_sleep - last - waited_);
    if (spare > 0) std::this_thread::sleep_for(std::chrono::duration<double>(spare));
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
