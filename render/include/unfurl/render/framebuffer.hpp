// A multisampled framebuffer to draw into, resolved into a texture that can
// be read back (headless frames) or shown (the GUI's viewport).
#pragma once

#include <cstdint>
#include <vector>


namespace unfurl::render {

// An RGB image, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
  const std::uint8_t* pixel(int x, int y) const { return &rgb[3 * (static_cast<std::size_t>(y) * width + x)]; }
};

class Framebuffer {
 public:
  Framebuffer(int width, int height, int samples = 4);
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Binds the multisampled target and sets the viewport.
  void bind();
  // Resolves the samples into the texture.
  void resolve();
  // Reads the resolved image (after resolve()).
  void read(Image& image);
  unsigned texture() const { return texture_; }

 private:
  int width_, height_;
  unsigned msaa_fbo_ = 0, color_rb_ = 0, depth_rb_ = 0;
  unsigned resolve_fbo_ = 0, texture_ = 0;
};

}  // namespace unfurl::render
