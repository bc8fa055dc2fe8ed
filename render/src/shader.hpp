// A linked GLSL program; compile and link errors throw with the log.
#pragma once

#include <string>

#include "gl.hpp"

namespace unfurl::render {

class Shader {
 public:
  Shader(const char* vertex_source, const char* fragment_source);
  ~Shader();
  Shader(const Shader&) = delete;
  Shader& operator=(const Shader&) = delete;

  void use() const { glUseProgram(program_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

}  // namespace unfurl::render
