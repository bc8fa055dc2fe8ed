#include "glfw_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>

#include "unfurl/render/window_surface.hpp"

namespace unfurl::app {

namespace {
std::string last_glfw_error;
void remember_error(int, const char* description) { last_glfw_error = description; }
}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  glfwSetErrorCallback(remember_error);
  if (!glfwInit()) throw std::runtime_error("cannot open a window (" + last_glfw_error + "); is DISPLAY set?");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 window (" + last_glfw_error + ")");
  }
  make_current();
  if (!render::load_gl_functions(glfwGetProcAddress)) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw std::runtime_error("cannot load the OpenGL functions");
  }
  glfwSwapInterval(1);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::make_current() { glfwMakeContextCurrent(window_); }
std::string GlfwWindow::description() const { return "GLFW window"; }
bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_) != 0; }
void GlfwWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::swap() { glfwSwapBuffers(window_); }
void GlfwWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

float GlfwWindow::content_scale() const {
  float x = 1, y = 1;
  glfwGetWindowContentScale(window_, &x, &y);
  return y > 0 ? y : 1;
}

}  // namespace unfurl::app
