#include "unfurl/render/gl_context.hpp"

#include <stdexcept>

#include "offscreen_contexts.hpp"

namespace unfurl::render {

std::optional<GlBackend> parse_gl_backend(const std::string& name) {
  if (name == "auto") return GlBackend::automatic;
  if (name == "egl") return GlBackend::egl;
  if (name == "osmesa") return GlBackend::osmesa;
  return std::nullopt;
}

const char* gl_backend_name(GlBackend backend) {
  switch (backend) {
    case GlBackend::automatic: return "auto";
    case GlBackend::egl: return "egl";
    case GlBackend::osmesa: return "osmesa";
  }
  return "?";
}

std::vector<GlBackend> available_gl_backends() {
  std::vector<GlBackend> out;
#ifdef UNFURL_HAVE_EGL
  out.push_back(GlBackend::egl);
#endif
#ifdef UNFURL_HAVE_OSMESA
  out.push_back(GlBackend::osmesa);
#endif
  return out;
}

std::unique_ptr<GlContext> make_offscreen_context(GlBackend backend) {
  std::string why;
#ifdef UNFURL_HAVE_EGL
  if (backend != GlBackend::osmesa) {
    try {
      return make_egl_context();
    } catch (const std::exception& e) {
      if (backend == GlBackend::egl) throw;
      why = e.what();
    }
  }
#endif
#ifdef UNFURL_HAVE_OSMESA
  if (backend != GlBackend::egl) return make_osmesa_context();
#endif
  throw std::runtime_error(std::string("no offscreen OpenGL context: this build has no ") + gl_backend_name(backend) +
                           " backend" + (why.empty() ? "" : " (EGL: " + why + ")"));
}

}  // namespace unfurl::render
