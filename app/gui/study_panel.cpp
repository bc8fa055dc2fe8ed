// The Study tab: a finished study's counts, histograms of its headline
// outputs and the table of its cases; a click on a case shows it.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gui_panels.hpp"

namespace unfurl::app {

namespace {

ImVec4 status_colour(studies::CaseStatus status) {
  switch (status) {
    case studies::CaseStatus::deployed:
      return ImVec4(0.55f, 0.85f, 0.55f, 1);
    case studies::CaseStatus::not_deployed:
      return ImVec4(1.0f, 0.7f, 0.3f, 1);
    case studies::CaseStatus::failed:
      return ImVec4(1.0f, 0.4f, 0.4f, 1);
  }
  return ImVec4(1, 1, 1, 1);
}

// A histogram of output `name` over the deployed cases, 20 bins.
void histogram(const StudyBrowser& b, const std::string& name, const char* unit, float width_px) {
  std::vector<double> x;
  const auto it = std::find(b.columns.outputs.begin(), b.columns.outputs.end(), name);
  if (it == b.columns.outputs.end()) return;
  const std::size_t k = static_cast<std::size_t>(it - b.columns.outputs.begin());
  for (const studies::CaseResult& r : b.rows)
    if (r.status == studies::CaseStatus::deployed && std::isfinite(r.outputs[k])) x.push_back(r.outputs[k]);
  if (x.empty()) return;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  constexpr int kBins = 20;
  float bins[kBins] = {};
  const double width = (*hi - *lo) / kBins;
  for (double v : x) bins[width > 0 ? std::min(kBins - 1, static_cast<int>((v - *lo) / width)) : 0] += 1;
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "%.4g .. %.4g %s", *lo, *hi, unit);
  ImGui::PlotHistogram(("##" + name).c_str(), bins, kBins, 0, overlay, 0, FLT_MAX,
                       ImVec2(width_px, 60));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s over the %zu deployed cases", name.c_str(), x.size());
}

void cases_table(StudyBrowser& b, Requests& requests) {
  const int n = static_cast<int>(b.table_columns.size());
  const ImGuiTableFlags flags = ImGuiTableFlags_Sortable | ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersV | ImGuiTableFlags_Resizable |
                                ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("cases", n, flags, ImGui::GetContentRegionAvail())) return;
  ImGui::TableSetupScrollFreeze(1, 1);
  for (int d = 0; d < n; ++d) {
    const int column = b.table_columns[d];
    ImGui::TableSetupColumn(b.column_name(column).c_str(), d == 0 ? ImGuiTableColumnFlags_DefaultSort : 0, 0,
                            static_cast<ImGuiID>(column));
  }
  ImGui::TableHeadersRow();
  if (ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs && specs->SpecsDirty) {
    if (specs->SpecsCount > 0)
      b.sort(static_cast<int>(specs->Specs[0].ColumnUserID), specs->Specs[0].SortDirection == ImGuiSortDirection_Ascending);
    specs->SpecsDirty = false;
  }
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(b.order.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const studies::CaseResult& r = b.rows[b.order[i]];
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      if (ImGui::Selectable(r.id.c_str(), r.id == b.shown, ImGuiSelectableFlags_SpanAllColumns))
        requests.open_case = r.id;
      if (ImGui::IsItemHovered() && (!r.failure.empty() || !r.reason.empty()))
        ImGui::SetTooltip("%s%s%s", r.failure.c_str(), r.failure.empty() || r.reason.empty() ? "" : ": ",
                          r.reason.c_str());
      ImGui::TableSetColumnIndex(1);
      ImGui::TextColored(status_colour(r.status), "%s", studies::case_status_name(r.status));
      for (int d = 2; d < n; ++d) {
        ImGui::TableSetColumnIndex(d);
        const double v = b.value(r, b.table_columns[d]);
        if (std::isnan(v))
          ImGui::TextDisabled("-");
        else
          ImGui::Text("%.6g", v);
      }
    }
  }
  ImGui::EndTable();
}

}  // namespace

void study_panel(GuiState& state, Requests& requests) {
  StudyBrowser& b = *state.study;
  long count[3] = {0, 0, 0};
  for (const studies::CaseResult& r : b.rows) ++count[static_cast<int>(r.status)];
  ImGui::TextWrapped("%s: %zu of %zu cases finished in %s", b.study_path.c_str(), b.rows.size(), b.cases.size(),
                     b.dir.c_str());
  ImGui::TextColored(status_colour(studies::CaseStatus::deployed), "%ld deployed", count[0]);
  ImGui::SameLine();
  ImGui::TextColored(status_colour(studies::CaseStatus::not_deployed), "%ld not deployed", count[1]);
  ImGui::SameLine();
  ImGui::TextColored(status_colour(studies::CaseStatus::failed), "%ld failed", count[2]);
  const float half = 0.5f * ImGui::GetContentRegionAvail().x - 4;
  ImGui::TextDisabled("deployment time");
  ImGui::SameLine(half + 8);
  ImGui::TextDisabled("peak latch torque");
  histogram(b, "deployment_time", "s", half);
  ImGui::SameLine(half + 8);
  histogram(b, "peak_latch_torque", "N m", half);
  if (b.shown.empty())
    ImGui::TextDisabled("Click a case to show it (it re-runs here; the panel's edits apply on top).");
  else
    ImGui::Text("On show: %s", b.shown.c_str());
  const std::size_t hidden = static_cast<std::size_t>(b.column_count()) - b.table_columns.size();
  if (hidden > 0)
    ImGui::TextDisabled("%zu more columns (per latch, per joint) are in %s/cases.csv", hidden, b.dir.c_str());
  cases_table(b, requests);
}

}  // namespace unfurl::app
