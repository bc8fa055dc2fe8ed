// The scene's parameters: every force element's, the regulator's and the
// integrator's; undo, redo, saving the edited scene.
#include "gui_panels.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

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
      const std::vector<sim::ElementParameter> parameters = e.parameters(scene.model);
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

// The regulator's bandwidth: automatic (chosen from the mechanism's own
// rate; the last run's choice shown) or set by the scene.
void bandwidth_field(const GuiState& state, Requests& requests) {
  const std::optional<double>& v_max = state.scene.regulator.v_max;
  const std::optional<sim::ClosureTuning>& last = state.progress.closure;
  bool automatic = !v_max;
  if (ImGui::Checkbox("automatic bandwidth", &automatic))
    requests.edit = sim::Override{"regulator.v_max", automatic ? "auto" : sim::format_number(last ? last->v_max : 2000)};
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("v_max chosen from the mechanism's fastest own rate (%g x that rate)",
                      sim::Regulator::kBandwidthPerRate);
  if (v_max) {
    value_field("v_max [rad/s]", "regulator.v_max", *v_max, 10, requests, 1e-3, 1e9, "%.6g",
                "the regulator's bandwidth: how fast it closes a loop's gap");
  } else if (last) {
    ImGui::TextDisabled("v_max %.4g rad/s (rate %.3g rad/s, length %.3g m)", last->v_max, last->rate, last->length);
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
    bandwidth_field(state, requests);
    value_field("p0", "regulator.p0", r.p0, 0.01, requests, 1e-3, 100, "%.6g", "pole placement of the PID gains (16)");
    value_field("p1", "regulator.p1", r.p1, 0.01, requests, 1e-3, 0.999, "%.6g",
                "pole placement of the PID gains (16)");
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

}  // namespace unfurl::app
