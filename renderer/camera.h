// The camera of RENDERING.md: a pinhole's primary rays, and where in a pixel
// each of its samples lies.
#pragma once

#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "renderer/direction_grid.h"
#include "renderer/render_scene.h"
#include "renderer/render_settings.h"
#include "scenefile/scene.h"

namespace render {

// Primary rays of the scene's camera: a pinhole at the eye, forward and up
// orthonormalised (forward first), the vertical field of view given and the
// horizontal one from the aspect ratio.
class PinholeCamera {
 public:
  PinholeCamera(const scene::Camera& camera, const RenderSettings& settings);
  // The ray through image position (x, y), in pixels from the top-left
  // corner: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
  Ray rayThrough(double x, double y) const { return Ray{eye_, directionThrough(x, y)}; }
  // rayThrough's direction alone, inline: a packet's rays are filled member
  // by member, since a whole Ray copied from a temporary was loaded 16 bytes
  // at a time across the 8-byte stores that made it, and the loads waited.
  glm::dvec3 directionThrough(double x, double y) const {
    double sx = (2.0 * x / width_ - 1.0) * tanHalfWidth_;
    double sy = (1.0 - 2.0 * y / height_) * tanHalfHeight_;
    return glm::normalize(forward_ + sx * right_ + sy * up_);
  }
  // The camera's frame, orthonormal, and the tangents of half its fields of
  // view: rayThrough's terms, for the GPU renderer and for sfbuild's
  // OpenGL view, which must show what the renderer draws.
  const glm::dvec3& eye() const { return eye_; }
  const glm::dvec3& forward() const { return forward_; }
  const glm::dvec3& up() const { return up_; }
  const glm::dvec3& right() const { return right_; }
  double tanHalfWidth() const { return tanHalfWidth_; }
  double tanHalfHeight() const { return tanHalfHeight_; }
  // The directions of the image as a window of a direction grid (the
  // camera's frame, the image's tangent extents), cut into columns x rows.
  GridWindow imageWindow(int columns, int rows) const;

 private:
  glm::dvec3 eye_, forward_, up_, right_;
  double tanHalfHeight_;
  double tanHalfWidth_;
  double width_, height_;
};

// The position of sample `index` of `count` in pixel (i, j): the centre for
// one sample, else point `index` of the pixel's Owen-scrambled Sobol
// sequence (PixelSampleSequence), the same for a given seed whatever the
// thread.
glm::dvec2 samplePosition(int i, int j, int index, int count, std::uint64_t seed);

}  // namespace render
