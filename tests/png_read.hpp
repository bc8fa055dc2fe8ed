// Reads a PNG as 8-bit RGB (libpng's simplified API), for tests.
#pragma once

#include <png.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "unfurl/render/framebuffer.hpp"

namespace unfurl::test {

inline render::Image read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) throw std::runtime_error(path + ": " + png.message);
  png.format = PNG_FORMAT_RGB;
  render::Image image;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr))
    throw std::runtime_error(path + ": " + png.message);
  return image;
}

}  // namespace unfurl::test
