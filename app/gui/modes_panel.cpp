// The Modes tab: the natural frequencies of the current run's deployed
// end, and one mode animated in the view.
#include <cstdio>

#include "gui_panels.hpp"
#include "panel_widgets.hpp"

namespace unfurl::app {

namespace {

void modes_table(GuiState& state, Requests& requests, const sim::ModesResult& r) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_ScrollY;
  if (!ImGui::BeginTable("modes", 4, flags, ImVec2(0, em(260)))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("mode");
  ImGui::TableSetupColumn("kind");
  ImGui::TableSetupColumn("frequency, Hz");
  ImGui::TableSetupColumn("damping ratio");
  ImGui::TableHeadersRow();
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const sim::Mode& m = r.modes[k];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    char label[32];
    std::snprintf(label, sizeof label, "%zu", k + 1);
    const bool shown = state.modes.shown == static_cast<int>(k);
    if (ImGui::Selectable(label, shown, ImGuiSelectableFlags_SpanAllColumns))
      requests.show_mode = shown ? -1 : static_cast<int>(k);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(shown ? "back to the run" : "animate this mode in the view");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(sim::mode_kind_name(m.kind));
    ImGui::TableNextColumn();
    ImGui::Text("%.5g", m.frequency_hz);
    ImGui::TableNextColumn();
    if (m.kind == sim::ModeKind::elastic) ImGui::Text("%.4g", m.damping_ratio);
  }
  ImGui::EndTable();
}

}  // namespace

void modes_panel(GuiState& state, Requests& requests) {
  ModesView& v = state.modes;
  const bool finished = state.run_pinnable();
  ImGui::BeginDisabled(!finished || v.current(state.generation));
  if (ImGui::Button("Compute the deployed state's modes")) requests.compute_modes = true;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(!finished ? "once the run has finished"
                                : "linearized about where the run ends, settled to its static equilibrium; "
                                  "loops respected (unfurl modes)");
  if (!v.error.empty()) ImGui::TextWrapped("%s", v.error.c_str());
  if (!v.current(state.generation)) {
    if (v.result) ImGui::TextDisabled("the modes shown were of an earlier run");
    if (!v.result) return;
  }
  const sim::ModesResult& r = *v.result;
  ImGui::Text("%d coordinates", r.coordinates);
  if (r.loop_rank > 0) {
    ImGui::SameLine();
    ImGui::Text(", %d independent", r.coordinates - r.loop_rank);
  }
  if (r.weak_loop_directions > 0)
    ImGui::TextWrapped("The loops are near a branch point here: %d constraints hold only weakly, and the real "
                       "array's frequencies depend on its pins' compliance.",
                       r.weak_loop_directions);
  ImGui::SetNextItemWidth(em(160));
  if (ImGui::SliderFloat("amplitude, rad", &v.amplitude, 0.01f, 0.5f, "%.2f") && v.shown >= 0)
    requests.show_mode = v.shown;
  if (v.shown >= 0) {
    ImGui::SameLine();
    if (ImGui::SmallButton("back to the run")) requests.show_mode = -1;
  }
  modes_table(state, requests, r);
}

}  // namespace unfurl::app
