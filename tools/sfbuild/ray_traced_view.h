// Shows the ray-traced view's latest frame (progressive_render.h) over the
// whole window: a texture of its 8-bit levels, nearest-neighbour, so that a
// coarse level shows as blocks and the full-size one pixel for pixel, as
// sfrender wrote it. Needs a current OpenGL 3.3 context.
#pragma once

#include <epoxy/gl.h>

#include "tools/sfbuild/progressive_render.h"

namespace sfbuild {

class RayTracedView {
 public:
  RayTracedView();
  ~RayTracedView();
  RayTracedView(const RayTracedView&) = delete;
  RayTracedView& operator=(const RayTracedView&) = delete;

  void upload(const RenderedFrame& frame);
  // Forgets the frame shown: until the next upload, draw clears to black.
  void clear() { hasFrame_ = false; }
  void draw(int width, int height) const;

 private:
  GLuint program_ = 0, texture_ = 0, vao_ = 0;
  bool hasFrame_ = false;
};

}  // namespace sfbuild
