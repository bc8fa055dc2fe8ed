#include "gui_panels.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "unfurl/sim/number_text.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"

namespace unfurl::app {

namespace {

constexpr double kFrame = 1.0 / 30;  // one frame of playback

// A number field for a scene value: a single click and typing (Enter or
// leaving the field commits), - and + step it; on commit, requests `path` =
// value. The tooltip says what the value is.
void value_field(const char* label, const std::string& path, double value, double step, Requests& requests,
                 double lo = 0, double hi = 0, const char* format = "%.6g", const char* help = nullptr) {
  double v = value;
  ImGui::SetNextItemWidth(em(190));
  const bool stepped = ImGui::InputScalar(label, ImGuiDataType_Double, &v, &step, nullptr, format);
  if (help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", help, path.c_str());
  const bool commit = ImGui::IsItemDeactivatedAfterEdit() || (stepped && !ImGui::IsItemActive());
  if (lo < hi) v = std::clamp(v, lo, hi);
  if (commit && v != value) requests.edit = sim::Override{path, sim::format_number(v)};
}

double run_end(const GuiState& state) { return state.scene.run.t_end; }

// An element the shown study case's failure put in the scene: its fields
// are drawn disabled (from construction to the end of the scope) with a
// note saying why.
class FailureLock {
 public:
  FailureLock(const GuiState& state, const std::string& path)
      : state_(state),
        locked_(std::find(state.failure_elements.begin(), state.failure_elements.end(), path) !=
                state.failure_elements.end()) {
    if (locked_) ImGui::BeginDisabled();
  }
  ~FailureLock() {
    if (locked_) ImGui::EndDisabled();
  }
  FailureLock(const FailureLock&) = delete;
  FailureLock& operator=(const FailureLock&) = delete;

  void note() const {
    if (!locked_) return;
    ImGui::SameLine();
    ImGui::TextDisabled("(the case's failure: %s; set by the study file)", state_.failure_text.c_str());
  }

 private:
  const GuiState& state_;
  bool locked_;
};

}  // namespace

std::string toolbar_error(const GuiState& state) {
  std::string error = state.scene_error;
  if (state.progress.status == sim::RunStatus::failed && !state.progress.failure.empty())
    error += (error.empty() ? "" : "\n") + std::string("run failed: ") + state.progress.failure;
  return error;
}

void toolbar_panel(GuiState& state, Requests& requests) {
  char* path = state.scene_path;
  if (path[0] == 0) std::snprintf(path, sizeof state.scene_path, "%s", state.scene_name.c_str());
  ImGui::TextUnformatted("Scene");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(em(360));
  if (state.focus_scene_field) {
    ImGui::SetKeyboardFocusHere();
    state.focus_scene_field = false;
  }
  const bool entered = ImGui::InputText("##scene", path, sizeof state.scene_path, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::Button("Open") || entered) requests.open = std::string(path);
  browse_button(state, FileField::open_scene, "Browse...");
  ImGui::SameLine();
  if (ImGui::Button("Reload")) requests.reload = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(em(110));
  ImGui::SliderFloat("UI scale", &state.ui_scale_field, 0.75f, 2.5f, "%.2fx");
  // Applied on release: the fonts are made again at the new size.
  if (ImGui::IsItemDeactivatedAfterEdit()) state.ui_scale = state.ui_scale_field;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("text and widget size, on top of the monitor's content scale");
  ImGui::SameLine();
  if (state.study && !state.study->shown.empty())
    ImGui::TextDisabled("%s of study %s", state.study->shown.c_str(), state.study->study_path.c_str());
  else
    ImGui::TextDisabled("%s", state.scene.source.c_str());
  if (!state.run_settled()) {
    ImGui::SameLine();
    const float pulse = 0.6f + 0.4f * std::sin(static_cast<float>(ImGui::GetTime()) * 6);
    ImGui::TextColored(ImVec4(1.0f, 0.75f * pulse, 0.2f, 1), "re-simulating...");
  }
  const std::string error = toolbar_error(state);
  if (error.empty()) return;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
  ImGui::PopTextWrapPos();
}

void viewport_panel(GuiState& state, unsigned texture, const Eigen::AlignedBox3f& bounds) {
  // The presets, the active one highlighted (until the view is orbited).
  for (const std::string& name : render::camera_preset_names()) {
    const bool active = name == state.camera_name;
    if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    if (ImGui::SmallButton(name.c_str())) {
      const bool orthographic = state.camera.orthographic;
      state.camera = *render::camera_preset(name, bounds, float(state.viewport_width) / std::max(1, state.viewport_height));
      state.camera.orthographic = orthographic;
      state.camera_name = name;
    }
    if (active) ImGui::PopStyleColor();
    ImGui::SameLine();
  }
  if (ImGui::SmallButton("reset view")) state.camera_fitted = false;
  ImGui::SameLine();
  ImGui::Checkbox("orthographic", &state.camera.orthographic);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("parallel projection: with side, a true view along the hinge axes");
  if (state.scene.model.free_floating()) {
    ImGui::SameLine();
    bool ride = state.camera_frame == render::CameraFrame::bus;
    if (ImGui::Checkbox("ride with the bus", &ride)) {
      state.camera_frame = ride ? render::CameraFrame::bus : render::CameraFrame::inertial;
      state.camera_fitted = false;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("on: the camera moves with the free-floating bus; off: it stays in the inertial frame, where "
                        "the bus turns and drifts");
  }
  const ImVec2 size = ImGui::GetContentRegionAvail();
  state.viewport_width = std::max(16, static_cast<int>(size.x));
  state.viewport_height = std::max(16, static_cast<int>(size.y));
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(0, 1), ImVec2(1, 0));
  if (!ImGui::IsItemHovered()) return;
  const ImGuiIO& io = ImGui::GetIO();
  render::Camera& c = state.camera;
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    state.camera_name.clear();
    c.azimuth_deg -= 0.3f * io.MouseDelta.x;
    c.elevation_deg = std::clamp(c.elevation_deg + 0.3f * io.MouseDelta.y, -89.9f, 89.9f);
  }
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle)) {
    const Eigen::Matrix4f V = c.view();
    const float scale = c.distance * 0.0015f;
    c.target -= scale * io.MouseDelta.x * V.block<1, 3>(0, 0).transpose();
    c.target += scale * io.MouseDelta.y * V.block<1, 3>(1, 0).transpose();
  }
  if (io.MouseWheel != 0) c.distance *= std::pow(0.9f, io.MouseWheel);
}

void timeline_panel(GuiState& state) {
  const double t_end = run_end(state);
  if (ImGui::Button(state.playing ? "Pause" : "Play", ImVec2(em(70), 0))) state.playing = !state.playing;
  ImGui::SameLine();
  if (ImGui::ArrowButton("back", ImGuiDir_Left)) state.playing = false, state.play_time -= kFrame;
  ImGui::SameLine();
  if (ImGui::ArrowButton("forward", ImGuiDir_Right)) state.playing = false, state.play_time += kFrame;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(em(140));
  ImGui::SliderFloat("speed", &state.speed, 0.1f, 10.0f, "%.2fx", ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  ImGui::Checkbox("loop", &state.loop);
  ImGui::SameLine();
  ImGui::Text("t = %.3f s", state.play_time);
  const bool computed_here = !state.trajectory.empty() && state.play_time <= state.trajectory.t_end() + 1e-9;
  if (!computed_here) {
    // The view shows the last computed state until the run gets here.
    ImGui::SameLine();
    if (state.trajectory.empty())
      ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.2f, 1), "not computed yet");
    else
      ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.2f, 1), "not computed yet: showing t = %.3f s",
                         state.trajectory.t_end());
  }

  // The scrubber, with what is computed shaded and the latches marked.
  float t = static_cast<float>(state.play_time);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderFloat("##time", &t, 0.0f, static_cast<float>(t_end), "%.3f s")) state.play_time = t;
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float computed = static_cast<float>(std::min(1.0, state.progress.t_reached / t_end));
  draw->AddRectFilled(ImVec2(lo.x, hi.y - 3), ImVec2(lo.x + computed * (hi.x - lo.x), hi.y), IM_COL32(80, 170, 255, 200));
  // Latches: this run's full height in red, the previous run's (the
  // ghost) in the lower half in grey; the joint's name on hover.
  const bool hovered = ImGui::IsItemHovered();
  const float mouse_x = ImGui::GetIO().MousePos.x;
  std::string names;
  auto marks = [&](const sim::Trajectory& tr, float top, ImU32 colour, const char* which) {
    for (const sim::LatchEvent& e : tr.events) {
      const float x = lo.x + static_cast<float>(e.t / t_end) * (hi.x - lo.x);
      draw->AddLine(ImVec2(x, top), ImVec2(x, hi.y), colour, 2);
      if (hovered && std::abs(mouse_x - x) <= 3 && e.joint < state.scene.model.size()) {
        char line[128];
        std::snprintf(line, sizeof line, "%slatch %s at %.6f s (%s run)", names.empty() ? "" : "\n",
                      state.scene.model.joints[e.joint].name.c_str(), e.t, which);
        names += line;
      }
    }
  };
  marks(state.ghost, 0.5f * (lo.y + hi.y), IM_COL32(170, 170, 170, 220), "previous");
  marks(state.trajectory, lo.y, IM_COL32(255, 90, 90, 255), "this");
  if (!names.empty()) ImGui::SetTooltip("%s", names.c_str());
  // Time ticks under the scrubber, as many as fit.
  const float label_width = ImGui::CalcTextSize("00.0 s").x + 12;
  const int count = std::max(2, static_cast<int>((hi.x - lo.x) / label_width));
  for (double tick : render::nice_ticks(0, t_end, count)) {
    const float x = lo.x + static_cast<float>(tick / t_end) * (hi.x - lo.x);
    draw->AddLine(ImVec2(x, hi.y), ImVec2(x, hi.y + 4), IM_COL32(200, 200, 200, 255));
    char label[32];
    std::snprintf(label, sizeof label, "%g s", tick + 0.0);  // no "-0"
    const float w = ImGui::CalcTextSize(label).x;
    draw->AddText(ImVec2(std::clamp(x - w / 2, lo.x, hi.x - w), hi.y + 4), IM_COL32(200, 200, 200, 255), label);
  }
  ImGui::Dummy(ImVec2(0, ImGui::GetTextLineHeight() + 4));
  state.play_time = std::clamp(state.play_time, 0.0, t_end);
}

namespace {

// "point_springs" -> "Point springs": a list's heading.
std::string list_title(std::string list) {
  for (char& c : list) c = c == '_' ? ' ' : c;
  if (!list.empty()) list[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(list[0])));
  return list;
}

// Every force element's parameters, a section per list of the scene file,
// in the order the lists first appear.
void elements_section(GuiState& state, Requests& requests) {
  const sim::Scene& scene = state.scene;
  std::vector<std::string> lists;
  for (const auto& e : scene.elements)
    if (std::find(lists.begin(), lists.end(), e->list()) == lists.end()) lists.push_back(e->list());
  for (std::size_t n = 0; n < lists.size(); ++n) {
    if (!ImGui::CollapsingHeader(list_title(lists[n]).c_str(), n == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
    for (std::size_t k = 0; k < scene.elements.size(); ++k) {
      const sim::ForceElement& e = *scene.elements[k];
      if (e.list() != lists[n]) continue;
      const std::vector<sim::ElementParameter> parameters = e.parameters();
      const std::string path = scene.element_path(k);
      ImGui::PushID(static_cast<int>(k));
      const FailureLock lock(state, path);
      const std::string handle = e.handle(scene.model);
      ImGui::Text("%s %s", e.kind().c_str(), handle.c_str());
      lock.note();
      if (const std::string note = e.note(); !note.empty()) ImGui::TextDisabled("  %s", note.c_str());
      for (const sim::ElementParameter& p : parameters)
        value_field((p.label + "##" + p.key).c_str(), path + "." + p.key, p.value, p.step, requests, p.lo, p.hi, "%.6g",
                    p.help.c_str());
      ImGui::PopID();
    }
  }
}

}  // namespace

void parameters_panel(GuiState& state, Requests& requests) {
  const sim::Scene& scene = state.scene;
  if (state.save_path[0] == 0) {
    const std::string stem = std::filesystem::path(state.scene_name).stem().string();
    std::snprintf(state.save_path, sizeof state.save_path, "%s_edited.yaml", stem.c_str());
  }
  if (ImGui::Button("Reset to the file's values")) requests.reset_edits = true;
  ImGui::SameLine();
  ImGui::BeginDisabled(state.undo.empty());
  if (ImGui::Button("Undo")) requests.undo = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(state.redo.empty());
  if (ImGui::Button("Redo")) requests.redo = true;
  ImGui::EndDisabled();
  ImGui::SetNextItemWidth(em(220));
  ImGui::InputText("##save", state.save_path, sizeof state.save_path);
  browse_button(state, FileField::save_scene, "...##save");
  ImGui::SameLine();
  if (ImGui::Button("Save scene (YAML)")) requests.save_scene = std::string(state.save_path);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The scene with the edits below, as a file that reloads to the same run (Ctrl+S)");
  if (state.ask_overwrite) {
    ImGui::OpenPopup("Overwrite?");
    state.ask_overwrite = false;
  }
  if (ImGui::BeginPopupModal("Overwrite?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s exists. Replace it?", state.confirm_overwrite.c_str());
    if (ImGui::Button("Replace")) {
      requests.save_scene = state.confirm_overwrite;
      requests.overwrite = true;
      state.confirm_overwrite.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      state.confirm_overwrite.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  elements_section(state, requests);
  if (!scene.loops.empty() && ImGui::CollapsingHeader("Loop regulator", ImGuiTreeNodeFlags_DefaultOpen)) {
    const sim::RegulatorSettings& r = scene.regulator;
    int gains = r.gains == sim::GainTuning::full ? 0 : 1;
    ImGui::SetNextItemWidth(em(160));
    if (ImGui::Combo("gains", &gains, "full (current W)\0paper (16), diagonal\0"))
      requests.edit = sim::Override{"regulator.gains", gains == 0 ? "full" : "paper"};
    value_field("v_max [rad/s]", "regulator.v_max", r.v_max, 10, requests, 1e-3, 1e9, "%.6g",
                "the regulator's bandwidth: how fast it closes a loop's gap");
    value_field("p0", "regulator.p0", r.p0, 0.01, requests, 1e-3, 100, "%.6g", "pole placement of the PID gains (16)");
    value_field("p1", "regulator.p1", r.p1, 0.01, requests, 1e-3, 0.999, "%.6g", "pole placement of the PID gains (16)");
  }
  if (ImGui::CollapsingHeader("Integrator", ImGuiTreeNodeFlags_DefaultOpen)) {
    const sim::RunSettings& run = scene.run;
    int current = 0;
    const auto& kinds = sim::all_integrators();
    for (std::size_t k = 0; k < kinds.size(); ++k)
      if (kinds[k] == run.integrator) current = static_cast<int>(k);
    ImGui::SetNextItemWidth(em(160));
    if (ImGui::Combo("integrator", &current, "cvode-bdf\0cvode-adams\0arkode-erk\0arkode-dirk\0rk4\0"))
      requests.edit = sim::Override{"run.integrator", sim::integrator_name(kinds[current])};
    if (run.integrator == sim::IntegratorKind::rk4) {
      value_field("step [s]", "run.dt", run.dt, 1e-6, requests, 1e-9, 1, "%.3g", "the fixed step of RK4");
    } else {
      value_field("rtol", "run.rtol", run.rtol, 1e-10, requests, 1e-14, 1e-1, "%.3g",
                  "relative tolerance of the integrator's local error");
      value_field("atol", "run.atol", run.atol, 1e-12, requests, 1e-16, 1e-1, "%.3g",
                  "absolute tolerance for the angles, rad (momenta 100x)");
    }
    value_field("t_end [s]", "run.t_end", run.t_end, 0.1, requests, 1e-3, 1e6, "%.6g", "the simulated span");
  }
  if (!state.edits.empty()) {
    ImGui::Separator();
    ImGui::TextDisabled("changed from the file:");
    for (const sim::Override& o : state.edits) ImGui::TextDisabled("  %s = %s", o.path.c_str(), o.value.c_str());
  }
}

std::vector<render::PlotKind> shown_plots(const GuiState& state) {
  const std::vector<render::PlotKind> kinds = render::plot_kinds(state.scene);
  if (state.plot_tab >= 0 && state.plot_tab < static_cast<int>(kinds.size())) return {kinds[state.plot_tab]};
  return kinds;
}

ImVec4 plot_cell(std::size_t k, std::size_t count, ImVec2 panel) {
  if (count == 1) return ImVec4(0, 0, panel.x, panel.y);
  const std::size_t rows = (count + 1) / 2;
  const float w = panel.x / 2, h = panel.y / static_cast<float>(rows);
  return ImVec4(static_cast<float>(k % 2) * w, static_cast<float>(k / 2) * h, w - 4, h - 4);
}

render::PlotChoice plot_choice(const GuiState& state) {
  render::PlotChoice choice;
  if (!state.ghost.empty()) choice.others.push_back({&state.ghost, "", 0});
  for (const PinnedRun& p : state.pinned)
    if (p.shown) choice.others.push_back({&p.trajectory, p.name, p.color});
  choice.coordinates = state.plot_coordinates;
  choice.time_range = state.time_zoom;
  return choice;
}

namespace {

// The joints the plots draw: a checklist, with all, none and the default.
void curves_checklist(GuiState& state) {
  const sim::Model& model = state.scene.model;
  if (ImGui::SmallButton("curves...")) ImGui::OpenPopup("curves");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("choose the joints the plots draw");
  if (!ImGui::BeginPopup("curves")) return;
  std::vector<int>& chosen = state.plot_coordinates;
  const auto set = [&](std::vector<int> coordinates) {
    chosen = std::move(coordinates);
    ++state.plots_version;
  };
  if (ImGui::SmallButton("all")) {
    std::vector<int> all(model.scalar_coordinates);
    for (int c = 0; c < model.scalar_coordinates; ++c) all[c] = c;
    set(all);
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("first 12")) set({});
  // Empty means the first 12: show them as ticked.
  std::vector<int> shown = render::chosen_coordinates(model, plot_choice(state));
  const float rows = std::min(20.0f, static_cast<float>(model.scalar_coordinates));
  ImGui::BeginChild("joints", ImVec2(em(220), rows * ImGui::GetFrameHeightWithSpacing()));
  for (int c = 0; c < model.scalar_coordinates; ++c) {
    bool on = std::find(shown.begin(), shown.end(), c) != shown.end();
    ImGui::PushStyleColor(ImGuiCol_Text, render::palette(c));
    ImGui::Checkbox(model.joints[model.joint_of_position[c]].name.c_str(), &on);
    ImGui::PopStyleColor();
    if (ImGui::IsItemEdited()) {
      if (on)
        shown.insert(std::upper_bound(shown.begin(), shown.end(), c), c);
      else
        shown.erase(std::remove(shown.begin(), shown.end(), c), shown.end());
      // None ticked would mean the default: keep one.
      if (shown.empty()) shown.push_back(c);
      set(shown);
    }
  }
  ImGui::EndChild();
  ImGui::EndPopup();
}

// Wheel over a plot zooms the time axis about the cursor, right drag pans
// it, double click shows the whole run. The play-head follows: it goes to
// the time zoomed into and moves with a pan, so the 3D view shows what the
// plots show.
void zoom_and_pan(GuiState& state, const render::PlotFrame& f) {
  const ImGuiIO& io = ImGui::GetIO();
  const double t_end = run_end(state);
  auto [t0, t1] = state.time_zoom.value_or(std::pair<double, double>(0.0, t_end));
  const double width = f.plot_max.x - f.plot_min.x;
  if (io.MouseWheel != 0) {
    const double t = std::clamp(f.x_at(io.MousePos.x), 0.0, t_end), k = std::pow(0.8, io.MouseWheel);
    const double span = std::clamp((t1 - t0) * k, 1e-6 * t_end, t_end);
    const double fraction = (t - t0) / (t1 - t0);
    t0 = std::clamp(t - fraction * span, 0.0, t_end - span);
    t1 = t0 + span;
    state.play_time = t;
    state.playing = false;
  } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) && width > 0) {
    const double shift = -io.MouseDelta.x / width * (t1 - t0);
    const double moved = std::clamp(t0 + shift, 0.0, t_end - (t1 - t0)) - t0;
    t0 += moved, t1 += moved;
    state.play_time = std::clamp(state.play_time + moved, 0.0, t_end);
  } else if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    t0 = 0, t1 = t_end;
  } else {
    return;
  }
  if (t1 - t0 >= t_end * (1 - 1e-9))
    state.time_zoom.reset();
  else
    state.time_zoom = std::pair(t0, t1);
  ++state.plots_version;
}

}  // namespace

void plots_panel(GuiState& state, unsigned texture, const std::vector<render::PlotFrame>& frames) {
  const std::vector<render::PlotKind> all = render::plot_kinds(state.scene);
  for (std::size_t k = 0; k <= all.size(); ++k) {
    if (k > 0) ImGui::SameLine();
    const char* name = k < all.size() ? render::plot_kind_name(all[k]) : "all";
    if (ImGui::RadioButton(name, state.plot_tab == static_cast<int>(k))) state.plot_tab = static_cast<int>(k);
  }
  ImGui::SameLine();
  curves_checklist(state);
  ImGui::SameLine();
  if (state.time_zoom) {
    if (ImGui::SmallButton("whole run")) state.time_zoom.reset(), ++state.plots_version;
    ImGui::SameLine();
    ImGui::TextDisabled("%.4g to %.4g s", state.time_zoom->first, state.time_zoom->second);
  } else {
    ImGui::TextDisabled("wheel: zoom, right drag: pan");
  }
  const ImVec2 size = ImGui::GetContentRegionAvail();
  state.plots_width = std::max(16, static_cast<int>(size.x));
  state.plots_height = std::max(16, static_cast<int>(size.y));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(0, 1), ImVec2(1, 0));
  const bool hovered = ImGui::IsItemHovered(), clicked = ImGui::IsItemClicked();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::vector<render::PlotKind> kinds = shown_plots(state);
  for (std::size_t k = 0; k < frames.size() && k < kinds.size(); ++k) {
    render::PlotFrame f = frames[k];
    f.plot_min = ImVec2(f.plot_min.x + origin.x, f.plot_min.y + origin.y);
    f.plot_max = ImVec2(f.plot_max.x + origin.x, f.plot_max.y + origin.y);
    const float x = f.to_screen(state.play_time, f.log_y ? 1 : f.y_min).x;
    if (x >= f.plot_min.x && x <= f.plot_max.x)
      draw->AddLine(ImVec2(x, f.plot_min.y), ImVec2(x, f.plot_max.y), IM_COL32(240, 240, 240, 220), 1.5f);
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    if (!hovered || mouse.x < f.plot_min.x || mouse.x > f.plot_max.x || mouse.y < f.plot_min.y ||
        mouse.y > f.plot_max.y || state.trajectory.empty())
      continue;
    zoom_and_pan(state, f);
    const double t = f.x_at(mouse.x);
    if (clicked) state.play_time = t, state.playing = false;
    const render::PlotSpec spec = render::trajectory_plot(kinds[k], state.scene, state.trajectory, plot_choice(state));
    ImGui::BeginTooltip();
    ImGui::Text("t = %.4f s", t);
    // This run's values, then the other runs' (dimmed).
    for (const bool ghost : {false, true})
      for (const render::Series& s : spec.series) {
        if (s.x.empty() || s.ghost != ghost) continue;
        const auto it = std::lower_bound(s.x.begin(), s.x.end(), t);
        const std::size_t i = std::min<std::size_t>(it - s.x.begin(), s.x.size() - 1);
        ImVec4 colour = ImGui::ColorConvertU32ToFloat4(s.color);
        if (ghost) colour.w = std::min(colour.w, 0.6f);
        const std::string run = !ghost ? "" : " (" + (s.run.empty() ? std::string("previous run") : s.run) + ")";
        ImGui::TextColored(colour, "%s%s: %.6g", s.label.c_str(), run.c_str(), s.y[i]);
      }
    ImGui::EndTooltip();
  }
}

void export_panel(GuiState& state, Requests& requests) {
  ExportForm& f = state.export_form;
  char* frame_path = f.frame_path;
  char* csv_path = f.csv_path;
  char* dir = f.dir;
  char* video = f.video;
  float& from = f.from;
  float& to = f.to;
  float& fps = f.fps;
  int* size = f.size;
  bool& with_video = f.with_video;
  bool& frames = f.frames;
  if (to <= 0) to = static_cast<float>(state.scene.run.t_end);

  ImGui::SetNextItemWidth(em(200));
  ImGui::InputInt2("size [px]", size);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("of a saved frame and of exported frames and video");
  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##frame", frame_path, sizeof f.frame_path);
  browse_button(state, FileField::frame, "...##frame");
  ImGui::SameLine();
  if (ImGui::Button("Save frame (PNG)")) requests.save_frame = std::string(frame_path);

  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##csv", csv_path, sizeof f.csv_path);
  browse_button(state, FileField::trajectory, "...##csv");
  ImGui::SameLine();
  if (ImGui::Button("Save trajectory (CSV)")) requests.save_trajectory = std::string(csv_path);

  ImGui::Separator();
  ImGui::TextUnformatted("Frames or video of a time range");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("from [s]", &from, 0.1f, 1.0f, "%.3f");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("to [s]", &to, 0.1f, 1.0f, "%.3f");
  ImGui::SetNextItemWidth(em(200));
  ImGui::InputFloat("fps", &fps, 1, 10, "%.1f");
  ImGui::SetNextItemWidth(em(260));
  ImGui::InputText("##directory", dir, sizeof f.dir);
  browse_button(state, FileField::export_dir, "...##dir");
  ImGui::SameLine();
  ImGui::TextUnformatted("directory");
  ImGui::Checkbox("PNG frames", &frames);
  ImGui::SameLine();
  ImGui::Checkbox("video", &with_video);
  if (with_video) {
    ImGui::SetNextItemWidth(em(260));
    ImGui::InputText("##video", video, sizeof f.video);
    browse_button(state, FileField::video, "...##video");
    ImGui::SameLine();
    ImGui::TextUnformatted("video file");
  }
  const ExportProgress& ex = state.export_progress;
  if (ex.active) {
    ImGui::ProgressBar(ex.total ? float(ex.done) / ex.total : 0.0f, ImVec2(-em(90), 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel##export")) requests.cancel_export = true;
  } else if (ImGui::Button("Export")) {
    ExportRequest r;
    r.dir = dir;
    r.frames = frames;
    r.options.from = from;
    r.options.to = to;
    r.options.fps = std::max(1.0f, fps);
    r.options.width = std::clamp(size[0], 16, 8192);
    r.options.height = std::clamp(size[1], 16, 8192);
    if (with_video) r.options.video = std::string(video);
    requests.export_range = r;
  }
  if (!ex.message.empty()) ImGui::TextWrapped("%s", ex.message.c_str());
}

namespace {

// The text field a file field is, and what its dialog looks like.
struct FileFieldSpec {
  char* text;
  std::size_t size;
  const char* title;
  FileDialog::Mode mode;
  std::vector<std::string> extensions;
};

FileFieldSpec file_field_spec(GuiState& state, FileField field) {
  ExportForm& f = state.export_form;
  using Mode = FileDialog::Mode;
  switch (field) {
    case FileField::open_scene:
      return {state.scene_path, sizeof state.scene_path, "Open a scene", Mode::open_file, {".yaml", ".yml"}};
    case FileField::save_scene:
      return {state.save_path, sizeof state.save_path, "Save the scene as", Mode::save_file, {".yaml", ".yml"}};
    case FileField::frame: return {f.frame_path, sizeof f.frame_path, "Save the frame as", Mode::save_file, {".png"}};
    case FileField::trajectory:
      return {f.csv_path, sizeof f.csv_path, "Save the trajectory as", Mode::save_file, {".csv"}};
    case FileField::export_dir: return {f.dir, sizeof f.dir, "Export frames to", Mode::choose_directory, {}};
    case FileField::video: return {f.video, sizeof f.video, "Save the video as", Mode::save_file, {".mp4"}};
    case FileField::none: break;
  }
  return {nullptr, 0, "", Mode::open_file, {}};
}

}  // namespace

void open_file_dialog(GuiState& state, FileField field) {
  const FileFieldSpec spec = file_field_spec(state, field);
  if (!spec.text) return;
  state.file_field = field;
  state.file_dialog.show(spec.title, spec.mode, spec.text, spec.extensions);
}

void browse_button(GuiState& state, FileField field, const char* id) {
  ImGui::SameLine();
  if (ImGui::Button(id)) open_file_dialog(state, field);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("choose with a file browser");
}

void file_dialog_panel(GuiState& state, Requests& requests) {
  const std::optional<std::string> chosen = state.file_dialog.draw();
  if (!chosen) return;
  // Relative to the working directory when inside it: shorter, and what
  // the user typed before.
  std::error_code ec;
  const std::filesystem::path relative = std::filesystem::relative(*chosen, std::filesystem::current_path(ec), ec);
  const std::string path = !ec && !relative.empty() && relative.string().rfind("..", 0) != 0 ? relative.string() : *chosen;
  const FileFieldSpec spec = file_field_spec(state, state.file_field);
  if (spec.text) std::snprintf(spec.text, spec.size, "%s", path.c_str());
  if (state.file_field == FileField::open_scene) requests.open = path;
  state.file_field = FileField::none;
}

void status_bar(const GuiState& state) {
  const RunProgress& p = state.progress;
  const double factor = p.wall_time_s > 0 ? p.t_reached / p.wall_time_s : 0;
  const sim::RunSettings& run = state.scene.run;
  ImGui::Text(
      "simulated %.3f / %.3g s | wall %.3f s | %ld steps | %ld RHS | %.1fx real time | %s rtol %.0e | %s | UI %.0f fps",
      p.t_reached, run.t_end, p.wall_time_s, p.steps, p.rhs_calls, factor, sim::integrator_name(run.integrator),
      run.rtol, p.running ? "running" : sim::run_status_name(p.status), state.fps);
  if (!state.notice.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("| %s", state.notice.c_str());
  }
}

}  // namespace unfurl::app
