// A GLSL program from its vertex and fragment shaders, for the builder's
// views. Needs a current OpenGL 3.3 context.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace sfbuild {

// Compiles and links the two shaders into a program; throws
// std::runtime_error naming `what` with the compiler's log when one does
// not compile, or when the program does not link.
GLuint linkGlProgram(const char* vertexSource, const char* fragmentSource, const std::string& what);

}  // namespace sfbuild
