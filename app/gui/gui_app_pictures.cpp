// Pictures from the workbench: the view as PNG, a screenshot of the whole
// window, camera presets for scripts.
#include "gui_app.hpp"

#include <cstdio>

#include "unfurl/io/output_file.hpp"
#include "unfurl/io/png_file.hpp"
#include "unfurl/render/window_surface.hpp"

namespace unfurl::app {

void GuiApp::save_view_png(const std::string& path) {
  try {
    const std::string dir = std::filesystem::path(path).parent_path().string();
    if (!dir.empty()) io::make_directory(dir);
    // At the export form's size, not the viewport's: the same camera and
    // play-head, drawn again off screen.
    const int w = std::clamp(state_.export_form.size[0], 16, 8192),
              h = std::clamp(state_.export_form.size[1], 16, 8192);
    render::FrameRenderer renderer(state_.scene, state_.visuals, w, h, mesh_directories(state_.scene));
    std::vector<sim::Pose> poses;
    current_poses(poses);
    std::vector<double> q;
    current_coordinates(q);
    renderer.deform(state_.scene.model, q.data(), state_.exaggeration);
    std::string legend;
    const std::vector<render::LoadArrow> arrows = current_load_arrows(poses, legend);
    render::Image image;
    renderer.frame(poses, render::time_caption(state_.play_time), state_.camera, image, arrows, legend);
    io::write_png(image, path);
    state_.notice = "saved " + path + " (" + std::to_string(w) + "x" + std::to_string(h) + ")";
  } catch (const std::exception& e) {
    state_.notice = e.what();
  }
}

void GuiApp::screenshot(const std::string& path) {
  int W = 0, H = 0;
  window_.framebuffer_size(W, H);
  render::Image image;
  render::read_window(W, H, image);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  if (!dir.empty()) io::make_directory(dir);
  io::write_png(image, path, 6);
}

void GuiApp::camera_preset(const std::string& name) {
  if (const auto cam = render::camera_preset(name, swept_bounds(),
                                             float(state_.viewport_width) / std::max(1, state_.viewport_height))) {
    const bool orthographic = state_.camera.orthographic;
    state_.camera = *cam;
    state_.camera.orthographic = orthographic;
    state_.camera_name = name;
    state_.camera_fitted = true;
  }
}

}  // namespace unfurl::app
