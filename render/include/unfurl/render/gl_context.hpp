// An OpenGL 3.3 core context, however it was made: offscreen (OSMesa, for
// headless rendering) or a window's (GLFW, made by the GUI). The renderer
// draws into its own framebuffer objects and needs nothing else from it.
#pragma once

#include <memory>

namespace unfurl::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void make_current() = 0;
};

// An offscreen context needing no display (OSMesa, llvmpipe); loads the GL
// functions. Throws std::runtime_error when no context can be made.
std::unique_ptr<GlContext> make_offscreen_context();

}  // namespace unfurl::render
