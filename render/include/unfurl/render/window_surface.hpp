// Drawing into a window's own framebuffer (the workbench's GLFW window),
// with the GL functions loaded through the window system's loader: the
// application needs no GL headers of its own.
#pragma once

#include "unfurl/render/framebuffer.hpp"

namespace unfurl::render {

// Loads the GL functions through `get_proc` (glfwGetProcAddress, ...) for
// the current context. False when they cannot be loaded.
using GlProcLoader = void (*(*)(const char*))();
bool load_gl_functions(GlProcLoader get_proc);

// Binds the window's framebuffer, sets the viewport and clears it.
void begin_window_frame(int width, int height, float red, float green, float blue);

// Clears the framebuffer bound now.
void clear_bound_framebuffer(float red, float green, float blue);

// The window's back buffer as an image (top row first).
void read_window(int width, int height, Image& out);

}  // namespace unfurl::render
