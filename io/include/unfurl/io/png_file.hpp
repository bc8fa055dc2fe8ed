// PNG files from rendered images (libpng), written completely or not at all.
#pragma once

#include <string>

#include "unfurl/render/framebuffer.hpp"

namespace unfurl::io {

// compression: zlib level 0-9 (1 is fast and small enough for frames).
void write_png(const render::Image& image, const std::string& path, int compression = 1);

}  // namespace unfurl::io
