// The timeline: play, pause, speed, single steps, the scrubber with the
// computed span, the latches and the spans of contact marked.
#include "gui_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "panel_widgets.hpp"
#include "unfurl/io/output_file.hpp"
#include "unfurl/render/trajectory_plots.hpp"
#include "unfurl/sim/number_text.hpp"

namespace unfurl::app {

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
  draw->AddRectFilled(ImVec2(lo.x, hi.y - 3), ImVec2(lo.x + computed * (hi.x - lo.x), hi.y),
                      IM_COL32(80, 170, 255, 200));
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
  // Spans in which two bodies not jointed together touch or interpenetrate:
  // an orange band along the top, the pair on hover.
  if (state.progress.summary && state.progress.summary->clearance)
    for (const sim::ClearanceContact& c : state.progress.summary->clearance->contacts) {
      const float x0 = lo.x + static_cast<float>(c.t_begin / t_end) * (hi.x - lo.x);
      const float x1 = std::max(x0 + 2, lo.x + static_cast<float>(c.t_end / t_end) * (hi.x - lo.x));
      draw->AddRectFilled(ImVec2(x0, lo.y), ImVec2(x1, lo.y + 4), IM_COL32(255, 150, 30, 255));
      if (hovered && mouse_x >= x0 - 3 && mouse_x <= x1 + 3) {
        char line[256];
        std::snprintf(line, sizeof line, "%s%s and %s touch or interpenetrate from %.6f s to %.6f s",
                      names.empty() ? "" : "\n", c.body_a.c_str(), c.body_b.c_str(), c.t_begin, c.t_end);
        names += line;
      }
    }
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

}  // namespace unfurl::app
