// Dear ImGui for drawing 2D on top of a frame (overlay text, plots) in a
// context without a window: the frame's size is given, no input is read.
// The GUI makes its own ImGui context with GLFW; the drawing functions
// (overlay, plots) take an ImDrawList and serve both.
#pragma once

#include <imgui.h>

namespace unfurl::render {

// Loads DejaVu Sans (Debian's fonts-dejavu-core) at `pixels`, or ImGui's
// built-in font when it is missing, into the current context's atlas.
ImFont* load_font(float pixels);

class ImGuiLayer {
 public:
  explicit ImGuiLayer(float font_pixels = 18);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts a frame of width x height; draw through draw_list(). The
  // caller's own ImGui context (a GUI's) is set aside until end_frame().
  void begin_frame(int width, int height);
  // Renders what was drawn into the bound framebuffer.
  void end_frame();
  ImDrawList* draw_list() const { return ImGui::GetForegroundDrawList(); }

 private:
  ImGuiContext* context_ = nullptr;
  ImGuiContext* callers_ = nullptr;
};

}  // namespace unfurl::render
