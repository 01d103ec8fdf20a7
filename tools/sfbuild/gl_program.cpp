#include "tools/sfbuild/gl_program.h"

#include <stdexcept>

namespace sfbuild {

namespace {

GLuint compile(GLenum type, const char* source, const std::string& what) {
  GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(what + " shader: " + log);
  }
  return shader;
}

}  // namespace

GLuint linkGlProgram(const char* vertexSource, const char* fragmentSource,
                     const std::string& what) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertexSource, what);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentSource, what);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    glDeleteProgram(program);
    throw std::runtime_error(what + " shader program does not link");
  }
  return program;
}

}  // namespace sfbuild
