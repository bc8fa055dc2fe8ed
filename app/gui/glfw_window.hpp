// The platform adapter: a GLFW window with an OpenGL 3.3 core context, GL
// functions loaded through glad. The rest of the GUI does not know GLFW.
#pragma once

#include <string>

#include "unfurl/render/gl_context.hpp"

struct GLFWwindow;

namespace unfurl::app {

class GlfwWindow : public render::GlContext {
 public:
  // Throws std::runtime_error when there is no display or no GL 3.3.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  void make_current() override;
  std::string description() const override;
  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void swap();
  void framebuffer_size(int& width, int& height) const;
  // The monitor's content scale (1 on a standard display, 2 on a HiDPI
  // one), as GLFW reports it for the window.
  float content_scale() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace unfurl::app
