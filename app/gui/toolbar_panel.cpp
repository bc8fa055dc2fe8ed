// The toolbar: the scene field, open, reload, the UI scale, the
// re-simulating indicator and errors.
#include "gui_panels.hpp"

#include <cmath>
#include <cstdio>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

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

}  // namespace unfurl::app
