// The offscreen context makers this build has (gl_context.cpp picks).
#pragma once

#include <memory>

#include "unfurl/render/gl_context.hpp"

namespace unfurl::render {

#ifdef UNFURL_HAVE_EGL
std::unique_ptr<GlContext> make_egl_context();
#endif
#ifdef UNFURL_HAVE_OSMESA
std::unique_ptr<GlContext> make_osmesa_context();
#endif

}  // namespace unfurl::render
