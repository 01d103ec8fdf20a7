#include "tools/sfbuild/ray_traced_view.h"

#include <stdexcept>
#include <string>

#include "tools/sfbuild/gl_program.h"

namespace sfbuild {
namespace {

// A triangle that covers the window, its texture coordinates upside down:
// the frame's rows go from the top, OpenGL's from the bottom.
const char* kImageVertexShader = R"(#version 330 core
out vec2 uv;
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  uv = vec2(corner.x, 1.0 - corner.y);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* kImageFragmentShader = R"(#version 330 core
in vec2 uv;
uniform sampler2D image;
out vec4 fragment;
void main() {
  fragment = vec4(texture(image, uv).rgb, 1.0);
}
)";

}  // namespace

RayTracedView::RayTracedView() {
  program_ = linkGlProgram(kImageVertexShader, kImageFragmentShader, "the ray-traced view's");
  glGenVertexArrays(1, &vao_);
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
}

RayTracedView::~RayTracedView() {
  glDeleteTextures(1, &texture_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void RayTracedView::upload(const RenderedFrame& frame) {
  if (frame.rgb.empty()) return;
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of 3 bytes a pixel, unpadded
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, frame.width, frame.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
               frame.rgb.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  hasFrame_ = true;
}

void RayTracedView::draw(int width, int height) const {
  glViewport(0, 0, width, height);
  glDisable(GL_DITHER);
  glDisable(GL_DEPTH_TEST);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!hasFrame_) return;
  glUseProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glUniform1i(glGetUniformLocation(program_, "image"), 0);
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace sfbuild
