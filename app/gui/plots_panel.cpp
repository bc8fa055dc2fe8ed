// The plots panel: the plots' texture, the play-head, values on hover,
// zoom and pan, the joints drawn.
#include "gui_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

std::vector<render::PlotKind> plot_kinds(const GuiState& state) {
  std::vector<render::PlotKind> kinds = render::plot_kinds(state.scene);
  if (!state.scene.latches().empty()) kinds.push_back(render::PlotKind::torque_margin);
  return kinds;
}

std::vector<render::PlotKind> shown_plots(const GuiState& state) {
  const std::vector<render::PlotKind> kinds = plot_kinds(state);
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
  if (state.progress.summary) choice.torque_margins = &state.progress.summary->torque_margins;
  choice.required_factor = state.scene.torque_margin.required;
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
  const std::vector<render::PlotKind> all = plot_kinds(state);
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

}  // namespace unfurl::app
