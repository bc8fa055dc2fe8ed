// Pictures of a scene: 3D frames with the overlay (scene name, time), drawn
// into an offscreen framebuffer and read back. One per GL
// context; the context must be current.
#pragma once

#include <memory>
#include <string>

#include "unfurl/render/camera.hpp"
#include "unfurl/render/framebuffer.hpp"
#include "unfurl/render/imgui_layer.hpp"
#include "unfurl/render/mesh_library.hpp"
#include "unfurl/render/scene_view.hpp"

namespace unfurl::render {

class FrameRenderer {
 public:
  // Throws std::runtime_error when a mesh is missing or GL fails.
  FrameRenderer(const sim::Scene& scene, const sim::SceneVisuals& visuals, int width, int height,
                std::vector<std::string> mesh_directories);

  const SceneView& view() const { return *view_; }
  // Flexible bodies drawn bent as at q (SceneView::deform).
  void deform(const sim::Model& model, const double* q, double exaggeration) { view_->deform(model, q, exaggeration); }
  int width() const { return framebuffer_.width(); }
  int height() const { return framebuffer_.height(); }

  // The scene at these poses, labelled with the scene name and time.
  void frame(const std::vector<sim::Pose>& poses, double t, const Camera& camera, Image& out);
  // The same with another second line ("mode 1: 0.413 Hz"), and loads
  // drawn as arrows with their legend as a third line.
  void frame(const std::vector<sim::Pose>& poses, const std::string& caption, const Camera& camera, Image& out,
             const std::vector<LoadArrow>& arrows = {}, const std::string& legend = "");

 private:
  std::string scene_name_;
  MeshLibrary meshes_;
  Framebuffer framebuffer_;
  std::unique_ptr<SceneView> view_;
  ImGuiLayer imgui_;
};

// Writes the scene name and a caption (the time) in the top-left corner,
// and a legend (the load arrows') under them when there is one.
void draw_overlay(ImDrawList* draw, const std::string& scene_name, const std::string& caption,
                  const std::string& legend = "");
// "t = 1.500 s".
std::string time_caption(double t);

}  // namespace unfurl::render
