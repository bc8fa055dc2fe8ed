// The 3D view and its camera controls.
#include "gui_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

void viewport_panel(GuiState& state, unsigned texture, const Eigen::AlignedBox3f& bounds) {
  // The presets, the active one highlighted (until the view is orbited).
  for (const std::string& name : render::camera_preset_names()) {
    const bool active = name == state.camera_name;
    if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    if (ImGui::SmallButton(name.c_str())) {
      const bool orthographic = state.camera.orthographic;
      state.camera =
          *render::camera_preset(name, bounds, float(state.viewport_width) / std::max(1, state.viewport_height));
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
      ImGui::SetTooltip(
          "on: the camera moves with the free-floating bus; off: it stays in the inertial frame, where "
          "the bus turns and drifts");
  }
  ImGui::SameLine();
  ImGui::Checkbox("loads", &state.show_loads);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "arrows at the play-head: each hinge's force on its child (green; grey where rigid loops leave the forces "
        "undetermined) and each engaged latch's torque (violet, double-headed, right-hand rule)");
  if (state.show_loads) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(em(130));
    ImGui::SliderFloat("##load_scale", &state.load_scale, 0.1f, 10.0f, "arrows x%.2g", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the arrows' length: the run's largest load is this times a quarter of the array");
  }
  if (state.scene.model.has_flexible_bodies()) {  // on a row of its own: the toolbar is full
    ImGui::SetNextItemWidth(em(160));
    ImGui::SliderFloat("##exaggeration", &state.exaggeration, 1.0f, 1000.0f, "bending x%.3g",
                       ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("flexible bodies' elastic displacements drawn this many times");
  }
  const ImVec2 size = ImGui::GetContentRegionAvail();
  state.viewport_width = std::max(16, static_cast<int>(size.x));
  state.viewport_height = std::max(16, static_cast<int>(size.y));
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture)), size, ImVec2(0, 1), ImVec2(1, 0));
  if (state.modes.shown >= 0 && state.modes.result) {
    const sim::Mode& m = state.modes.result->modes[state.modes.shown];
    char label[96];
    std::snprintf(label, sizeof label, "mode %d: %.4g Hz (%s), animated", state.modes.shown + 1, m.frequency_hz,
                  sim::mode_kind_name(m.kind));
    ImGui::GetWindowDrawList()->AddText(ImVec2(corner.x + em(8), corner.y + em(6)), IM_COL32(255, 255, 255, 255),
                                        label);
  }
  if (state.show_loads && !state.load_legend.empty() && state.modes.shown < 0)
    ImGui::GetWindowDrawList()->AddText(ImVec2(corner.x + em(0.6f), corner.y + size.y - em(1.6f)),
                                        IM_COL32(255, 200, 190, 255), state.load_legend.c_str());
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

}  // namespace unfurl::app
