// An OpenGL 3.3 core context, however it was made: offscreen (EGL's
// surfaceless platform or OSMesa, for headless rendering) or a window's
// (GLFW, made by the workbench). The renderer draws into its own
// framebuffer objects and needs nothing else from it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace unfurl::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void make_current() = 0;
  // "EGL 1.5, 4.5 (Core Profile) Mesa 22.3.6", for reports.
  virtual std::string description() const = 0;
};

// How to make an offscreen context: EGL (surfaceless: Mesa's llvmpipe, or a
// GPU where Mesa has a driver for one), OSMesa (removed from Mesa in 25.1),
// or automatic (EGL when it works, else OSMesa).
enum class GlBackend { automatic, egl, osmesa };

// "auto", "egl", "osmesa"; nullopt for anything else.
std::optional<GlBackend> parse_gl_backend(const std::string& name);
const char* gl_backend_name(GlBackend backend);

// The backends this build has.
std::vector<GlBackend> available_gl_backends();

// An offscreen context needing no display; loads the GL functions. Throws
// std::runtime_error when none can be made (naming why).
std::unique_ptr<GlContext> make_offscreen_context(GlBackend backend = GlBackend::automatic);

}  // namespace unfurl::render
