#include "unfurl/render/window_surface.hpp"

#include <algorithm>
#include <vector>

#include "gl.hpp"

namespace unfurl::render {

bool load_gl_functions(GlProcLoader get_proc) { return gladLoadGL(reinterpret_cast<GLADloadfunc>(get_proc)) != 0; }

void begin_window_frame(int width, int height, float red, float green, float blue) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  clear_bound_framebuffer(red, green, blue);
}

void clear_bound_framebuffer(float red, float green, float blue) {
  glClearColor(red, green, blue, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

void read_window(int width, int height, Image& out) {
  out.width = width;
  out.height = height;
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
  // GL's first row is the bottom one.
  out.rgb.resize(rows.size());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) std::copy_n(&rows[(height - 1 - y) * row], row, &out.rgb[y * row]);
}

}  // namespace unfurl::render
