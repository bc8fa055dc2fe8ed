// Offscreen GL through OSMesa. glad must come before GL/osmesa.h.
#include "gl.hpp"
// clang-format off
#include <GL/osmesa.h>
// clang-format on

#include <stdexcept>
#include <string>
#include <vector>

#include "offscreen_contexts.hpp"

namespace unfurl::render {

namespace {

class OsmesaContext : public GlContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("cannot create an OSMesa OpenGL 3.3 core context");
    make_current();
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress)))
      throw std::runtime_error("cannot load the OpenGL functions through OSMesa");
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  std::string description() const override {
    return std::string("OSMesa, ") + reinterpret_cast<const char*>(glGetString(GL_VERSION));
  }

  void make_current() override {
    // The renderer draws into its own framebuffers; the context's own buffer
    // only has to exist.
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSide, kSide))
      throw std::runtime_error("OSMesaMakeCurrent failed");
  }

 private:
  static constexpr int kSide = 16;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(kSide * kSide * 4);
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsmesaContext>(); }

}  // namespace unfurl::render
