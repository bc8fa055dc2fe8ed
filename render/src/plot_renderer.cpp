#include "unfurl/render/plot_renderer.hpp"

#include "gl.hpp"

#include <algorithm>

namespace unfurl::render {

PlotRenderer::PlotRenderer(int width, int height)
    : framebuffer_(width, height), imgui_(std::max(14.0f, height / 40.0f)) {}

PlotFrame PlotRenderer::draw(const PlotSpec& spec, Image& out) {
  framebuffer_.bind();
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const int w = framebuffer_.width(), h = framebuffer_.height();
  imgui_.begin_frame(w, h);
  const PlotFrame frame =
      draw_plot(imgui_.draw_list(), ImVec2(0, 0), ImVec2(static_cast<float>(w), static_cast<float>(h)), spec, true);
  imgui_.end_frame();
  framebuffer_.resolve();
  framebuffer_.read(out);
  return frame;
}

}  // namespace unfurl::render
