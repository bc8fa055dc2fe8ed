// Offscreen GL through EGL's surfaceless platform (Mesa): no display, no
// window system, no default framebuffer (the renderer draws into its own
// framebuffer objects). Mesa picks a GPU render node where it has a driver
// for one, llvmpipe otherwise. glad loads GL through eglGetProcAddress.
#include "gl.hpp"
// clang-format off
#include <EGL/egl.h>
#include <EGL/eglext.h>
// clang-format on

#include <cstdio>
#include <stdexcept>
#include <string>

#include "offscreen_contexts.hpp"

namespace unfurl::render {

namespace {

std::string egl_error(const char* call) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", eglGetError());
  return std::string(call) + " failed (EGL error " + code + ")";
}

class EglContext : public GlContext {
 public:
  EglContext() {
    display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) throw std::runtime_error(egl_error("eglGetPlatformDisplay(surfaceless)"));
    if (!eglInitialize(display_, &major_, &minor_)) throw std::runtime_error(egl_error("eglInitialize"));
    try {
      create();
    } catch (...) {
      eglTerminate(display_);
      throw;
    }
  }

  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  void make_current() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error(egl_error("eglMakeCurrent"));
  }

  std::string description() const override {
    return "EGL " + std::to_string(major_) + "." + std::to_string(minor_) + ", " +
           reinterpret_cast<const char*>(glGetString(GL_VERSION));
  }

 private:
  void create() {
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(egl_error("eglBindAPI(OpenGL)"));
    // The default surface type is a window, which a surfaceless display has
    // none of; its configs offer pbuffers.
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display_, config_attributes, &config, 1, &count) || count < 1)
      throw std::runtime_error(egl_error("eglChooseConfig(OpenGL)"));
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) throw std::runtime_error(egl_error("eglCreateContext(OpenGL 3.3 core)"));
    make_current();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
      throw std::runtime_error("cannot load the OpenGL functions through EGL");
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLint major_ = 0, minor_ = 0;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace unfurl::render
