// The one place OpenGL is included: glad's loader (generated at build time
// for GL 3.3 core).
#pragma once

#include <glad/gl.h>
