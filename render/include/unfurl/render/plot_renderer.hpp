// Plots as pictures: a plot drawn on white into an offscreen framebuffer and
// read back. Needs a current GL context; knows nothing of scenes.
#pragma once

#include "unfurl/render/framebuffer.hpp"
#include "unfurl/render/imgui_layer.hpp"
#include "unfurl/render/plot.hpp"

namespace unfurl::render {

class PlotRenderer {
 public:
  PlotRenderer(int width, int height);

  // The plot filling the whole picture; returns where its axes are.
  PlotFrame draw(const PlotSpec& spec, Image& out);

 private:
  Framebuffer framebuffer_;
  ImGuiLayer imgui_;
};

}  // namespace unfurl::render
