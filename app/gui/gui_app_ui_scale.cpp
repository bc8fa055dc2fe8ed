// Fonts and sizes for the UI scale and the monitor's content scale; the
// frame-time statistics the session report gives.
#include "gui_app.hpp"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>

namespace unfurl::app {

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

}  // namespace unfurl::app
