#include "unfurl/render/imgui_layer.hpp"

#include <imgui_impl_opengl3.h>

#include <filesystem>
#include <stdexcept>

namespace unfurl::render {

ImFont* load_font(float pixels) {
  ImGuiIO& io = ImGui::GetIO();
  const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    ImFontConfig config;
    config.OversampleH = 2;
    if (ImFont* font = io.Fonts->AddFontFromFileTTF(path, pixels, &config)) return font;
  }
  ImFontConfig config;
  config.SizePixels = pixels;
  return io.Fonts->AddFontDefault(&config);
}

ImGuiLayer::ImGuiLayer(float font_pixels) {
  ImGuiContext* callers = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  load_font(font_pixels);
  const bool ok = ImGui_ImplOpenGL3_Init("#version 330");
  ImGui::SetCurrentContext(callers);
  if (!ok) throw std::runtime_error("cannot set up Dear ImGui's OpenGL backend");
}

ImGuiLayer::~ImGuiLayer() {
  ImGuiContext* callers = ImGui::GetCurrentContext();
  ImGui::SetCurrentContext(context_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_);
  ImGui::SetCurrentContext(callers == context_ ? nullptr : callers);
}

void ImGuiLayer::begin_frame(int width, int height) {
  callers_ = ImGui::GetCurrentContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = 1.0f / 30;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::end_frame() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ImGui::SetCurrentContext(callers_);
}

}  // namespace unfurl::render
