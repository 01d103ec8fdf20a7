// Draws a BuilderState with OpenGL 3.3 core: objects lit by the scene's
// lights (Phong, as sfrender), the ground grid,
// lights as small yellow spheres, the selection outlined; or, in the id view,
// each object in its flat idColour. Needs a current context.
#pragma once

#include <epoxy/gl.h>

#include <array>

#include "scenefile/mesh.h"
#include "tools/sfbuild/builder_state.h"

namespace sfbuild {

class GlView {
 public:
  GlView();
  ~GlView();
  GlView(const GlView&) = delete;
  GlView& operator=(const GlView&) = delete;

  void draw(const BuilderState& state);

 private:
  struct Mesh {
    GLuint vao = 0, vbo = 0, ebo = 0;
    GLsizei count = 0;
  };
  Mesh upload(const scene::TriangleMesh& mesh);

  GLuint program_ = 0;
  GLint mvpLocation_ = -1, normalLocation_ = -1, colourLocation_ = -1, litLocation_ = -1;
  GLint modelLocation_ = -1, highlightLocation_ = -1, eyeLocation_ = -1;
  GLint lightCountLocation_ = -1, lightPositionsLocation_ = -1, lightColoursLocation_ = -1;
  GLint materialLocation_ = -1;
  std::array<Mesh, std::size(scene::kObjectKinds)> meshes_{};  // by scene::ObjectKind
  Mesh grid_;
};

}  // namespace sfbuild
