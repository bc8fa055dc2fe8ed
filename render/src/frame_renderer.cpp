#include "unfurl/render/frame_renderer.hpp"

#include <algorithm>
#include <cstdio>

namespace unfurl::render {

FrameRenderer::FrameRenderer(const sim::Scene& scene, const sim::SceneVisuals& visuals, int width, int height,
                             std::vector<std::string> mesh_directories)
    : scene_name_(scene.name),
      meshes_(std::move(mesh_directories)),
      framebuffer_(width, height),
      view_(std::make_unique<SceneView>(scene, visuals, meshes_)),
      imgui_(std::max(14.0f, height / 40.0f)) {}

void draw_overlay(ImDrawList* draw, const std::string& scene_name, const std::string& caption,
                  const std::string& legend) {
  const char* time = caption.c_str();
  const float font = ImGui::GetFontSize();
  const ImVec2 at(0.8f * font, 0.6f * font);
  const ImVec2 name_size = ImGui::CalcTextSize(scene_name.c_str()), time_size = ImGui::CalcTextSize(time);
  const float w = std::max({name_size.x, time_size.x, ImGui::CalcTextSize(legend.c_str()).x});
  const float lines = legend.empty() ? 2 : 3;
  draw->AddRectFilled(ImVec2(at.x - 0.4f * font, at.y - 0.3f * font),
                      ImVec2(at.x + w + 0.4f * font, at.y + (1.2f * lines + 0.1f) * font), IM_COL32(0, 0, 0, 110),
                      0.3f * font);
  draw->AddText(at, IM_COL32(255, 255, 255, 255), scene_name.c_str());
  draw->AddText(ImVec2(at.x, at.y + 1.2f * font), IM_COL32(210, 220, 255, 255), time);
  if (!legend.empty()) draw->AddText(ImVec2(at.x, at.y + 2.4f * font), IM_COL32(255, 200, 190, 255), legend.c_str());
}

std::string time_caption(double t) {
  char time[64];
  std::snprintf(time, sizeof time, "t = %.3f s", t);
  return time;
}

void FrameRenderer::frame(const std::vector<sim::Pose>& poses, double t, const Camera& camera, Image& out) {
  frame(poses, time_caption(t), camera, out);
}

void FrameRenderer::frame(const std::vector<sim::Pose>& poses, const std::string& caption, const Camera& camera,
                          Image& out, const std::vector<LoadArrow>& arrows, const std::string& legend) {
  framebuffer_.bind();
  view_->draw(poses, camera, width(), height(), arrows);
  imgui_.begin_frame(width(), height());
  draw_overlay(imgui_.draw_list(), scene_name_, caption, legend);
  imgui_.end_frame();
  framebuffer_.resolve();
  framebuffer_.read(out);
}

}  // namespace unfurl::render
