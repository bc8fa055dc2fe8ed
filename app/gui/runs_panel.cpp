// The Runs tab: pin the current run under a name, name, show or drop the
// pinned runs, and the table of their differences from the current run.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gui_panels.hpp"

namespace unfurl::app {

namespace {

// A name that says what the run was: its edits, or the file's values.
std::string default_pin_name(const GuiState& state) {
  std::string name = state.study && !state.study->shown.empty() ? state.study->shown : "file values";
  if (!state.edits.empty()) {
    const sim::Override& last = state.edits.back();
    const std::size_t dot = last.path.find('.');
    name = (dot == std::string::npos ? last.path : last.path.substr(dot + 1)) + "=" + last.value;
    if (state.edits.size() > 1) name += " +" + std::to_string(state.edits.size() - 1);
  }
  return name;
}

// A pinned run's figure as its difference from the current run's (the
// value itself on hover): the column reads as what changed.
void difference_cell(double value, double current) {
  if (!std::isfinite(value)) {
    ImGui::TextDisabled("-");
  } else if (!std::isfinite(current)) {
    ImGui::Text("%.6g", value);
  } else if (value == current) {
    ImGui::TextDisabled("same");
  } else {
    const double d = value - current;
    // Differences below a part in 1e9 are the integrator's noise, not the change.
    const bool noise = std::abs(d) <= 1e-9 * std::max(std::abs(current), std::abs(value));
    ImGui::TextColored(noise ? ImVec4(0.6f, 0.6f, 0.6f, 1) : ImVec4(1.0f, 0.85f, 0.4f, 1), "%+.4g", d);
  }
  if (ImGui::IsItemHovered() && std::isfinite(value)) ImGui::SetTooltip("%.10g", value);
}

void difference_table(const GuiState& state) {
  const std::vector<ComparisonRow> rows = compare_runs(*state.progress.summary, state.pinned);
  const int columns = 2 + static_cast<int>(state.pinned.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit |
                                ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY;
  if (!ImGui::BeginTable("differences", columns, flags, ImVec2(0, 0))) return;
  ImGui::TableSetupScrollFreeze(1, 1);
  ImGui::TableSetupColumn("figure");
  ImGui::TableSetupColumn("current");
  for (const PinnedRun& p : state.pinned) ImGui::TableSetupColumn(p.name.c_str());
  ImGui::TableHeadersRow();
  for (const ComparisonRow& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.name.c_str());
    ImGui::TableNextColumn();
    if (std::isfinite(row.current))
      ImGui::Text("%.6g", row.current);
    else
      ImGui::TextDisabled("-");
    for (double v : row.pinned) {
      ImGui::TableNextColumn();
      difference_cell(v, row.current);
    }
  }
  ImGui::EndTable();
}

}  // namespace

void runs_panel(GuiState& state, Requests& requests) {
  const bool finished = state.run_pinnable();
  // The name field offers a name for each new run; what is typed stays
  // until the run changes.
  if (const std::string offered = default_pin_name(state); offered != state.pin_name_offered) {
    std::snprintf(state.pin_name, sizeof state.pin_name, "%s", offered.c_str());
    state.pin_name_offered = offered;
  }
  ImGui::SetNextItemWidth(em(220));
  ImGui::InputText("##pin_name", state.pin_name, sizeof state.pin_name);
  ImGui::SameLine();
  ImGui::BeginDisabled(!finished);
  if (ImGui::Button("Pin this run")) requests.pin = std::string(state.pin_name);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(finished ? "Keep this run for comparison: drawn in the plots, tabled below"
                               : "The run is still computing (or failed to start)");
  for (std::size_t k = 0; k < state.pinned.size(); ++k) {
    PinnedRun& p = state.pinned[k];
    ImGui::PushID(static_cast<int>(k));
    ImGui::ColorButton("##colour", ImGui::ColorConvertU32ToFloat4(p.color), ImGuiColorEditFlags_NoTooltip);
    ImGui::SameLine();
    if (ImGui::Checkbox("##shown", &p.shown)) ++state.plots_version;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("draw it in the plots");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(em(220));
    if (ImGui::InputText("##name", p.name_field, sizeof p.name_field, ImGuiInputTextFlags_EnterReturnsTrue) ||
        ImGui::IsItemDeactivatedAfterEdit()) {
      p.name = p.name_field;
      ++state.plots_version;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) requests.unpin = k;
    ImGui::PopID();
  }
  ImGui::Separator();
  if (state.pinned.empty()) {
    ImGui::TextWrapped("Pin runs to compare them: each one is drawn in the plots in its colour, and "
                       "tabled here against the current run.");
    return;
  }
  if (!state.progress.summary) {
    ImGui::TextDisabled("the table fills in when the current run finishes");
    return;
  }
  ImGui::TextDisabled("pinned runs: difference from the current run (hover for the value)");
  difference_table(state);
}

}  // namespace unfurl::app
