#include "unfurl/io/png_file.hpp"

#include <png.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <vector>

namespace unfurl::io {

void write_png(const render::Image& image, const std::string& path, int compression) {
  const std::string temp = path + ".partial-" + std::to_string(::getpid());
  FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) throw std::runtime_error(path + ": cannot write");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    std::fclose(file);
    std::remove(temp.c_str());
    throw std::runtime_error(path + ": libpng could not start");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    std::remove(temp.c_str());
    throw std::runtime_error(path + ": writing the PNG failed");
  }
  png_init_io(png, file);
  png_set_compression_level(png, compression);
  png_set_filter(png, 0, PNG_FILTER_SUB);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  const bool ok = std::fflush(file) == 0 && !std::ferror(file);
  std::fclose(file);
  if (!ok || std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    throw std::runtime_error(path + ": writing failed");
  }
}

}  // namespace unfurl::io
